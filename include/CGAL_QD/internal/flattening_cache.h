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

// Two independent 64-bit digests of a byte stream: FNV-1a, and a
// multiply-rotate mix of 8-byte words.
class Digest
{
public:
  void add(const void* data, std::size_t bytes)
  {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for(std::size_t i = 0; i < bytes; ++i) {
      m_fnv = (m_fnv ^ p[i]) * 0x100000001b3ull;
      m_word |= std::uint64_t(p[i]) << (8 * m_fill);
      if(++m_fill == 8) flush();
    }
  }
  template <class T>
  void add_vector(const std::vector<T>& v)
  {
    const std::uint64_t n = v.size();
    add(&n, sizeof(n));
    if(!v.empty()) add(v.data(), v.size() * sizeof(T));
  }
  std::pair<std::uint64_t, std::uint64_t> value()
  {
    if(m_fill > 0) flush();
    return {m_fnv, m_mix ^ (m_mix >> 29)};
  }

private:
  void flush()
  {
    m_mix ^= m_word * 0x9e3779b97f4a7c15ull;
    m_mix = ((m_mix << 27) | (m_mix >> 37)) * 0xbf58476d1ce4e5b9ull + 0x94d049bb133111ebull;
    m_word = 0;
    m_fill = 0;
  }
  std::uint64_t m_fnv = 0xcbf29ce484222325ull, m_mix = 0x6a09e667f3bcc908ull, m_word = 0;
  int m_fill = 0;
};

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
