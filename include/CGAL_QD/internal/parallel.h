// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_PARALLEL_H
#define CGAL_QD_INTERNAL_PARALLEL_H

// The loops that the segmentation runs in parallel with CGAL::Parallel_tag.

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cstddef>
#include <thread>
#include <type_traits>

namespace CGAL_QD {
namespace internal {

// Runs `task(i)` for i in [0, n), in parallel when ConcurrencyTag is
// CGAL::Parallel_tag and TBB is linked.
template <class ConcurrencyTag, class Task>
void for_each_index(std::size_t n, const Task& task)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value && n > 1) {
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) { task(i); });
    return;
  }
#endif
  for(std::size_t i = 0; i < n; ++i) task(i);
}

template <class ConcurrencyTag>
std::size_t batch_size()
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value)
    return (std::max)(2u, 2 * std::thread::hardware_concurrency());
#endif
  return 1;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_PARALLEL_H
