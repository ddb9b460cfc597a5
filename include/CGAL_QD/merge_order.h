// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_MERGE_ORDER_H
#define CGAL_QD_MERGE_ORDER_H

/// \file merge_order.h
/// The orders in which the merging of `merge_charts_by_boundaries()` (and of
/// `segment_quasi_developable()`) tries the boundary curves between charts.

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// the order in which `merge_charts_by_boundaries()` tries the boundary curves.
enum class Merge_order
{
  /// the paper's: the curve whose two charts have the largest total area first
  LARGEST_AREA_FIRST,
  /// the curve whose two charts have the smallest total area first: small, cheap trials first
  SMALLEST_AREA_FIRST,
  /// the curve with the largest length / sqrt(area of its two charts) first: charts that share much border
  LONGEST_RELATIVE_CURVE_FIRST,
  /// the curve whose removal gives the most compact chart first (largest 4 pi area / perimeter^2, the
  /// perimeter in 3D with cuts inside the chart counted twice): round pieces rather than sprawling ones
  MOST_COMPACT_FIRST
};

} // namespace CGAL_QD

#endif // CGAL_QD_MERGE_ORDER_H
