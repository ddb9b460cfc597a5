// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_LRU_BY_BYTES_H
#define CGAL_QD_INTERNAL_LRU_BY_BYTES_H

// A thread-safe store of values keyed by a 128-bit digest, holding at most a
// given number of bytes: the value stored or found least recently goes first.
// The ordering cache (ordering_cache.h) and the trial memory
// (trial_memory.h) keep their values in one.

#include <cstddef>
#include <cstdint>
#include <list>
#include <map>
#include <mutex>
#include <utility>

namespace CGAL_QD {
namespace internal {

// `bytes(value)` tells the size a value counts for
template <class Value>
class Lru_by_bytes
{
public:
  typedef std::pair<std::uint64_t, std::uint64_t> Key;
  typedef std::size_t (*Bytes)(const Value&);

  Lru_by_bytes(std::size_t max_bytes, Bytes bytes) : m_max_bytes(max_bytes), m_size_of(bytes) {}

  // a copy of the value stored for `key`, if any, into `value`; it is now the most recent
  bool find(const Key& key, Value& value)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto it = m_index.find(key);
    if(it == m_index.end()) {
      ++m_misses;
      return false;
    }
    m_used.splice(m_used.begin(), m_used, it->second);
    value = it->second->value;
    ++m_hits;
    return true;
  }

  // stores `value` for `key` (unless a value is stored for it, or it is larger
  // than the whole store), dropping the least recently used beyond the bytes
  void store(const Key& key, Value&& value)
  {
    const std::size_t bytes = m_size_of(value);
    std::lock_guard<std::mutex> lock(m_mutex);
    if(bytes > m_max_bytes || m_index.count(key)) return;
    m_used.push_front(Entry{key, std::move(value)});
    m_index[key] = m_used.begin();
    m_bytes += bytes;
    while(m_bytes > m_max_bytes) {
      m_bytes -= m_size_of(m_used.back().value);
      m_index.erase(m_used.back().key);
      m_used.pop_back();
    }
  }

  std::size_t hits() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_hits;
  }
  std::size_t misses() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_misses;
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
    Value value;
  };
  mutable std::mutex m_mutex;
  std::list<Entry> m_used;  // the most recently used first
  std::map<Key, typename std::list<Entry>::iterator> m_index;
  std::size_t m_max_bytes, m_bytes = 0, m_hits = 0, m_misses = 0;
  Bytes m_size_of;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_LRU_BY_BYTES_H
