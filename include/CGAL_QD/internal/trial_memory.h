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
#include <CGAL_QD/internal/digest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <list>
#include <map>
#include <mutex>
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
  typedef std::pair<std::uint64_t, std::uint64_t> Key;
  static constexpr std::size_t default_max_bytes = std::size_t(32) << 20;

  explicit Trial_memory(std::size_t max_bytes = default_max_bytes) : m_max_bytes(max_bytes) {}

  bool find(const Key& key, Trial_start& start)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto it = m_index.find(key);
    if(it == m_index.end()) return false;
    m_used.splice(m_used.begin(), m_used, it->second);  // now the most recent
    start = it->second->start;
    ++m_hits;
    return true;
  }

  void store(const Key& key, Trial_start&& start)
  {
    const std::size_t bytes = start.bytes();
    std::lock_guard<std::mutex> lock(m_mutex);
    if(bytes > m_max_bytes || m_index.count(key)) return;
    m_used.push_front(Entry{key, std::move(start)});
    m_index[key] = m_used.begin();
    m_bytes += bytes;
    while(m_bytes > m_max_bytes) {
      m_bytes -= m_used.back().start.bytes();
      m_index.erase(m_used.back().key);
      m_used.pop_back();
    }
  }

  std::size_t hits() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_hits;
  }

  std::size_t size() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_index.size();
  }

private:
  struct Entry
  {
    Key key;
    Trial_start start;
  };
  mutable std::mutex m_mutex;
  std::list<Entry> m_used;  // the most recently used first
  std::map<Key, std::list<Entry>::iterator> m_index;
  std::size_t m_max_bytes, m_bytes = 0, m_hits = 0;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_TRIAL_MEMORY_H
