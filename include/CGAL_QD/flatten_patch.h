// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_FLATTEN_PATCH_H
#define CGAL_QD_FLATTEN_PATCH_H

/// \file flatten_patch.h
/// LPFB+IP: the length-preserved free boundary, then the intrinsic (cotangent)
/// parameterization of the interior with that border fixed (paper Section 4.1,
/// Eq. 15-18).

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/length_preserved_free_boundary.h>
#include <CGAL_QD/internal/lower_triangle.h>
#include <CGAL_QD/internal/point_scale.h>
#include <CGAL_QD/internal/timing.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/validation.h>
#include <CGAL_QD/sparse_solvers.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <cmath>
#include <cstddef>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// diagnostics of `flatten_patch()`.
struct Flattening_result
{
  Error_code status = Error_code::OK;
  Free_boundary_result border;  ///< the LPFB of the border
  std::size_t number_of_vertices = 0;
  std::size_t number_of_faces = 0;
  std::size_t number_of_border_vertices = 0;
  std::size_t number_of_interior_vertices = 0;  ///< the size of the linear system
  std::size_t number_of_nonzeros = 0;           ///< in the lower triangle of the system
  std::string solver;                           ///< the solver that produced the interior
  bool used_fallback = false;  ///< the first solver failed and `SparseLU` solved the system
  double time_border_ms = 0;         ///< validation, virtual cutting and LPFB
  double time_assembly_ms = 0;       ///< cotangent weights and the system
  double time_factorization_ms = 0;  ///< all factorisations, the fallback's included
  /// the symbolic analysis that a solver such as `Size_adaptive_solver` ran
  /// ahead, on a second thread, while the border and the system were computed
  /// (0 where none ran; overlapped, so not part of the total)
  double time_analysis_ms = 0;
  double time_solve_ms = 0;          ///< the solves for u and v
  double time_total_ms = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};


namespace internal {

struct Uv_pair
{
  double x, y;
  Uv_pair(double a = 0, double b = 0) : x(a), y(b) {}
};

// a writable property map from vertices to Uv_pair, stored by vertex index
template <class VIM>
struct Indexed_uv_map
{
  typedef typename boost::property_traits<VIM>::key_type key_type;
  typedef Uv_pair value_type;
  typedef Uv_pair& reference;
  typedef boost::read_write_property_map_tag category;
  std::vector<Uv_pair>* data;
  VIM vim;
  friend void put(const Indexed_uv_map& m, const key_type& k, const Uv_pair& p) { (*m.data)[get(m.vim, k)] = p; }
  friend Uv_pair get(const Indexed_uv_map& m, const key_type& k) { return (*m.data)[get(m.vim, k)]; }
};

template <class T> const T& unwrap(const T& t) { return t; }
template <class T> const T& unwrap(const std::reference_wrapper<T>& t) { return t.get(); }

// The symbolic analysis of the interior system, run on a second thread by a
// solver that offers it (`Analyzes_ahead`) for a system of its size, while
// `flatten_patch()` validates the patch, solves the border and assembles the
// system. The pattern is found from the mesh alone: a row per vertex that
// no border halfedge ends at, in the order of `vertices(tm)`, and an entry
// per edge between two of them, which is the pattern of the system wherever
// the patch is valid. The solver uses the analysis only if the system has
// exactly that pattern; any failure here leaves it to analyse the system
// itself. The thread only reads the mesh.
template <class Solver>
class Analysis_ahead
{
public:
  template <class TriangleMesh, class VIM>
  Analysis_ahead(Solver& solver, const TriangleMesh& tm, const VIM& vim)
  {
    if constexpr(Analyzes_ahead<Solver>::value) {
      if(!solver.analyzes_ahead(static_cast<std::size_t>(num_vertices(tm)))) return;
      try {
        m_thread = std::thread([this, &solver, &tm, vim] {
          const auto start = std::chrono::steady_clock::now();
          try {
            analyze(solver, tm, vim);
          } catch(...) {
            // the solver analyses the system itself
          }
          m_ms = milliseconds_since(start);
        });
      } catch(...) {
        // no thread: the solver analyses the system itself
      }
    }
  }
  Analysis_ahead(const Analysis_ahead&) = delete;
  Analysis_ahead& operator=(const Analysis_ahead&) = delete;
  ~Analysis_ahead() { wait(); }

