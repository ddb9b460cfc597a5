// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_ASSEMBLY_ORDER_H
#define CGAL_QD_IO_INTERNAL_ASSEMBLY_ORDER_H

// The order in which a maker joins the pieces of a pattern: outward from the
// largest piece, each step adding the piece that shares the longest seams
// with those already joined (Prim's maximum spanning tree on the pieces,
// weighted by seam length), and sewing every seam between it and them.

#include <CGAL_QD/IO/pattern_options.h>

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// seam label of index k: A..Z, then A1..Z1, ...
inline std::string seam_label(std::size_t k)
{
  std::string s(1, char('A' + k % 26));
  if(k >= 26) s += std::to_string(k / 26);
  return s;
}

// `area` and `used` by chart id; curve k joins the charts `curve_charts[k]`
// (the same chart twice for a cut inside it) over a length `curve_length[k]`.
// Ties go to the smaller chart id, so the order is deterministic.
inline std::vector<IO::Assembly_step> assembly_order(const std::vector<double>& area, const std::vector<bool>& used,
                                                     const std::vector<std::pair<std::size_t, std::size_t>>& curve_charts,
                                                     const std::vector<double>& curve_length)
{
  const std::size_t n = area.size();
  std::map<std::pair<std::size_t, std::size_t>, double> shared;  // (smaller, larger chart) -> seam length
  for(std::size_t k = 0; k < curve_charts.size(); ++k)
    if(curve_charts[k].first != curve_charts[k].second) shared[curve_charts[k]] += curve_length[k];
  std::vector<bool> joined(n, false);
  std::vector<IO::Assembly_step> steps;
  auto join = [&](std::size_t piece, std::size_t onto) {
    joined[piece] = true;
    IO::Assembly_step step;
    step.piece = piece;
    step.onto = onto;
    for(std::size_t k = 0; k < curve_charts.size(); ++k) {
      const std::size_t a = curve_charts[k].first, b = curve_charts[k].second;
      if((a == piece && joined[b]) || (b == piece && joined[a])) step.seams.push_back(seam_label(k));
    }
    steps.push_back(step);
  };
  for(;;) {
    // the unjoined piece sharing the longest seams with a joined one
    double best = 0;
    std::size_t piece = n, onto = n;
    for(const auto& s : shared) {
      const std::size_t a = s.first.first, b = s.first.second;
      if(joined[a] == joined[b] || !(s.second > best)) continue;
      best = s.second;
      piece = joined[a] ? b : a;
      onto = joined[a] ? a : b;
    }
    if(piece < n) {
      join(piece, onto);
      continue;
    }
    // none: the largest piece not joined yet starts the model, or a part of it
    std::size_t start = n;
    for(std::size_t k = 0; k < n; ++k)
      if(used[k] && !joined[k] && (start == n || area[k] > area[start])) start = k;
    if(start == n) break;
    join(start, start);
  }
  return steps;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_ASSEMBLY_ORDER_H
