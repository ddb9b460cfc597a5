// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_PARALLEL_H
#define CGAL_QD_INTERNAL_PARALLEL_H

// The loops that the segmentation runs in parallel with CGAL::Parallel_tag.

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <type_traits>
#include <vector>

namespace CGAL_QD {
namespace internal {

// how many threads the loops of `ConcurrencyTag` run on: those of TBB's
// arena with CGAL::Parallel_tag where TBB is linked, else 1
template <class ConcurrencyTag>
std::size_t number_of_workers()
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value)
    return static_cast<std::size_t>((std::max)(1, tbb::this_task_arena::max_concurrency()));
#endif
  return 1;
}

// Runs `task(i)` for i in [0, n), in parallel when ConcurrencyTag is
// CGAL::Parallel_tag and TBB is linked: the indices are handed out in
// increasing order, each to the first thread that is free, so that tasks
// given from the dearest to the cheapest end together (the tasks of the
// segmentation, flattenings of charts of very different sizes, are few).
template <class ConcurrencyTag, class Task>
void for_each_index(std::size_t n, const Task& task)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value && n > 1) {
    std::atomic<std::size_t> next{0};
    const std::size_t threads = (std::min)(n, number_of_workers<ConcurrencyTag>());
    tbb::parallel_for(
        std::size_t(0), threads,
        [&](std::size_t) {
          for(std::size_t i = next++; i < n; i = next++) task(i);
        },
        tbb::simple_partitioner());
    return;
  }
#endif
  for(std::size_t i = 0; i < n; ++i) task(i);
}

// the indices of `cost` from the largest cost to the smallest (ties by index)
template <class Cost>
std::vector<std::size_t> dearest_first(const std::vector<Cost>& cost)
{
  std::vector<std::size_t> order(cost.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  return order;
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
