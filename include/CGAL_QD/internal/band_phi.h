// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_BAND_PHI_H
#define CGAL_QD_INTERNAL_BAND_PHI_H

// The signed distance phi of a band vertex to the smoothed copy of a border
// curve, positive on chart A's side: the zero set that `Band_cut` cuts the
// band along (used by `Chart_boundary_smoother`).

#include <CGAL_QD/internal/band_cut.h>
#include <CGAL_QD/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {

// the smoothed curve: its points, its vertex normals (from the faces of A and
// B), which of its edges are kept (sharp or constrained), whether it is closed,
// and the mean edge length of the curve before smoothing
struct Smoothed_curve
{
  const std::vector<std::array<double, 3>>& target;
  const std::vector<std::array<double, 3>>& normals;
  const std::vector<char>& kept;
  bool closed;
  double mean_edge;
};

// phi (and its raw value) at node n: the side of the band outside it, 0 where
// the node is fixed, else the distance to the nearest point of the curve,
// signed by the side of the curve's frame there
inline void band_node_phi(Band_node& n, const Smoothed_curve& c)
{
  typedef std::array<double, 3> P;
  const std::size_t nv = c.target.size(), ne = c.closed ? nv : nv - 1;
  n.phi = n.raw = 0;
  if(!n.in_band) {
    n.phi = n.raw = n.side;
    return;
  }
  if(n.fixed) return;
  double best = -1, best_t = 0;
  std::size_t best_i = 0;
  for(std::size_t i = 0; i < ne; ++i) {
    double t;
    const double d = vec3::segment_distance(n.p, c.target[i], c.target[(i + 1) % nv], t);
    if(best < 0 || d < best) {
      best = d;
      best_t = t;
      best_i = i;
    }
  }
  const std::size_t j = best_t <= 0 ? best_i : (best_t >= 1 ? (best_i + 1) % nv : nv);
  double phi;
  if(j < nv && !c.closed && (j == 0 || j + 1 == nv) && n.side != 0)
    phi = n.side * best;  // beyond an end of the curve: the vertex keeps its side
  else if(j < nv && (c.closed || (j > 0 && j + 1 < nv))) {
    // nearest to a corner of the smoothed curve: the side of the bisector of its two frames
    const std::size_t i0 = (j + nv - 1) % nv, i1 = (j + 1) % nv;
    const P s0 = vec3::cross(c.normals[j], vec3::sub(c.target[j], c.target[i0])),
            s1 = vec3::cross(c.normals[j], vec3::sub(c.target[i1], c.target[j]));
    const double l0 = vec3::norm(s0), l1 = vec3::norm(s1);
    P s = {0., 0., 0.};
    for(int k = 0; k < 3; ++k) s[k] = (l0 > 0 ? s0[k] / l0 : 0.) + (l1 > 0 ? s1[k] / l1 : 0.);
    const double ls = vec3::norm(s);
    phi = ls > 0 ? vec3::dot(vec3::sub(n.p, c.target[j]), s) / ls : 0.;
    if(std::abs(phi) < best) phi = phi < 0 ? -best : best;
    if(n.side != 0 && (c.kept[i0] || c.kept[j % ne])) phi = n.side * best;
  }
  else {
    const P& a = c.target[best_i];
    const P& b = c.target[(best_i + 1) % nv];
    const P d = vec3::sub(b, a);
    P nm;
    for(int k = 0; k < 3; ++k) nm[k] = (1 - best_t) * c.normals[best_i][k] + best_t * c.normals[(best_i + 1) % nv][k];
    const P s = vec3::cross(nm, d);
    const double ls = vec3::norm(s);
    const P q = {a[0] + best_t * d[0], a[1] + best_t * d[1], a[2] + best_t * d[2]};
    phi = ls > 0 ? vec3::dot(vec3::sub(n.p, q), s) / ls : 0.;
    // beside a kept (sharp or constrained) edge, the faces keep their chart
    if(c.kept[best_i] && n.side != 0) phi = n.side * best;
  }
  // a vertex next to the outside of the band keeps its side: the new curve stays in the band
  if(n.locked && !(phi * n.side > 0)) phi = n.side * (std::max)(std::abs(phi), 1e-3 * c.mean_edge);
  n.phi = n.raw = phi;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_BAND_PHI_H
