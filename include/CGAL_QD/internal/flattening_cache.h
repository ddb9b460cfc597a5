// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_FLATTENING_CACHE_H
#define CGAL_QD_INTERNAL_FLATTENING_CACHE_H

// The flattenings of charts met again: the seam smoothing flattens every
// chart of the mesh at each try, and most charts are the same as at the try
// before. A chart's flattening depends only on its triangles cut open (the
// points of its wedges and the wedges of its corners), the target lengths and
// start of a fit, and the thresholds; the cache keys it by a 128-bit digest
// of all of them.

#include <CGAL_QD/internal/digest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// Thread-safe. An entry is dropped when a generation goes by without it
// being stored or found, so the cache holds about two tries' flattenings.
template <class Report>
class Flattening_cache
{
public:
  typedef std::pair<std::uint64_t, std::uint64_t> Key;

  // starts the next try: drops the entries the last one did not use
  void next_generation()
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    for(auto it = m_entries.begin(); it != m_entries.end();)
      it = it->second.used < m_generation ? m_entries.erase(it) : std::next(it);
    ++m_generation;
  }

  // every entry dropped
  void clear()
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_entries.clear();
  }

  bool find(const Key& key, Report& report, std::vector<std::array<double, 2>>* uv)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto it = m_entries.find(key);
    if(it == m_entries.end()) return false;
    it->second.used = m_generation;
    report = it->second.report;
    if(uv) *uv = it->second.uv;
    ++m_hits;
    return true;
  }

  void store(const Key& key, const Report& report, const std::vector<std::array<double, 2>>* uv)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    Entry& e = m_entries[key];
    e.report = report;
    e.uv = uv ? *uv : std::vector<std::array<double, 2>>();
    e.used = m_generation;
  }

  std::size_t hits() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_hits;
  }

  std::size_t size() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_entries.size();
  }

private:
  struct Entry
  {
    Report report;
    std::vector<std::array<double, 2>> uv;
    std::size_t used = 0;
  };
  mutable std::mutex m_mutex;
  std::map<Key, Entry> m_entries;
  std::size_t m_generation = 1, m_hits = 0;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_FLATTENING_CACHE_H
