// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_BOUNDARY_REFINEMENT_H
#define CGAL_QD_BOUNDARY_REFINEMENT_H

/// \file boundary_refinement.h
/// Step 2 of the quasi-developable segmentation (paper Section 2): the border
/// between every two adjacent charts is moved to a minimum cut of a fuzzy band
/// of faces around it, weighted by dihedral angles (after Katz and Tal,
/// "Hierarchical mesh decomposition using fuzzy clustering and cuts", SIGGRAPH
/// 2003).

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/vsa_segmentation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// diagnostics of `refine_chart_boundaries()`.
struct Refinement_result
{
  Error_code status = Error_code::OK;
  std::size_t number_of_charts = 0;
  std::size_t pairs_refined = 0;  ///< pairs of adjacent charts whose border was moved
  std::size_t pairs_kept = 0;     ///< pairs whose cut would have split a chart, left as they were
  std::size_t faces_moved = 0;    ///< faces whose chart changed
  std::size_t faces_smoothed = 0; ///< of which moved by the final ear removal
  double border_cost_before = 0;  ///< sum of the edge costs (see `refine_chart_boundaries()`) over the borders
  double border_cost_after = 0;
  double time_ms = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};

namespace internal {

typedef boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS> Flow_traits;
typedef boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS,
    boost::property<boost::vertex_index_t, long,
                    boost::property<boost::vertex_color_t, boost::default_color_type,
                                    boost::property<boost::vertex_distance_t, long,
                                                    boost::property<boost::vertex_predecessor_t,
                                                                    Flow_traits::edge_descriptor>>>>,
    boost::property<boost::edge_capacity_t, double,
                    boost::property<boost::edge_residual_capacity_t, double,
                                    boost::property<boost::edge_reverse_t, Flow_traits::edge_descriptor>>>>
    Flow_graph;

inline void add_flow_edge(Flow_graph& g, std::size_t u, std::size_t v, double cap_uv, double cap_vu)
{
  auto capacity = get(boost::edge_capacity, g);
  auto reverse = get(boost::edge_reverse, g);
  const auto e = add_edge(u, v, g).first, r = add_edge(v, u, g).first;
  put(capacity, e, cap_uv);
  put(capacity, r, cap_vu);
  put(reverse, e, r);
  put(reverse, r, e);
}

// The cost of cutting the dual edge between two faces (Katz and Tal 2003):
// length / (1 + d / mean d), with the angular distance d = eta (1 - cos alpha)
// for the dihedral angle alpha, eta = 1 at concave edges and 0.2 at convex ones,
// so concave creases are the cheapest to cut, then convex ones.
template <class TriangleMesh, class VPM, class FIM>
std::vector<double> dual_edge_costs(const TriangleMesh& tm, const VPM& vpm, const FIM& fim,
                                    const std::vector<Face_geometry>& geo,
                                    const std::function<std::size_t(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor)>& hid)
{
  std::vector<double> d(num_halfedges(tm), 0.), length(num_halfedges(tm), 0.);
  double sum = 0;
  std::size_t count = 0;
  for(auto h : halfedges(tm)) {
    const auto o = opposite(h, tm);
    if(is_border(h, tm) || is_border(o, tm)) continue;
    const Face_geometry &a = geo[get(fim, face(h, tm))], &b = geo[get(fim, face(o, tm))];
    const double cosine = a.normal[0] * b.normal[0] + a.normal[1] * b.normal[1] + a.normal[2] * b.normal[2];
    // concave when the other face's centroid is above this face's plane
    const double above = (b.centroid[0] - a.centroid[0]) * a.normal[0] + (b.centroid[1] - a.centroid[1]) * a.normal[1] +
                         (b.centroid[2] - a.centroid[2]) * a.normal[2];
    const double eta = above > 0 ? 1. : 0.2;
    d[hid(h)] = eta * (1. - (std::min)(1., cosine));
    length[hid(h)] = distance3(point_of<TriangleMesh>(source(h, tm), vpm), point_of<TriangleMesh>(target(h, tm), vpm));
    sum += d[hid(h)];
    ++count;
  }
  const double mean = count > 0 && sum > 0 ? sum / count : 1.;
  for(std::size_t i = 0; i < d.size(); ++i) d[i] = length[i] / (1. + d[i] / mean);
  return d;
}

// Gives the pieces of chart `from` (among `faces`) that are not its largest
// connected piece to chart `to`.
template <class TriangleMesh, class FIM>
void give_islands_away(const TriangleMesh& tm, const FIM& fim,
                       const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces,
                       std::vector<std::size_t>& chart, std::size_t from, std::size_t to)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  std::vector<long> piece_of(chart.size(), -1);
  std::vector<std::vector<face_descriptor>> pieces;
  for(face_descriptor s : faces) {
    if(chart[get(fim, s)] != from || piece_of[get(fim, s)] >= 0) continue;
    pieces.emplace_back(1, s);
    piece_of[get(fim, s)] = static_cast<long>(pieces.size() - 1);
    std::vector<face_descriptor>& p = pieces.back();
    for(std::size_t q = 0; q < p.size(); ++q)
      for(auto h : CGAL::halfedges_around_face(halfedge(p[q], tm), tm)) {
        const auto o = opposite(h, tm);
        if(is_border(o, tm)) continue;
        const std::size_t g = get(fim, face(o, tm));
        if(chart[g] == from && piece_of[g] < 0) {
          piece_of[g] = piece_of[get(fim, s)];
          p.push_back(face(o, tm));
        }
      }
  }
  if(pieces.size() < 2) return;
  std::size_t largest = 0;
  for(std::size_t k = 1; k < pieces.size(); ++k)
    if(pieces[k].size() > pieces[largest].size()) largest = k;
  for(std::size_t k = 0; k < pieces.size(); ++k)
    if(k != largest)
      for(face_descriptor f : pieces[k]) chart[get(fim, f)] = to;
}

