// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_SEGMENTATION_MEASURES_H
#define CGAL_QD_SEGMENTATION_MEASURES_H

/// \file segmentation_measures.h
/// Measures of a segmentation that a person cutting the charts out sees: the
/// zigzag of the seam curves and the compactness of the charts.

#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// the zigzag of the seam curves, computed by `seam_zigzag()`.
///
/// A seam curve is a chain of seam edges between two junctions (vertices with a
/// number of seam edges other than 2), or a closed loop of seam edges. Its
/// zigzag is its 3D length divided by its 3D length after a few rounds of
/// moving every inner vertex halfway towards the midpoint of its two curve
/// neighbours (ends fixed; a closed loop has no ends): a smooth curve gives
/// about 1.00 to 1.02, a staircase along triangle edges 1.2 to 1.4.
struct Seam_zigzag
{
  std::size_t number_of_curves = 0;
  std::vector<double> curve_length;           ///< per curve: the 3D length
  std::vector<double> smoothed_curve_length;  ///< per curve: the 3D length after the smoothing rounds
  std::vector<double> curve_zigzag;           ///< per curve: length / smoothed length (1 for a zero length)
  std::vector<bool> curve_is_closed;          ///< per curve: whether it is a closed loop
  double length = 0;                          ///< the sum of the curve lengths
  double smoothed_length = 0;                 ///< the sum of the smoothed lengths
  double zigzag = 1;  ///< `length / smoothed_length`, the length-weighted zigzag; 1 without seams
};

/// \ingroup PkgCGAL_QDRef
/// the compactness of the charts of a segmentation, computed by `chart_compactness()`.
struct Chart_compactness
{
  std::size_t number_of_charts = 0;
  std::vector<std::size_t> chart_id;  ///< per chart (in increasing order of ids): the id given by the map
  std::vector<double> area;           ///< per chart: the 3D area
  std::vector<double> perimeter;      ///< per chart: the length of its border, cuts inside it counted twice
  std::vector<double> chart_compactness;  ///< per chart: `4 pi area / perimeter^2` (0 without perimeter)
  double compactness = 0;  ///< the area-weighted mean of the per-chart compactness
};

namespace internal {

// A chain of seam edges: `vertices` has one more element than `halfedges`
// for an open curve, and as many for a closed one (the first vertex is not
// repeated). halfedges[i] goes from vertices[i] to vertices[i + 1].
template <class TriangleMesh>
struct Seam_curve
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<typename GT::vertex_descriptor> vertices;
  std::vector<typename GT::halfedge_descriptor> halfedges;
  bool closed = false;
};

// Splits the seam edges (given by one halfedge each, without repetition) into
// curves: chains between ends (vertices with a number of seam edges other
// than 2, or for which `is_end` holds), and closed loops.
template <class TriangleMesh, class VIM, class HIM, class IsEnd>
std::vector<Seam_curve<TriangleMesh>> seam_curves(
    const TriangleMesh& tm, const std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& seams,
    const VIM& vim, const HIM& him, const IsEnd& is_end)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  std::vector<char> seam(num_halfedges(tm), 0), visited(num_halfedges(tm), 0);
  std::vector<std::size_t> degree(num_vertices(tm), 0);
  for(halfedge_descriptor h : seams) {
    seam[get(him, h)] = seam[get(him, opposite(h, tm))] = 1;
    ++degree[get(vim, source(h, tm))];
    ++degree[get(vim, target(h, tm))];
  }
  auto end = [&](vertex_descriptor v) { return degree[get(vim, v)] != 2 || is_end(v); };
  auto mark = [&](halfedge_descriptor h) { visited[get(him, h)] = visited[get(him, opposite(h, tm))] = 1; };
  // the other seam halfedge leaving the (degree-2) target of h
  auto continuation = [&](halfedge_descriptor h) {
    for(halfedge_descriptor g : CGAL::halfedges_around_source(target(h, tm), tm))
      if(seam[get(him, g)] && g != opposite(h, tm)) return g;
    return GT::null_halfedge();
  };

  std::vector<Seam_curve<TriangleMesh>> curves;
  // open curves, from every end
  for(halfedge_descriptor s : seams)
    for(halfedge_descriptor h : {s, opposite(s, tm)}) {
      if(visited[get(him, h)] || !end(source(h, tm))) continue;
      Seam_curve<TriangleMesh> c;
      c.vertices.push_back(source(h, tm));
      for(;;) {
        mark(h);
        c.halfedges.push_back(h);
        c.vertices.push_back(target(h, tm));
        if(end(target(h, tm))) break;
        h = continuation(h);
        if(h == GT::null_halfedge() || visited[get(him, h)]) break;
      }
      curves.push_back(std::move(c));
    }
  // closed loops: every vertex has two seam edges
  for(halfedge_descriptor s : seams) {
    if(visited[get(him, s)]) continue;
    Seam_curve<TriangleMesh> c;
    c.closed = true;
    halfedge_descriptor h = s;
    do {
      mark(h);
      c.vertices.push_back(source(h, tm));
      c.halfedges.push_back(h);
      h = continuation(h);
    } while(h != GT::null_halfedge() && !visited[get(him, h)]);
    curves.push_back(std::move(c));
  }
  return curves;
}

