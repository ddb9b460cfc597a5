// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_TIMING_H
#define CGAL_QD_INTERNAL_TIMING_H

// The wall-clock times reported in the results (`time_ms` and the like).

#include <chrono>

namespace CGAL_QD {
namespace internal {

inline double milliseconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_TIMING_H
