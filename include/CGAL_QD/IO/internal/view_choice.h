// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_VIEW_CHOICE_H
#define CGAL_QD_IO_INTERNAL_VIEW_CHOICE_H

// The direction from which a segmented mesh shows the most charts: a few
// directions around the mesh, each drawn into a small depth buffer of chart
// ids, and the one where the most charts can be seen is kept.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL_QD {
namespace internal {

// A view as in IO::Picture_options: a turn about the y axis, then a tilt above
// the horizontal plane, both in radians. `point(p)` gives x right, y up and z
// toward the viewer.
struct View_angles
{
  double azimuth = 0.6, elevation = 0.35;
  std::array<double, 3> point(const std::array<double, 3>& p) const
  {
    const double ca = std::cos(azimuth), sa = std::sin(azimuth), ce = std::cos(elevation), se = std::sin(elevation);
    const double x = ca * p[0] + sa * p[2], z = -sa * p[0] + ca * p[2];
    return {{x, ce * p[1] - se * z, se * p[1] + ce * z}};
  }
  // the unit vector from the mesh toward the viewer, in the mesh's frame
  std::array<double, 3> toward_viewer() const
  {
    const double ca = std::cos(azimuth), sa = std::sin(azimuth), ce = std::cos(elevation), se = std::sin(elevation);
    // the inverse of point() applied to (0, 0, 1)
    return {{-sa * ce, se, ca * ce}};
  }
};

// The charts seen from `view`: the triangles (3 vertex indices each, chart
// `chart[t]`) drawn by a depth buffer of `size` x `size` pixels; returns the
// number of pixels of every chart.
inline std::vector<std::size_t> visible_chart_pixels(const std::vector<std::array<double, 3>>& points,
                                                     const std::vector<std::array<std::size_t, 3>>& triangles,
                                                     const std::vector<std::size_t>& chart, std::size_t n,
                                                     const View_angles& view, int size)
{
  std::vector<std::array<double, 3>> q(points.size());
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for(std::size_t i = 0; i < points.size(); ++i) {
    q[i] = view.point(points[i]);
    for(int k = 0; k < 2; ++k) lo[k] = (std::min)(lo[k], q[i][k]), hi[k] = (std::max)(hi[k], q[i][k]);
  }
  const double span = (std::max)((std::max)(hi[0] - lo[0], hi[1] - lo[1]), 1e-300);
  const double s = (size - 1) / span;
  for(auto& p : q) p[0] = (p[0] - lo[0]) * s, p[1] = (p[1] - lo[1]) * s;
  std::vector<double> depth(std::size_t(size) * size, -std::numeric_limits<double>::infinity());
  std::vector<long> id(std::size_t(size) * size, -1);
  for(std::size_t t = 0; t < triangles.size(); ++t) {
    const std::array<double, 3>&a = q[triangles[t][0]], &b = q[triangles[t][1]], &c = q[triangles[t][2]];
    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    if(!(std::abs(area) > 0)) continue;
    const int x0 = (std::max)(0, int(std::ceil((std::min)({a[0], b[0], c[0]})))),
              x1 = (std::min)(size - 1, int(std::floor((std::max)({a[0], b[0], c[0]})))),
              y0 = (std::max)(0, int(std::ceil((std::min)({a[1], b[1], c[1]})))),
              y1 = (std::min)(size - 1, int(std::floor((std::max)({a[1], b[1], c[1]}))));
    for(int y = y0; y <= y1; ++y)
      for(int x = x0; x <= x1; ++x) {
        // barycentric coordinates of the pixel centre
        const double wa = ((b[0] - x) * (c[1] - y) - (c[0] - x) * (b[1] - y)) / area,
                     wb = ((c[0] - x) * (a[1] - y) - (a[0] - x) * (c[1] - y)) / area, wc = 1 - wa - wb;
        if(wa < 0 || wb < 0 || wc < 0) continue;
        const double z = wa * a[2] + wb * b[2] + wc * c[2];
        const std::size_t pixel = std::size_t(y) * size + x;
        if(z > depth[pixel]) {
          depth[pixel] = z;
          id[pixel] = static_cast<long>(chart[t]);
        }
      }
  }
  std::vector<std::size_t> pixels(n, 0);
  for(long c : id)
    if(c >= 0) ++pixels[std::size_t(c)];
  return pixels;
}

// Of 8 turns about the y axis at 35 degrees above and below the horizontal,
// and straight from above and below, the view that shows the most charts (a
// chart counts when it covers at least 0.2 % of the mesh's pixels, and at
// least 3); ties go to the view that shows the most of the surface, then to
// the earlier one. `preferred` is tried first.
inline View_angles view_showing_most_charts(const std::vector<std::array<double, 3>>& points,
                                            const std::vector<std::array<std::size_t, 3>>& triangles,
                                            const std::vector<std::size_t>& chart, std::size_t n,
                                            const View_angles& preferred, int size = 160)
{
  const double pi = 3.141592653589793;
  std::vector<View_angles> candidates{preferred};
  for(double elevation : {0.61, -0.61})
    for(int k = 0; k < 8; ++k) candidates.push_back(View_angles{preferred.azimuth + k * pi / 4, elevation});
  candidates.push_back(View_angles{preferred.azimuth, pi / 2});
  candidates.push_back(View_angles{preferred.azimuth, -pi / 2});
  View_angles best = preferred;
  std::size_t best_charts = 0, best_pixels = 0;
  for(const View_angles& v : candidates) {
    const std::vector<std::size_t> pixels = visible_chart_pixels(points, triangles, chart, n, v, size);
    std::size_t covered = 0;
    for(std::size_t p : pixels) covered += p;
    const std::size_t least = (std::max)(std::size_t(3), covered / 500);
    std::size_t seen = 0;
    for(std::size_t p : pixels)
      if(p >= least) ++seen;
    if(seen > best_charts || (seen == best_charts && covered > best_pixels)) {
      best = v;
      best_charts = seen;
      best_pixels = covered;
    }
  }
  return best;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_VIEW_CHOICE_H
