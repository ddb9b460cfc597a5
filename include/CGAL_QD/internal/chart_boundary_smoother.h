// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CHART_BOUNDARY_SMOOTHER_H
#define CGAL_QD_INTERNAL_CHART_BOUNDARY_SMOOTHER_H

// The smoothing of one border curve between two charts by a cut through the
// triangles of a band around it; used by `smooth_chart_boundaries()`.

#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/labelled_triangles.h>
#include <CGAL_QD/internal/vec3.h>
#include <CGAL_QD/internal/validation.h>
#include <CGAL_QD/segmentation_measures.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <boost/container_hash/hash.hpp>
#include <boost/graph/graph_traits.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// The smoothing of the chart borders, one curve at a time. Each curve between
// charts A and B gets a band of faces of A and B within a few vertex rings; a
// smoothed copy of the curve (Jacobi rounds of moving each free vertex halfway
// towards the midpoint of its neighbours; ends, sharp and constrained edges
// fixed) defines on the band vertices a signed distance phi, positive on the A
// side. The band is cut along phi = 0: a new vertex on every edge where phi
// changes sign, the faces split, and every face relabelled by the sign of phi.
// The cut is planned on a copy of the combinatorics of A and B and checked
// (both charts connected, same Euler characteristic, border loops and pinch
// vertices, the same border edges at the curve's ends, no degenerate
// triangle) before the mesh is changed.
template <class TriangleMesh, class VPM, class FaceChartMap, class ECM>
class Chart_boundary_smoother
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<FaceChartMap>::value_type Label;
  typedef typename boost::property_traits<VPM>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  typedef std::array<double, 3> P;

public:
  static constexpr double snap_fraction = 0.2;       // crossings closer to a vertex snap onto it
  static constexpr double smooth_enough = 1.01;      // curves below this zigzag are left alone

  Chart_boundary_smoother(TriangleMesh& tm, VPM vpm, FaceChartMap chart, ECM ecm, double sharp_angle_degrees,
                          std::size_t rings, std::size_t rounds)
      : m_tm(tm), m_vpm(vpm), m_chart(chart), m_ecm(ecm),
        m_cos_sharp(std::cos(sharp_angle_degrees * 3.14159265358979323846 / 180.)), m_rings(rings), m_rounds(rounds)
  {}

  enum class Outcome { SMOOTHED, ALREADY_SMOOTH, KEPT_SHARP, FAILED };

  // whether the edge of h is sharp (dihedral angle beyond the threshold) or constrained
  bool is_kept(halfedge_descriptor h) const
  {
    if(get(m_ecm, edge(h, m_tm))) return true;
    if(is_border_edge(h, m_tm)) return false;
    const P a = normal(face(h, m_tm)), b = normal(face(opposite(h, m_tm), m_tm));
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] < m_cos_sharp;
  }

  bool is_end_vertex(vertex_descriptor v) const
  {
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, m_tm))
      if(is_border(h, m_tm) || is_border(opposite(h, m_tm), m_tm) || get(m_ecm, edge(h, m_tm))) return true;
    return false;
  }

  // Smooths the curve through `curve` (consecutive vertices joined by border
  // edges between two charts; closed: the last joins the first).
  Outcome smooth(const std::vector<vertex_descriptor>& curve, bool closed)
  {
    m_curve = curve;
    m_closed = closed;
    const std::size_t nv = curve.size(), ne = closed ? nv : nv - 1;
    if(ne == 0) return Outcome::FAILED;
    m_curve_halfedges.clear();
    for(std::size_t i = 0; i < ne; ++i) {
      const auto h = halfedge(curve[i], curve[(i + 1) % nv], m_tm);
      if(!h.second || is_border_edge(h.first, m_tm)) return Outcome::FAILED;
      m_curve_halfedges.push_back(h.first);
    }
    m_a = get(m_chart, face(m_curve_halfedges[0], m_tm));
    m_b = get(m_chart, face(opposite(m_curve_halfedges[0], m_tm), m_tm));
    if(m_a == m_b) return Outcome::FAILED;
    for(halfedge_descriptor h : m_curve_halfedges)
      if(get(m_chart, face(h, m_tm)) != m_a || get(m_chart, face(opposite(h, m_tm), m_tm)) != m_b)
        return Outcome::FAILED;

    // fixed curve vertices: the ends of an open curve and the vertices of kept edges
    m_kept.assign(ne, 0);
    m_fixed.assign(nv, 0);
    if(!closed) m_fixed.front() = m_fixed.back() = 1;
    bool all_kept = true;
    for(std::size_t i = 0; i < ne; ++i) {
      m_kept[i] = is_kept(m_curve_halfedges[i]);
      if(m_kept[i]) m_fixed[i] = m_fixed[(i + 1) % nv] = 1;
      else all_kept = false;
    }
    if(all_kept) return Outcome::KEPT_SHARP;
    m_original.clear();
    for(vertex_descriptor v : curve) m_original.push_back(point(v));
    {
      std::vector<P> p = m_original;
      const double length = polyline_length(p, closed);
      smooth_polyline(p, closed, 20);
      const double smoothed = polyline_length(p, closed);
      if(smoothed <= 0 || length / smoothed <= smooth_enough) return Outcome::ALREADY_SMOOTH;
    }
    m_mean_edge = polyline_length(m_original, closed) / double(ne);

    build_charts();
    for(int label = 0; label < 2; ++label) m_before[label] = labelled_topology(m_tris, label, m_nodes.size());
    for(std::size_t rounds = m_rounds; rounds >= 2; rounds /= 2) {
      if(!compute_phi(rounds)) continue;
      remove_islands();
      snap();
      remove_islands();
      if(!plan()) continue;
      if(!verify()) continue;
      measure_move();
      apply();
      return Outcome::SMOOTHED;
    }
    return Outcome::FAILED;
  }

  std::size_t vertices_added = 0, faces_added = 0;
  double max_move = 0, max_relative_move = 0;

