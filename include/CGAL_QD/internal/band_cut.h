// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_BAND_CUT_H
#define CGAL_QD_INTERNAL_BAND_CUT_H

// The cut of a band of faces between two charts A and B along the zero set of
// a signed distance phi, planned on a copy of their combinatorics (node ids
// and labelled triangles) and checked before `Chart_boundary_smoother`
// changes the mesh: islands removed, crossings near a vertex snapped onto it,
// every band face split along phi = 0 and labelled by its sign, and the two
// charts' topology compared before and after.

#include <CGAL_QD/internal/labelled_triangles.h>
#include <CGAL_QD/internal/parallel.h>
#include <CGAL_QD/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// A node of the band: a vertex of A or B
struct Band_node
{
  std::array<double, 3> p;
  int side = 0;         // +1: only A faces, -1: only B faces, 0: both
  bool locked = false;  // next to a face outside the band, the mesh border or a constrained edge
  bool fixed = false;   // phi stays 0
  bool in_band = false;
  int curve_index = -1;  // index in the curve, or -1
  double phi = 0, raw = 0;
};

class Band_cut
{
public:
  typedef std::array<double, 3> P;
  typedef Labelled_triangle Tri;  // label 0: A, 1: B

  static constexpr double snap_fraction = 0.2;  // crossings closer to a vertex snap onto it

  // a band face split along phi = 0
  struct Face_plan
  {
    std::size_t face;                                       // index in `tris`
    std::vector<std::pair<std::size_t, std::size_t>> cuts;  // diagonals, in order
    std::vector<Tri> tris;
  };

  // the copy: the nodes, the faces of A and B and which of them are in the band
  std::vector<Band_node> nodes;
  std::vector<Tri> tris;
  std::vector<char> in_band;
  // the plan: the faces after the cut (`tris`' own, then the new ones), the
  // new nodes (ids from `nodes.size()` on) on the edges that phi crosses,
  // as (plus, minus) node pairs, and the faces split
  std::vector<Tri> after;
  std::vector<P> new_points;
  std::vector<std::pair<std::size_t, std::size_t>> split_edges;
  std::vector<Face_plan> plans;
  // whether `verify()` and `move()` run their independent parts on the
  // threads of CGAL::Parallel_tag (the same results)
  bool parallel = false;

  // `task(i)` for i in [0, n), on the threads of CGAL::Parallel_tag where `parallel`
  template <class Task>
  void for_each(std::size_t n, const Task& task) const
  {
    if(parallel)
      for_each_index<CGAL::Parallel_tag>(n, task);
    else
      for_each_index<CGAL::Sequential_tag>(n, task);
  }

  // Flips the sign of every component of positive (negative) band nodes,
  // connected through band edges, that reaches no locked node of side A (B):
  // it would be an island of one chart inside the other.
  void remove_islands()
  {
    std::vector<std::vector<std::size_t>> adjacent(nodes.size());
    for(std::size_t i = 0; i < tris.size(); ++i)
      if(in_band[i])
        for(int k = 0; k < 3; ++k) adjacent[tris[i].n[k]].push_back(tris[i].n[(k + 1) % 3]);
    for(int sign : {1, -1}) {
      std::vector<int> component(nodes.size(), -1);
      std::vector<char> anchored;
      std::vector<std::size_t> size;
      for(std::size_t x = 0; x < nodes.size(); ++x) {
        if(!nodes[x].in_band || !(nodes[x].phi * sign > 0) || component[x] >= 0) continue;
        const int c = int(anchored.size());
        anchored.push_back(0);
        size.push_back(0);
        std::vector<std::size_t> queue{x};
        component[x] = c;
        for(std::size_t q = 0; q < queue.size(); ++q) {
          const Band_node& n = nodes[queue[q]];
          ++size.back();
          if(n.locked && n.side == sign) anchored.back() = 1;
          for(std::size_t y : adjacent[queue[q]])
            if(component[y] < 0 && nodes[y].phi * sign > 0) {
              component[y] = c;
              queue.push_back(y);
            }
        }
      }
      if(std::find(anchored.begin(), anchored.end(), 1) == anchored.end()) {
        // no anchor at all (a chart inside the band): keep the largest component
        if(size.empty()) continue;
        anchored[std::size_t(std::max_element(size.begin(), size.end()) - size.begin())] = 1;
      }
      for(std::size_t x = 0; x < nodes.size(); ++x)
        if(component[x] >= 0 && !anchored[std::size_t(component[x])]) nodes[x].phi = -nodes[x].phi;
    }
  }

