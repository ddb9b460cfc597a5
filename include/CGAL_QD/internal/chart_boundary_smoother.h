// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CHART_BOUNDARY_SMOOTHER_H
#define CGAL_QD_INTERNAL_CHART_BOUNDARY_SMOOTHER_H

// The smoothing of one border curve between two charts by a cut through the
// triangles of a band around it; used by `smooth_chart_boundaries()`.

#include <CGAL_QD/internal/band_cut.h>
#include <CGAL_QD/internal/band_phi.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/labelled_triangles.h>
#include <CGAL_QD/internal/vec3.h>
#include <CGAL_QD/internal/validation.h>
#include <CGAL_QD/segmentation_measures.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
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
#include <map>
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
// The cut is planned on a copy of the combinatorics of A and B (`Band_cut`,
// band_cut.h) and checked (both charts connected, same Euler characteristic,
// border loops and pinch vertices, the same border edges at the curve's ends,
// no degenerate triangle) before the mesh is changed.
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
  static constexpr double smooth_enough = 1.01;  // curves below this zigzag are left alone

  // With `charts_change_only_here`, the caller changes no chart between
  // two curves (the charts change only where a curve is smoothed), and the
  // topology of a chart is measured once (see `topology_before()`).
  Chart_boundary_smoother(TriangleMesh& tm, VPM vpm, FaceChartMap chart, ECM ecm, double sharp_angle_degrees,
                          std::size_t rings, std::size_t rounds, bool charts_change_only_here = false)
      : m_tm(tm), m_vpm(vpm), m_chart(chart), m_ecm(ecm), m_keep_topology(charts_change_only_here),
        m_cos_sharp(std::cos(sharp_angle_degrees * 3.14159265358979323846 / 180.)), m_rings(rings), m_rounds(rounds),
        m_node_ids(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm)),
        m_face_ids(get(CGAL::dynamic_face_property_t<std::size_t>(), tm))
  {}

  enum class Outcome { SMOOTHED, ALREADY_SMOOTH, KEPT_SHARP, FAILED };

  // whether phi, the check of a planned cut and its move are computed on the
  // threads of CGAL::Parallel_tag (each node, each chart, each block of the
  // distances on its own: the same results)
  void run_in_parallel(bool parallel) { m_cut.parallel = parallel; }

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
    topology_before();
    for(std::size_t rounds = m_rounds; rounds >= 2; rounds /= 2) {
      if(!compute_phi(rounds)) continue;
      m_cut.remove_islands();
      m_cut.snap();
      m_cut.remove_islands();
      if(!plan_and_verify()) continue;
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
  typedef Band_node Node;
  typedef Labelled_triangle Tri;  // label 0: A, 1: B

  // the node of a vertex met for this curve, and of a face of A or B
  std::size_t node_id(vertex_descriptor v) const { return get(m_node_ids, v) - 1; }
  bool has_face_id(face_descriptor f) const { return get(m_face_ids, f) != 0; }
  std::size_t face_id(face_descriptor f) const { return get(m_face_ids, f) - 1; }
  void set_node_id(vertex_descriptor v, std::size_t id)
  {
    put(m_node_ids, v, id + 1);
    m_numbered.push_back(v);
  }

  std::size_t node_of(vertex_descriptor v)
  {
    if(get(m_node_ids, v) != 0) return node_id(v);
    set_node_id(v, m_cut.nodes.size());
    Node n;
    n.p = point(v);
    m_cut.nodes.push_back(n);
    m_vertex.push_back(v);
    return m_cut.nodes.size() - 1;
  }

  void build_charts()
  {
    // the ids of the curve before, reset (0: none; else the id + 1)
    for(vertex_descriptor v : m_numbered) put(m_node_ids, v, 0);
    for(face_descriptor f : m_faces) put(m_face_ids, f, 0);
    m_numbered.clear();
    m_cut.nodes.clear();
    m_vertex.clear();
    m_faces.clear();
    m_cut.tris.clear();
    // every face of A and B, by breadth-first search from the curve
    for(int s = 0; s < 2; ++s) {
      const Label label = s == 0 ? m_a : m_b;
      const face_descriptor start =
          s == 0 ? face(m_curve_halfedges[0], m_tm) : face(opposite(m_curve_halfedges[0], m_tm), m_tm);
      const std::size_t first = m_faces.size();
      m_faces.push_back(start);
      put(m_face_ids, start, first + 1);
      for(std::size_t q = first; q < m_faces.size(); ++q)
        for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(m_faces[q], m_tm), m_tm)) {
          const halfedge_descriptor o = opposite(h, m_tm);
          if(is_border(o, m_tm) || get(m_chart, face(o, m_tm)) != label || has_face_id(face(o, m_tm))) continue;
          put(m_face_ids, face(o, m_tm), m_faces.size() + 1);
          m_faces.push_back(face(o, m_tm));
        }
    }
    m_cut.tris.resize(m_faces.size());
    for(std::size_t i = 0; i < m_faces.size(); ++i) {
      const halfedge_descriptor h = halfedge(m_faces[i], m_tm);
      m_cut.tris[i].n = {node_of(source(h, m_tm)), node_of(target(h, m_tm)), node_of(target(next(h, m_tm), m_tm))};
      m_cut.tris[i].label = get(m_chart, m_faces[i]) == m_a ? 0 : 1;
    }
    for(std::size_t i = 0; i < m_curve.size(); ++i) m_cut.nodes[node_of(m_curve[i])].curve_index = int(i);

    // the band: faces of A and B within m_rings vertex rings of the curve
    m_cut.in_band.assign(m_faces.size(), 0);
    std::vector<std::size_t> ring;
    std::vector<char> reached(m_cut.nodes.size(), 0);
    for(vertex_descriptor v : m_curve) {
      ring.push_back(node_id(v));
      reached[ring.back()] = 1;
    }
    for(std::size_t r = 0; r < m_rings; ++r) {
      std::vector<std::size_t> next_ring;
      for(std::size_t k : ring)
        for(halfedge_descriptor h : CGAL::halfedges_around_target(m_vertex[k], m_tm)) {
          if(is_border(h, m_tm)) continue;
          if(!has_face_id(face(h, m_tm))) continue;
          const std::size_t t = face_id(face(h, m_tm));
          if(m_cut.in_band[t]) continue;
          m_cut.in_band[t] = 1;
          for(std::size_t x : m_cut.tris[t].n)
            if(!reached[x]) {
              reached[x] = 1;
              next_ring.push_back(x);
            }
        }
      ring.swap(next_ring);
    }
    // sides, locks
    for(std::size_t i = 0; i < m_faces.size(); ++i)
      if(m_cut.in_band[i])
        for(std::size_t x : m_cut.tris[i].n) m_cut.nodes[x].in_band = true;
    for(std::size_t x = 0; x < m_cut.nodes.size(); ++x) {
      Node& n = m_cut.nodes[x];
      if(!n.in_band) continue;
      bool a = false, b = false;
      for(halfedge_descriptor h : CGAL::halfedges_around_target(m_vertex[x], m_tm)) {
        if(get(m_ecm, edge(h, m_tm))) n.locked = true;
        if(is_border(h, m_tm)) {
          n.locked = true;
          continue;
        }
        if(is_border(opposite(h, m_tm), m_tm)) n.locked = true;
        const bool in_ab = has_face_id(face(h, m_tm));
        if(!in_ab || !m_cut.in_band[face_id(face(h, m_tm))]) n.locked = true;
        if(in_ab) (m_cut.tris[face_id(face(h, m_tm))].label == 0 ? a : b) = true;
      }
      n.side = a && b ? 0 : (a ? 1 : -1);
      // on this curve: fixed where the curve is; elsewhere on A and B's border: fixed
      n.fixed = n.curve_index >= 0 ? bool(m_fixed[std::size_t(n.curve_index)]) : n.side == 0;
    }
    for(std::size_t i = 0; i < m_curve.size(); ++i) {
      Node& n = m_cut.nodes[node_id(m_curve[i])];
      if(n.locked) n.fixed = true;  // a curve vertex next to a cut or the border stays
    }
  }

  // The topology of A and B before the change. Where only this smoother
  // changes the charts, a chart met before keeps the topology found then:
  // every cut applied since kept it (`Band_cut::verify()`). That holds for a
  // chart held whole in the copy, which is grown from the curve and holds
  // only the faces of the chart connected to it: a chart with more faces
  // than its copy is measured every time.
  void topology_before()
  {
    if(!m_keep_topology) {
      m_cut.for_each(2, [&](std::size_t label) {
        m_before[label] = labelled_topology(m_cut.tris, int(label), m_cut.nodes.size());
      });
      return;
    }
    if(!m_counted) {
      for(face_descriptor f : faces(m_tm)) ++m_chart_faces[get(m_chart, f)];
      m_counted = true;
    }
    std::array<std::size_t, 2> copied = {{0, 0}};
    for(const Tri& t : m_cut.tris) ++copied[std::size_t(t.label)];
    for(int label = 0; label < 2; ++label) {
      const Label chart = label == 0 ? m_a : m_b;
      const bool whole = copied[std::size_t(label)] == m_chart_faces[chart];
      const auto known = m_topology.find(chart);
      if(whole && known != m_topology.end()) {
        m_before[std::size_t(label)] = known->second;
        continue;
      }
      m_before[std::size_t(label)] = labelled_topology(m_cut.tris, label, m_cut.nodes.size());
      if(whole) m_topology[chart] = m_before[std::size_t(label)];
    }
  }

  // a face more (+1) or less (-1) in chart c, once the charts are counted
  void count_face(Label c, int change)
  {
    if(!m_counted) return;
    std::size_t& n = m_chart_faces[c];
    n = change > 0 ? n + 1 : n - 1;
  }

  // ------------------------------------------------------------------ phi
  bool compute_phi(std::size_t rounds)
  {
    const std::size_t nv = m_curve.size();
    std::vector<char> fixed(nv, 0);
    for(std::size_t i = 0; i < nv; ++i) fixed[i] = m_cut.nodes[node_id(m_curve[i])].fixed;
    m_target = m_original;
    smooth_polyline(m_target, m_closed, rounds, fixed);
    // vertex normals of the curve, from the faces of A and B
    std::vector<P> normals(nv, P{0., 0., 0.});
    for(std::size_t i = 0; i < nv; ++i) {
      for(halfedge_descriptor h : CGAL::halfedges_around_target(m_curve[i], m_tm)) {
        if(is_border(h, m_tm) || !has_face_id(face(h, m_tm))) continue;
        const halfedge_descriptor g = halfedge(face(h, m_tm), m_tm);
        const P a = point(source(g, m_tm)), b = point(target(g, m_tm)), c = point(target(next(g, m_tm), m_tm));
        const P n = vec3::cross(vec3::sub(b, a), vec3::sub(c, a));
        for(int k = 0; k < 3; ++k) normals[i][k] += n[k];
      }
      const double l = vec3::norm(normals[i]);
      if(l > 0) for(double& x : normals[i]) x /= l;
    }
    // every node on its own, in blocks
    const std::size_t block = 256, blocks = (m_cut.nodes.size() + block - 1) / block;
    const Smoothed_curve curve{m_target, normals, m_kept, m_closed, m_mean_edge};
    m_cut.for_each(blocks, [&](std::size_t b) {
      for(std::size_t x = b * block; x < (std::min)(m_cut.nodes.size(), (b + 1) * block); ++x)
        band_node_phi(m_cut.nodes[x], curve);
    });
    return true;
  }

  // the point of node x, as the kernel's
  Point kernel_point(std::size_t x) const
  {
    if(x < m_cut.nodes.size()) return get(m_vpm, m_vertex[x]);
    const P& p = m_cut.new_points[x - m_cut.nodes.size()];
    return Point(p[0], p[1], p[2]);
  }

  // ------------------------------------------------------- plan and checks
  // the cut planned along phi = 0 (no degenerate triangle) and checked
  bool plan_and_verify()
  {
    if(!m_cut.plan([&](std::size_t a, std::size_t b, std::size_t c) {
         return typename Kernel::Collinear_3()(kernel_point(a), kernel_point(b), kernel_point(c));
       }))
      return false;
    std::vector<std::size_t> ends;
    if(!m_closed) ends = {node_id(m_curve.front()), node_id(m_curve.back())};
    return m_cut.verify(m_before, ends);
  }

  void measure_move()
  {
    const double move = m_cut.move(m_original, m_closed);
    max_move = (std::max)(max_move, move);
    if(m_mean_edge > 0) max_relative_move = (std::max)(max_relative_move, move / m_mean_edge);
  }

  // ----------------------------------------------------------------- apply
  void apply()
  {
    std::vector<vertex_descriptor> vertex_of(m_cut.nodes.size() + m_cut.new_points.size());
    for(std::size_t x = 0; x < m_cut.nodes.size(); ++x) vertex_of[x] = m_vertex[x];
    for(std::size_t k = 0; k < m_cut.split_edges.size(); ++k) {
      const std::size_t plus = m_cut.split_edges[k].first, minus = m_cut.split_edges[k].second;
      const halfedge_descriptor h = halfedge(m_vertex[plus], m_vertex[minus], m_tm).first;
      const bool constrained = get(m_ecm, edge(h, m_tm));
      const halfedge_descriptor hnew = CGAL::Euler::split_edge(h, m_tm);
      const vertex_descriptor w = target(hnew, m_tm);
      const P& p = m_cut.new_points[k];
      put(m_vpm, w, Point(p[0], p[1], p[2]));
      if(constrained) {
        put(m_ecm, edge(hnew, m_tm), true);
        put(m_ecm, edge(h, m_tm), true);
      }
      vertex_of[m_cut.nodes.size() + k] = w;
      set_node_id(w, m_cut.nodes.size() + k);
      ++vertices_added;
    }
    for(const Band_cut::Face_plan& fp : m_cut.plans) {
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
      count_face(m_cut.tris[fp.face].label == 0 ? m_a : m_b, -1);
      for(face_descriptor g : parts) {
        const halfedge_descriptor h = halfedge(g, m_tm);
        std::array<std::size_t, 3> t;
        int k = 0;
        for(halfedge_descriptor e : CGAL::halfedges_around_face(h, m_tm)) {
          const vertex_descriptor v = target(e, m_tm);
          t[std::size_t(k++ % 3)] = node_id(v);
        }
        const Label chart = m_cut.label_of(t, m_cut.tris[fp.face].label) == 0 ? m_a : m_b;
        put(m_chart, g, chart);
        count_face(chart, 1);
      }
    }
    // faces without a split that changed sides
    std::vector<char> split(m_cut.tris.size(), 0);
    for(const Band_cut::Face_plan& fp : m_cut.plans) split[fp.face] = 1;
    for(std::size_t i = 0; i < m_cut.tris.size(); ++i)
      if(m_cut.in_band[i] && m_cut.after[i].label != m_cut.tris[i].label && !split[i]) {
        put(m_chart, m_faces[i], m_cut.after[i].label == 0 ? m_a : m_b);
        count_face(m_cut.tris[i].label == 0 ? m_a : m_b, -1);
        count_face(m_cut.after[i].label == 0 ? m_a : m_b, 1);
      }
  }

  TriangleMesh& m_tm;
  VPM m_vpm;
  FaceChartMap m_chart;
  ECM m_ecm;
  bool m_keep_topology;
  double m_cos_sharp;
  std::size_t m_rings, m_rounds;

  std::vector<vertex_descriptor> m_curve;
  std::vector<halfedge_descriptor> m_curve_halfedges;
  bool m_closed = false;
  Label m_a{}, m_b{};
  std::vector<char> m_kept, m_fixed;
  std::vector<P> m_original, m_target;
  double m_mean_edge = 0;

  Band_cut m_cut;                       // the copy of A and B, and the cut planned on it
  std::vector<vertex_descriptor> m_vertex;  // of every node of `m_cut`
  std::vector<face_descriptor> m_faces;     // of every triangle of `m_cut`
  // the node of every vertex and the triangle of every face of `m_cut`, plus
  // one (0: none), in property maps of the mesh (arrays for a Surface_mesh),
  // reset from `m_numbered` and `m_faces` for the next curve: the ids of two
  // whole charts are written for every curve
  typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t>>::type m_node_ids;
  typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::size_t>>::type m_face_ids;
  std::vector<vertex_descriptor> m_numbered;  // the vertices with a node id
  std::array<Labelled_topology, 2> m_before;  // of A and B, before the change
  // the faces of every chart, counted at the first curve and kept up to date
  // by `apply()`, and the topology of the charts met whole
  std::map<Label, std::size_t> m_chart_faces;
  bool m_counted = false;
  std::map<Label, Labelled_topology> m_topology;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CHART_BOUNDARY_SMOOTHER_H
