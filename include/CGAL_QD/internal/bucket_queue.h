// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_BUCKET_QUEUE_H
#define CGAL_QD_INTERNAL_BUCKET_QUEUE_H

// The two queues of step 1's flood (normal_vsa.h), with one interface: a
// binary heap, and a queue of buckets for entries whose key is a finite
// double, zero or more, which gives the entry of the smallest key first.
// Where no two entries have the same key, that is the order of any other such
// queue, a binary heap included, so the flood without copies takes the same
// decisions with it; where two have the same key, which comes first is this
// queue's own (the flood then starts again with the binary heap).
//
// The entries are kept in buckets by the leading bits of their key's binary
// representation (which orders nonnegative doubles as their values): its
// exponent and the first `mantissa_bits` bits of its mantissa, over the
// `octaves` below the largest key the queue is told of (smaller keys share the
// first bucket, larger ones the last), so the keys of one bucket are within a
// factor of 1 + 2^-mantissa_bits of each other. Each bucket is a list whose
// first entry is its smallest, and three levels of bit masks say which
// buckets hold entries. Taking the smallest entry is then a few bit scans and
// a look through the rest of its bucket, instead of the dozen levels of a
// binary heap with a hard-to-predict branch at each.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace CGAL_QD {
namespace internal {

// `key_of(entry)`, with `KeyOf key_of`: the entry's key
template <class Entry, class KeyOf>
class Bucket_queue
{
public:
  static constexpr int mantissa_bits = 12;
  static constexpr int octaves = 40;
  static constexpr std::size_t number_of_buckets = std::size_t(octaves) << mantissa_bits;

  explicit Bucket_queue(KeyOf key_of = KeyOf()) : m_key_of(key_of) {}

  // the largest key the queue will hold, said before the first entry comes:
  // keys below 2^-octaves times it share the first bucket
  void set_largest_key(double largest)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &largest, sizeof bits);
    const std::uint64_t top = bits >> (52 - mantissa_bits);
    m_base = top + 1 > number_of_buckets ? top + 1 - number_of_buckets : 0;
  }

  bool empty() const { return m_size == 0; }
  std::size_t size() const { return m_size; }

  // `key_of(e)` must be finite and not negative
  void push(const Entry& e)
  {
    if(m_head.empty()) allocate();
    const std::size_t b = bucket(m_key_of(e));
    std::uint32_t n;
    if(m_free != none) {
      n = m_free;
      m_free = m_nodes[n].next;
      m_nodes[n].entry = e;
    } else {
      n = static_cast<std::uint32_t>(m_nodes.size());
      m_nodes.push_back(Node{e, none});
    }
    std::uint32_t& head = m_head[b];
    if(head == none) {
      m_nodes[n].next = none;
      head = n;
      mark(b);
      if(m_size == 0 || b < m_min) m_min = b;
    } else if(m_key_of(e) < m_key_of(m_nodes[head].entry)) {
      m_nodes[n].next = head;  // the new smallest of its bucket
      head = n;
    } else {
      m_nodes[n].next = m_nodes[head].next;
      m_nodes[head].next = n;
    }
    ++m_size;
  }

  // the entry of the smallest key; not empty
  const Entry& front() const { return m_nodes[m_head[m_min]].entry; }

  // takes `front()` away; not empty
  void pop()
  {
    std::uint32_t& head = m_head[m_min];
    const std::uint32_t taken = head, rest = m_nodes[taken].next;
    m_nodes[taken].next = m_free;
    m_free = taken;
    --m_size;
    if(rest == none) {
      head = none;
      unmark(m_min);
      if(m_size > 0) m_min = first_marked();
      return;
    }
    // the smallest of the rest to the front of the bucket (the first of equals)
    std::uint32_t best = rest, before_best = none;
    for(std::uint32_t prev = rest, n = m_nodes[rest].next; n != none; prev = n, n = m_nodes[n].next)
      if(m_key_of(m_nodes[n].entry) < m_key_of(m_nodes[best].entry)) {
        best = n;
        before_best = prev;
      }
    if(before_best != none) {
      m_nodes[before_best].next = m_nodes[best].next;
      m_nodes[best].next = rest;
    }
    head = best;
  }

  // empties the queue, keeping its storage
  void clear()
  {
    while(m_size > 0) {
      const std::size_t b = m_min;
      std::uint32_t n = m_head[b];
      while(n != none) {
        const std::uint32_t next = m_nodes[n].next;
        --m_size;
        n = next;
      }
      m_head[b] = none;
      unmark(b);
      if(m_size > 0) m_min = first_marked();
    }
    m_nodes.clear();
    m_free = none;
  }

