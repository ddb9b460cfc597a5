// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_SMOOTH_CHART_BOUNDARIES_H
#define CGAL_QD_SMOOTH_CHART_BOUNDARIES_H

/// \file smooth_chart_boundaries.h
/// Replaces the zigzag borders between charts, which follow triangle edges,
/// by smooth curves that cut through triangles: the mesh is refined along the
/// new curves so that a person can cut the charts out with scissors.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/internal/chart_boundary_smoother.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/parallel.h>
#include <CGAL_QD/internal/validation.h>
#include <CGAL_QD/segmentation_measures.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// what `smooth_chart_boundaries()` did.
struct Boundary_smoothing_result
{
  Error_code status = Error_code::OK;
  /// the border curves between two charts (chains of border edges between
  /// junctions, mesh-border vertices and cut ends, or closed loops)
  std::size_t number_of_curves = 0;
  std::size_t curves_smoothed = 0;        ///< replaced by a smooth curve
  std::size_t curves_already_smooth = 0;  ///< left as they were: their zigzag was below 1.01
  std::size_t curves_kept_sharp = 0;      ///< left as they were: every edge is sharp or constrained
  /// left as they were: no smooth curve within the band kept both charts' topology
  std::size_t curves_failed = 0;
  std::size_t vertices_added = 0;
  std::size_t faces_added = 0;
  double zigzag_before = 1;  ///< `seam_zigzag()` of the chart borders and constrained edges, before
  double zigzag_after = 1;   ///< and after
  /// the largest distance between a border curve and its replacement (the
  /// largest distance from a vertex of either curve to the other curve)
  double max_border_move = 0;
  /// `max_border_move` relative to the mean edge length of the original curve
  double max_relative_border_move = 0;
  double time_ms = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};

namespace internal {

// counts what the smoother did with one curve
template <class Outcome>
void count_outcome(Boundary_smoothing_result& result, Outcome outcome)
{
  switch(outcome) {
  case Outcome::SMOOTHED: ++result.curves_smoothed; break;
  case Outcome::ALREADY_SMOOTH: ++result.curves_already_smooth; break;
  case Outcome::KEPT_SHARP: ++result.curves_kept_sharp; break;
  case Outcome::FAILED: ++result.curves_failed; break;
  }
}

// what the smoother changed in the mesh over all its curves
template <class Smoother>
void record_changes(Boundary_smoothing_result& result, const Smoother& smoother)
{
  result.vertices_added = smoother.vertices_added;
  result.faces_added = smoother.faces_added;
  result.max_border_move = smoother.max_move;
  result.max_relative_border_move = smoother.max_relative_move;
}

} // namespace internal


