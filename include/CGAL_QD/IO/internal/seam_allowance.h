// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_SEAM_ALLOWANCE_H
#define CGAL_QD_IO_INTERNAL_SEAM_ALLOWANCE_H

// The seam allowance of a printed piece: the outline of the points within a
// given distance of the piece, computed with Clipper (Debian's
// libpolyclipping-dev) in integer coordinates: the union of the piece's
// triangles (which closes the slits of cuts inside it), offset outward with
// round corners. Used by IO/internal/pattern_drawing.h when
// CGAL_QD_HAS_CLIPPER is defined.

#include <polyclipping/clipper.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL_QD {
namespace internal {

// `triangles` in drawing units; `resolution` the drawing length of one
// integer step; the outlines are closed polygons (the last point is not
// repeated), outer ones and those of holes
inline std::vector<std::vector<std::array<double, 2>>> seam_allowance_outline(
    const std::vector<std::array<std::array<double, 2>, 3>>& triangles, double allowance, double resolution)
{
  auto to_int = [&](const std::array<double, 2>& p) {
    return ClipperLib::IntPoint(static_cast<ClipperLib::cInt>(std::llround(p[0] / resolution)),
                                static_cast<ClipperLib::cInt>(std::llround(p[1] / resolution)));
  };
  ClipperLib::Paths faces;
  faces.reserve(triangles.size());
  for(const auto& t : triangles) faces.push_back({to_int(t[0]), to_int(t[1]), to_int(t[2])});
  ClipperLib::Clipper clipper;
  clipper.AddPaths(faces, ClipperLib::ptSubject, true);
  ClipperLib::Paths region, outline;
  clipper.Execute(ClipperLib::ctUnion, region, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  // round corners within 1/5000 of the allowance of the true circle
  ClipperLib::ClipperOffset offset(2.0, (std::max)(1., 0.0002 * allowance / resolution));
  offset.AddPaths(region, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  offset.Execute(outline, allowance / resolution);
  std::vector<std::vector<std::array<double, 2>>> result;
  for(const ClipperLib::Path& path : outline) {
    result.emplace_back();
    for(const ClipperLib::IntPoint& p : path)
      result.back().push_back({{static_cast<double>(p.X) * resolution, static_cast<double>(p.Y) * resolution}});
  }
  return result;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_SEAM_ALLOWANCE_H
