// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CONSTANTS_H
#define CGAL_QD_INTERNAL_CONSTANTS_H

namespace CGAL_QD {
namespace internal {

inline constexpr double pi = 3.14159265358979323846;

// the fraction of the local area distortion bound that the segmentation's
// splitting and merging leave free for the final flattening (seam lengths
// matched, seams smoothed); the final charts are measured against the bound
inline constexpr double local_area_distortion_margin = 0.05;

// a seam curve matches when its two sides differ by at most this fraction of
// the longer (the final flattening fits them to it; the pattern names the
// seams that do not)
inline constexpr double matched_seam_tolerance = 0.005;

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CONSTANTS_H
