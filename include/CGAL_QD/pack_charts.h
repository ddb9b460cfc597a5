// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_PACK_CHARTS_H
#define CGAL_QD_PACK_CHARTS_H

/// \file pack_charts.h
/// A texture atlas: the flattened charts of a segmentation, each turned to its
/// smallest enclosing rectangle and packed without overlap into the unit square.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/internal/point_scale.h>
#include <CGAL_QD/parameters.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/convex_hull_2.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// where one chart went in the atlas: `atlas = scale * R(angle) * uv + offset`.
struct Chart_placement
{
  double angle = 0;                    ///< rotation of the chart's UVs, in radians
  std::array<double, 2> offset{{0, 0}};
  std::array<double, 2> size{{0, 0}};  ///< the chart's box in the atlas, margin excluded
};

/// \ingroup PkgCGAL_QDRef
/// the result of `pack_charts()`.
struct Atlas_result
{
  Error_code status = Error_code::OK;
  /// atlas units per UV unit, the same for every chart (the charts keep their relative sizes)
  double scale = 0;
  /// the area of the charts' UV triangles over the area of the unit square
  double coverage = 0;
  std::vector<Chart_placement> charts;
  /// the packed UV of every corner, in the layout of `Segmentation_result::corner_uv`
  std::vector<std::array<double, 2>> corner_uv;

  explicit operator bool() const { return status == Error_code::OK; }
};

namespace internal {

// the smallest-area enclosing rectangle of a point set: rotating the points by
// `angle` puts them in [low, low + size]
struct Rectangle
{
  double angle = 0;
  std::array<double, 2> low{{0, 0}}, size{{0, 0}};
};

inline Rectangle min_area_rectangle(const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_2>& points)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point;
  Rectangle best;
  if(points.empty()) return best;
  std::vector<Point> hull;
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  double best_area = std::numeric_limits<double>::infinity();
  for(std::size_t e = 0; e < hull.size(); ++e) {
    const Point &p = hull[e], &q = hull[(e + 1) % hull.size()];
    const double dx = q.x() - p.x(), dy = q.y() - p.y();
    // rotate by -atan2(dy, dx): the hull edge becomes horizontal
    const double angle = hull.size() < 2 || !(std::hypot(dx, dy) > 0) ? 0. : -std::atan2(dy, dx);
    const double c = std::cos(angle), s = std::sin(angle);
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    for(const Point& h : hull) {
      const double x = c * h.x() - s * h.y(), y = s * h.x() + c * h.y();
      x0 = (std::min)(x0, x);
      x1 = (std::max)(x1, x);
      y0 = (std::min)(y0, y);
      y1 = (std::max)(y1, y);
    }
    if((x1 - x0) * (y1 - y0) < best_area) {
      best_area = (x1 - x0) * (y1 - y0);
      best.angle = angle;
      best.low = {{x0, y0}};
      best.size = {{x1 - x0, y1 - y0}};
    }
    if(hull.size() < 2) break;
  }
  return best;
}

struct Packing_box
{
  std::size_t chart;
  double w, h;  // with the margin
  double x = 0, y = 0;
  bool turned = false;  // placed turned by 90 degrees
  bool placed = false;  // false: it did not fit below the height limit
};