  // phi set to 0 at the free nodes that phi crosses an edge near
  void snap()
  {
    std::vector<char> snap(nodes.size(), 0);
    for(std::size_t i = 0; i < tris.size(); ++i) {
      if(!in_band[i]) continue;
      for(int k = 0; k < 3; ++k) {
        const std::size_t u = tris[i].n[k], v = tris[i].n[(k + 1) % 3];
        const double pu = nodes[u].phi, pv = nodes[v].phi;
        if(!(pu * pv < 0)) continue;
        const double t = pu / (pu - pv);  // from u
        if(t < snap_fraction && !nodes[u].locked) snap[u] = 1;
        if(t > 1 - snap_fraction && !nodes[v].locked) snap[v] = 1;
      }
    }
    for(std::size_t x = 0; x < nodes.size(); ++x)
      if(snap[x]) nodes[x].phi = 0;
  }

  double phi_of(std::size_t x) const { return x < nodes.size() ? nodes[x].phi : 0.; }
  const P& position(std::size_t x) const { return x < nodes.size() ? nodes[x].p : new_points[x - nodes.size()]; }

  // the label of a face: the sign of phi at its nodes, else of the raw phi summed, else `fallback`
  int label_of(const std::array<std::size_t, 3>& t, int fallback) const
  {
    double s = 0;
    for(std::size_t x : t) {
      if(phi_of(x) > 0) return 0;
      if(phi_of(x) < 0) return 1;
      if(x < nodes.size()) s += nodes[x].raw;
    }
    return s > 0 ? 0 : (s < 0 ? 1 : fallback);
  }

