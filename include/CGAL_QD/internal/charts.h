// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CHARTS_H
#define CGAL_QD_INTERNAL_CHARTS_H

// Charts of a segmentation held as a vector of compact ids by face index; the
// per-face geometry the segmentation steps share; the seams between charts
// given by a property map.

#include <CGAL_QD/internal/validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {

// Reads the chart ids of the faces into `chart` (by face index), renumbered
// into [0, n) in increasing order of the given ids; `ids` receives the given
// id of every compact id. Returns n.
template <class TriangleMesh, class FaceChartMap, class FIM>
std::size_t read_charts(const TriangleMesh& tm, const FaceChartMap& face_chart, const FIM& fim,
                        std::vector<std::size_t>& chart, std::vector<std::size_t>& ids)
{
  chart.assign(num_faces(tm), 0);
  for(auto f : faces(tm)) chart[get(fim, f)] = static_cast<std::size_t>(get(face_chart, f));
  ids = chart;
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  for(std::size_t& c : chart) c = static_cast<std::size_t>(std::lower_bound(ids.begin(), ids.end(), c) - ids.begin());
  return ids.size();
}

// the face indices in the order of `faces(tm)`
template <class TriangleMesh, class FIM>
std::vector<std::size_t> faces_in_order(const TriangleMesh& tm, const FIM& fim)
{
  std::vector<std::size_t> order;
  order.reserve(num_faces(tm));
  for(auto f : faces(tm)) order.push_back(get(fim, f));
  return order;
}

// the faces across the edges of every face (by face index), in the order of
// `faces_around_face()`; `std::size_t(-1)` across a border
template <class TriangleMesh, class FIM>
std::vector<std::array<std::size_t, 3>> face_neighbours(const TriangleMesh& tm, const FIM& fim)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<std::array<std::size_t, 3>> next_to(num_faces(tm));
  for(typename GT::face_descriptor f : faces(tm)) {
    std::array<std::size_t, 3>& n = next_to[get(fim, f)];
    n.fill(std::size_t(-1));
    int k = 0;
    for(typename GT::face_descriptor g : CGAL::faces_around_face(halfedge(f, tm), tm)) {
      if(k == 3) break;  // triangles only
      if(g != GT::null_face()) n[k] = get(fim, g);
      ++k;
    }
  }
  return next_to;
}

// the connected component of every face (through the edges of
// `face_neighbours()`), numbered from 0 in the order of their first face;
// returns how many there are
inline std::size_t face_components(const std::vector<std::array<std::size_t, 3>>& next_to,
                                   std::vector<std::size_t>& component)
{
  const std::size_t none = std::size_t(-1);
  component.assign(next_to.size(), none);
  std::vector<std::size_t> queue;
  std::size_t n = 0;
  for(std::size_t s = 0; s < next_to.size(); ++s) {
    if(component[s] != none) continue;
    component[s] = n;
    queue.assign(1, s);
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(std::size_t g : next_to[queue[q]])
        if(g != none && component[g] == none) {
          component[g] = n;
          queue.push_back(g);
        }
    ++n;
  }
  return n;
}

// compactness 4 pi A / P^2 of a chart of area `area` and perimeter `perimeter` (1 without perimeter)
inline double compactness_of(double area, double perimeter)
{
  return perimeter > 0 ? 4 * 3.14159265358979323846 * area / (perimeter * perimeter) : 1.;
}

// Per-face unit normal, area and centroid.
struct Face_geometry
{
  std::array<double, 3> normal, centroid;
  double area;
};

template <class TriangleMesh, class VPM, class FIM>
std::vector<Face_geometry> face_geometry(const TriangleMesh& tm, const VPM& vpm, const FIM& fim)
{
  std::vector<Face_geometry> g(num_faces(tm));
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const auto a = point_of<TriangleMesh>(source(h, tm), vpm), b = point_of<TriangleMesh>(target(h, tm), vpm),
               c = point_of<TriangleMesh>(target(next(h, tm), tm), vpm);
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    Face_geometry& x = g[get(fim, f)];
    for(int i = 0; i < 3; ++i) {
      x.normal[i] = len > 0 ? n[i] / len : 0.;
      x.centroid[i] = (a[i] + b[i] + c[i]) / 3.;
    }
    x.area = 0.5 * len;
  }
  return g;
}

// Whether the faces of chart `k` (given by `members`) are connected through
// edges, looking only at faces whose `label` is k. `seen`, if given: a
// scratch array of the mesh's face count, all 0, and left so (else one of its
// own is made).
template <class TriangleMesh, class FIM>
bool chart_is_connected(const TriangleMesh& tm, const FIM& fim,
                        const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& members,
                        const std::vector<std::size_t>& label, std::size_t k, std::vector<char>* seen = nullptr)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<char> own;
  if(!seen) {
    own.assign(label.size(), 0);
    seen = &own;
  }
  std::vector<char>& mark = *seen;
  std::vector<typename GT::face_descriptor> queue;
  std::size_t count = 0, total = 0;
  for(auto f : members)
    if(label[get(fim, f)] == k) {
      ++total;
      if(queue.empty()) {
        queue.push_back(f);
        mark[get(fim, f)] = 1;
      }
    }
  for(std::size_t q = 0; q < queue.size(); ++q, ++count)
    for(auto h : CGAL::halfedges_around_face(halfedge(queue[q], tm), tm)) {
      const auto o = opposite(h, tm);
      if(is_border(o, tm)) continue;
      const std::size_t g = get(fim, face(o, tm));
      if(!mark[g] && label[g] == k) {
        mark[g] = 1;
        queue.push_back(face(o, tm));
      }
    }
  if(seen != &own)
    for(auto f : queue) mark[get(fim, f)] = 0;
  return total > 0 && count == total;
}

// a point with a constructor from three coordinates
struct Xyz
{
  double x, y, z;
  Xyz(double a = 0, double b = 0, double c = 0) : x(a), y(b), z(c) {}
};

// a writable vertex point map that stores points in a vector by vertex index
template <class VIM>
struct Vector_point_map
{
  typedef typename boost::property_traits<VIM>::key_type key_type;
  typedef Xyz value_type;
  typedef Xyz reference;
  typedef boost::writable_property_map_tag category;
  std::vector<std::array<double, 3>>* data;
  VIM vim;
  friend void put(const Vector_point_map& m, const key_type& k, const Xyz& p) { (*m.data)[get(m.vim, k)] = {p.x, p.y, p.z}; }
};

// writes points stored by vertex index into a point map, or nothing when no map was given
template <class TriangleMesh, class VIM>
void write_points(const TriangleMesh&, const std::vector<std::array<double, 3>>&, const VIM&, CGAL::internal_np::Param_not_found)
{}

template <class TriangleMesh, class VIM, class PointMap>
void write_points(const TriangleMesh& tm, const std::vector<std::array<double, 3>>& points, const VIM& vim, PointMap out)
{
  typedef typename boost::property_traits<PointMap>::value_type Point;
  for(auto v : vertices(tm)) {
    const std::array<double, 3>& p = points[get(vim, v)];
    put(out, v, Point(p[0], p[1], p[2]));
  }
}

// The points of `tm` by vertex index
template <class TriangleMesh, class VPM, class VIM>
std::vector<std::array<double, 3>> points_by_index(const TriangleMesh& tm, const VPM& vpm, const VIM& vim)
{
  std::vector<std::array<double, 3>> points(num_vertices(tm));
  for(auto v : vertices(tm)) points[get(vim, v)] = point_of<TriangleMesh>(v, vpm);
  return points;
}

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

#endif // CGAL_QD_INTERNAL_CHARTS_H