  // waits for the analysis; its time in ms (0 where none ran)
  double wait()
  {
    if(m_thread.joinable()) m_thread.join();
    return m_ms;
  }

private:
  template <class TriangleMesh, class VIM>
  static void analyze(Solver& solver, const TriangleMesh& tm, const VIM& vim)
  {
    typedef boost::graph_traits<TriangleMesh> GT;
    const std::size_t nv = num_vertices(tm);
    std::vector<long> row(nv, 0);
    for(typename GT::halfedge_descriptor h : halfedges(tm))
      if(is_border(h, tm)) row[get(vim, target(h, tm))] = -1;
    long n = 0;
    for(typename GT::vertex_descriptor v : vertices(tm)) {
      long& r = row[get(vim, v)];
      r = halfedge(v, tm) == GT::null_halfedge() || r < 0 ? -1 : n++;
    }
    if(!solver.analyzes_ahead(static_cast<std::size_t>(n))) return;
    internal::Lower_triangle_assembly t(n, 3 * static_cast<std::size_t>(num_faces(tm)));
    for(typename GT::face_descriptor f : faces(tm)) {
      const typename GT::halfedge_descriptor h = halfedge(f, tm);
      const long r[3] = {row[get(vim, source(h, tm))], row[get(vim, target(h, tm))],
                         row[get(vim, target(next(h, tm), tm))]};
      for(int k = 0; k < 3; ++k) {
        const long ri = r[(k + 1) % 3], rj = r[(k + 2) % 3];
        if(ri >= 0 && rj >= 0) t.add((std::max)(ri, rj), (std::min)(ri, rj), 1.);
      }
    }
    for(long i = 0; i < n; ++i) t.add(i, i, 1.);
    Eigen::SparseMatrix<double> pattern;
    t.assemble(pattern);
    solver.analyze(pattern);
  }

  std::thread m_thread;
  double m_ms = 0;
};

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// flattens a triangle patch by LPFB+IP: its border at the length-preserved
/// free boundary (every loop, see `compute_length_preserved_free_boundary()`),
/// its interior by the intrinsic parameterization with that border fixed: for
/// every interior vertex i, sum_j w_ij (u_j - u_i) = 0 with the cotangent
/// weights w_ij = (cot gamma_ij + cot xi_ij) / 2.
///
/// The border columns are moved to the right-hand side, so the system has one
/// row per interior vertex and is symmetric; it is factorised once and solved
/// for u and v together. If the solver fails (negative cotangent weights can
/// make the matrix indefinite) or its residual is poor, `Eigen::SparseLU` solves
/// the system instead. A solver that can analyse the pattern of the system
/// ahead (`Size_adaptive_solver` on systems of 100,000 unknowns and more) does
/// so on a second thread, from the mesh, while the border is solved and the
/// system assembled.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexUVMap a model of `WritablePropertyMap` from vertices to a 2D
///         point type constructible from two `double`
/// \param tm a connected triangle patch of genus 0 with at least one border loop
/// \param uv receives the planar position of every vertex of `tm`
/// \param np optional named parameters: those of `compute_length_preserved_free_boundary()`
///        (the longest loop is the outer loop), and
///        `CGAL_QD::parameters::sparse_solver`: a solver object with `bool
///        factorize(const Eigen::SparseMatrix<double>& lower)`, `bool solve(const
///        Eigen::MatrixXd& B, Eigen::MatrixXd& X)` and `const char* name()`
///        (default: `Default_flattening_solver`, that is `Size_adaptive_solver`:
///        `Simplicial_LDLT_solver`, and `Cholmod_supernodal_solver` from 100,000
///        interior vertices where CMake found CHOLMOD; see sparse_solvers.h).
/// \returns a `Flattening_result`; on a status other than `OK` nothing is written.
/// The statuses are those of `compute_length_preserved_free_boundary()`, and
/// `SOLVER_FAILED` when no solver could solve the interior system.
///
/// Coordinates in any finite range are accepted: where the largest |coordinate| is
/// beyond [2^-64, 2^64] the patch is flattened scaled by a power of two (exact) and
/// the UVs, `boundary_length_error` and `cut_length` are scaled back
/// (`COORDINATES_OUT_OF_RANGE` only if a UV would then overflow).
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Flattening_result flatten_patch(const TriangleMesh& tm, VertexUVMap uv,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexUVMap>::value_type Point_2;

  const auto start = std::chrono::steady_clock::now();
  Flattening_result result;
  const auto input_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_const_property_map(CGAL::vertex_point, tm));
  // coordinates beyond [2^-64, 2^64] are scaled by a power of two, which is
  // exact (internal/point_scale.h); the UVs and lengths are scaled back
  const double scale = internal::normalizing_scale(internal::largest_coordinate(vertices(tm), input_vpm));
  const internal::Scaled_point_map<typename std::remove_const<decltype(input_vpm)>::type> vpm{input_vpm, scale};
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  // a copy: the solver keeps its factorisation
  auto solver = internal::unwrap(
      choose_parameter<Default_flattening_solver>(get_parameter(np, internal_np::sparse_solver_t())));
  if(faces(tm).empty()) {
    result.status = Error_code::EMPTY_MESH;
    return result;
  }
  internal::Analysis_ahead<decltype(solver)> analysis(solver, tm, vim);

