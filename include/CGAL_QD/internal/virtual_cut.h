// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_VIRTUAL_CUT_H
#define CGAL_QD_INTERNAL_VIRTUAL_CUT_H

// Virtual cutting (paper Section 3.2) and the angle-space problem of a patch.
//
// The inner loops are joined to the outer loop one at a time by shortest paths
// along interior edges: a multi-source Dijkstra grows from everything already
// joined (the outer loop, the joined loops and the cut paths) and stops at the
// first vertex of a loop not yet joined, so the closest loop comes first. The
// mesh itself is never cut: the border of the cut patch is traced directly, one
// "corner" per visit of a vertex, each corner carrying the surface angle of its
// wedge (the faces between its incoming and outgoing border-or-cut edges).

#include <CGAL_QD/internal/lpfb_solver.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

template <class TriangleMesh>
struct Virtual_cut_border
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;

  Lpfb_problem problem;
  std::vector<halfedge_descriptor> corner_halfedge;  // halfedge leaving corner i (face on its left)
  std::vector<vertex_descriptor> corner_vertex;
  // original loops (loop 0 is the outer loop): interior-side halfedges in order
  std::vector<std::vector<halfedge_descriptor>> loop_halfedges;
  std::vector<double> loop_length;
  std::unordered_set<edge_descriptor> cut_edges;
  double cut_length = 0;
};

// angle at target(h) of the face of h
template <class TriangleMesh, class VPM>
double corner_angle(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                    const TriangleMesh& tm, const VPM& vpm)
{
  const auto o = point_of<TriangleMesh>(target(h, tm), vpm);
  const auto a = point_of<TriangleMesh>(source(h, tm), vpm);
  const auto b = point_of<TriangleMesh>(target(next(h, tm), tm), vpm);
  const double u[3] = {a[0] - o[0], a[1] - o[1], a[2] - o[2]};
  const double w[3] = {b[0] - o[0], b[1] - o[1], b[2] - o[2]};
  const double c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                    u[0] * w[0] + u[1] * w[1] + u[2] * w[2]);
}

