// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FOR_EACH_INDEX_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FOR_EACH_INDEX_H

// The loops of the per-vertex and per-cell passes, serial or on TBB's threads
// as the concurrency tag says (CGAL's convention: `Parallel_tag` needs TBB,
// `Parallel_if_available_tag` uses it when CGAL_LINKED_WITH_TBB).
// Either way the results do not depend on the tag or on the number of
// threads.

#include <CGAL/Conformal_alpha_shapes_3/interruption.h>
#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// Calls body(i, workspace) for every i in [0, n), which writes only the
// results of index i; `make_workspace()` makes the buffers of one thread
// (one workspace in a serial run). Throws `Interrupted` when the calling
// thread's interruption check asks it to stop (interruption.h).
template <typename ConcurrencyTag, typename MakeWorkspace, typename Body>
void for_each_index(std::size_t n, MakeWorkspace make_workspace, Body body)
{
  Interruption_point interruption;
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#else
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    tbb::enumerable_thread_specific<decltype(make_workspace())> workspaces(make_workspace);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t>& range) {
      if(interruption.stop_requested())
        return;
      auto& workspace = workspaces.local();
      for(std::size_t i = range.begin(); i != range.end(); ++i)
        body(i, workspace);
    });
    interruption.throw_if_stop_was_requested();
    return;
  }
#endif
  auto workspace = make_workspace();
  for(std::size_t i = 0; i < n; ++i)
  {
    if(i % 256 == 0)
      interruption.throw_if_stopped();
    body(i, workspace);
  }
}

// Calls body(begin, end, partial) on contiguous chunks of [0, n), one per
// thread (a single chunk in a serial run), each with its own partial result
// from `make_partial()`, and returns the partial results in the order of the
// chunks. For the passes that gather a value from many indices (a vertex's
// value from all its cells): the caller merges the partial results, in a
// way that does not depend on how [0, n) was cut.
template <typename ConcurrencyTag, typename MakePartial, typename Body>
std::vector<decltype(std::declval<MakePartial&>()())> partial_results_in_chunks(std::size_t n,
                                                                               MakePartial make_partial, Body body)
{
  std::size_t chunks = 1;
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
    chunks = (std::max)(std::size_t(1), (std::min)(std::size_t(tbb::this_task_arena::max_concurrency()), n / 4096));
#endif
  std::vector<decltype(make_partial())> partial;
  partial.reserve(chunks);
  for(std::size_t k = 0; k < chunks; ++k)
    partial.push_back(make_partial());
  auto run = [&](std::size_t k) { body(k * n / chunks, (k + 1) * n / chunks, partial[k]); };
#ifdef CGAL_LINKED_WITH_TBB
  if(chunks > 1)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const tbb::blocked_range<std::size_t>& range) {
      for(std::size_t k = range.begin(); k != range.end(); ++k)
        run(k);
    });
    return partial;
  }
#endif
  for(std::size_t k = 0; k < chunks; ++k)
    run(k);
  return partial;
}

// Sorts [first, last) by `less`, on TBB's threads as the concurrency tag
// says. `less` must order every two elements (no two equivalent), so that
// the order is the same whichever sort makes it.
template <typename ConcurrencyTag, typename RandomAccessIterator, typename Less>
void sort_distinct(RandomAccessIterator first, RandomAccessIterator last, Less less)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    tbb::parallel_sort(first, last, less);
    return;
  }
#endif
  std::sort(first, last, less);
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FOR_EACH_INDEX_H
