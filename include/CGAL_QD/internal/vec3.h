// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_VEC3_H
#define CGAL_QD_INTERNAL_VEC3_H

// Small vector operations on 3D points held as std::array<double, 3>, and the
// distance from a point to a segment and to a polyline.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {
namespace vec3 {

typedef std::array<double, 3> P;

inline P sub(const P& a, const P& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

inline P cross(const P& u, const P& w)
{
  return {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
}

inline double dot(const P& u, const P& w) { return u[0] * w[0] + u[1] * w[1] + u[2] * w[2]; }

inline double norm(const P& u) { return std::sqrt(dot(u, u)); }

// distance from p to the segment [a, b], and in `t` the parameter of the nearest point
inline double segment_distance(const P& p, const P& a, const P& b, double& t)
{
  const P d = sub(b, a);
  const double dd = dot(d, d);
  t = dd > 0 ? (std::max)(0., (std::min)(1., dot(sub(p, a), d) / dd)) : 0.;
  const P q = {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]};
  return norm(sub(p, q));
}

// distance from p to the polyline through `line` (closed: its last point joins the first)
inline double polyline_distance(const P& p, const std::vector<P>& line, bool closed)
{
  if(line.empty()) return 0.;
  double best = norm(sub(p, line[0])), t;
  const std::size_t n = line.size(), ne = closed ? n : n - 1;
  for(std::size_t i = 0; i < ne; ++i) best = (std::min)(best, segment_distance(p, line[i], line[(i + 1) % n], t));
  return best;
}

} // namespace vec3
} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_VEC3_H
