// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_ASSEMBLY_ORDER_H
#define CGAL_QD_IO_INTERNAL_ASSEMBLY_ORDER_H

// The order in which a maker joins the pieces of a pattern: outward from the
// largest piece, each step adding the piece that shares the longest seams
// with those already joined (Prim's maximum spanning tree on the pieces,
// weighted by seam length), and sewing every seam between it and them.

#include <CGAL_QD/IO/pattern_options.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <queue>
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
// Ties go to the smaller chart id, so the order is deterministic. The pairs
// of pieces that could join next wait in a heap, so that a pattern of many
// thousand pieces is ordered in O(c log c) for c curves.
inline std::vector<IO::Assembly_step> assembly_order(const std::vector<double>& area, const std::vector<bool>& used,
                                                     const std::vector<std::pair<std::size_t, std::size_t>>& curve_charts,
                                                     const std::vector<double>& curve_length)
{
  typedef std::pair<std::size_t, std::size_t> Pair;
  const std::size_t n = area.size();
  std::map<Pair, double> shared;  // (smaller, larger chart) -> seam length
  for(std::size_t k = 0; k < curve_charts.size(); ++k)
    if(curve_charts[k].first != curve_charts[k].second) shared[curve_charts[k]] += curve_length[k];
  // per chart: its curves in curve order, and the pairs it is in
  std::vector<std::vector<std::size_t>> curves_of(n);
  for(std::size_t k = 0; k < curve_charts.size(); ++k) {
    curves_of[curve_charts[k].first].push_back(k);
    if(curve_charts[k].second != curve_charts[k].first) curves_of[curve_charts[k].second].push_back(k);
  }
  std::vector<std::vector<std::pair<Pair, double>>> pairs_of(n);
  for(const auto& s : shared) {
    pairs_of[s.first.first].push_back(s);
    pairs_of[s.first.second].push_back(s);
  }
  // the longest seams first, then the smaller pair
  struct Candidate
  {
    double length;
    Pair pair;
    bool operator<(const Candidate& o) const { return length < o.length || (length == o.length && pair > o.pair); }
  };
  std::priority_queue<Candidate> candidates;
  std::vector<bool> joined(n, false);
  std::vector<IO::Assembly_step> steps;
  auto join = [&](std::size_t piece, std::size_t onto) {
    joined[piece] = true;
    IO::Assembly_step step;
    step.piece = piece;
    step.onto = onto;
    for(std::size_t k : curves_of[piece]) {
      const std::size_t a = curve_charts[k].first, b = curve_charts[k].second;
      if(joined[a == piece ? b : a]) step.seams.push_back(seam_label(k));
    }
    steps.push_back(step);
    for(const auto& s : pairs_of[piece])
      if(s.second > 0 && joined[s.first.first] != joined[s.first.second]) candidates.push({s.second, s.first});
  };
  // the pieces that start the model or a part of it: the largest first
  std::vector<std::size_t> by_area;
  for(std::size_t k = 0; k < n; ++k)
    if(used[k]) by_area.push_back(k);
  std::stable_sort(by_area.begin(), by_area.end(), [&](std::size_t a, std::size_t b) { return area[a] > area[b]; });
  std::size_t next_start = 0;
  for(;;) {
    // the unjoined piece sharing the longest seams with a joined one
    while(!candidates.empty() && joined[candidates.top().pair.first] && joined[candidates.top().pair.second])
      candidates.pop();
    if(!candidates.empty()) {
      const Pair p = candidates.top().pair;
      candidates.pop();
      join(joined[p.first] ? p.second : p.first, joined[p.first] ? p.first : p.second);
      continue;
    }
    // none: the largest piece not joined yet starts the model, or a part of it
    while(next_start < by_area.size() && joined[by_area[next_start]]) ++next_start;
    if(next_start == by_area.size()) break;
    join(by_area[next_start], by_area[next_start]);
  }
  return steps;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_ASSEMBLY_ORDER_H
