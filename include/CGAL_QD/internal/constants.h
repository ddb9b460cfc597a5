// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CONSTANTS_H
#define CGAL_QD_INTERNAL_CONSTANTS_H

namespace CGAL_QD {
namespace internal {

inline constexpr double pi = 3.14159265358979323846;

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CONSTANTS_H