private:
  static constexpr std::uint32_t none = UINT32_MAX;
  struct Node
  {
    Entry entry;
    std::uint32_t next;
  };

  std::size_t bucket(double key) const
  {
    std::uint64_t bits;
    std::memcpy(&bits, &key, sizeof bits);
    bits >>= 52 - mantissa_bits;
    if(bits <= m_base) return 0;
    return static_cast<std::size_t>((std::min)(bits - m_base, std::uint64_t(number_of_buckets - 1)));
  }

  void allocate()
  {
    m_head.assign(number_of_buckets, none);
    m_bits[0].assign(number_of_buckets / 64 + 1, 0);
    m_bits[1].assign(number_of_buckets / 64 / 64 + 1, 0);
    m_bits[2].assign(number_of_buckets / 64 / 64 / 64 + 1, 0);
  }

  void mark(std::size_t b)
  {
    for(int level = 0; level < 3; ++level, b >>= 6) {
      std::uint64_t& word = m_bits[level][b >> 6];
      const bool was_empty = word == 0;
      word |= std::uint64_t(1) << (b & 63);
      if(!was_empty) return;  // the levels above know of it
    }
  }

  void unmark(std::size_t b)
  {
    for(int level = 0; level < 3; ++level, b >>= 6) {
      std::uint64_t& word = m_bits[level][b >> 6];
      word &= ~(std::uint64_t(1) << (b & 63));
      if(word != 0) return;  // the levels above still see it
    }
  }

  static int lowest_bit(std::uint64_t x)
  {
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_ctzll(x);
#else
    int i = 0;
    while(!(x & 1)) {
      x >>= 1;
      ++i;
    }
    return i;
#endif
  }

  // the first bucket with entries; some bucket has
  std::size_t first_marked() const
  {
    std::size_t w = 0;
    while(m_bits[2][w] == 0) ++w;
    std::size_t b = (w << 6) + std::size_t(lowest_bit(m_bits[2][w]));
    b = (b << 6) + std::size_t(lowest_bit(m_bits[1][b]));
    return (b << 6) + std::size_t(lowest_bit(m_bits[0][b]));
  }

  KeyOf m_key_of;
  std::vector<Node> m_nodes;
  std::uint32_t m_free = none;
  std::vector<std::uint32_t> m_head;  // the first entry of every bucket
  std::array<std::vector<std::uint64_t>, 3> m_bits;  // level 0: a bit per bucket; above: per word below
  std::uint64_t m_base = 0;
  std::size_t m_size = 0, m_min = 0;  // m_min: the first bucket with entries, where there are
};

// A binary heap with the same interface, as std::priority_queue keeps it
// (the first entry is the largest by `Entry::operator<`), whose storage is
// kept from one use to the next
template <class Entry>
struct Binary_heap
{
  std::vector<Entry> heap;
  bool empty() const { return heap.empty(); }
  const Entry& front() const { return heap.front(); }
  void push(const Entry& e)
  {
    heap.push_back(e);
    std::push_heap(heap.begin(), heap.end());
  }
  void pop()
  {
    std::pop_heap(heap.begin(), heap.end());
    heap.pop_back();
  }
  void clear() { heap.clear(); }
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_BUCKET_QUEUE_H