inline double polyline_length(const std::vector<std::array<double, 3>>& p, bool closed)
{
  double length = 0;
  for(std::size_t i = 0; i + 1 < p.size(); ++i) length += distance3(p[i], p[i + 1]);
  if(closed && p.size() > 2) length += distance3(p.back(), p.front());
  return length;
}

// Jacobi rounds of moving every free vertex halfway towards the midpoint of its
// two neighbours; the ends of an open polyline and the vertices with
// `fixed[i]` stay (`fixed` may be empty).
inline void smooth_polyline(std::vector<std::array<double, 3>>& p, bool closed, std::size_t rounds,
                            const std::vector<char>& fixed = {})
{
  const std::size_t n = p.size();
  if(n < 3) return;
  std::vector<std::array<double, 3>> q(n);
  for(std::size_t r = 0; r < rounds; ++r) {
    for(std::size_t i = 0; i < n; ++i) {
      const bool inner = closed || (i > 0 && i + 1 < n);
      if(!inner || (!fixed.empty() && fixed[i])) {
        q[i] = p[i];
        continue;
      }
      const std::array<double, 3>& a = p[(i + n - 1) % n];
      const std::array<double, 3>& b = p[(i + 1) % n];
      for(int k = 0; k < 3; ++k) q[i][k] = 0.5 * p[i][k] + 0.25 * (a[k] + b[k]);
    }
    p.swap(q);
  }
}

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// measures the zigzag of the seam curves formed by `seam_edges` (see
/// `Seam_zigzag`): a curve along which a person can cut with scissors has a
/// zigzag close to 1.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam EdgeRange a range of `edge_descriptor` (repetitions are ignored)
/// \param tm the mesh
/// \param seam_edges the seam edges, e.g. `Segmentation_result::seam_edges`
/// \param np optional named parameters:
///   - `number_of_iterations`: the smoothing rounds (default 20)
///   - `vertex_point_map`, `vertex_index_map`, `halfedge_index_map`
/// \returns the per-curve and overall zigzag; without seams, no curve and a zigzag of 1.
template <class TriangleMesh, class EdgeRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
Seam_zigzag seam_zigzag(const TriangleMesh& tm, const EdgeRange& seam_edges,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, np);
  const std::size_t rounds = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 20);

  std::vector<halfedge_descriptor> seams;
  std::vector<char> taken(num_halfedges(tm), 0);
  for(const auto& e : seam_edges) {
    const halfedge_descriptor h = halfedge(e, tm);
    if(taken[get(him, h)]) continue;
    taken[get(him, h)] = taken[get(him, opposite(h, tm))] = 1;
    seams.push_back(h);
  }
  const auto curves = internal::seam_curves(tm, seams, vim, him, [](vertex_descriptor) { return false; });

  Seam_zigzag z;
  z.number_of_curves = curves.size();
  for(const auto& c : curves) {
    std::vector<std::array<double, 3>> p;
    for(vertex_descriptor v : c.vertices) p.push_back(internal::point_of<TriangleMesh>(v, vpm));
    const double length = internal::polyline_length(p, c.closed);
    internal::smooth_polyline(p, c.closed, rounds);
    const double smoothed = internal::polyline_length(p, c.closed);
    z.curve_length.push_back(length);
    z.smoothed_curve_length.push_back(smoothed);
    z.curve_zigzag.push_back(smoothed > 0 ? length / smoothed : 1.);
    z.curve_is_closed.push_back(c.closed);
    z.length += length;
    z.smoothed_length += smoothed;
  }
  z.zigzag = z.smoothed_length > 0 ? z.length / z.smoothed_length : 1.;
  return z;
}

