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

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CONSTANTS_H
