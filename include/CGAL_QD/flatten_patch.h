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
#include <CGAL_QD/internal/point_scale.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#ifdef CGAL_QD_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL_QD {
namespace internal {

template <class EigenSolver>
struct Is_simplicial_LDLT : std::false_type
{};
template <class Matrix, int UpLo, class Ordering>
struct Is_simplicial_LDLT<Eigen::SimplicialLDLT<Matrix, UpLo, Ordering>> : std::true_type
{};

// X = A^-1 B with the factorisation P A P^T = L D L^T of `ldlt`. A B of two
// columns (the u and v of a flattening) is solved in one pass over L for each
// triangular solve, where Eigen makes one per column; every column goes
// through the same operations in the same order as in Eigen's
// SimplicialLDLT::solve(), so X is the same to the last bit. Any other B, or
// an L not in compressed storage, goes to Eigen's solve().
template <class Solver>
void solve_ldlt_columns(const Solver& ldlt, const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
{
  const auto& L = ldlt.matrixL().nestedExpression();  // strictly lower part, by columns
  if(B.cols() != 2 || L.innerNonZeroPtr()) {
    X = ldlt.solve(B);
    return;
  }
  // the two columns of a row side by side
  Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> y;
  if(ldlt.permutationP().size() > 0) y = ldlt.permutationP() * B;
  else y = B;  // natural ordering
  double* Y = y.data();
  const Eigen::Index n = L.cols();
  const auto* outer = L.outerIndexPtr();
  const auto* inner = L.innerIndexPtr();
  const double* value = L.valuePtr();
  const auto& d = ldlt.vectorD();
  // L y = y
  for(Eigen::Index j = 0; j < n; ++j) {
    const double a = Y[2 * j], b = Y[2 * j + 1];
    if(a == 0 && b == 0) continue;
    for(auto p = outer[j], e = outer[j + 1]; p < e; ++p) {
      double* yi = Y + 2 * inner[p];
      if(a != 0) yi[0] -= a * value[p];
      if(b != 0) yi[1] -= b * value[p];
    }
  }
  // D y = y
  for(Eigen::Index i = 0; i < n; ++i) {
    const double inverse = 1. / d[i];
    Y[2 * i] = inverse * Y[2 * i];
    Y[2 * i + 1] = inverse * Y[2 * i + 1];
  }
  // L^T y = y
  for(Eigen::Index j = n - 1; j >= 0; --j) {
    double a = Y[2 * j], b = Y[2 * j + 1];
    for(auto p = outer[j], e = outer[j + 1]; p < e; ++p) {
      const double* yi = Y + 2 * inner[p];
      a -= value[p] * yi[0];
      b -= value[p] * yi[1];
    }
    Y[2 * j] = a;
    Y[2 * j + 1] = b;
  }
  if(ldlt.permutationPinv().size() > 0) X = ldlt.permutationPinv() * y;
  else X = y;
}

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// A sparse direct solver of symmetric systems for `flatten_patch()`, wrapping
/// an Eigen solver that reads the lower triangle (`SimplicialLDLT`,
/// `SimplicialLLT`, `CholmodSupernodalLLT`, `CholmodDecomposition`, ...).
/// A model of the solver concept of `flatten_patch()`: `factorize(A)` then
/// `solve(B, X)` for a matrix `B` with several columns, both returning whether
/// they succeeded, and `name()`.
template <class EigenSolver>
class Eigen_symmetric_solver
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  explicit Eigen_symmetric_solver(const char* name) : m_name(name) {}
  /// copies the configuration, not a factorisation (Eigen's solvers are not all copyable)
  Eigen_symmetric_solver(const Eigen_symmetric_solver& other) : m_name(other.m_name) {}
  Eigen_symmetric_solver& operator=(const Eigen_symmetric_solver& other)
  {
    m_solver.reset();
    m_name = other.m_name;
    return *this;
  }
  bool factorize(const Matrix& lower)
  {
    m_solver.reset(new EigenSolver);
    m_solver->compute(lower);
    return m_solver->info() == Eigen::Success;
  }
  bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
  {
    if(!m_solver) return false;
    if constexpr(internal::Is_simplicial_LDLT<EigenSolver>::value) {
      if(m_solver->info() != Eigen::Success || m_solver->rows() != B.rows()) return false;
      internal::solve_ldlt_columns(*m_solver, B, X);
    } else {
      X = m_solver->solve(B);
    }
    return m_solver->info() == Eigen::Success && X.allFinite();
  }
  const char* name() const { return m_name; }

private:
  std::unique_ptr<EigenSolver> m_solver;
  const char* m_name;
};

/// \ingroup PkgCGAL_QDRef
/// Eigen's `SimplicialLDLT` with AMD ordering.
struct Simplicial_LDLT_solver
    : Eigen_symmetric_solver<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>>>
{
  Simplicial_LDLT_solver() : Eigen_symmetric_solver("SimplicialLDLT") {}
};

#ifdef CGAL_QD_USE_CHOLMOD
/// \ingroup PkgCGAL_QDRef
/// SuiteSparse's CHOLMOD (it chooses simplicial or supernodal), available when
/// CMake found it (`CGAL_QD_USE_CHOLMOD` is then defined).
struct Cholmod_solver
    : Eigen_symmetric_solver<Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower>>
{
  Cholmod_solver() : Eigen_symmetric_solver("CHOLMOD") {}
};
#endif

/// \ingroup PkgCGAL_QDRef
/// the default solver of `flatten_patch()`: `Simplicial_LDLT_solver` (see
/// `doc/performance.md` for the comparison with CHOLMOD).
typedef Simplicial_LDLT_solver Default_flattening_solver;

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

inline double milliseconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

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
/// the system instead.
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
///        (default: `Default_flattening_solver`, that is `Simplicial_LDLT_solver`;
///        `Cholmod_solver` when CMake found SuiteSparse).
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
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(3 * result.number_of_faces + n);
    std::vector<double> diagonal(n, 0.);
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
        if(ri >= 0) diagonal[ri] += w;
        if(rj >= 0) diagonal[rj] += w;
        if(ri >= 0 && rj >= 0) {
          triplets.emplace_back((std::max)(ri, rj), (std::min)(ri, rj), -w);
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
    for(std::size_t r = 0; r < n; ++r) triplets.emplace_back(r, r, diagonal[r]);
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(triplets.begin(), triplets.end());
    std::vector<Eigen::Triplet<double>>().swap(triplets);  // freed before the factorisation
    result.number_of_nonzeros = static_cast<std::size_t>(A.nonZeros());
    result.time_assembly_ms = internal::milliseconds_since(t);

    // ------------------------------------------- factorisation and solve
    auto good = [&](const Eigen::MatrixXd& sol) {
      if(!sol.allFinite()) return false;
      const Eigen::MatrixXd residual = A.selfadjointView<Eigen::Lower>() * sol - B;
      return residual.norm() <= 1e-8 * (B.norm() + A.norm() * sol.norm());
    };
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
