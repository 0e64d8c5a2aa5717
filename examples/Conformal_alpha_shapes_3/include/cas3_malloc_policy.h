// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The program's use of the C allocator (the manual, "Performance"):
// transparent huge pages, one arena, and freed memory given back once the
// front is freed.

#ifndef CAS3_MALLOC_POLICY_H
#define CAS3_MALLOC_POLICY_H

#include <cstdlib>
#include <fstream>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#if defined(__linux__) && defined(__GLIBC__)
#include <climits>
#include <sys/auxv.h>
#include <unistd.h>
#endif

namespace cas3 {

// The GLIBC_TUNABLES under which glibc's malloc asks the kernel for
// transparent huge pages: `current` (null when unset) with
// glibc.malloc.hugetlb=1 added, or an empty string when there is nothing
// to add: `current` names that tunable already (the user's choice; =0
// turns it off), or the kernel does not give huge pages on request.
// `kernel_mode` is the line of /sys/kernel/mm/transparent_hugepage/enabled:
// only "[madvise]" needs the request ("[always]" gives them anyway,
// "[never]" never).
inline std::string tunables_with_huge_pages(const char* current, const std::string& kernel_mode)
{
  const std::string tunable = "glibc.malloc.hugetlb";
  if(kernel_mode.find("[madvise]") == std::string::npos)
    return std::string();
  if(current == nullptr || *current == '\0')
    return tunable + "=1";
  if(std::string(current).find(tunable) != std::string::npos)
    return std::string();
  return std::string(current) + ":" + tunable + "=1";
}

// Starts the program again, with glibc's malloc asking for transparent huge
// pages where the kernel gives them only on request: the stages walk the
// triangulation and large arrays out of memory order, and fault fresh
// memory in 4 KiB at a time otherwise (the manual, "The allocator"). A
// tunable is read when a process starts, so the program executes itself
// anew (execv: the same process, with its id and arguments) with
// GLIBC_TUNABLES extended by `tunables_with_huge_pages()`; where that adds
// nothing, or the executable cannot be found, it goes on as it is. Not
// under valgrind (the new image would run outside it) nor in a
// secure-execution process. Call it first in main().
inline void use_transparent_huge_pages(char** argv)
{
#if defined(__linux__) && defined(__GLIBC__)
  if(std::getenv("VALGRIND_LAUNCHER") != nullptr || getauxval(AT_SECURE) != 0)
    return;
  std::string kernel_mode;
  {
    // closed before the exec, which would pass its descriptor on
    std::ifstream kernel("/sys/kernel/mm/transparent_hugepage/enabled");
    std::getline(kernel, kernel_mode);
  }
  const char* current = std::getenv("GLIBC_TUNABLES");
  const std::string tunables = tunables_with_huge_pages(current, kernel_mode);
  if(tunables.empty())
    return;
  char self[PATH_MAX];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  if(length <= 0)
    return;
  self[length] = '\0';
  const bool was_set = current != nullptr;
  const std::string before = was_set ? current : "";
  if(setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0)
    return;
  execv(self, argv);
  // not started again: on as before
  if(was_set)
    setenv("GLIBC_TUNABLES", before.c_str(), 1);
  else
    unsetenv("GLIBC_TUNABLES");
#else
  (void)argv;
#endif
}

// One malloc arena for all threads, unless MALLOC_ARENA_MAX says otherwise.
// glibc gives each thread that allocates an arena of its own: what TBB's
// threads free in theirs is not reused by the serial stages after them
// (the advancing front above all), which fault in fresh pages instead, and
// page faults are slow on virtual machines. Call it before any other
// thread starts.
inline void use_one_malloc_arena()
{
#if defined(__GLIBC__)
  if(std::getenv("MALLOC_ARENA_MAX") == nullptr)
    mallopt(M_ARENA_MAX, 1);
#endif
}

// Gives the pages of freed memory back to the system (malloc_trim). The
// advancing front's copy of the triangulation is freed in the middle of
// the heap, which glibc would keep resident. Call it after the surface is
// extracted, before the curvature.
inline void return_freed_memory()
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

} // namespace cas3

#endif // CAS3_MALLOC_POLICY_H