/// \ingroup PkgCGAL_QDRef
/// replaces the borders between charts by smooth curves that cut through
/// triangles, so that the charts can be cut out with scissors along them.
///
/// Each border curve between two charts A and B (a chain of border edges
/// between junctions, mesh-border vertices and ends of cuts, or a closed loop)
/// is smoothed separately: a copy of the curve is smoothed by Jacobi rounds of
/// moving every vertex halfway towards the midpoint of its two neighbours (its
/// ends, and the vertices of sharp or constrained edges, stay), and the faces
/// of A and B within three vertex rings of the curve are cut along the surface
/// curve that follows this copy (the zero set of the signed distance to it):
/// a vertex is inserted on every edge the new curve crosses, the faces are
/// split, and every face takes the chart of its side. A crossing closer than
/// 20 % of the edge to a vertex is moved onto the vertex, so that no sliver
/// appears. The new curve passes through the same junctions and mesh-border
/// ends, and every sharp edge (dihedral angle beyond the threshold) and
/// constrained edge of a border stays a border edge.
///
/// A curve is replaced only if both of its charts stay connected and keep their
/// topology (Euler characteristic, number of border loops, pinch vertices), the
/// curve still meets its ends the same way and no triangle is degenerate;
/// otherwise fewer smoothing rounds are tried, and if none fits, the curve is
/// left unchanged. Curves whose zigzag is already below 1.01 are left
/// unchanged. The border moves by at most about the band width, three edge
/// lengths; `Boundary_smoothing_result::max_relative_border_move` gives the
/// largest move relative to the mean edge length of the curve.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`: the distances of each curve's band to its smoothed
///         copy, the check of its two charts' topology and the move of the cut on several threads;
///         the result is the same
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph`
/// \tparam FaceChartMap a model of `ReadWritePropertyMap` from faces to an integral chart id; it
///         must accept the new faces (e.g. a `Surface_mesh` property map or an associative map)
/// \param tm the triangle mesh, refined in place: new vertices on edges, faces split
/// \param face_chart the chart of every face; the faces that change side and every new face
///        receive the chart of their side
/// \param np optional named parameters:
///   - `number_of_iterations`: the smoothing rounds of each curve (default 32; fewer are tried when
///     a curve does not fit)
///   - `sharpness_angle`: the dihedral angle in degrees beyond which a border edge is sharp and
///     stays (default 40)
///   - `edge_is_constrained_map`: a `ReadWritePropertyMap` from edges to `bool`: cuts inside charts
///     (and any other edge) that must stay; the halves of a split constrained edge are constrained
///     (default: none)
///   - `vertex_point_map`: a `ReadWritePropertyMap`, receives the points of the new vertices
///     (default: the mesh's)
/// \returns a `Boundary_smoothing_result`; `EMPTY_MESH`, `NOT_TRIANGLE_MESH`,
///          `INVALID_COORDINATES` or `DEGENERATE_FACE` on invalid input, in which case nothing is
///          changed.
/// \sa `seam_zigzag()`, `flatten_charts()` (the charts change shape: flatten them again)
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class FaceChartMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Boundary_smoothing_result smooth_chart_boundaries(TriangleMesh& tm, FaceChartMap face_chart,
                                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;

  const auto start = std::chrono::steady_clock::now();
  Boundary_smoothing_result result;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, tm));
  const auto ecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                    CGAL::Static_boolean_property_map<edge_descriptor, false>());
  const std::size_t rounds = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 32);
  const double sharp = choose_parameter(get_parameter(np, CGAL::internal_np::sharpness_angle), 40.);

  result.status = internal::validate_mesh_to_segment(tm, vpm);
  if(result.status != Error_code::OK) return result;

  const auto measure_np = CGAL::parameters::vertex_point_map(vpm);
  result.zigzag_before = seam_zigzag(tm, internal::chart_seams(tm, face_chart, ecm), measure_np).zigzag;

  typedef internal::Chart_boundary_smoother<TriangleMesh, typename std::remove_const<decltype(vpm)>::type,
                                            FaceChartMap, typename std::remove_const<decltype(ecm)>::type>
      Smoother;
  Smoother smoother(tm, vpm, face_chart, ecm, sharp, 3, rounds, true);
  smoother.run_in_parallel(internal::number_of_workers<ConcurrencyTag>() > 1);

  // the curves, as vertex chains, before any change
  std::vector<std::pair<std::vector<vertex_descriptor>, bool>> curves;
  {
    const auto vim = CGAL::get_initialized_vertex_index_map(tm);
    const auto him = CGAL::get_initialized_halfedge_index_map(tm);
    std::vector<halfedge_descriptor> borders;
    for(edge_descriptor e : edges(tm)) {
      const halfedge_descriptor h = halfedge(e, tm);
      if(!is_border_edge(h, tm) && get(face_chart, face(h, tm)) != get(face_chart, face(opposite(h, tm), tm)))
        borders.push_back(h);
    }
    for(const auto& c : internal::seam_curves(tm, borders, vim, him,
                                              [&](vertex_descriptor v) { return smoother.is_end_vertex(v); }))
      curves.push_back({c.vertices, c.closed});
  }
  result.number_of_curves = curves.size();
  for(const auto& c : curves) internal::count_outcome(result, smoother.smooth(c.first, c.second));
  internal::record_changes(result, smoother);
  result.zigzag_after = seam_zigzag(tm, internal::chart_seams(tm, face_chart, ecm), measure_np).zigzag;
  result.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace CGAL_QD

#endif // CGAL_QD_SMOOTH_CHART_BOUNDARIES_H