private:
  // --------------------------------------------------------------- geometry
  P point(vertex_descriptor v) const { return point_of<TriangleMesh>(v, m_vpm); }

  P normal(face_descriptor f) const
  {
    const halfedge_descriptor h = halfedge(f, m_tm);
    const P a = point(source(h, m_tm)), b = point(target(h, m_tm)), c = point(target(next(h, m_tm), m_tm));
    P n = vec3::cross(vec3::sub(b, a), vec3::sub(c, a));
    const double l = vec3::norm(n);
    if(l > 0) for(double& x : n) x /= l;
    return n;
  }

  // ------------------------------------------------- the two charts, as ids
  struct Node
  {
    vertex_descriptor v;
    P p;
    int side = 0;         // +1: only A faces, -1: only B faces, 0: both
    bool locked = false;  // next to a face outside the band, the mesh border or a constrained edge
    bool fixed = false;   // phi stays 0
    bool in_band = false;
    int curve_index = -1;  // index in the curve, or -1
    double phi = 0, raw = 0;
  };
  typedef Labelled_triangle Tri;  // label 0: A, 1: B

  std::size_t node_of(vertex_descriptor v)
  {
    auto it = m_node_id.find(v);
    if(it != m_node_id.end()) return it->second;
    m_node_id.emplace(v, m_nodes.size());
    Node n;
    n.v = v;
    n.p = point(v);
    m_nodes.push_back(n);
    return m_nodes.size() - 1;
  }

  void build_charts()
  {
    m_nodes.clear();
    m_node_id.clear();
    m_faces.clear();
    m_face_id.clear();
    m_tris.clear();
    // every face of A and B, by breadth-first search from the curve
    for(int s = 0; s < 2; ++s) {
      const Label label = s == 0 ? m_a : m_b;
      const face_descriptor start =
          s == 0 ? face(m_curve_halfedges[0], m_tm) : face(opposite(m_curve_halfedges[0], m_tm), m_tm);
      const std::size_t first = m_faces.size();
      m_faces.push_back(start);
      m_face_id.emplace(start, first);
      for(std::size_t q = first; q < m_faces.size(); ++q)
        for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(m_faces[q], m_tm), m_tm)) {
          const halfedge_descriptor o = opposite(h, m_tm);
          if(is_border(o, m_tm) || get(m_chart, face(o, m_tm)) != label) continue;
          if(m_face_id.emplace(face(o, m_tm), m_faces.size()).second) m_faces.push_back(face(o, m_tm));
        }
    }
    m_tris.resize(m_faces.size());
    for(std::size_t i = 0; i < m_faces.size(); ++i) {
      const halfedge_descriptor h = halfedge(m_faces[i], m_tm);
      m_tris[i].n = {node_of(source(h, m_tm)), node_of(target(h, m_tm)), node_of(target(next(h, m_tm), m_tm))};
      m_tris[i].label = get(m_chart, m_faces[i]) == m_a ? 0 : 1;
    }
    for(std::size_t i = 0; i < m_curve.size(); ++i) m_nodes[node_of(m_curve[i])].curve_index = int(i);

    // the band: faces of A and B within m_rings vertex rings of the curve
    m_in_band.assign(m_faces.size(), 0);
    std::vector<std::size_t> ring;
    std::vector<char> reached(m_nodes.size(), 0);
    for(vertex_descriptor v : m_curve) {
      ring.push_back(m_node_id.at(v));
      reached[ring.back()] = 1;
    }
    for(std::size_t r = 0; r < m_rings; ++r) {
      std::vector<std::size_t> next_ring;
      for(std::size_t k : ring)
        for(halfedge_descriptor h : CGAL::halfedges_around_target(m_nodes[k].v, m_tm)) {
          if(is_border(h, m_tm)) continue;
          const auto it = m_face_id.find(face(h, m_tm));
          if(it == m_face_id.end() || m_in_band[it->second]) continue;
          m_in_band[it->second] = 1;
          for(std::size_t x : m_tris[it->second].n)
            if(!reached[x]) {
              reached[x] = 1;
              next_ring.push_back(x);
            }
        }
      ring.swap(next_ring);
    }
    // sides, locks
    for(std::size_t i = 0; i < m_faces.size(); ++i)
      if(m_in_band[i])
        for(std::size_t x : m_tris[i].n) m_nodes[x].in_band = true;
    for(Node& n : m_nodes) {
      if(!n.in_band) continue;
      bool a = false, b = false;
      for(halfedge_descriptor h : CGAL::halfedges_around_target(n.v, m_tm)) {
        if(get(m_ecm, edge(h, m_tm))) n.locked = true;
        if(is_border(h, m_tm)) {
          n.locked = true;
          continue;
        }
        if(is_border(opposite(h, m_tm), m_tm)) n.locked = true;
        const auto it = m_face_id.find(face(h, m_tm));
        if(it == m_face_id.end() || !m_in_band[it->second]) n.locked = true;
        if(it != m_face_id.end()) (m_tris[it->second].label == 0 ? a : b) = true;
      }
      n.side = a && b ? 0 : (a ? 1 : -1);
      // on this curve: fixed where the curve is; elsewhere on A and B's border: fixed
      n.fixed = n.curve_index >= 0 ? bool(m_fixed[std::size_t(n.curve_index)]) : n.side == 0;
    }
    for(std::size_t i = 0; i < m_curve.size(); ++i) {
      Node& n = m_nodes[m_node_id.at(m_curve[i])];
      if(n.locked) n.fixed = true;  // a curve vertex next to a cut or the border stays
    }
  }

  // ------------------------------------------------------------------ phi
  bool compute_phi(std::size_t rounds)
  {
    const std::size_t nv = m_curve.size(), ne = m_closed ? nv : nv - 1;
    std::vector<char> fixed(nv, 0);
    for(std::size_t i = 0; i < nv; ++i) fixed[i] = m_nodes[m_node_id.at(m_curve[i])].fixed;
    m_target = m_original;
    smooth_polyline(m_target, m_closed, rounds, fixed);
    // vertex normals of the curve, from the faces of A and B
    std::vector<P> normals(nv, P{0., 0., 0.});
    for(std::size_t i = 0; i < nv; ++i) {
      for(halfedge_descriptor h : CGAL::halfedges_around_target(m_curve[i], m_tm)) {
        if(is_border(h, m_tm) || !m_face_id.count(face(h, m_tm))) continue;
        const halfedge_descriptor g = halfedge(face(h, m_tm), m_tm);
        const P a = point(source(g, m_tm)), b = point(target(g, m_tm)), c = point(target(next(g, m_tm), m_tm));
        const P n = vec3::cross(vec3::sub(b, a), vec3::sub(c, a));
        for(int k = 0; k < 3; ++k) normals[i][k] += n[k];
      }
      const double l = vec3::norm(normals[i]);
      if(l > 0) for(double& x : normals[i]) x /= l;
    }
    for(Node& n : m_nodes) {
      n.phi = n.raw = 0;
      if(!n.in_band) {
        n.phi = n.raw = n.side;
        continue;
      }
      if(n.fixed) continue;
      double best = -1, best_t = 0;
      std::size_t best_i = 0;
      for(std::size_t i = 0; i < ne; ++i) {
        double t;
        const double d = vec3::segment_distance(n.p, m_target[i], m_target[(i + 1) % nv], t);
        if(best < 0 || d < best) {
          best = d;
          best_t = t;
          best_i = i;
        }
      }
      const std::size_t j = best_t <= 0 ? best_i : (best_t >= 1 ? (best_i + 1) % nv : nv);
      double phi;
      if(j < nv && !m_closed && (j == 0 || j + 1 == nv) && n.side != 0)
        phi = n.side * best;  // beyond an end of the curve: the vertex keeps its side
      else if(j < nv && (m_closed || (j > 0 && j + 1 < nv))) {
        // nearest to a corner of the smoothed curve: the side of the bisector of its two frames
        const std::size_t i0 = (j + nv - 1) % nv, i1 = (j + 1) % nv;
        P s0 = vec3::cross(normals[j], vec3::sub(m_target[j], m_target[i0])), s1 = vec3::cross(normals[j], vec3::sub(m_target[i1], m_target[j]));
        const double l0 = vec3::norm(s0), l1 = vec3::norm(s1);
        P s = {0., 0., 0.};
        for(int k = 0; k < 3; ++k) s[k] = (l0 > 0 ? s0[k] / l0 : 0.) + (l1 > 0 ? s1[k] / l1 : 0.);
        const double ls = vec3::norm(s);
        phi = ls > 0 ? vec3::dot(vec3::sub(n.p, m_target[j]), s) / ls : 0.;
        if(std::abs(phi) < best) phi = phi < 0 ? -best : best;
        if(n.side != 0 && (m_kept[i0] || m_kept[j % ne])) phi = n.side * best;
      }
      else {
        const P& a = m_target[best_i];
        const P& b = m_target[(best_i + 1) % nv];
        const P d = vec3::sub(b, a);
        P nm;
        for(int k = 0; k < 3; ++k) nm[k] = (1 - best_t) * normals[best_i][k] + best_t * normals[(best_i + 1) % nv][k];
        const P s = vec3::cross(nm, d);
        const double ls = vec3::norm(s);
        const P q = {a[0] + best_t * d[0], a[1] + best_t * d[1], a[2] + best_t * d[2]};
        phi = ls > 0 ? vec3::dot(vec3::sub(n.p, q), s) / ls : 0.;
        // beside a kept (sharp or constrained) edge, the faces keep their chart
        if(m_kept[best_i] && n.side != 0) phi = n.side * best;
      }
      // a vertex next to the outside of the band keeps its side: the new curve stays in the band
      if(n.locked && !(phi * n.side > 0)) phi = n.side * (std::max)(std::abs(phi), 1e-3 * m_mean_edge);
      n.phi = n.raw = phi;
    }
    return true;
  }

  // Flips the sign of every component of positive (negative) band vertices,
  // connected through band edges, that reaches no locked vertex of side A (B):
  // it would be an island of one chart inside the other.
  void remove_islands()
  {
    std::vector<std::vector<std::size_t>> adjacent(m_nodes.size());
    for(std::size_t i = 0; i < m_tris.size(); ++i)
      if(m_in_band[i])
        for(int k = 0; k < 3; ++k) adjacent[m_tris[i].n[k]].push_back(m_tris[i].n[(k + 1) % 3]);
    for(int sign : {1, -1}) {
      std::vector<int> component(m_nodes.size(), -1);
      std::vector<char> anchored;
      std::vector<std::size_t> size;
      for(std::size_t x = 0; x < m_nodes.size(); ++x) {
        if(!m_nodes[x].in_band || !(m_nodes[x].phi * sign > 0) || component[x] >= 0) continue;
        const int c = int(anchored.size());
        anchored.push_back(0);
        size.push_back(0);
        std::vector<std::size_t> queue{x};
        component[x] = c;
        for(std::size_t q = 0; q < queue.size(); ++q) {
          const Node& n = m_nodes[queue[q]];
          ++size.back();
          if(n.locked && n.side == sign) anchored.back() = 1;
          for(std::size_t y : adjacent[queue[q]])
            if(component[y] < 0 && m_nodes[y].phi * sign > 0) {
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
      for(std::size_t x = 0; x < m_nodes.size(); ++x)
        if(component[x] >= 0 && !anchored[std::size_t(component[x])]) m_nodes[x].phi = -m_nodes[x].phi;
    }
  }

  void snap()
  {
    std::vector<char> snap(m_nodes.size(), 0);
    for(std::size_t i = 0; i < m_tris.size(); ++i) {
      if(!m_in_band[i]) continue;
      for(int k = 0; k < 3; ++k) {
        const std::size_t u = m_tris[i].n[k], v = m_tris[i].n[(k + 1) % 3];
        const double pu = m_nodes[u].phi, pv = m_nodes[v].phi;
        if(!(pu * pv < 0)) continue;
        const double t = pu / (pu - pv);  // from u
        if(t < snap_fraction && !m_nodes[u].locked) snap[u] = 1;
        if(t > 1 - snap_fraction && !m_nodes[v].locked) snap[v] = 1;
      }
    }
    for(std::size_t x = 0; x < m_nodes.size(); ++x)
      if(snap[x]) m_nodes[x].phi = 0;
  }

  // ------------------------------------------------------------------ plan
  static std::uint64_t key(std::size_t a, std::size_t b) { return edge_key(a, b); }

  double phi_of(std::size_t x) const { return x < m_nodes.size() ? m_nodes[x].phi : 0.; }
  const P& position(std::size_t x) const { return x < m_nodes.size() ? m_nodes[x].p : m_new_points[x - m_nodes.size()]; }
  Point kernel_point(std::size_t x) const
  {
    if(x < m_nodes.size()) return get(m_vpm, m_nodes[x].v);
    const P& p = m_new_points[x - m_nodes.size()];
    return Point(p[0], p[1], p[2]);
  }

  int label_of(const std::array<std::size_t, 3>& t, int fallback) const
  {
    double s = 0;
    for(std::size_t x : t) {
      if(phi_of(x) > 0) return 0;
      if(phi_of(x) < 0) return 1;
      if(x < m_nodes.size()) s += m_nodes[x].raw;
    }
    return s > 0 ? 0 : (s < 0 ? 1 : fallback);
  }

  bool degenerate(std::size_t a, std::size_t b, std::size_t c) const
  {
    return typename Kernel::Collinear_3()(kernel_point(a), kernel_point(b), kernel_point(c));
  }

  // smallest angle of a triangle, as its sine-like measure: twice the area over the longest edge squared
  double quality(std::size_t a, std::size_t b, std::size_t c) const
  {
    const P &pa = position(a), &pb = position(b), &pc = position(c);
    const double l = (std::max)({vec3::dot(vec3::sub(pa, pb), vec3::sub(pa, pb)), vec3::dot(vec3::sub(pb, pc), vec3::sub(pb, pc)),
                                 vec3::dot(vec3::sub(pc, pa), vec3::sub(pc, pa))});
    return l > 0 ? vec3::norm(vec3::cross(vec3::sub(pb, pa), vec3::sub(pc, pa))) / l : 0.;
  }

  struct Face_plan
  {
    std::size_t face;                                      // index in m_faces
    std::vector<std::pair<std::size_t, std::size_t>> cuts;  // diagonals, in order
    std::vector<Tri> tris;
  };

  bool plan()
  {
    m_new_points.clear();
    m_split_edges.clear();
    m_split_node.clear();
    m_plans.clear();
    m_after = m_tris;
    m_new_tris.clear();
    const std::size_t base = m_nodes.size();
    for(std::size_t i = 0; i < m_tris.size(); ++i) {
      if(!m_in_band[i]) continue;
      const Tri& t = m_tris[i];
      std::vector<std::size_t> poly;
      for(int k = 0; k < 3; ++k) {
        const std::size_t u = t.n[k], v = t.n[(k + 1) % 3];
        poly.push_back(u);
        const double pu = m_nodes[u].phi, pv = m_nodes[v].phi;
        if(!(pu * pv < 0)) continue;
        auto it = m_split_node.find(key(u, v));
        if(it == m_split_node.end()) {
          const std::size_t plus = pu > 0 ? u : v, minus = pu > 0 ? v : u;
          const double fp = m_nodes[plus].phi, fm = m_nodes[minus].phi;
          const double s = (std::max)(snap_fraction, (std::min)(1 - snap_fraction, fp / (fp - fm)));
          const P& a = m_nodes[plus].p;
          const P& b = m_nodes[minus].p;
          m_new_points.push_back({a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])});
          it = m_split_node.emplace(key(u, v), base + m_new_points.size() - 1).first;
          m_split_edges.push_back({plus, minus});
        }
        poly.push_back(it->second);
      }
      if(poly.size() == 3) {
        m_after[i].label = label_of(t.n, t.label);
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
      m_after[i] = fp.tris[0];
      for(std::size_t k = 1; k < fp.tris.size(); ++k) m_new_tris.push_back(fp.tris[k]);
      m_plans.push_back(std::move(fp));
    }
    m_after.insert(m_after.end(), m_new_tris.begin(), m_new_tris.end());
    return true;
  }

  // ---------------------------------------------------------------- checks
  bool verify()
  {
    const std::size_t total = m_nodes.size() + m_new_points.size();
    for(int label = 0; label < 2; ++label) {
      const Labelled_topology after = labelled_topology(m_after, label, total);
      if(!(m_before[label] == after) || after.components != 1) return false;
    }
    if(!m_closed) {
      std::vector<Tri> near_before, near_after;
      for(std::size_t x : {m_node_id.at(m_curve.front()), m_node_id.at(m_curve.back())}) {
        near_before.clear();
        near_after.clear();
        for(const Tri& t : m_tris)
          if(t.n[0] == x || t.n[1] == x || t.n[2] == x) near_before.push_back(t);
        for(const Tri& t : m_after)
          if(t.n[0] == x || t.n[1] == x || t.n[2] == x) near_after.push_back(t);
        if(border_edges_at(near_before, x) != border_edges_at(near_after, x)) return false;
      }
    }
    // something must change
    bool changed = !m_new_points.empty();
    for(std::size_t i = 0; i < m_tris.size() && !changed; ++i) changed = m_after[i].label != m_tris[i].label;
    return changed;
  }

  void measure_move()
  {
    // the new border: edges of the planned triangles between A and B near the curve
    std::unordered_map<std::uint64_t, int> mask;
    for(std::size_t i = 0; i < m_after.size(); ++i) {
      if(i < m_tris.size() && !m_in_band[i]) continue;
      for(int k = 0; k < 3; ++k) mask[key(m_after[i].n[k], m_after[i].n[(k + 1) % 3])] |= (1 << m_after[i].label);
    }
    std::vector<std::pair<P, P>> segments;
    for(const auto& m : mask)
      if(m.second == 3) segments.push_back({position(std::size_t(m.first >> 32)), position(std::size_t(m.first & 0xffffffffu))});
    double move = 0;
    for(const auto& s : segments)
      for(const P& p : {s.first, s.second}) move = (std::max)(move, vec3::polyline_distance(p, m_original, m_closed));
    for(const P& p : m_original) {
      double best = -1, t;
      for(const auto& s : segments) {
        const double d = vec3::segment_distance(p, s.first, s.second, t);
        if(best < 0 || d < best) best = d;
      }
      move = (std::max)(move, (std::max)(best, 0.));
    }
    max_move = (std::max)(max_move, move);
    if(m_mean_edge > 0) max_relative_move = (std::max)(max_relative_move, move / m_mean_edge);
  }

  // ----------------------------------------------------------------- apply
  void apply()
  {
    std::vector<vertex_descriptor> vertex_of(m_nodes.size() + m_new_points.size());
    for(std::size_t x = 0; x < m_nodes.size(); ++x) vertex_of[x] = m_nodes[x].v;
    for(std::size_t k = 0; k < m_split_edges.size(); ++k) {
      const std::size_t plus = m_split_edges[k].first, minus = m_split_edges[k].second;
      const halfedge_descriptor h = halfedge(m_nodes[plus].v, m_nodes[minus].v, m_tm).first;
      const bool constrained = get(m_ecm, edge(h, m_tm));
      const halfedge_descriptor hnew = CGAL::Euler::split_edge(h, m_tm);
      const vertex_descriptor w = target(hnew, m_tm);
      const P& p = m_new_points[k];
      put(m_vpm, w, Point(p[0], p[1], p[2]));
      if(constrained) {
        put(m_ecm, edge(hnew, m_tm), true);
        put(m_ecm, edge(h, m_tm), true);
      }
      vertex_of[m_nodes.size() + k] = w;
      m_node_id.emplace(w, m_nodes.size() + k);
      ++vertices_added;
    }
    for(const Face_plan& fp : m_plans) {
      std::vector<face_descriptor> parts{m_faces[fp.face]};
      for(const auto& cut : fp.cuts) {
        const vertex_descriptor x = vertex_of[cut.first], y = vertex_of[cut.second];
        for(face_descriptor g : parts) {
          halfedge_descriptor hx = GT::null_halfedge(), hy = GT::null_halfedge();
          for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(g, m_tm), m_tm)) {
            if(target(h, m_tm) == x) hx = h;
            if(target(h, m_tm) == y) hy = h;
          }
          if(hx == GT::null_halfedge() || hy == GT::null_halfedge()) continue;
          const halfedge_descriptor h3 = CGAL::Euler::split_face(hx, hy, m_tm);
          parts.push_back(face(opposite(h3, m_tm), m_tm));
          ++faces_added;
          break;
        }
      }
      for(face_descriptor g : parts) {
        const halfedge_descriptor h = halfedge(g, m_tm);
        std::array<std::size_t, 3> t;
        int k = 0;
        for(halfedge_descriptor e : CGAL::halfedges_around_face(h, m_tm)) {
          const vertex_descriptor v = target(e, m_tm);
          t[std::size_t(k++ % 3)] = m_node_id.at(v);
        }
        put(m_chart, g, label_of(t, m_tris[fp.face].label) == 0 ? m_a : m_b);
      }
    }
    // faces without a split that changed sides
    std::vector<char> split(m_tris.size(), 0);
    for(const Face_plan& fp : m_plans) split[fp.face] = 1;
    for(std::size_t i = 0; i < m_tris.size(); ++i)
      if(m_in_band[i] && m_after[i].label != m_tris[i].label && !split[i])
        put(m_chart, m_faces[i], m_after[i].label == 0 ? m_a : m_b);
  }

  TriangleMesh& m_tm;
  VPM m_vpm;
  FaceChartMap m_chart;
  ECM m_ecm;
  double m_cos_sharp;
  std::size_t m_rings, m_rounds;

  std::vector<vertex_descriptor> m_curve;
  std::vector<halfedge_descriptor> m_curve_halfedges;
  bool m_closed = false;
  Label m_a{}, m_b{};
  std::vector<char> m_kept, m_fixed;
  std::vector<P> m_original, m_target, m_new_points;
  double m_mean_edge = 0;

  std::vector<Node> m_nodes;
  std::unordered_map<vertex_descriptor, std::size_t, boost::hash<vertex_descriptor>> m_node_id;
  std::vector<face_descriptor> m_faces;
  std::unordered_map<face_descriptor, std::size_t, boost::hash<face_descriptor>> m_face_id;
  std::vector<Tri> m_tris, m_after, m_new_tris;
  std::array<Labelled_topology, 2> m_before;  // of A and B, before the change
  std::vector<char> m_in_band;
  std::unordered_map<std::uint64_t, std::size_t> m_split_node;
  std::vector<std::pair<std::size_t, std::size_t>> m_split_edges;  // (plus, minus) nodes
  std::vector<Face_plan> m_plans;
};

// the edges between two charts, and the constrained edges
template <class TriangleMesh, class FaceChartMap, class ECM>
std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor> chart_seams(const TriangleMesh& tm,
                                                                                     const FaceChartMap& chart,
                                                                                     const ECM& ecm)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor> seams;
  for(auto e : edges(tm)) {
    const auto h = halfedge(e, tm);
    if(get(ecm, e) ||
       (!is_border_edge(h, tm) && get(chart, face(h, tm)) != get(chart, face(opposite(h, tm), tm))))
      seams.push_back(e);
  }
  return seams;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CHART_BOUNDARY_SMOOTHER_H
