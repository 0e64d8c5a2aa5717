// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FRONT_PRIORITY_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FRONT_PRIORITY_H

// What decides the advancing front's order beyond the conformal values:
// when it stops seeding new parts, and how it breaks exact ties. Shared by
// the library's front (conformal_front.h) and CGAL's front, which the tests
// and the benchmark compare it with (cgal_front.h).

#include <CGAL/Conformal_alpha_shapes_3/internal/order_free.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// Each new part of the front starts from the smallest facet whose vertices
// are all off the surface, found by a scan over every facet. Where the front
// finds only small pockets (points it could not attach, a sponge of noise)
// those scans would make it quadratic: seeding stops once the last 16 parts
// held fewer than 8 faces each on average (they are pockets too small to
// carry curvature), or after 64 + n / 1000 parts.
struct Front_seeding
{
  int maximum_parts;
  std::vector<int> faces_before_part;  // by part, the front's faces when it was seeded
  bool stopped = false;

  explicit Front_seeding(std::size_t number_of_vertices) : maximum_parts(64 + int(number_of_vertices / 1000)) {}

  // Called with every seed candidate: false once seeding has stopped.
  template <class AdvancingFront>
  bool may_seed(const AdvancingFront& front)
  {
    const int part = front.number_of_connected_components();
    if(!stopped && part > int(faces_before_part.size()))
    {
      faces_before_part.push_back(front.number_of_facets());
      const std::size_t n = faces_before_part.size();
      stopped = int(n) > maximum_parts
                || (n > 16 && faces_before_part[n - 1] - faces_before_part[n - 17] < 16 * 8);
    }
    return !stopped;
  }
};

// A number in [0, 1) that depends only on the three vertices of a facet:
// the front orders equal priorities by memory address, so that exact ties
// (frequent on regular samples) would make the surface depend on how the
// input was allocated; a relative nudge of 1e-12 by this number breaks them
// the same way on every run.
inline double facet_tie_breaker(std::size_t u, std::size_t v, std::size_t w)
{
  if(u > v) std::swap(u, v);
  if(v > w) std::swap(v, w);
  if(u > v) std::swap(u, v);
  const std::uint64_t h = mix_hash(mix_hash(mix_hash(0, u), v), w);
  return double(h >> 11) / 9007199254740992.0;  // 2^53
}

// A facet's value nudged by its tie breaker: the priority both fronts use.
inline double tie_broken_value(double value, std::size_t u, std::size_t v, std::size_t w)
{
  return value * (1 + 1e-12 * facet_tie_breaker(u, v, w));
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FRONT_PRIORITY_H
