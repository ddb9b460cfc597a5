// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_BOUNDARY_DENOISING_H
#define CGAL_QD_BOUNDARY_DENOISING_H

/// \file boundary_denoising.h
/// Step 3 of the quasi-developable segmentation (paper Section 2, optional):
/// least-squares denoising of the vertices on the borders between charts.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/vsa_segmentation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// diagnostics of `denoise_chart_boundaries()`.
struct Denoising_result
{
  Error_code status = Error_code::OK;
  std::size_t number_of_border_vertices = 0;  ///< vertices on a border between two charts
  std::size_t rejected_moves = 0;             ///< updates undone because a face would fold or degenerate
  double max_displacement = 0;                ///< the largest distance a vertex moved
  double time_ms = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};

/// \ingroup PkgCGAL_QDRef
/// moves every vertex on a border between charts toward the planes of its
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// \param out receives the new position of every vertex
/// charts (paper Section 2, step 3). The faces of the vertex's star take the
/// normal n_c of their chart (its area-weighted mean face normal), and the
/// vertex is moved by the update of the paper's reference [38],
/// v_i <- v_i + lambda sum_j sum_{f in F_ij} n_f n_f^T (v_j - v_i),
/// a gradient step on E(v_i) = sum_j sum_{f in F_ij} (n_f . (v_i - v_j))^2, F_ij
/// being the faces of edge ij. lambda is 1 / (the number of terms), which makes
/// every step a descent step. The chart normals are those of the input; a move
/// that would fold a face of the star (turn its normal by more than 90 degrees)
/// or make it degenerate is undone.
///
/// The positions of `tm` are read from `vertex_point_map` and the new
/// positions of all vertices are written to `out`, which may be the same map
/// (then `tm` changes) or another one (then it does not).
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `ReadablePropertyMap` from faces to an integral chart id
/// \tparam OutPointMap a model of `WritablePropertyMap` from vertices to a point type constructible
///         from three `double`
/// \param np optional named parameters:
///   - `CGAL_QD::parameters::denoising_iterations`: the number of updates (default 10)
///   - `vertex_point_map`, `vertex_index_map`, `face_index_map`
/// \returns a `Denoising_result`; on invalid input (the statuses of `segment_by_error_controlled_vsa()`)
///          nothing is written.
template <class TriangleMesh, class FaceChartMap, class OutPointMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Denoising_result denoise_chart_boundaries(const TriangleMesh& tm, const FaceChartMap& face_chart, OutPointMap out,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef std::array<double, 3> P;

  const auto start = std::chrono::steady_clock::now();
  Denoising_result result;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const std::size_t iterations = choose_parameter(get_parameter(np, internal_np::denoising_iterations_t()), 10);
  result.status = internal::validate_mesh_to_segment(tm, vpm);
  if(result.status != Error_code::OK) return result;

  std::vector<std::size_t> chart, ids;
  const std::size_t n = internal::read_charts(tm, face_chart, fim, chart, ids);
  const std::vector<internal::Face_geometry> geo = internal::face_geometry(tm, vpm, fim);
  std::vector<P> chart_normal(n, P{0., 0., 0.});
  for(std::size_t i = 0; i < chart.size(); ++i)
    for(int k = 0; k < 3; ++k) chart_normal[chart[i]][k] += geo[i].area * geo[i].normal[k];
  for(P& c : chart_normal) {
    const double l = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if(l > 0) for(int k = 0; k < 3; ++k) c[k] /= l;
  }

  std::vector<P> point(num_vertices(tm));
  for(vertex_descriptor v : vertices(tm)) point[get(vim, v)] = internal::point_of<TriangleMesh>(v, vpm);
  std::vector<vertex_descriptor> moving;
  for(vertex_descriptor v : vertices(tm)) {
    if(halfedge(v, tm) == GT::null_halfedge()) continue;
    std::size_t first = std::size_t(-1);
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, tm), tm)) {
      if(is_border(h, tm)) continue;
      const std::size_t c = chart[get(fim, face(h, tm))];
      if(first == std::size_t(-1)) first = c;
      else if(c != first) {
        moving.push_back(v);
        break;
      }
    }
  }
  result.number_of_border_vertices = moving.size();

  // the normal of a face of the star of v with v at position p; false if degenerate
  auto star_ok = [&](vertex_descriptor v, const P& p) {
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, tm), tm)) {
      if(is_border(h, tm)) continue;
      const P& a = point[get(vim, source(h, tm))];
      const P& b = point[get(vim, target(next(h, tm), tm))];
      // the face is (a, v, b) in this order
      const double u[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]}, w[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const double nn[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
      const double len = std::sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
      const internal::Face_geometry& g = geo[get(fim, face(h, tm))];
      // a face keeps at least a millionth of its area and turns by less than 90 degrees
      if(!(len > 2e-6 * g.area)) return false;
      if(nn[0] * g.normal[0] + nn[1] * g.normal[1] + nn[2] * g.normal[2] <= 0) return false;
    }
    return true;
  };

  std::vector<P> update(moving.size());
  for(std::size_t it = 0; it < iterations; ++it) {
    for(std::size_t m = 0; m < moving.size(); ++m) {
      const vertex_descriptor v = moving[m];
      const P& p = point[get(vim, v)];
      double step[3] = {0., 0., 0.};
      std::size_t terms = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, tm), tm)) {
        // the edge from v to source(h); its faces are face(h) and face(opposite(h))
        const P& q = point[get(vim, source(h, tm))];
        const double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        for(halfedge_descriptor side : {h, opposite(h, tm)}) {
          if(is_border(side, tm)) continue;
          const P& nf = chart_normal[chart[get(fim, face(side, tm))]];
          const double s = nf[0] * d[0] + nf[1] * d[1] + nf[2] * d[2];
          for(int k = 0; k < 3; ++k) step[k] += s * nf[k];
          ++terms;
        }
      }
      P q = p;
      if(terms > 0) for(int k = 0; k < 3; ++k) q[k] += step[k] / double(terms);
      update[m] = q;
    }
    // Jacobi update; a move that spoils a face is undone
    for(std::size_t m = 0; m < moving.size(); ++m) {
      if(star_ok(moving[m], update[m])) point[get(vim, moving[m])] = update[m];
      else ++result.rejected_moves;
    }
  }

  typedef typename boost::property_traits<OutPointMap>::value_type Out_point;
  for(vertex_descriptor v : vertices(tm)) {
    const P& p = point[get(vim, v)];
    result.max_displacement = (std::max)(result.max_displacement,
                                         internal::distance3(p, internal::point_of<TriangleMesh>(v, vpm)));
    put(out, v, Out_point(p[0], p[1], p[2]));
  }
  result.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace CGAL_QD

#endif // CGAL_QD_BOUNDARY_DENOISING_H