  // Plans the cut: false where a face would not split into triangles along
  // phi = 0 or `degenerate(a, b, c)` holds for a new triangle
  template <class Degenerate>
  bool plan(const Degenerate& degenerate)
  {
    std::unordered_map<std::uint64_t, std::size_t> split_node;
    std::vector<Tri> new_tris;
    new_points.clear();
    split_edges.clear();
    plans.clear();
    after = tris;
    const std::size_t base = nodes.size();
    for(std::size_t i = 0; i < tris.size(); ++i) {
      if(!in_band[i]) continue;
      const Tri& t = tris[i];
      std::vector<std::size_t> poly;
      for(int k = 0; k < 3; ++k) {
        const std::size_t u = t.n[k], v = t.n[(k + 1) % 3];
        poly.push_back(u);
        const double pu = nodes[u].phi, pv = nodes[v].phi;
        if(!(pu * pv < 0)) continue;
        auto it = split_node.find(edge_key(u, v));
        if(it == split_node.end()) {
          const std::size_t plus = pu > 0 ? u : v, minus = pu > 0 ? v : u;
          const double fp = nodes[plus].phi, fm = nodes[minus].phi;
          const double s = (std::max)(snap_fraction, (std::min)(1 - snap_fraction, fp / (fp - fm)));
          const P& a = nodes[plus].p;
          const P& b = nodes[minus].p;
          new_points.push_back({a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])});
          it = split_node.emplace(edge_key(u, v), base + new_points.size() - 1).first;
          split_edges.push_back({plus, minus});
        }
        poly.push_back(it->second);
      }
      if(poly.size() == 3) {
        after[i].label = label_of(t.n, t.label);
        continue;
      }
      // the two zeros of the polygon, not adjacent
      std::vector<std::size_t> zeros;
      for(std::size_t k = 0; k < poly.size(); ++k)
        if(phi_of(poly[k]) == 0) zeros.push_back(k);
      if(zeros.size() != 2 || zeros[1] - zeros[0] < 2 || zeros[1] - zeros[0] > poly.size() - 2) return false;
      Face_plan fp;
      fp.face = i;
      fp.cuts.push_back({poly[zeros[0]], poly[zeros[1]]});
      for(int part = 0; part < 2; ++part) {
        std::vector<std::size_t> sub_poly;
        const std::size_t from = zeros[part], to = zeros[1 - part];
        for(std::size_t k = from;; k = (k + 1) % poly.size()) {
          sub_poly.push_back(poly[k]);
          if(k == to) break;
        }
        if(sub_poly.size() == 3) {
          fp.tris.push_back({{sub_poly[0], sub_poly[1], sub_poly[2]}, 0});
        }
        else if(sub_poly.size() == 4) {
          const std::size_t* q = sub_poly.data();
          const double d02 = (std::min)(quality(q[0], q[1], q[2]), quality(q[0], q[2], q[3]));
          const double d13 = (std::min)(quality(q[1], q[2], q[3]), quality(q[1], q[3], q[0]));
          if(d02 >= d13) {
            fp.cuts.push_back({q[0], q[2]});
            fp.tris.push_back({{q[0], q[1], q[2]}, 0});
            fp.tris.push_back({{q[0], q[2], q[3]}, 0});
          }
          else {
            fp.cuts.push_back({q[1], q[3]});
            fp.tris.push_back({{q[1], q[2], q[3]}, 0});
            fp.tris.push_back({{q[1], q[3], q[0]}, 0});
          }
        }
        else
          return false;
      }
      for(Tri& x : fp.tris) {
        x.label = label_of(x.n, t.label);
        if(degenerate(x.n[0], x.n[1], x.n[2])) return false;
      }
      after[i] = fp.tris[0];
      for(std::size_t k = 1; k < fp.tris.size(); ++k) new_tris.push_back(fp.tris[k]);
      plans.push_back(std::move(fp));
    }
    after.insert(after.end(), new_tris.begin(), new_tris.end());
    return true;
  }

  // Whether the planned cut keeps the topology `before` of A and B (each one
  // connected), the border edges at the nodes `ends` of an open curve, and
  // changes something.
  bool verify(const std::array<Labelled_topology, 2>& before, const std::vector<std::size_t>& ends) const
  {
    const std::size_t total = nodes.size() + new_points.size();
    std::array<Labelled_topology, 2> t;
    for_each(2, [&](std::size_t label) { t[label] = labelled_topology(after, int(label), total); });
    for(int label = 0; label < 2; ++label)
      if(!(before[label] == t[label]) || t[label].components != 1) return false;
    std::vector<Tri> near_before, near_after;
    for(std::size_t x : ends) {
      near_before.clear();
      near_after.clear();
      for(const Tri& t : tris)
        if(t.n[0] == x || t.n[1] == x || t.n[2] == x) near_before.push_back(t);
      for(const Tri& t : after)
        if(t.n[0] == x || t.n[1] == x || t.n[2] == x) near_after.push_back(t);
      if(border_edges_at(near_before, x) != border_edges_at(near_after, x)) return false;
    }
    // something must change
    bool changed = !new_points.empty();
    for(std::size_t i = 0; i < tris.size() && !changed; ++i) changed = after[i].label != tris[i].label;
    return changed;
  }

  // the Hausdorff distance between the planned border between A and B near
  // the curve and the polyline `original` (closed or not)
  double move(const std::vector<P>& original, bool closed) const
  {
    std::unordered_map<std::uint64_t, int> mask;
    for(std::size_t i = 0; i < after.size(); ++i) {
      if(i < tris.size() && !in_band[i]) continue;
      for(int k = 0; k < 3; ++k) mask[edge_key(after[i].n[k], after[i].n[(k + 1) % 3])] |= (1 << after[i].label);
    }
    std::vector<std::pair<P, P>> segments;
    for(const auto& m : mask)
      if(m.second == 3) segments.push_back({position(std::size_t(m.first >> 32)), position(std::size_t(m.first & 0xffffffffu))});
    // the largest of the distances, block by block (a maximum is the same in any order)
    const std::size_t block = 64, ns = (segments.size() + block - 1) / block, no = (original.size() + block - 1) / block;
    std::vector<double> largest(ns + no, 0.);
    for_each(ns + no, [&](std::size_t b) {
      double move = 0;
      if(b < ns) {
        for(std::size_t k = b * block; k < (std::min)(segments.size(), (b + 1) * block); ++k)
          for(const P& p : {segments[k].first, segments[k].second})
            move = (std::max)(move, vec3::polyline_distance(p, original, closed));
      } else {
        for(std::size_t k = (b - ns) * block; k < (std::min)(original.size(), (b - ns + 1) * block); ++k) {
          double best = -1, t;
          for(const auto& s : segments) {
            const double d = vec3::segment_distance(original[k], s.first, s.second, t);
            if(best < 0 || d < best) best = d;
          }
          move = (std::max)(move, (std::max)(best, 0.));
        }
      }
      largest[b] = move;
    });
    double move = 0;
    for(double m : largest) move = (std::max)(move, m);
    return move;
  }

private:
  // smallest angle of a triangle, as its sine-like measure: twice the area over the longest edge squared
  double quality(std::size_t a, std::size_t b, std::size_t c) const
  {
    const P &pa = position(a), &pb = position(b), &pc = position(c);
    const double l = (std::max)({vec3::dot(vec3::sub(pa, pb), vec3::sub(pa, pb)), vec3::dot(vec3::sub(pb, pc), vec3::sub(pb, pc)),
                                 vec3::dot(vec3::sub(pc, pa), vec3::sub(pc, pa))});
    return l > 0 ? vec3::norm(vec3::cross(vec3::sub(pb, pa), vec3::sub(pc, pa))) / l : 0.;
  }
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_BAND_CUT_H
