// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_SMOOTH_CHART_CUTS_H
#define CGAL_QD_SMOOTH_CHART_CUTS_H

/// \file smooth_chart_cuts.h
/// Replaces the zigzag cuts inside charts (seams with the same chart on both
/// sides, which follow triangle edges) by smooth curves through the triangles.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/internal/chart_boundary_smoother.h>
#include <CGAL_QD/internal/parallel.h>
#include <CGAL_QD/internal/validation.h>
#include <CGAL_QD/segmentation_measures.h>
#include <CGAL_QD/smooth_chart_boundaries.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/container_hash/hash.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// Constrained for the smoother: an edge that must stay or a cut not being
// smoothed; the halves of a split edge stay what the edge was.
template <class ECM, class CutMap>
struct Constrained_or_cut_map
{
  typedef typename boost::property_traits<CutMap>::key_type key_type;
  typedef bool value_type;
  typedef bool reference;
  typedef boost::read_write_property_map_tag category;

  ECM ecm;
  CutMap cuts;

  friend bool get(const Constrained_or_cut_map& m, const key_type& e) { return get(m.ecm, e) || get(m.cuts, e); }
  friend void put(const Constrained_or_cut_map& m, const key_type& e, bool value) { put(m.cuts, e, value); }
};

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// replaces the cuts inside charts by smooth curves that cut through
/// triangles, so that the slits of the pieces can be cut with scissors.
///
/// A cut is a seam with the same chart on both of its sides (a slit that lets
/// a chart flatten, as the merging leaves them). Each cut curve (a chain of
/// cut edges between junctions, mesh-border vertices, chart borders, other
/// constrained edges and its free ends) is smoothed separately like a border
/// between two charts in `smooth_chart_boundaries()`: the faces of its chart
/// within five vertex rings are split into the two sides of the curve (beyond
/// a free end of the cut, the faces go to the side they are nearer to, which
/// extends the curve virtually), the two sides are cut along the smoothed copy
/// of the curve within three vertex rings, and the new curve becomes the cut.
/// The curve keeps its ends, every sharp edge on it stays, and the change is
/// made only if both sides stay connected and keep their topology and no
/// triangle is degenerate; otherwise fewer smoothing rounds are tried, and if
/// none fits, the cut is left as it was. The charts of the faces do not change.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`: the distances of each curve's band to its smoothed
///         copy, the check of its two charts' topology and the move of the cut on several threads;
///         the result is the same
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph`
/// \tparam FaceChartMap a model of `ReadWritePropertyMap` from faces to an integral chart id; it
///         must accept the new faces, which receive the chart of the face they come from
/// \tparam CutMap a model of `ReadWritePropertyMap` from edges to `bool` that accepts new edges
/// \param tm the triangle mesh, refined in place: new vertices on edges, faces split
/// \param face_chart the chart of every face
/// \param cuts the cut edges to smooth; on return, the edges of the new cuts are `true` and the
///        edges they replaced `false` (edges with different charts on their sides are ignored)
/// \param np optional named parameters:
///   - `number_of_iterations`: the smoothing rounds of each cut (default 32; fewer are tried when
///     a cut does not fit)
///   - `sharpness_angle`: the dihedral angle in degrees beyond which a cut edge is sharp and
///     stays (default 40)
///   - `edge_is_constrained_map`: a `ReadablePropertyMap` from edges to `bool`: edges that must stay
///     (other cuts, for instance); no new cut crosses them (default: none)
///   - `vertex_point_map`: a `ReadWritePropertyMap`, receives the points of the new vertices
///     (default: the mesh's)
/// \returns a `Boundary_smoothing_result` whose curves are the cut curves and whose zigzags are
///          those of the cuts; `EMPTY_MESH`, `NOT_TRIANGLE_MESH`, `INVALID_COORDINATES` or
///          `DEGENERATE_FACE` on invalid input, in which case nothing is changed.
/// \sa `smooth_chart_boundaries()`, `seam_zigzag()`, `flatten_charts()`
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class FaceChartMap, class CutMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Boundary_smoothing_result smooth_chart_cuts(TriangleMesh& tm, FaceChartMap face_chart, CutMap cuts,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<FaceChartMap>::value_type Label;

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

  auto same_chart = [&](halfedge_descriptor h) {
    return !is_border_edge(h, tm) && get(face_chart, face(h, tm)) == get(face_chart, face(opposite(h, tm), tm));
  };
  auto cut_edges = [&]() {
    std::vector<edge_descriptor> out;
    for(edge_descriptor e : edges(tm))
      if(get(cuts, e) && same_chart(halfedge(e, tm))) out.push_back(e);
    return out;
  };
  const auto measure_np = CGAL::parameters::vertex_point_map(vpm);
  result.zigzag_before = seam_zigzag(tm, cut_edges(), measure_np).zigzag;

  // the cut curves, before any change; their ends: vertices on the mesh border,
  // on a chart border or on an edge that must stay
  std::vector<std::pair<std::vector<vertex_descriptor>, bool>> curves;
  Label largest{};  // the largest chart id: the two ids above it are the two sides of a cut while it is smoothed
  {
    bool first = true;
    for(face_descriptor f : faces(tm)) {
      const Label l = get(face_chart, f);
      if(first || l > largest) largest = l;
      first = false;
    }
    const auto vim = CGAL::get_initialized_vertex_index_map(tm);
    const auto him = CGAL::get_initialized_halfedge_index_map(tm);
    std::vector<halfedge_descriptor> seams;
    for(edge_descriptor e : cut_edges()) seams.push_back(halfedge(e, tm));
    auto is_end = [&](vertex_descriptor v) {
      for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
        if(is_border_edge(h, tm) || !same_chart(h) || get(ecm, edge(h, tm))) return true;
      return false;
    };
    for(const auto& c : internal::seam_curves(tm, seams, vim, him, is_end)) curves.push_back({c.vertices, c.closed});
  }
  const Label side_a = largest + 1, side_b = largest + 2;
  result.number_of_curves = curves.size();

  typedef internal::Constrained_or_cut_map<typename std::remove_const<decltype(ecm)>::type, CutMap> Either;
  const Either either{ecm, cuts};
  typedef internal::Chart_boundary_smoother<TriangleMesh, typename std::remove_const<decltype(vpm)>::type,
                                            FaceChartMap, Either>
      Smoother;
  const std::size_t rings = 3, region_rings = rings + 2;
  Smoother smoother(tm, vpm, face_chart, either, sharp, rings, rounds);
  smoother.run_in_parallel(internal::number_of_workers<ConcurrencyTag>() > 1);

  typedef std::unordered_set<face_descriptor, boost::hash<face_descriptor>> Face_set;
  for(const auto& c : curves) {
    const std::vector<vertex_descriptor>& curve = c.first;
    const std::size_t nv = curve.size(), ne = c.second ? nv : nv - 1;
    // the curve's edges, still cuts of one chart
    std::vector<halfedge_descriptor> hs;
    for(std::size_t i = 0; i < ne; ++i) {
      const auto h = halfedge(curve[i], curve[(i + 1) % nv], tm);
      if(!h.second || !get(cuts, edge(h.first, tm)) || !same_chart(h.first) ||
         get(face_chart, face(h.first, tm)) != get(face_chart, face(hs.empty() ? h.first : hs.front(), tm)))
        break;
      hs.push_back(h.first);
    }
    if(ne == 0 || hs.size() != ne) {
      ++result.curves_failed;
      continue;
    }
    const Label chart = get(face_chart, face(hs.front(), tm));

    // the faces of the chart within a few vertex rings of the curve
    Face_set region;
    {
      std::unordered_set<vertex_descriptor, boost::hash<vertex_descriptor>> reached(curve.begin(), curve.end());
      std::vector<vertex_descriptor> ring(curve.begin(), curve.end());
      for(std::size_t r = 0; r < region_rings; ++r) {
        std::vector<vertex_descriptor> next_ring;
        for(vertex_descriptor v : ring)
          for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm)) {
            if(is_border(h, tm) || get(face_chart, face(h, tm)) != chart || !region.insert(face(h, tm)).second)
              continue;
            for(vertex_descriptor w : CGAL::vertices_around_face(h, tm))
              if(reached.insert(w).second) next_ring.push_back(w);
          }
        ring.swap(next_ring);
      }
    }
    // the two sides: breadth-first from the faces along the curve, without
    // crossing the curve or any other cut or constrained edge
    for(halfedge_descriptor h : hs) put(cuts, edge(h, tm), false);
    std::unordered_map<face_descriptor, int, boost::hash<face_descriptor>> side;
    std::vector<face_descriptor> queue;
    bool conflict = false;
    for(int s = 0; s < 2; ++s)
      for(halfedge_descriptor h : hs) {
        const face_descriptor f = face(s == 0 ? h : opposite(h, tm), tm);
        const auto it = side.emplace(f, s);
        if(it.second) queue.push_back(f);
        else if(it.first->second != s) conflict = true;
      }
    std::unordered_set<halfedge_descriptor, boost::hash<halfedge_descriptor>> on_curve;
    for(halfedge_descriptor h : hs) {
      on_curve.insert(h);
      on_curve.insert(opposite(h, tm));
    }
    for(std::size_t q = 0; q < queue.size() && !conflict; ++q) {
      const int s = side.at(queue[q]);
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(queue[q], tm), tm)) {
        const halfedge_descriptor o = opposite(h, tm);
        if(is_border(o, tm) || on_curve.count(h) || get(either, edge(h, tm)) || !region.count(face(o, tm))) continue;
        if(side.emplace(face(o, tm), s).second) queue.push_back(face(o, tm));
      }
    }
    if(conflict) {
      for(halfedge_descriptor h : hs) put(cuts, edge(h, tm), true);
      ++result.curves_failed;
      continue;
    }
    // the edges between the two sides that are not on the curve: they stay
    std::unordered_set<halfedge_descriptor, boost::hash<halfedge_descriptor>> extension;
    for(const auto& fs : side) {
      put(face_chart, fs.first, fs.second == 0 ? side_a : side_b);
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(fs.first, tm), tm)) {
        if(on_curve.count(h)) continue;
        const auto it = side.find(face(opposite(h, tm), tm));
        if(!is_border(opposite(h, tm), tm) && it != side.end() && it->second != fs.second)
          extension.insert(h);
      }
    }
    const auto outcome = smoother.smooth(curve, c.second);
    // the new cut: the edges between the two sides, but the extensions; the
    // faces go back to their chart
    std::vector<face_descriptor> stack;
    for(const auto& fs : side) stack.push_back(fs.first);
    while(!stack.empty()) {
      const face_descriptor f = stack.back();
      stack.pop_back();
      const Label l = get(face_chart, f);
      if(l != side_a && l != side_b) continue;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
        const halfedge_descriptor o = opposite(h, tm);
        if(is_border(o, tm)) continue;
        const Label lo = get(face_chart, face(o, tm));
        if((lo == side_a || lo == side_b) && lo != l && !extension.count(h) && !extension.count(o))
          put(cuts, edge(h, tm), true);
        if(lo == side_a || lo == side_b) stack.push_back(face(o, tm));
      }
      put(face_chart, f, chart);
    }
    internal::count_outcome(result, outcome);
  }
  internal::record_changes(result, smoother);
  result.zigzag_after = seam_zigzag(tm, cut_edges(), measure_np).zigzag;
  result.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace CGAL_QD

#endif // CGAL_QD_SMOOTH_CHART_CUTS_H