// Builds the cut border of a validated patch. `outer` is the index in
// patch.loops of the outer loop. Returns false if the traced border is not a
// single loop (which validation should already have excluded).
// The target angles are the corner angles measured with `angle_vpm`, the
// lengths of the cut edges those of `vpm` and the length of every border edge
// `border_length(e)` (`angle_vpm` and `border_length` differ from `vpm` when the
// border is fitted to another embedding, or seams are given common lengths).
template <class TriangleMesh, class VPM, class VIM, class AngleVPM, class BorderLength>
bool build_virtual_cut_border(const TriangleMesh& tm, const Patch<TriangleMesh>& patch, std::size_t outer,
                              const VPM& vpm, const VIM& vim, Virtual_cut_border<TriangleMesh>& out,
                              const AngleVPM& angle_vpm, const BorderLength& border_length)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  const std::size_t K = patch.loops.size();
  const std::size_t nv = num_vertices(tm);

  // loops in the order outer first; loop_of: loop id of a border vertex
  std::vector<int> loop_of(nv, -1);
  std::vector<std::size_t> order;
  order.push_back(outer);
  for(std::size_t i = 0; i < K; ++i) if(i != outer) order.push_back(i);
  out.loop_halfedges.assign(K, {});
  out.loop_length.assign(K, 0.);
  std::size_t border_edges = 0;
  for(std::size_t l = 0; l < K; ++l) {
    // the border halfedges run with the outside on their left; their opposites,
    // walked backwards, run with the surface on their left
    const halfedge_descriptor b = patch.loops[order[l]];
    std::vector<halfedge_descriptor>& hs = out.loop_halfedges[l];
    halfedge_descriptor h = b;
    do {
      hs.push_back(opposite(h, tm));
      loop_of[get(vim, target(h, tm))] = static_cast<int>(l);
      h = prev(h, tm);
    } while(h != b);
    out.loop_length[l] = patch.loop_length[order[l]];
    border_edges += hs.size();
  }

  // ------------------------------------------------------------ cut paths
  out.cut_edges.clear();
  out.cut_length = 0;
  if(K > 1) {
    std::vector<vertex_descriptor> vertex_of(nv);
    for(vertex_descriptor v : patch.vertices) vertex_of[get(vim, v)] = v;
    std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
    std::vector<halfedge_descriptor> pred(nv, GT::null_halfedge());  // halfedge into the vertex
    typedef std::pair<double, std::size_t> Entry;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
    auto add_source = [&](vertex_descriptor v) {
      const std::size_t i = get(vim, v);
      dist[i] = 0;
      pred[i] = GT::null_halfedge();
      heap.push(Entry(0., i));
    };
    std::vector<char> joined(K, 0);
    auto join_loop = [&](std::size_t l) {
      joined[l] = 1;
      for(halfedge_descriptor h : out.loop_halfedges[l]) add_source(source(h, tm));
    };
    join_loop(0);
    for(std::size_t round = 1; round < K; ++round) {
      std::size_t found = nv;
      while(!heap.empty()) {
        const Entry e = heap.top();
        heap.pop();
        if(e.first > dist[e.second]) continue;
        const int l = loop_of[e.second];
        if(l >= 0 && !joined[l]) { found = e.second; break; }
        for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(vertex_of[e.second], tm), tm)) {
          if(is_border_edge(h, tm)) continue;
          const vertex_descriptor w = source(h, tm);
          const std::size_t wi = get(vim, w);
          const double nd = e.first + distance3(point_of<TriangleMesh>(w, vpm),
                                                point_of<TriangleMesh>(target(h, tm), vpm));
          if(nd < dist[wi]) {
            dist[wi] = nd;
            pred[wi] = opposite(h, tm);
            heap.push(Entry(nd, wi));
          }
        }
      }
      if(found == nv) return false;
      const std::size_t l = static_cast<std::size_t>(loop_of[found]);
      // walk the path back to the joined set; its inner vertices become sources
      std::vector<vertex_descriptor> path_vertices;
      for(halfedge_descriptor h = pred[found]; h != GT::null_halfedge(); h = pred[get(vim, source(h, tm))]) {
        out.cut_edges.insert(edge(h, tm));
        out.cut_length += distance3(point_of<TriangleMesh>(source(h, tm), vpm),
                                    point_of<TriangleMesh>(target(h, tm), vpm));
        if(pred[get(vim, source(h, tm))] != GT::null_halfedge()) path_vertices.push_back(source(h, tm));
      }
      join_loop(l);
      for(vertex_descriptor v : path_vertices) add_source(v);
    }
  }

  // ------------------------------------------------- trace the cut border
  auto is_cut = [&](halfedge_descriptor h) {
    return is_border_edge(h, tm) || (!out.cut_edges.empty() && out.cut_edges.count(edge(h, tm)));
  };
  const std::size_t n = border_edges + 2 * out.cut_edges.size();
  out.corner_halfedge.clear();
  out.corner_halfedge.reserve(n);
  std::vector<double> wedge;  // surface angle at target(corner_halfedge[i])
  wedge.reserve(n);
  const halfedge_descriptor h0 = out.loop_halfedges[0].front();
  halfedge_descriptor h = h0;
  do {
    out.corner_halfedge.push_back(h);
    double angle = corner_angle(h, tm, angle_vpm);
    halfedge_descriptor g = next(h, tm);
    std::size_t guard = 0;
    while(!is_cut(g)) {
      const halfedge_descriptor o = opposite(g, tm);
      angle += corner_angle(o, tm, angle_vpm);
      g = next(o, tm);
      if(++guard > n + patch.faces.size()) return false;
    }
    wedge.push_back(angle);
    h = g;
  } while(h != h0 && out.corner_halfedge.size() <= n);
  if(h != h0 || out.corner_halfedge.size() != n) return false;

  // ------------------------------------------------------------- problem
  Lpfb_problem& pb = out.problem;
  pb.number_of_loops = static_cast<int>(K);
  pb.target_angle.resize(n);
  pb.edge_length.resize(n);
  pb.edge_loop.resize(n);
  pb.corner_group.resize(n);
  pb.group_sum.assign(K, 0.);
  for(std::size_t l = 0; l < K; ++l) {
    const double nl = static_cast<double>(out.loop_halfedges[l].size());
    pb.group_sum[l] = (l == 0 ? nl - 2. : nl + 2.) * pi;
  }
  std::unordered_map<std::size_t, int> interior_group;
  out.corner_vertex.resize(n);
  for(std::size_t i = 0; i < n; ++i) {
    const halfedge_descriptor hi = out.corner_halfedge[i];
    const vertex_descriptor v = source(hi, tm);
    out.corner_vertex[i] = v;
    pb.target_angle[i] = wedge[(i + n - 1) % n];
    pb.edge_length[i] = is_border_edge(hi, tm) ? double(border_length(edge(hi, tm)))
                                               : distance3(point_of<TriangleMesh>(v, vpm),
                                                           point_of<TriangleMesh>(target(hi, tm), vpm));
    if(!(pb.edge_length[i] > 0) || !std::isfinite(pb.edge_length[i])) return false;
    pb.edge_loop[i] = is_border_edge(hi, tm) ? loop_of[get(vim, v)] : -1;
    const int l = loop_of[get(vim, v)];
    if(l >= 0) {
      pb.corner_group[i] = l;
    } else {
      auto it = interior_group.find(get(vim, v));
      if(it == interior_group.end()) {
        it = interior_group.emplace(get(vim, v), static_cast<int>(pb.group_sum.size())).first;
        pb.group_sum.push_back(2. * pi);
      }
      pb.corner_group[i] = it->second;
    }
  }
  return true;
}

// the 3D length of an edge
template <class TriangleMesh, class VPM>
struct Edge_length_3
{
  const TriangleMesh* tm;
  VPM vpm;
  double operator()(typename boost::graph_traits<TriangleMesh>::edge_descriptor e) const
  {
    return distance3(point_of<TriangleMesh>(source(e, *tm), vpm), point_of<TriangleMesh>(target(e, *tm), vpm));
  }
};

template <class TriangleMesh, class VPM, class VIM>
bool build_virtual_cut_border(const TriangleMesh& tm, const Patch<TriangleMesh>& patch, std::size_t outer,
                              const VPM& vpm, const VIM& vim, Virtual_cut_border<TriangleMesh>& out)
{
  return build_virtual_cut_border(tm, patch, outer, vpm, vim, out, vpm, Edge_length_3<TriangleMesh, VPM>{&tm, vpm});
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_VIRTUAL_CUT_H
