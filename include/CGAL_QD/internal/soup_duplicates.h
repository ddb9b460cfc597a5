// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_SOUP_DUPLICATES_H
#define CGAL_QD_INTERNAL_SOUP_DUPLICATES_H

// Whether a polygon soup has points at the same position, or triangles on the
// same three points, found by sorting arrays. The repair asks first: where
// there are none, CGAL's `merge_duplicate_points_in_polygon_soup()` and
// `merge_duplicate_polygons_in_polygon_soup()` would leave the soup as it is,
// and they build a `std::map` of every point and a hash set of every polygon
// to find that out (a quarter of the time a mesh of a million faces took to be
// read and repaired).

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL_QD {
namespace internal {

// whether two points of `points` compare equal in x, y and z (as
// `Less_xyz_3`, which CGAL's merge uses, compares them)
template <class Point>
bool has_duplicate_points(const std::vector<Point>& points)
{
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&points](std::size_t a, std::size_t b) {
    return CGAL::compare_xyz(points[a], points[b]) == CGAL::SMALLER;
  });
  for(std::size_t i = 1; i < order.size(); ++i)
    if(CGAL::compare_xyz(points[order[i - 1]], points[order[i]]) == CGAL::EQUAL) return true;
  return false;
}

// whether two polygons of `polygons` are triangles on the same three point
// indices, in either orientation (CGAL's duplicates, where no two points are
// at the same position); `NOT_ALL_TRIANGLES` where a polygon is not a
// triangle (CGAL's merge then decides)
enum class Duplicate_triangles { NONE, SOME, NOT_ALL_TRIANGLES };

template <class PolygonRange>
Duplicate_triangles find_duplicate_triangles(const PolygonRange& polygons)
{
  std::vector<std::array<std::size_t, 3>> sorted;
  sorted.reserve(polygons.size());
  for(const auto& polygon : polygons) {
    if(polygon.size() != 3) return Duplicate_triangles::NOT_ALL_TRIANGLES;
    std::array<std::size_t, 3> t = {static_cast<std::size_t>(polygon[0]), static_cast<std::size_t>(polygon[1]),
                                    static_cast<std::size_t>(polygon[2])};
    std::sort(t.begin(), t.end());
    sorted.push_back(t);
  }
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end() ? Duplicate_triangles::SOME
                                                                          : Duplicate_triangles::NONE;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_SOUP_DUPLICATES_H
