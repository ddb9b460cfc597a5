// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_AMD_ORDER_OF_TRIANGLES_H
#define CGAL_QD_INTERNAL_AMD_ORDER_OF_TRIANGLES_H

// One fill-reducing order of the vertices of a triangle mesh for every
// system on a part of them.

#include <CGAL_QD/sparse_solvers.h>

#include <Eigen/OrderingMethods>
#include <Eigen/Sparse>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {

// The AMD order of the `n` vertices of the triangles `corner` (3 vertex
// indices a triangle): `order[k]` is the vertex eliminated k-th in the
// factorisation of a matrix with a diagonal and an entry for every edge
// (from `cache`, if given, where it holds the pattern, and stored there). A
// system on a subset of the vertices, numbered in this order, has no more
// fill than this ordering of the whole graph gives it: a path of fill
// between two of its vertices is one in the whole graph.
inline std::vector<int> amd_order_of_triangles(std::size_t n, const std::vector<std::size_t>& corner,
                                               Ordering_cache* cache)
{
  Eigen::SparseMatrix<double> C(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  {
    // both triangles of the pattern: in every column the diagonal, then the
    // other ends of the edges in the order the triangles give them, each once
    // (every corner gives the two edges of its triangle that end there)
    std::vector<int> start(n + 1, 0);
    for(std::size_t c = 0; c < corner.size(); ++c) start[corner[c] + 1] += 2;
    for(std::size_t i = 0; i < n; ++i) start[i + 1] += start[i] + 1;
    std::vector<int> bucket(static_cast<std::size_t>(start[n])), fill(n, 1);
    for(std::size_t i = 0; i < n; ++i) bucket[static_cast<std::size_t>(start[i])] = static_cast<int>(i);
    for(std::size_t t = 0; t + 2 < corner.size(); t += 3)
      for(int k = 0; k < 3; ++k) {
        const std::size_t a = corner[t + k], b = corner[t + (k + 1) % 3];
        bucket[static_cast<std::size_t>(start[b] + fill[b]++)] = static_cast<int>(a);
        bucket[static_cast<std::size_t>(start[a] + fill[a]++)] = static_cast<int>(b);
      }
    // room for the AMD routine's elbow room, as it asks for it
    C.data().reserve(static_cast<Eigen::Index>(bucket.size() + bucket.size() / 5 + 2 * n));
    C.resizeNonZeros(static_cast<Eigen::Index>(bucket.size()));
    int* outer = C.outerIndexPtr();
    int* inner = C.innerIndexPtr();
    std::vector<std::size_t> seen(n, n);  // the last column that holds a row
    int nnz = 0;
    outer[0] = 0;
    for(std::size_t j = 0; j < n; ++j) {
      for(int e = start[j]; e < start[j] + fill[j]; ++e) {
        const std::size_t i = static_cast<std::size_t>(bucket[static_cast<std::size_t>(e)]);
        if(seen[i] == j) continue;
        seen[i] = j;
        inner[nnz++] = static_cast<int>(i);
      }
      outer[j + 1] = nnz;
    }
    C.resizeNonZeros(nnz);
    std::fill(C.valuePtr(), C.valuePtr() + nnz, 0.);
  }  // the buckets freed before the ordering
  Ordering_cache::Permutation p;
  cached_ordering(cache, C, p, [&](Ordering_cache::Permutation& q) { Eigen::internal::minimum_degree_ordering(C, q); });
  std::vector<int> order(n);
  for(std::size_t k = 0; k < n; ++k) order[k] = p.size() > 0 ? p.indices()[static_cast<Eigen::Index>(k)] : int(k);
  return order;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_AMD_ORDER_OF_TRIANGLES_H
