// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_DIGEST_H
#define CGAL_QD_INTERNAL_DIGEST_H

// A 128-bit digest of a byte stream, the key of the caches of flattenings
// (flattening_cache.h) and of orderings (sparse_solvers.h).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// Two independent 64-bit digests of a byte stream: FNV-1a (on whole 8-byte
// words where a call starts at a word boundary of the stream, on single bytes
// elsewhere), and a multiply-rotate mix of 8-byte words. The same calls with
// the same bytes give the same digest.
class Digest
{
public:
  void add(const void* data, std::size_t bytes)
  {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    std::size_t i = 0;
    if(m_fill == 0)
      for(; i + 8 <= bytes; i += 8) {
        std::memcpy(&m_word, p + i, 8);
        m_fnv = (m_fnv ^ m_word) * 0x100000001b3ull;
        flush();
      }
    for(; i < bytes; ++i) {
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

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_DIGEST_H