// Whether chart `c`, connected before the faces of `band` were relabelled
// and the same outside them, is still connected, as far as the faces near the
// band tell: its faces in the band and its faces outside next to one of the
// band (its rim) all reach one another through faces of `c` in the band or
// within `layers` faces of it outside. Every face of `c` outside the band
// reaches the rim through faces of `c` outside the band (on a path to a face
// of the band, the face before it), so that is enough; `false` says nothing,
// and the caller looks at the whole chart. With the rim alone, 1,878 of the
// 3,491 changed pairs of the 138 meshes of libcgal-demo needed the whole
// chart (the rim breaks where the band ends: its pieces meet one or two faces
// further out); with 3 layers, 290. `in_band(i)`: whether face i is in the
// band; `outside`: how many faces of `c` lie outside the band (with none,
// there is no rim to reach); `mark`: a scratch array of the mesh's face
// count, all 0, and left so.
template <class TriangleMesh, class FIM, class InBand>
bool connected_near_band(const TriangleMesh& tm, const FIM& fim,
                         const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_of,
                         const std::vector<std::size_t>& band, const InBand& in_band,
                         const std::vector<std::size_t>& chart, std::size_t c, std::size_t outside,
                         std::vector<char>& mark, int layers = 3)
{
  std::vector<std::size_t> near;  // the faces of c in the band, then layer by layer outside it
  for(std::size_t i : band)
    if(chart[i] == c) {
      mark[i] = 1;
      near.push_back(i);
    }
  auto next_to = [&](std::size_t i, const auto& f) {
    for(auto h : CGAL::halfedges_around_face(halfedge(face_of[i], tm), tm)) {
      const auto o = opposite(h, tm);
      if(!is_border(o, tm)) f(get(fim, face(o, tm)));
    }
  };
  std::size_t layer_begin = near.size();
  for(std::size_t i : band)  // the rim
    next_to(i, [&](std::size_t j) {
      if(chart[j] != c || mark[j] || in_band(j)) return;
      mark[j] = 1;
      near.push_back(j);
    });
  const std::size_t rim = near.size() - layer_begin;
  for(int layer = 1; layer < layers; ++layer) {
    const std::size_t layer_end = near.size();
    for(std::size_t k = layer_begin; k < layer_end; ++k)
      next_to(near[k], [&](std::size_t j) {
        if(chart[j] != c || mark[j] || in_band(j)) return;
        mark[j] = 1;
        near.push_back(j);
      });
    layer_begin = layer_end;
  }
  bool connected = !near.empty() && (rim > 0 || outside == 0);
  if(connected) {
    // through the faces marked 1, marking those reached 2
    std::size_t reached = 1;
    std::vector<std::size_t> queue(1, near.front());
    mark[near.front()] = 2;
    for(std::size_t q = 0; q < queue.size(); ++q)
      next_to(queue[q], [&](std::size_t j) {
        if(mark[j] != 1) return;
        mark[j] = 2;
        queue.push_back(j);
        ++reached;
      });
    connected = reached == near.size();
  }
  for(std::size_t i : near) mark[i] = 0;
  return connected;
}

