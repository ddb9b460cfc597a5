// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_CHART_PALETTE_H
#define CGAL_QD_IO_CHART_PALETTE_H

/// \file IO/chart_palette.h
/// Colours for the charts of a segmentation such that charts that share a
/// border get clearly different colours, as a map colouring does.

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// a squared difference of two colours that follows what the eye sees better
// than plain RGB: red, green and blue weighted 2, 4 and 3
inline double color_distance2(const std::array<unsigned char, 3>& a, const std::array<unsigned char, 3>& b)
{
  const double dr = double(a[0]) - b[0], dg = double(a[1]) - b[1], db = double(a[2]) - b[2];
  return 2 * dr * dr + 4 * dg * dg + 3 * db * db;
}

} // namespace internal

namespace IO {

/// \ingroup PkgCGAL_QDRef
/// the twelve colours `chart_palette()` chooses from: light enough for dark
/// seam lines on them, far apart in hue and lightness.
inline const std::vector<std::array<unsigned char, 3>>& palette_colors()
{
  static const std::vector<std::array<unsigned char, 3>> colors = {
      {{240, 163, 50}},  {{92, 170, 232}},  {{60, 178, 120}},  {{238, 221, 90}},  {{178, 120, 210}},
      {{232, 104, 86}},  {{150, 210, 230}}, {{160, 205, 100}}, {{240, 150, 190}}, {{120, 130, 220}},
      {{200, 160, 110}}, {{90, 200, 190}}};
  return colors;
}


/// \ingroup PkgCGAL_QDRef
/// a colour for every chart id in `[0, n)`, n the largest id plus one, from
/// `palette_colors()`: charts that share an edge get different colours
/// whenever the palette allows it. The charts are coloured greedily, those
/// with the most neighbours first (ties by id); each takes, of the palette
/// colours clearly different from those of its coloured neighbours, the least
/// used one (then the one farthest from them, then the first), so that all
/// colours are used; where none is clearly different, the one farthest from
/// them (the nearest neighbour's colour counts). The result depends only on
/// the charts and their adjacency.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `ReadablePropertyMap` from faces to an integral chart id
template <class TriangleMesh, class FaceChartMap>
std::vector<std::array<unsigned char, 3>> chart_palette(const TriangleMesh& tm, const FaceChartMap& face_chart)
{
  std::size_t n = 0;
  for(auto f : faces(tm)) n = (std::max)(n, static_cast<std::size_t>(get(face_chart, f)) + 1);
  std::vector<std::set<std::size_t>> neighbours(n);
  for(auto h : halfedges(tm)) {
    if(is_border_edge(h, tm)) continue;
    const std::size_t a = static_cast<std::size_t>(get(face_chart, face(h, tm))),
                      b = static_cast<std::size_t>(get(face_chart, face(opposite(h, tm), tm)));
    if(a != b) neighbours[a].insert(b);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return neighbours[x].size() > neighbours[y].size(); });
  const std::vector<std::array<unsigned char, 3>>& colors = palette_colors();
  std::vector<long> color_of(n, -1);
  std::vector<std::size_t> used(colors.size(), 0);
  // colours closer than this (in color_distance2()) to a neighbour's are not clearly different
  const double clear = 120. * 120.;
  for(std::size_t k : order) {
    long best = -1;
    double best_distance = -1;
    for(std::size_t c = 0; c < colors.size(); ++c) {
      double nearest = 1e300;
      for(std::size_t m : neighbours[k])
        if(color_of[m] >= 0) nearest = (std::min)(nearest, internal::color_distance2(colors[c], colors[color_of[m]]));
      bool better = best < 0;
      if(!better) {
        const std::size_t b = std::size_t(best);
        const bool clear_c = nearest >= clear, clear_b = best_distance >= clear;
        if(clear_c != clear_b) better = clear_c;
        else if(clear_c) better = used[c] < used[b] || (used[c] == used[b] && nearest > best_distance);
        else better = nearest > best_distance;
      }
      if(better) {
        best = static_cast<long>(c);
        best_distance = nearest;
      }
    }
    color_of[k] = best;
    ++used[std::size_t(best)];
  }
  std::vector<std::array<unsigned char, 3>> result(n);
  for(std::size_t k = 0; k < n; ++k) result[k] = colors[std::size_t(color_of[k])];
  return result;
}

} // namespace IO
} // namespace CGAL_QD

#endif // CGAL_QD_IO_CHART_PALETTE_H
