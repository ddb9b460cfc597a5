// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_TRIAL_MEMORY_H
#define CGAL_QD_INTERNAL_TRIAL_MEMORY_H

// What an accepted trial computed before its decision: LPFB+IP's map and the
// free optimisation's map after the trial's iterations. The final flattening
// of a chart runs the same two steps on the same chart cut open, then goes
// on (up to 70 more iterations, and the fallbacks of a chart not accepted):
// where the chart's last accepted trial is remembered, it starts from there
// instead of computing them again, with the same numbers to the last bit.
// The chart a trial accepts is most often the chart flattened at the end (a
// merge's joined chart, a chart whose cuts were shortened), so only accepted
// trials are kept.

#include <CGAL_QD/optimize_flattening.h>
#include <CGAL_QD/internal/lru_by_bytes.h>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// an accepted trial's work, by wedge of the chart cut open (in the order the
// evaluator gives the wedges)
struct Trial_start
{
  std::size_t border_loops = 0;
  std::vector<std::array<double, 2>> lpfb_ip;
  // empty where LPFB+IP was accepted and the trial ran no optimisation
  std::vector<std::array<double, 2>> optimized;
  Optimization_result optimization;

  std::size_t bytes() const { return (lpfb_ip.size() + optimized.size()) * sizeof(std::array<double, 2>); }
};

// Thread-safe. The trials kept take at most `max_bytes`; the one stored or
// found least recently goes first. A trial is keyed by a 128-bit digest of
// its chart cut open (the points of its wedges and the wedges of its corners)
// and of the options of its flattening, not of the thresholds, which decide
// only what is accepted.
class Trial_memory
{
public:
  typedef Lru_by_bytes<Trial_start>::Key Key;
  static constexpr std::size_t default_max_bytes = std::size_t(32) << 20;

  explicit Trial_memory(std::size_t max_bytes = default_max_bytes) : m_store(max_bytes, &bytes_of) {}

  bool find(const Key& key, Trial_start& start) { return m_store.find(key, start); }
  void store(const Key& key, Trial_start&& start) { m_store.store(key, std::move(start)); }
  std::size_t hits() const { return m_store.hits(); }
  std::size_t size() const { return m_store.size(); }

private:
  static std::size_t bytes_of(const Trial_start& start) { return start.bytes(); }
  Lru_by_bytes<Trial_start> m_store;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_TRIAL_MEMORY_H