  // ------------------------------------------------------------- border
  const std::size_t nv = num_vertices(tm);
  std::vector<internal::Uv_pair> buffer(nv);
  std::vector<char> is_border_vertex(nv, 0);
  typedef typename std::remove_const<decltype(vim)>::type VIM;
  internal::Indexed_uv_map<VIM> border_uv{&buffer, vim};
  result.border = internal::length_preserved_free_boundary_impl(
      tm, *faces(tm).begin(), true, GT::null_halfedge(), border_uv, vpm, vim, fim, internal::lpfb_options_from(np),
      [&](vertex_descriptor v) { is_border_vertex[get(vim, v)] = 1; });
  result.time_border_ms = internal::milliseconds_since(start);
  if(!result.border) {
    result.status = result.border.status;
    result.time_total_ms = internal::milliseconds_since(start);
    return result;
  }

  // ----------------------------------------------------------- assembly
  auto t = std::chrono::steady_clock::now();
  std::vector<long> row(nv, -1);
  std::vector<vertex_descriptor> interior;
  for(vertex_descriptor v : vertices(tm)) {
    if(halfedge(v, tm) == GT::null_halfedge()) continue;
    ++result.number_of_vertices;
    if(is_border_vertex[get(vim, v)]) continue;
    row[get(vim, v)] = static_cast<long>(interior.size());
    interior.push_back(v);
  }
  const std::size_t n = interior.size();
  result.number_of_interior_vertices = n;
  result.number_of_border_vertices = result.number_of_vertices - n;
  result.number_of_faces = static_cast<std::size_t>(num_faces(tm));

