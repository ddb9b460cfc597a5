// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_ORDERING_CACHE_H
#define CGAL_QD_ORDERING_CACHE_H

/// \file ordering_cache.h
/// The fill-reducing orderings that the sparse solvers of `sparse_solvers.h`
/// keep from one factorisation of a pattern to the next (`Ordering_cache`),
/// and the AMD ordering that takes them from there.

#include <Eigen/Sparse>
#include <Eigen/OrderingMethods>

#include <CGAL_QD/internal/digest.h>
#include <CGAL_QD/internal/lru_by_bytes.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// The AMD orderings of the sparsity patterns that the `Simplicial_LDLT_solver`s
/// sharing it have factorised. An ordering depends on the pattern alone, and a
/// segmentation factorises the same pattern many times (a chart flattened in a
/// trial and again at the end, the fits of its seams, the tries of the seam
/// smoothing); a pattern met again takes the permutation found the first time,
/// so its factorisation is the same to the last bit. Patterns are told apart
/// by a 128-bit digest of their structure (size, column starts and row
/// indices). The permutations kept take at most `max_bytes`; the one used least
/// recently goes first. Thread-safe.
class Ordering_cache
{
public:
  typedef Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> Permutation;
  typedef std::pair<std::uint64_t, std::uint64_t> Key;
  static constexpr std::size_t default_max_bytes = std::size_t(16) << 20;

  explicit Ordering_cache(std::size_t max_bytes = default_max_bytes) : m_store(max_bytes, &bytes_of) {}

  /// the key of the pattern of `C`; false if `C` is not in compressed storage
  static bool key_of(const Eigen::SparseMatrix<double>& C, Key& key)
  {
    if(!C.isCompressed()) return false;
    internal::Digest d;
    const std::int64_t size[3] = {C.rows(), C.cols(), C.nonZeros()};
    d.add(size, sizeof(size));
    d.add(C.outerIndexPtr(), sizeof(int) * static_cast<std::size_t>(C.cols() + 1));
    d.add(C.innerIndexPtr(), sizeof(int) * static_cast<std::size_t>(C.nonZeros()));
    key = d.value();
    return true;
  }

  /// the permutation stored for `key`, if any, into `p`
  bool find(const Key& key, Permutation& p)
  {
    Eigen::VectorXi indices;
    if(!m_store.find(key, indices)) return false;
    p.indices() = std::move(indices);
    return true;
  }

  /// stores `p` for `key`, dropping the least recently used beyond `max_bytes`
  void store(const Key& key, const Permutation& p) { m_store.store(key, Eigen::VectorXi(p.indices())); }

  /// orderings found, and not found
  std::size_t hits() const { return m_store.hits(); }
  std::size_t misses() const { return m_store.misses(); }

private:
  static std::size_t bytes_of(const Eigen::VectorXi& indices)
  {
    return sizeof(int) * static_cast<std::size_t>(indices.size());
  }
  internal::Lru_by_bytes<Eigen::VectorXi> m_store;
};

namespace internal {

// the ordering cache of the factorisation running on this thread, if any
inline Ordering_cache*& ordering_cache_of_this_thread()
{
  static thread_local Ordering_cache* cache = nullptr;
  return cache;
}

// sets the ordering cache of this thread for its lifetime
class Ordering_cache_scope
{
public:
  explicit Ordering_cache_scope(Ordering_cache* cache) : m_before(ordering_cache_of_this_thread())
  {
    ordering_cache_of_this_thread() = cache;
  }
  ~Ordering_cache_scope() { ordering_cache_of_this_thread() = m_before; }
  Ordering_cache_scope(const Ordering_cache_scope&) = delete;
  Ordering_cache_scope& operator=(const Ordering_cache_scope&) = delete;

private:
  Ordering_cache* m_before;
};

// the ordering of the pattern of `C` into `p`: from `cache`, if given, where
// it holds that pattern, else `compute(p)`, then stored there
template <class Compute>
void cached_ordering(Ordering_cache* cache, const Eigen::SparseMatrix<double>& C, Ordering_cache::Permutation& p,
                     const Compute& compute)
{
  Ordering_cache::Key key;
  const bool keyed = cache && Ordering_cache::key_of(C, key);
  if(keyed && cache->find(key, p)) return;
  compute(p);
  if(keyed) cache->store(key, p);
}

// Eigen's AMD ordering, taken from the ordering cache of this thread where
// it holds the pattern (Eigen calls it with the full symmetric matrix)
template <class StorageIndex>
struct Cached_AMD_ordering
{
  typedef Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, StorageIndex> PermutationType;
  static_assert(std::is_same<StorageIndex, int>::value, "the ordering cache holds int permutations");

  template <class MatrixType>
  void operator()(const MatrixType& C, PermutationType& p)
  {
    cached_ordering(ordering_cache_of_this_thread(), C, p, [&](PermutationType& q) { amd_ordering_of_symmetric(C, q); });
  }

private:
  // Eigen's AMD ordering of C, a symmetric pattern (both triangles, as
  // SimplicialLDLT gives it). `Eigen::AMDOrdering` first forms the pattern of
  // C^T + C, which for such a C whose columns are sorted is C's own, entry for
  // entry; the AMD routine then gets a copy of C's pattern instead: the same
  // input, so the same permutation, without the transpose and the sum (about
  // a sixth of the ordering's time). Columns not sorted go through
  // `Eigen::AMDOrdering`.
  template <class MatrixType>
  static void amd_ordering_of_symmetric(const MatrixType& C, PermutationType& p)
  {
    typedef Eigen::SparseMatrix<typename MatrixType::Scalar, Eigen::ColMajor, StorageIndex> Pattern;
    const Eigen::Index n = C.cols();
    bool sorted = C.isCompressed() && C.rows() == n;
    const StorageIndex* outer = C.outerIndexPtr();
    const StorageIndex* inner = C.innerIndexPtr();
    for(Eigen::Index j = 0; sorted && j < n; ++j)
      for(StorageIndex k = outer[j] + 1; k < outer[j + 1]; ++k)
        if(!(inner[k - 1] < inner[k])) {
          sorted = false;
          break;
        }
    if(!sorted) {
      Eigen::AMDOrdering<StorageIndex>()(C, p);
      return;
    }
    const StorageIndex nnz = outer[n];
    Pattern symm(n, n);
    // room for the AMD routine's elbow room, as it asks for it, and the pattern
    symm.data().reserve(static_cast<Eigen::Index>(nnz + nnz / 5 + 2 * n));
    symm.resizeNonZeros(static_cast<Eigen::Index>(nnz));
    std::copy(outer, outer + n + 1, symm.outerIndexPtr());
    std::copy(inner, inner + nnz, symm.innerIndexPtr());
    std::fill(symm.valuePtr(), symm.valuePtr() + nnz, typename MatrixType::Scalar(0));
    Eigen::internal::minimum_degree_ordering(symm, p);
  }
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_ORDERING_CACHE_H
