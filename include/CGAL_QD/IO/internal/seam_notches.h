// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_SEAM_NOTCHES_H
#define CGAL_QD_IO_INTERNAL_SEAM_NOTCHES_H

// The notches of a pattern: across the cut line into the piece, at the same
// fractions of the 2D length of the two sides of every seam curve, so that
// they meet when the seam is sewn; numbered along the curve, from the same
// end on both sides.

#include <CGAL_QD/IO/internal/pattern_pieces.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// The notches of every chart (by chart id, `n` charts) with their numbers,
// about `spacing` apart along the curves whose `drawn` is true; `count`
// receives how many, counted once per side. `chart` gives the chart of every
// face by index (`fim`), `point_at(corner(h))` the drawing position of the
// target of halfedge h in its face, `notch_length(k)` the length of the
// notches of chart k, and `font` the largest label height.
template <class TriangleMesh, class FIM, class Corner, class PointAt, class NotchLength>
std::vector<std::vector<std::pair<Pattern_drawing::Line, Pattern_drawing::Text>>> seam_notches(
    const TriangleMesh& tm,
    const std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>& curves,
    const std::vector<char>& drawn, const std::vector<std::size_t>& chart, const FIM& fim, std::size_t n,
    double spacing, double font, const Corner& corner, const PointAt& point_at, const NotchLength& notch_length,
    std::size_t& count)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef std::array<double, 2> P2;
  std::vector<std::vector<std::pair<Pattern_drawing::Line, Pattern_drawing::Text>>> notches(n);
  count = 0;
  for(std::size_t id = 0; id < curves.size(); ++id) {
    if(!drawn[id]) continue;
    const std::vector<halfedge_descriptor>& hs = curves[id];
    const bool closed = target(hs.back(), tm) == source(hs.front(), tm) && hs.size() > 2;
    // each side as a polyline along the curve, with the normal into its piece on every edge
    struct Side
    {
      std::size_t chart;
      std::vector<P2> points, normals;
      std::vector<double> at;  // arc length at each point
    } sides[2];
    for(int side = 0; side < 2; ++side) {
      Side& sd = sides[side];
      sd.chart = chart[get(fim, face(side == 0 ? hs.front() : opposite(hs.front(), tm), tm))];
      for(std::size_t i = 0; i < hs.size(); ++i) {
        const halfedge_descriptor g = side == 0 ? hs[i] : opposite(hs[i], tm);
        const P2 a = point_at(corner(prev(g, tm))), b = point_at(corner(g));  // g runs from a to b
        const double dx = b[0] - a[0], dy = b[1] - a[1], l = std::hypot(dx, dy);
        const P2 from = side == 0 ? a : b, to = side == 0 ? b : a;
        if(i == 0) sd.points.push_back(from), sd.at.push_back(0);
        sd.points.push_back(to);
        sd.at.push_back(sd.at.back() + l);
        sd.normals.push_back(l > 0 ? P2{{dy / l, -dx / l}} : P2{{0, 0}});
      }
    }
    const double length = (sides[0].at.back() + sides[1].at.back()) / 2;
    if(!(length > 0)) continue;
    const std::size_t per_side = closed ? (std::max)(2., std::round(length / spacing))
                                        : (std::max)(1., std::round(length / spacing) - 1);
    for(const Side& sd : sides) {
      const double tick = notch_length(sd.chart), number = (std::min)(0.6 * font, 2 * tick);
      std::size_t e = 0;
      for(std::size_t j = 1; j <= per_side; ++j) {
        const double t = (closed ? double(j - 1) / per_side : double(j) / (per_side + 1)) * sd.at.back();
        while(e + 1 < sd.normals.size() && sd.at[e + 1] < t) ++e;
        const double span = sd.at[e + 1] - sd.at[e], u = span > 0 ? (t - sd.at[e]) / span : 0.;
        const P2 q{{sd.points[e][0] + u * (sd.points[e + 1][0] - sd.points[e][0]),
                    sd.points[e][1] + u * (sd.points[e + 1][1] - sd.points[e][1])}};
        const P2& nn = sd.normals[e];
        notches[sd.chart].emplace_back(
            Pattern_drawing::Line{Pattern_drawing::NOTCH, q, P2{{q[0] + tick * nn[0], q[1] + tick * nn[1]}},
                                  {{id, j}}},
            Pattern_drawing::Text{P2{{q[0] + (tick + 0.8 * number) * nn[0], q[1] + (tick + 0.8 * number) * nn[1]}},
                                  number, 0., std::to_string(j)});
        ++count;
      }
    }
  }
  return notches;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_SEAM_NOTCHES_H