// Skyline bottom-left packing into a strip of width `width`, up to `height`
// (a box that fits nowhere below it is left unplaced); returns the height used.
inline double skyline_pack(std::vector<Packing_box>& boxes, double width,
                           double height = std::numeric_limits<double>::infinity())
{
  struct Segment { double x, w, y; };
  std::vector<Segment> sky{{0., width, 0.}};
  double top = 0;
  for(Packing_box& b : boxes) {
    double best_y = std::numeric_limits<double>::infinity(), best_x = 0;
    bool best_turn = false;
    for(int turn = 0; turn < 2; ++turn) {
      const double w = turn ? b.h : b.w, h = turn ? b.w : b.h;
      if(w > width) continue;
      for(std::size_t i = 0; i < sky.size(); ++i) {
        const double x = sky[i].x;
        if(x + w > width * (1 + 1e-12)) break;
        double y = 0;
        for(std::size_t j = i; j < sky.size() && sky[j].x < x + w; ++j) y = (std::max)(y, sky[j].y);
        if(y + h > height * (1 + 1e-12)) continue;
        if(y + h < best_y || (y + h == best_y && x < best_x)) {
          best_y = y + h;
          best_x = x;
          best_turn = turn != 0;
        }
      }
    }
    b.placed = best_y < std::numeric_limits<double>::infinity();
    if(!b.placed) continue;
    // best_y holds the top of the placed box
    const double w = best_turn ? b.h : b.w, h = best_turn ? b.w : b.h;
    b.turned = best_turn;
    b.x = best_x;
    b.y = best_y - h;
    top = (std::max)(top, best_y);
    // raise the skyline over [x, x + w)
    std::vector<Segment> next;
    for(const Segment& s : sky) {
      const double s0 = s.x, s1 = s.x + s.w;
      if(s1 <= b.x || s0 >= b.x + w) {
        next.push_back(s);
        continue;
      }
      if(s0 < b.x) next.push_back({s0, b.x - s0, s.y});
      if(s1 > b.x + w) next.push_back({b.x + w, s1 - (b.x + w), s.y});
    }
    next.push_back({b.x, w, best_y});
    std::sort(next.begin(), next.end(), [](const Segment& p, const Segment& q) { return p.x < q.x; });
    // merge neighbours at the same height
    sky.clear();
    for(const Segment& s : next)
      if(!sky.empty() && sky.back().y == s.y && std::abs(sky.back().x + sky.back().w - s.x) <= 1e-15 * width)
        sky.back().w += s.w;
      else
        sky.push_back(s);
  }
  return top;
}

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// packs the flattened charts of a segmentation into the unit square, for a
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// texture atlas. Each chart is rotated to its smallest-area enclosing
/// rectangle (rotating calipers on its convex hull), the rectangles, with a
/// margin around each, are sorted by height and placed bottom-left on a
/// skyline, each either way up (90-degree turns allowed). Strip widths of 1,
/// 1.15, 1.3 and 1.5 times the square root of the boxes' area are tried and the
/// most compact square is kept. All charts get the same scale, so texel density
/// is uniform. Charts do not overlap: their boxes are disjoint.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `ReadablePropertyMap` from faces to a chart id in `[0, n)`
/// \param corner_uv the UVs of the corners, 3 per face by face index (as `Segmentation_result::corner_uv`)
/// \param np optional named parameters: `CGAL_QD::parameters::atlas_margin`, the free space around
///        each chart, about a fraction of the atlas side (default 0.005), and `face_index_map`
/// \returns an `Atlas_result`; `EMPTY_MESH` without faces, `INVALID_COORDINATES` if `corner_uv` has
///          the wrong size or a non-finite value.
template <class TriangleMesh, class FaceChartMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Atlas_result pack_charts(const TriangleMesh& tm, const FaceChartMap& face_chart,
                         const std::vector<std::array<double, 2>>& corner_uv,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  Atlas_result result;
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const double margin = (std::max)(0., choose_parameter(get_parameter(np, internal_np::atlas_margin_t()), 0.005));
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  if(nf == 0) {
    result.status = Error_code::EMPTY_MESH;
    return result;
  }
  if(corner_uv.size() != 3 * nf) {
    result.status = Error_code::INVALID_COORDINATES;
    return result;
  }
  for(const auto& p : corner_uv)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1])) {
      result.status = Error_code::INVALID_COORDINATES;
      return result;
    }
  // UVs beyond [2^-64, 2^64] (a mesh at 1e200) are packed scaled by a power of
  // two, which is exact: box areas would overflow (internal/point_scale.h)
  double largest = 0;
  for(const auto& p : corner_uv) largest = (std::max)({largest, std::abs(p[0]), std::abs(p[1])});
  const double uv_scale = internal::normalizing_scale(largest);
  std::vector<std::array<double, 2>> scaled_uv;
  if(uv_scale != 1.) {
    scaled_uv = corner_uv;
    for(auto& p : scaled_uv) p = {{p[0] * uv_scale, p[1] * uv_scale}};
  }
  const std::vector<std::array<double, 2>>& uv = uv_scale != 1. ? scaled_uv : corner_uv;

  std::vector<std::size_t> chart_of(nf);
  std::size_t n = 0;
  for(auto f : faces(tm)) {
    chart_of[get(fim, f)] = static_cast<std::size_t>(get(face_chart, f));
    n = (std::max)(n, chart_of[get(fim, f)] + 1);
  }

  // smallest enclosing rectangle of every chart
  std::vector<std::vector<K::Point_2>> points(n);
  for(std::size_t i = 0; i < nf; ++i) {
    for(int k = 0; k < 3; ++k) points[chart_of[i]].emplace_back(uv[3 * i + k][0], uv[3 * i + k][1]);
  }
  result.charts.resize(n);
  std::vector<std::array<double, 2>> low(n, {{0., 0.}});  // the rotated box's lower corner
  double box_area = 0;
  for(std::size_t k = 0; k < n; ++k) {
    if(points[k].empty()) continue;
    const internal::Rectangle r = internal::min_area_rectangle(points[k]);
    result.charts[k].angle = r.angle;
    result.charts[k].size = r.size;
    low[k] = r.low;
    box_area += result.charts[k].size[0] * result.charts[k].size[1];
  }
  if(!(box_area > 0)) box_area = 1;

  // the margin, as a fraction of the side of a square as large as the boxes
  const double pad = margin * std::sqrt(box_area);
  std::vector<internal::Packing_box> best_boxes;
  double best_side = std::numeric_limits<double>::infinity();
  for(double factor : {1.0, 1.15, 1.3, 1.5}) {
    std::vector<internal::Packing_box> boxes;
    double widest = 0;
    for(std::size_t k = 0; k < n; ++k) {
      if(points[k].empty()) continue;
      boxes.push_back({k, result.charts[k].size[0] + 2 * pad, result.charts[k].size[1] + 2 * pad});
      widest = (std::max)(widest, (std::min)(boxes.back().w, boxes.back().h));
    }
    std::stable_sort(boxes.begin(), boxes.end(), [](const internal::Packing_box& a, const internal::Packing_box& b) {
      return (std::max)(a.w, a.h) > (std::max)(b.w, b.h);
    });
    double total = 0;
    for(const auto& b : boxes) total += b.w * b.h;
    const double width = (std::max)(widest, factor * std::sqrt(total));
    const double height = internal::skyline_pack(boxes, width);
    double used_width = 0;
    for(const auto& b : boxes) used_width = (std::max)(used_width, b.x + (b.turned ? b.h : b.w));
    const double side = (std::max)(used_width, height);
    if(side < best_side) {
      best_side = side;
      best_boxes = boxes;
    }
  }
  result.scale = 1. / best_side;
  for(const internal::Packing_box& b : best_boxes) {
    Chart_placement& c = result.charts[b.chart];
    // the chart, rotated into its box, then turned if the box was, then placed
    const double w = c.size[0];
    double angle = c.angle;
    std::array<double, 2> origin = {{b.x + pad - low[b.chart][0], b.y + pad - low[b.chart][1]}};
    if(b.turned) {
      // turn by +90 degrees: (x, y) -> (-y, x); the box [0, w] x [0, h] goes to [-h, 0] x [0, w]
      angle += 1.5707963267948966;
      origin = {{b.x + pad + c.size[1] + low[b.chart][1], b.y + pad - low[b.chart][0]}};
      c.size = {{c.size[1], w}};
    }
    c.angle = angle;
    c.offset = {{origin[0] * result.scale, origin[1] * result.scale}};
    c.size = {{c.size[0] * result.scale, c.size[1] * result.scale}};
  }
  result.corner_uv.resize(3 * nf);
  for(std::size_t i = 0; i < nf; ++i) {
    const Chart_placement& c = result.charts[chart_of[i]];
    const double co = std::cos(c.angle), si = std::sin(c.angle);
    for(int k = 0; k < 3; ++k) {
      const auto& p = uv[3 * i + k];
      result.corner_uv[3 * i + k] = {{result.scale * (co * p[0] - si * p[1]) + c.offset[0],
                                      result.scale * (si * p[0] + co * p[1]) + c.offset[1]}};
    }
  }
  // measured in the unit square, where the area of a mesh at 1e200 (1e400 in
  // its units) is representable
  double covered = 0;
  for(std::size_t i = 0; i < nf; ++i) {
    const auto &a = result.corner_uv[3 * i], &b = result.corner_uv[3 * i + 1], &c = result.corner_uv[3 * i + 2];
    covered += 0.5 * std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
  }
  result.coverage = covered;
  result.scale *= uv_scale;  // atlas units per unit of the input UVs
  return result;
}

} // namespace CGAL_QD

#endif // CGAL_QD_PACK_CHARTS_H
