// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The program's use of the C allocator (the manual, "Performance"): one
// arena, and freed memory given back once the front is freed.

#ifndef CAS3_MALLOC_ARENA_H
#define CAS3_MALLOC_ARENA_H

#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cas3 {

// One malloc arena for all threads, unless MALLOC_ARENA_MAX says otherwise.
// glibc gives each thread that allocates an arena of its own: what TBB's
// threads free in theirs is not reused by the serial stages after them
// (the advancing front above all), which fault in fresh pages instead, and
// page faults are slow on virtual machines. Measured on 1,000,000 noisy
// points on a 2-core KVM guest: the whole job 83.7 s -> 66.9 s, the front
// 27.3 -> 17.8 s, the parallel curvature stage 32.7 -> 29.8 s. Call it
// before any other thread starts.
inline void use_one_malloc_arena()
{
#if defined(__GLIBC__)
  if(std::getenv("MALLOC_ARENA_MAX") == nullptr)
    mallopt(M_ARENA_MAX, 1);
#endif
}

// Gives the pages of freed memory back to the system (malloc_trim). The
// advancing front's copy of the triangulation is freed in the middle of
// the heap, which glibc keeps resident. On 1,000,000 noisy points the
// process held 2,172 MiB after the surface's extraction without it, 894 MiB
// with it; the curvature stage's peak moved less (2,239 -> 2,210 MiB, two
// runs), as it reuses most of what was kept. Call it after the surface is
// extracted, before the curvature.
inline void return_freed_memory()
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

} // namespace cas3

#endif // CAS3_MALLOC_ARENA_H
