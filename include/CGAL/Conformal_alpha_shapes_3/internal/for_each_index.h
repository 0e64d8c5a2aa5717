// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FOR_EACH_INDEX_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FOR_EACH_INDEX_H

// The loop of the per-vertex stages, serial or on TBB's threads as the
// concurrency tag says (CGAL's convention: `Parallel_tag` needs TBB,
// `Parallel_if_available_tag` uses it when CGAL_LINKED_WITH_TBB).
// Each index is computed by one call that writes only its own results, so
// the results do not depend on the tag or on the number of threads.

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// Calls body(i, workspace) for every i in [0, n); `make_workspace()` makes
// the buffers of one thread (one workspace in a serial run).
template <typename ConcurrencyTag, typename MakeWorkspace, typename Body>
void for_each_index(std::size_t n, MakeWorkspace make_workspace, Body body)
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#else
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    tbb::enumerable_thread_specific<decltype(make_workspace())> workspaces(make_workspace);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t>& range) {
      auto& workspace = workspaces.local();
      for(std::size_t i = range.begin(); i != range.end(); ++i)
        body(i, workspace);
    });
    return;
  }
#endif
  auto workspace = make_workspace();
  for(std::size_t i = 0; i < n; ++i)
    body(i, workspace);
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FOR_EACH_INDEX_H