/// \ingroup PkgCGAL_QDRef
/// measures how compact the charts are: per chart, its 3D area `A`, its
/// perimeter `P` (the length of its edges on the mesh border or next to
/// another chart, plus the cuts inside it counted twice, once per side) and
/// its compactness `4 pi A / P^2`, which is 1 for a flat disk and tends to 0 for
/// long thin strips (curved charts can exceed 1). A chart without perimeter
/// (a closed surface) gets 0.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `ReadablePropertyMap` from faces to an integral chart id
/// \param tm the triangle mesh
/// \param face_chart the chart of every face
/// \param np optional named parameters:
///   - `edge_is_constrained_map`: a `ReadablePropertyMap` from edges to `bool`, the cuts inside charts (default: none)
///   - `vertex_point_map`, `face_index_map`
/// \returns per chart (in increasing order of chart ids) the area, perimeter and compactness,
///          and the area-weighted mean compactness.
template <class TriangleMesh, class FaceChartMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Chart_compactness chart_compactness(const TriangleMesh& tm, const FaceChartMap& face_chart,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto constrained = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                            CGAL::Static_boolean_property_map<edge_descriptor, false>());

  Chart_compactness c;
  std::vector<std::size_t> chart;
  c.number_of_charts = internal::read_charts(tm, face_chart, fim, chart, c.chart_id);
  c.area.assign(c.number_of_charts, 0.);
  c.perimeter.assign(c.number_of_charts, 0.);
  for(const auto& f : faces(tm)) {
    const halfedge_descriptor h = halfedge(f, tm);
    c.area[chart[get(fim, f)]] +=
        0.5 * internal::double_area3(internal::point_of<TriangleMesh>(source(h, tm), vpm),
                                     internal::point_of<TriangleMesh>(target(h, tm), vpm),
                                     internal::point_of<TriangleMesh>(target(next(h, tm), tm), vpm));
  }
  // every halfedge of a chart face on the chart's border adds its length to that chart
  for(const auto& e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm);
    const double length = internal::distance3(internal::point_of<TriangleMesh>(source(h, tm), vpm),
                                              internal::point_of<TriangleMesh>(target(h, tm), vpm));
    const bool cut = get(constrained, e);
    for(halfedge_descriptor g : {h, opposite(h, tm)}) {
      if(is_border(g, tm)) continue;
      const halfedge_descriptor o = opposite(g, tm);
      const std::size_t k = chart[get(fim, face(g, tm))];
      if(cut || is_border(o, tm) || chart[get(fim, face(o, tm))] != k) c.perimeter[k] += length;
    }
  }
  double total_area = 0, weighted = 0;
  c.chart_compactness.assign(c.number_of_charts, 0.);
  for(std::size_t k = 0; k < c.number_of_charts; ++k) {
    const double p = c.perimeter[k];
    c.chart_compactness[k] = p > 0 ? 4 * 3.14159265358979323846 * c.area[k] / (p * p) : 0.;
    total_area += c.area[k];
    weighted += c.area[k] * c.chart_compactness[k];
  }
  c.compactness = total_area > 0 ? weighted / total_area : 0.;
  return c;
}

} // namespace CGAL_QD

#endif // CGAL_QD_SEGMENTATION_MEASURES_H
