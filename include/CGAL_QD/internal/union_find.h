// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_UNION_FIND_H
#define CGAL_QD_INTERNAL_UNION_FIND_H

// Disjoint sets of the integers [0, n). A union keeps the smaller of the two
// roots, so the root of a set is its smallest element whatever the order of
// the unions: ids derived from roots do not depend on it.

#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

class Union_find
{
public:
  explicit Union_find(std::size_t n = 0) { reset(n); }

  // n singletons
  void reset(std::size_t n)
  {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), std::size_t(0));
  }

  std::size_t size() const { return parent_.size(); }

  // the root of x's set, halving the path to it
  std::size_t find(std::size_t x)
  {
    while(parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }

  // the same without changing the structure (for const callers)
  std::size_t root(std::size_t x) const
  {
    while(parent_[x] != x) x = parent_[x];
    return x;
  }

  // joins the sets of x and y; returns the root of the union, the smaller of
  // their two roots
  std::size_t unite(std::size_t x, std::size_t y)
  {
    x = find(x);
    y = find(y);
    if(y < x) std::swap(x, y);
    parent_[y] = x;
    return x;
  }

private:
  std::vector<std::size_t> parent_;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_UNION_FIND_H
