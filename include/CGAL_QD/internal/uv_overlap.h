// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_UV_OVERLAP_H
#define CGAL_QD_INTERNAL_UV_OVERLAP_H

// The 2D tests behind the overlap part of `compute_distortion()`: whether two
// border segments cross beyond a tolerance, and whether the faces around two
// border edges that touch overlap.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL_QD {
namespace internal {

template <class UVMap, class V>
std::array<double, 2> uv_of(const UVMap& uv, const V& v)
{
  const auto& p = get(uv, v);
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
}

// The signed distance of r from the line through p and q (positive on the left).
inline double signed_distance(const std::array<double, 2>& p, const std::array<double, 2>& q,
                              const std::array<double, 2>& r)
{
  const double dx = q[0] - p[0], dy = q[1] - p[1], l = std::hypot(dx, dy);
  if(!(l > 0)) return std::hypot(r[0] - p[0], r[1] - p[1]);
  return (dx * (r[1] - p[1]) - dy * (r[0] - p[0])) / l;
}

// Whether segments ab and cd cross by more than delta: each has its endpoints
// strictly on either side of the other's line, further than delta. Segments
// that merely touch within delta (an endpoint on the other segment, two
// coincident sides of a slit) do not cross.
inline bool cross_beyond(const std::array<double, 2>& a, const std::array<double, 2>& b,
                         const std::array<double, 2>& c, const std::array<double, 2>& d, double delta)
{
  const double c1 = signed_distance(a, b, c), d1 = signed_distance(a, b, d);
  const double a1 = signed_distance(c, d, a), b1 = signed_distance(c, d, b);
  return ((c1 > delta && d1 < -delta) || (c1 < -delta && d1 > delta)) &&
         ((a1 > delta && b1 < -delta) || (a1 < -delta && b1 > delta));
}

// Whether a face around one of the vertices `a` overlaps a face around one of
// the vertices `b` in 2D, beyond touching: both faces are shrunk toward their
// centroids by a relative 1e-6 and then tested exactly.
template <class TriangleMesh, class VertexUVMap>
bool fans_overlap(const TriangleMesh& tm, const VertexUVMap& uv,
                  const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 2>& a,
                  const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 2>& b)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel EK;
  auto fan = [&](const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 2>& vs) {
    std::vector<face_descriptor> fs;
    for(auto v : vs)
      for(face_descriptor f : CGAL::faces_around_target(halfedge(v, tm), tm))
        if(f != boost::graph_traits<TriangleMesh>::null_face() && std::find(fs.begin(), fs.end(), f) == fs.end())
          fs.push_back(f);
    return fs;
  };
  auto shrunk = [&](face_descriptor f) {
    std::array<std::array<double, 2>, 3> q;
    int k = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) q[k++] = uv_of(uv, v);
    const double cx = (q[0][0] + q[1][0] + q[2][0]) / 3, cy = (q[0][1] + q[1][1] + q[2][1]) / 3;
    const double t = 1e-6;
    return EK::Triangle_2(EK::Point_2(q[0][0] + t * (cx - q[0][0]), q[0][1] + t * (cy - q[0][1])),
                          EK::Point_2(q[1][0] + t * (cx - q[1][0]), q[1][1] + t * (cy - q[1][1])),
                          EK::Point_2(q[2][0] + t * (cx - q[2][0]), q[2][1] + t * (cy - q[2][1])));
  };
  // a zero-area image is a fold: it is not a clean touch (and CGAL's
  // triangle intersection test requires non-degenerate triangles)
  const std::vector<face_descriptor> fa = fan(a), fb = fan(b);
  std::vector<EK::Triangle_2> tb;
  for(face_descriptor g : fb) {
    tb.push_back(shrunk(g));
    if(tb.back().is_degenerate()) return true;
  }
  for(face_descriptor f : fa) {
    const EK::Triangle_2 tf = shrunk(f);
    if(tf.is_degenerate()) return true;
    for(std::size_t k = 0; k < fb.size(); ++k)
      if(f != fb[k] && CGAL::do_intersect(tf, tb[k])) return true;
  }
  return false;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_UV_OVERLAP_H