  Eigen::MatrixXd X(n, 2);
  if(n > 0) {
    internal::Lower_triangle_assembly entries(static_cast<long>(n), 3 * result.number_of_faces);
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, 2);
    for(face_descriptor f : faces(tm)) {
      const halfedge_descriptor h = halfedge(f, tm);
      const vertex_descriptor v[3] = {source(h, tm), target(h, tm), target(next(h, tm), tm)};
      std::array<double, 3> q[3];
      for(int k = 0; k < 3; ++k) q[k] = internal::point_of<TriangleMesh>(v[k], vpm);
      for(int k = 0; k < 3; ++k) {
        // half the cotangent of the corner at v[k] weighs the opposite edge v[i] v[j]
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const double a[3] = {q[i][0] - q[k][0], q[i][1] - q[k][1], q[i][2] - q[k][2]};
        const double b[3] = {q[j][0] - q[k][0], q[j][1] - q[k][1], q[j][2] - q[k][2]};
        const double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
        const double w = 0.5 * (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / std::sqrt(cx * cx + cy * cy + cz * cz);
        const long ri = row[get(vim, v[i])], rj = row[get(vim, v[j])];
        if(ri >= 0) entries.add(ri, ri, w);  // the diagonal, summed as it comes
        if(rj >= 0) entries.add(rj, rj, w);
        if(ri >= 0 && rj >= 0) {
          entries.add((std::max)(ri, rj), (std::min)(ri, rj), -w);
        } else if(ri >= 0) {
          const internal::Uv_pair& p = buffer[get(vim, v[j])];
          B(ri, 0) += w * p.x;
          B(ri, 1) += w * p.y;
        } else if(rj >= 0) {
          const internal::Uv_pair& p = buffer[get(vim, v[i])];
          B(rj, 0) += w * p.x;
          B(rj, 1) += w * p.y;
        }
      }
    }
    Eigen::SparseMatrix<double> A;
    entries.assemble(A);  // the entries are freed before the factorisation
    result.number_of_nonzeros = static_cast<std::size_t>(A.nonZeros());
    result.time_assembly_ms = internal::milliseconds_since(t);

    // ------------------------------------------- factorisation and solve
    auto good = [&](const Eigen::MatrixXd& sol) {
      if(!sol.allFinite()) return false;
      const Eigen::MatrixXd residual = A.selfadjointView<Eigen::Lower>() * sol - B;
      return residual.norm() <= 1e-8 * (B.norm() + A.norm() * sol.norm());
    };
    result.time_analysis_ms = analysis.wait();
    t = std::chrono::steady_clock::now();
    bool ok = solver.factorize(A);
    result.time_factorization_ms = internal::milliseconds_since(t);
    t = std::chrono::steady_clock::now();
    ok = ok && solver.solve(B, X) && good(X);
    result.time_solve_ms = internal::milliseconds_since(t);
    result.solver = solver.name();
    if(!ok) {
      t = std::chrono::steady_clock::now();
      const Eigen::SparseMatrix<double> full = A.selfadjointView<Eigen::Lower>();
      Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
      lu.compute(full);
      result.time_factorization_ms += internal::milliseconds_since(t);
      t = std::chrono::steady_clock::now();
      if(lu.info() == Eigen::Success) {
        X = lu.solve(B);
        ok = lu.info() == Eigen::Success && good(X);
      }
      result.time_solve_ms += internal::milliseconds_since(t);
      result.used_fallback = true;
      result.solver = "SparseLU";
      if(!ok) {
        result.status = Error_code::SOLVER_FAILED;
        result.time_total_ms = internal::milliseconds_since(start);
        return result;
      }
    }
  }

  if(scale != 1.) {
    // scaled back, a flattening larger than its surface could overflow
    bool finite = !(n > 0) || (X / scale).allFinite();
    for(vertex_descriptor v : vertices(tm))
      if(row[get(vim, v)] < 0 && halfedge(v, tm) != GT::null_halfedge())
        finite = finite && std::isfinite(buffer[get(vim, v)].x / scale) && std::isfinite(buffer[get(vim, v)].y / scale);
    if(!finite) {
      result.status = Error_code::COORDINATES_OUT_OF_RANGE;
      result.time_total_ms = internal::milliseconds_since(start);
      return result;
    }
  }
  for(vertex_descriptor v : vertices(tm)) {
    if(halfedge(v, tm) == GT::null_halfedge()) continue;
    const long r = row[get(vim, v)];
    if(r >= 0) put(uv, v, Point_2(X(r, 0) / scale, X(r, 1) / scale));
    else put(uv, v, Point_2(buffer[get(vim, v)].x / scale, buffer[get(vim, v)].y / scale));
  }
  result.border.boundary_length_error /= scale;
  result.border.cut_length /= scale;
  result.time_total_ms = internal::milliseconds_since(start);
  return result;
}

} // namespace CGAL_QD

#endif // CGAL_QD_FLATTEN_PATCH_H