// Ear removal: a face with one neighbour in its own chart and two in another
// chart X moves to X. Each move shortens the borders by one edge, keeps both
// charts connected (the face is a leaf of its chart) and never empties a
// chart. Returns the number of moves.
template <class TriangleMesh, class FIM>
std::size_t remove_ears(const TriangleMesh& tm, const FIM& fim, std::vector<std::size_t>& chart,
                        const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_of)
{
  std::size_t moves = 0;
  std::vector<std::size_t> queue(chart.size());
  for(std::size_t i = 0; i < chart.size(); ++i) queue[i] = i;
  std::vector<char> queued(chart.size(), 1);
  for(std::size_t q = 0; q < queue.size(); ++q) {
    const std::size_t i = queue[q];
    queued[i] = 0;
    std::size_t own = 0, other[2] = {0, 0}, other_chart[2] = {std::size_t(-1), std::size_t(-1)};
    for(auto h : CGAL::halfedges_around_face(halfedge(face_of[i], tm), tm)) {
      const auto o = opposite(h, tm);
      if(is_border(o, tm)) continue;
      const std::size_t c = chart[get(fim, face(o, tm))];
      if(c == chart[i]) ++own;
      else if(other_chart[0] == std::size_t(-1) || other_chart[0] == c) other_chart[0] = c, ++other[0];
      else other_chart[1] = c, ++other[1];
    }
    if(own != 1 || other[0] != 2) continue;
    chart[i] = other_chart[0];
    ++moves;
    for(auto h : CGAL::halfedges_around_face(halfedge(face_of[i], tm), tm)) {
      const auto o = opposite(h, tm);
      if(is_border(o, tm)) continue;
      const std::size_t g = get(fim, face(o, tm));
      if(!queued[g]) {
        queued[g] = 1;
        queue.push_back(g);
      }
    }
  }
  return moves;
}

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// moves the border between every two adjacent charts to a minimum cut (paper
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// Section 2, step 2). For charts A and B, the fuzzy band is the set of faces
/// of A and B whose geodesic distance (along face centroids) to their common
/// border is at most `w sqrt(min(area(A), area(B)))`; the faces of the band
/// that touch the rest of A are tied to the source, those that touch the rest
/// of B to the sink. Cutting the dual edge of a mesh edge costs its length
/// divided by 1 + d / mean(d), with the angular distance d = eta (1 - cos alpha)
/// of Katz and Tal (eta = 1 at concave edges, 0.2 at convex ones). The band is
/// relabelled by Boost.Graph's `boykov_kolmogorov_max_flow`. Pieces of A that
/// the cut separates from A's largest piece go to B, and conversely; a new
/// border that would still disconnect A or B is not applied, so no chart
/// vanishes or splits. The pairs are processed in increasing order of their
/// chart ids. Last, ears are removed: a face with one neighbour in its chart
/// and two in another chart moves to that chart, until none is left.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `ReadWritePropertyMap` from faces to an integral chart id; only faces of
///         the band change, and they take the id of the neighbouring chart
/// \param np optional named parameters:
///   - `CGAL_QD::parameters::refinement_band_width`: w above (default 0.15)
///   - `vertex_point_map`, `face_index_map`, `halfedge_index_map`
/// \returns a `Refinement_result`; on invalid input (the statuses of `segment_by_error_controlled_vsa()`)
///          nothing is written.
template <class TriangleMesh, class FaceChartMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Refinement_result refine_chart_boundaries(const TriangleMesh& tm, FaceChartMap face_chart,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  const auto start = std::chrono::steady_clock::now();
  Refinement_result result;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, np);
  const double width = choose_parameter(get_parameter(np, internal_np::refinement_band_width_t()), 0.15);
  result.status = internal::validate_mesh_to_segment(tm, vpm);
  if(result.status != Error_code::OK) return result;

  std::vector<std::size_t> chart, ids;
  const std::size_t n = internal::read_charts(tm, face_chart, fim, chart, ids);
  result.number_of_charts = n;
  const std::vector<internal::Face_geometry> geo = internal::face_geometry(tm, vpm, fim);
  const std::function<std::size_t(halfedge_descriptor)> hid = [&](halfedge_descriptor h) {
    return static_cast<std::size_t>(get(him, h));
  };
  const std::vector<double> cost = internal::dual_edge_costs(tm, vpm, fim, geo, hid);

  const std::size_t nf = chart.size();
  std::vector<face_descriptor> face_of(nf);
  for(face_descriptor f : faces(tm)) face_of[get(fim, f)] = f;
  std::vector<double> area(n, 0.);
  std::vector<std::vector<face_descriptor>> members(n);
  for(std::size_t i = 0; i < nf; ++i) {
    area[chart[i]] += geo[i].area;
    members[chart[i]].push_back(face_of[i]);
  }
  auto border_cost = [&]() {
    double c = 0;
    for(halfedge_descriptor h : halfedges(tm))
      if(!is_border_edge(h, tm) && chart[get(fim, face(h, tm))] < chart[get(fim, face(opposite(h, tm), tm))])
        c += cost[hid(h)];
    return c;
  };
  result.border_cost_before = border_cost();

  // adjacent pairs, in increasing order
  std::map<std::pair<std::size_t, std::size_t>, std::vector<face_descriptor>> pairs;  // -> faces along the border
  for(halfedge_descriptor h : halfedges(tm)) {
    if(is_border_edge(h, tm)) continue;
    const std::size_t a = chart[get(fim, face(h, tm))], b = chart[get(fim, face(opposite(h, tm), tm))];
    if(a < b) {
      auto& v = pairs[std::make_pair(a, b)];
      v.push_back(face(h, tm));
      v.push_back(face(opposite(h, tm), tm));
    }
  }

  // which charts are connected: the pairs keep them so, and where one was
  // before a pair, whether it still is can mostly be told near the band
  // (one search per chart, over one array of marks)
  std::vector<char> connected(n, 0), mark(nf, 0);
  for(std::size_t c = 0; c < n; ++c) connected[c] = internal::chart_is_connected(tm, fim, members[c], chart, c, &mark);
  std::vector<double> dist(nf, std::numeric_limits<double>::infinity());
  std::vector<long> node(nf, -1);
  for(const auto& pair : pairs) {
    const std::size_t A = pair.first.first, B = pair.first.second;
    // the seeds may be stale after the previous pairs; keep the faces still on the border
    std::vector<face_descriptor> seeds;
    for(face_descriptor f : pair.second) {
      const std::size_t c = chart[get(fim, f)];
      if(c != A && c != B) continue;
      const std::size_t other = c == A ? B : A;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
        if(!is_border(opposite(h, tm), tm) && chart[get(fim, face(opposite(h, tm), tm))] == other) {
          seeds.push_back(f);
          break;
        }
    }
    if(seeds.empty()) continue;
    const double radius = width * std::sqrt((std::min)(area[A], area[B]));
    // Dijkstra from the border over the faces of A and B
    typedef std::pair<double, std::size_t> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    std::vector<std::size_t> touched;
    for(face_descriptor f : seeds) {
      const std::size_t i = get(fim, f);
      if(dist[i] == 0) continue;
      dist[i] = 0;
      touched.push_back(i);
      queue.emplace(0., i);
    }
    std::vector<std::size_t> band;
    while(!queue.empty()) {
      const Item it = queue.top();
      queue.pop();
      if(it.first > dist[it.second]) continue;
      band.push_back(it.second);
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of[it.second], tm), tm)) {
        const halfedge_descriptor o = opposite(h, tm);
        if(is_border(o, tm)) continue;
        const std::size_t g = get(fim, face(o, tm));
        if(chart[g] != A && chart[g] != B) continue;
        const double d = it.first + internal::distance3(geo[it.second].centroid, geo[g].centroid);
        if(d <= radius && d < dist[g]) {
          if(dist[g] == std::numeric_limits<double>::infinity()) touched.push_back(g);
          dist[g] = d;
          queue.emplace(d, g);
        }
      }
    }
    std::sort(band.begin(), band.end());
    for(std::size_t k = 0; k < band.size(); ++k) node[band[k]] = static_cast<long>(k);

    // every chart keeps a core outside the band: if the band swallows a chart,
    // its face furthest from the border is tied to its terminal
    const std::size_t S = band.size(), T = band.size() + 1;
    internal::Flow_graph g(band.size() + 2);
    const double infinite = 1e30;
    bool core[2] = {false, false};
    for(std::size_t i : band)
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of[i], tm), tm)) {
        const halfedge_descriptor o = opposite(h, tm);
        if(is_border(o, tm)) continue;
        const std::size_t j = get(fim, face(o, tm));
        if(chart[j] != A && chart[j] != B) continue;
        if(node[j] >= 0) {
          if(i < j) internal::add_flow_edge(g, node[i], node[j], cost[hid(h)], cost[hid(h)]);
        } else {
          const bool in_a = chart[j] == A;
          core[in_a ? 0 : 1] = true;
          // j keeps its chart: cutting between i and j costs the edge
          if(in_a) internal::add_flow_edge(g, S, node[i], cost[hid(h)], 0.);
          else internal::add_flow_edge(g, node[i], T, cost[hid(h)], 0.);
        }
      }
    for(int side = 0; side < 2; ++side) {
      if(core[side]) continue;
      const std::size_t label = side == 0 ? A : B;
      std::size_t far = std::size_t(-1);
      for(std::size_t i : band)
        if(chart[i] == label && (far == std::size_t(-1) || dist[i] > dist[far])) far = i;
      if(side == 0) internal::add_flow_edge(g, S, node[far], infinite, 0.);
      else internal::add_flow_edge(g, node[far], T, infinite, 0.);
    }
    boost::boykov_kolmogorov_max_flow(g, S, T);
    auto color = get(boost::vertex_color, g);
    std::vector<face_descriptor> both(members[A]);
    both.insert(both.end(), members[B].begin(), members[B].end());
    std::vector<std::size_t> before(both.size());
    for(std::size_t k = 0; k < both.size(); ++k) before[k] = chart[get(fim, both[k])];
    bool changed = false;
    std::size_t outside_a = members[A].size(), outside_b = members[B].size();
    for(std::size_t i : band) {
      --(chart[i] == A ? outside_a : outside_b);
      // black: the source side, reachable from A's core in the residual graph
      const std::size_t label = get(color, node[i]) == boost::black_color ? A : B;
      changed = changed || label != chart[i];
      chart[i] = label;
    }
    if(changed) {
      // pieces of A cut off from A's main part go to B, and conversely,
      // where the faces near the band do not already show both connected
      const auto in_band = [&](std::size_t i) { return node[i] >= 0; };
      auto near = [&](std::size_t c, std::size_t outside) {
        return connected[c] && internal::connected_near_band(tm, fim, face_of, band, in_band, chart, c, outside, mark);
      };
      bool both_connected = near(A, outside_a);
      if(!both_connected) internal::give_islands_away(tm, fim, both, chart, A, B);
      both_connected = both_connected && near(B, outside_b);
      if(!both_connected) {
        internal::give_islands_away(tm, fim, both, chart, B, A);
        both_connected =
            internal::chart_is_connected(tm, fim, both, chart, A) && internal::chart_is_connected(tm, fim, both, chart, B);
      }
      if(both_connected) {
        connected[A] = connected[B] = 1;
        // A and B exchanged faces; keep the member lists up to date
        std::vector<face_descriptor> ma, mb;
        for(face_descriptor f : both) (chart[get(fim, f)] == A ? ma : mb).push_back(f);
        members[A].swap(ma);
        members[B].swap(mb);
        area[A] = area[B] = 0;
        for(face_descriptor f : members[A]) area[A] += geo[get(fim, f)].area;
        for(face_descriptor f : members[B]) area[B] += geo[get(fim, f)].area;
        ++result.pairs_refined;
      } else {
        for(std::size_t k = 0; k < both.size(); ++k) chart[get(fim, both[k])] = before[k];
        ++result.pairs_kept;
      }
    }
    for(std::size_t i : touched) dist[i] = std::numeric_limits<double>::infinity();
    for(std::size_t i : band) node[i] = -1;
  }
  result.faces_smoothed = internal::remove_ears(tm, fim, chart, face_of);
  result.border_cost_after = border_cost();
  for(std::size_t i = 0; i < nf; ++i)
    if(ids[chart[i]] != static_cast<std::size_t>(get(face_chart, face_of[i]))) ++result.faces_moved;
  typedef typename boost::property_traits<FaceChartMap>::value_type Id;
  for(face_descriptor f : faces(tm))
    if(get(face_chart, f) != static_cast<Id>(ids[chart[get(fim, f)]])) put(face_chart, f, static_cast<Id>(ids[chart[get(fim, f)]]));
  result.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace CGAL_QD

#endif // CGAL_QD_BOUNDARY_REFINEMENT_H
