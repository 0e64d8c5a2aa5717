// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ORDER_FREE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ORDER_FREE_H

// Orders and samples of the points that depend on their coordinates alone
// (the manual, "Input Rules": any order of the same points gives the same
// results): where the work would otherwise follow the input's order (which
// points the noise estimate samples, in which order the triangulation is
// built and so numbers its vertices and cells), it follows these.

#include <CGAL/number_utils.h>

#include <algorithm>
#include <CGAL/Hilbert_sort_3.h>
#include <CGAL/Multiscale_sort.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// `h` with `x` mixed in by the SplitMix64 finalizer: every bit of the
// result depends on every bit of both.
inline std::uint64_t mix_hash(std::uint64_t h, std::uint64_t x)
{
  h = (h ^ x) + 0x9E3779B97F4A7C15ull;
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

// A 64-bit number that depends only on the coordinates of `p` (the same
// for +0 and -0), spread evenly over its range.
template <class Point>
std::uint64_t coordinate_hash(const Point& p)
{
  std::uint64_t h = 0;
  for(int d = 0; d < 3; ++d)
  {
    const double x = CGAL::to_double(p[d]) + 0.0;
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    h = mix_hash(h, bits);
  }
  return h;
}

// The order of a point by its coordinates alone: its hash, then its
// coordinates (only equal points compare equal).
template <class Point>
std::tuple<std::uint64_t, double, double, double> order_free_key(const Point& p)
{
  return std::make_tuple(coordinate_hash(p), CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                         CGAL::to_double(p.z()));
}

// The indices of `count` of `points` chosen by their coordinates alone
// (the smallest keys), in the order of their keys: a sample spread evenly
// over the points, the same points in the same order for any order of the
// input.
template <class Point>
std::vector<std::size_t> order_free_sample(const std::vector<Point>& points, std::size_t count)
{
  // the index in the key only separates equal points, which are interchangeable
  typedef std::pair<std::tuple<std::uint64_t, double, double, double>, std::size_t> Key;
  std::priority_queue<Key> kept;  // the largest kept key on top
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const Key k(order_free_key(points[i]), i);
    if(kept.size() < count)
      kept.push(k);
    else if(k < kept.top())
    {
      kept.pop();
      kept.push(k);
    }
  }
  std::vector<std::size_t> sample(kept.size());
  for(std::size_t k = sample.size(); k-- > 0; kept.pop())
    sample[k] = kept.top().second;
  return sample;
}

// The indices of `points` in the order of `hash` (of each point), ties by
// the points' coordinates: the same sequence of points for any order of
// the input. The hashes' leading bits place each point in one of about
// `points.size() / 2` buckets, so that only the few points in a bucket are
// compared, in linear time for hashes spread evenly over their range.
template <class Point>
std::vector<std::size_t> permutation_by_hash(const std::vector<std::uint64_t>& hash, const std::vector<Point>& points)
{
  const std::size_t n = points.size();
  int bits = 0;
  while(bits < 32 && (std::size_t(2) << bits) < n)
    ++bits;
  const int shift = 64 - bits;  // bits = 0: one bucket
  auto bucket = [shift](std::uint64_t h) { return shift == 64 ? std::size_t(0) : std::size_t(h >> shift); };
  std::vector<std::size_t> end(std::size_t(1) << bits, 0);  // by bucket, after the counting sort
  for(std::size_t i = 0; i < n; ++i)
    ++end[bucket(hash[i])];
  for(std::size_t b = 1; b < end.size(); ++b)
    end[b] += end[b - 1];
  std::vector<std::size_t> order(n);
  for(std::size_t i = n; i-- > 0;)
    order[--end[bucket(hash[i])]] = i;  // `end` becomes each bucket's beginning
  auto less = [&](std::size_t i, std::size_t j) {
    if(hash[i] != hash[j])
      return hash[i] < hash[j];
    return order_free_key(points[i]) < order_free_key(points[j]);
  };
  for(std::size_t b = 0; b < end.size(); ++b)
  {
    const std::size_t last = b + 1 < end.size() ? end[b + 1] : n;
    if(last - end[b] > 1)
      std::sort(order.begin() + std::ptrdiff_t(end[b]), order.begin() + std::ptrdiff_t(last), less);
  }
  return order;
}

// The coordinate hash of each of `points`.
template <class Point>
std::vector<std::uint64_t> coordinate_hashes(const std::vector<Point>& points)
{
  std::vector<std::uint64_t> hash(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    hash[i] = coordinate_hash(points[i]);
  return hash;
}

// A pseudo-random order of `points` by their keys: the indices of the
// points in that order, the same sequence of points for any order of the
// input.
template <class Point>
std::vector<std::size_t> order_free_permutation(const std::vector<Point>& points)
{
  return permutation_by_hash(coordinate_hashes(points), points);
}

// The points with their indices in the order in which they are inserted
// into a triangulation: `spatial_sort()` in its 3D settings (Hilbert leaves
// of 8 points, rounds of an eighth) with its random shuffle replaced by
// `order_free_permutation()`, so that the insertion order, and with it the
// numbering of the vertices and cells, is the same for any order of the
// input. The points are sorted with their indices beside them (sorting
// indices that point into the array makes every comparison a random read).
template <class Gt, class Point>
std::vector<std::pair<Point, std::size_t> > order_free_insertion_order(const std::vector<Point>& points)
{
  typedef std::pair<Point, std::size_t> Point_and_index;
  std::vector<Point_and_index> order;
  order.reserve(points.size());
  for(std::size_t i : order_free_permutation(points))
    order.emplace_back(points[i], i);
  typedef Spatial_sort_traits_adapter_3<Gt, First_of_pair_property_map<Point_and_index> > Sort_traits;
  // on TBB's threads the same order: the parallel sort splits the ranges as the serial one
  typedef Hilbert_sort_3<Sort_traits, Hilbert_sort_median_policy, Parallel_if_available_tag> Hilbert_sort;
  Multiscale_sort<Hilbert_sort>(Hilbert_sort(Sort_traits(), 8), 64, 0.125)(order.begin(), order.end());
  return order;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ORDER_FREE_H
