// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_INPUT_HYGIENE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_INPUT_HYGIENE_H

// Input hygiene: what the pipeline does to the input points before it builds
// the conformal alpha shape (the manual, section "Input rules"):
//
// 1. Every coordinate must be finite; otherwise std::invalid_argument names
//    the first offending index.
// 2. Points written more than once (equal coordinates) are merged into
//    their first copy: what follows sees each point once, and the copies
//    get the values of their first (an outlier's copies are outliers).
// 3. Isolated far outliers are removed and flagged. With d_k(p) the distance
//    from p to its k-th nearest other point (k = 6), a point is an isolated
//    outlier when
//      d_k(p) > 30 * m, m the median of the positive d_k over all points, and
//      d_k(p) > 30 * the median of d_k over p's k nearest neighbors.
//    The second condition keeps the points of a real cluster that is just
//    sparser than the rest (their neighbors are as sparse as they are); a
//    group of at most k points far from everything else is removed (no
//    group that small can make a surface patch of its own). Points whose
//    distance to the robust center exceeds 1e50 robust sizes are outliers
//    without further test (no double construction could hold both them and
//    the rest). With fewer than 2 (k + 1) points no point is tested.
// 4. The kept points are recentered on a robust center c, the per-axis
//    median of the kept points, and divided by a robust size s, a power of
//    two within a factor 2 of the median over the kept points of the
//    largest coordinate difference to c (the largest distance to c when
//    that median is 0; 1 when all kept points coincide). Multiplying by a
//    power of two is exact, so the normalized points are (p - c) / s
//    rounded once, whatever the magnitude: georeferenced offsets (1e6-1e7),
//    1e300 and 1e-300 scales all give points of size about 1.
//
// Back to input units: positions p = c + s q, lengths times s, mean and
// principal curvatures divided by s, Gaussian curvature divided by s^2;
// normals and directions are unchanged. (At extreme scales the Gaussian
// curvature may fall out of double's range: 1e300 gives K about 1e-600,
// which rounds to 0.)

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/order_free.h>

#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The range of coordinates in which the circumcenters of the shape can be
// computed in double: magnitudes and bounding-box extents up to 1e75,
// extents (along the longest axis) down to 1e-75.
constexpr double max_coordinate_magnitude = 1e75;
constexpr double min_coordinate_extent = 1e-75;

// Throws std::invalid_argument, its message starting with `who`, at the
// first point with a NaN or infinite coordinate, naming its index; with
// `in_double_range`, also at the first coordinate beyond
// `max_coordinate_magnitude`, then when the bounding box is out of range.
template <class Point>
void check_coordinates(const std::vector<Point>& points, const std::string& who, bool in_double_range)
{
  double low[3] = {0, 0, 0}, high[3] = {0, 0, 0};
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int d = 0; d < 3; ++d)
    {
      const double x = CGAL::to_double(points[i][d]);
      if(!std::isfinite(x))
        throw std::invalid_argument(who + "input point " + std::to_string(i)
                                    + " has a coordinate that is NaN or infinite");
      if(in_double_range && std::abs(x) > max_coordinate_magnitude)
        throw std::invalid_argument(who + "input point " + std::to_string(i)
                                    + " has a coordinate of magnitude above 1e75, out of the range in which "
                                      "circumcenters can be computed in double; normalize the coordinates or "
                                      "remove the outlier");
      low[d] = (i == 0) ? x : (std::min)(low[d], x);
      high[d] = (i == 0) ? x : (std::max)(high[d], x);
    }
  const double extent = (std::max)({high[0] - low[0], high[1] - low[1], high[2] - low[2]});
  if(!in_double_range)
    return;
  if(!points.empty() && extent > max_coordinate_magnitude)
    throw std::invalid_argument(who + "the bounding box of the input is longer than 1e75, out of the range in "
                                      "which circumcenters can be computed in double");
  if(extent > 0 && extent < min_coordinate_extent)
    throw std::invalid_argument(who + "the bounding box of the input is shorter than 1e-75, out of the range in "
                                      "which circumcenters can be computed in double; rescale the coordinates");
}

// The parameters of the outlier rule (see above).
struct Input_hygiene_options
{
  unsigned int k = 6;             // which neighbor measures isolation
  double isolation_factor = 30;   // how many median distances make a point isolated
  bool remove_outliers = true;
};

// The points to build on and what maps them back to the input.
template <class Kernel>
struct Normalized_input
{
  typedef typename Kernel::Point_3 Point;
  typedef typename Kernel::Vector_3 Vector;

  std::vector<Point> points;              // the kept points, normalized
  std::vector<std::size_t> input_index;   // kept point -> input index (of the first copy)
  std::vector<std::pair<std::size_t, std::size_t> > copies;  // later copies of kept points: (input index, first's)
  std::size_t number_of_copies = 0;       // input points equal to an earlier one, outliers' copies too
  std::vector<std::size_t> outliers;      // input indices of the removed points (and their copies), increasing
  std::vector<bool> is_outlier;           // by input index
  std::array<double, 3> center = {{0, 0, 0}};  // c, in input units
  int size_exponent = 0;                  // s = 2^size_exponent

  double size() const { return std::ldexp(1.0, size_exponent); }

  // input units <-> normalized units
  Point to_input(const Point& q) const
  {
    return Point(center[0] + std::ldexp(q.x(), size_exponent), center[1] + std::ldexp(q.y(), size_exponent),
                 center[2] + std::ldexp(q.z(), size_exponent));
  }
  Point to_normalized(const Point& p) const
  {
    return Point(difference(p.x(), center[0]), difference(p.y(), center[1]), difference(p.z(), center[2]));
  }
  double length_to_input(double l) const { return std::ldexp(l, size_exponent); }
  double length_from_input(double l) const { return std::ldexp(l, -size_exponent); }
  // mean and principal curvatures
  double curvature_to_input(double k) const { return std::ldexp(k, -size_exponent); }
  double gaussian_curvature_to_input(double k) const { return std::ldexp(k, -2 * size_exponent); }

  // (x - c) / s without overflow: the halves never overflow, and halving
  // and scaling by 2^(1 - e) are exact above the subnormal range.
  double difference(double x, double c) const
  { return std::ldexp(x / 2 - c / 2, 1 - size_exponent); }
};

namespace hygiene_detail {

inline double median(std::vector<double> v)
{
  if(v.empty())
    return 0;
  const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// per-axis median of the points whose indices are in `which`
template <class Point>
std::array<double, 3> median_center(const std::vector<Point>& p, const std::vector<std::size_t>& which)
{
  std::array<double, 3> c = {{0, 0, 0}};
  std::vector<double> v(which.size());
  for(int d = 0; d < 3; ++d)
  {
    for(std::size_t i = 0; i < which.size(); ++i)
      v[i] = CGAL::to_double(p[which[i]][d]);
    c[d] = median(v);
  }
  return c;
}

// the exponent e of the robust size 2^e (see the header comment)
template <class Point>
int size_exponent(const std::vector<Point>& p, const std::vector<std::size_t>& which,
                  const std::array<double, 3>& c)
{
  // halved coordinate differences: no overflow
  std::vector<double> half_radius(which.size());
  for(std::size_t i = 0; i < which.size(); ++i)
  {
    double r = 0;
    for(int d = 0; d < 3; ++d)
      r = (std::max)(r, std::abs(CGAL::to_double(p[which[i]][d]) / 2 - c[d] / 2));
    half_radius[i] = r;
  }
  double h = median(half_radius);
  if(!(h > 0))
    h = half_radius.empty() ? 0 : *std::max_element(half_radius.begin(), half_radius.end());
  if(!(h > 0))
    return 0;
  return std::ilogb(h) + 2;  // 2^e within [2h, 4h): the median radius maps into [0.5, 1)
}

} // namespace hygiene_detail

// By input index, the index of the first input point with the same
// coordinates (the point itself for a first copy).
template <class Point>
std::vector<std::size_t> first_copies(const std::vector<Point>& p)
{
  std::vector<std::size_t> order(p.size()), first(p.size());
  for(std::size_t i = 0; i < p.size(); ++i)
    order[i] = i;
  auto key = [&](std::size_t i) {
    return std::make_tuple(CGAL::to_double(p[i].x()) + 0.0, CGAL::to_double(p[i].y()) + 0.0,
                           CGAL::to_double(p[i].z()) + 0.0, i);
  };
  sort_distinct<CGAL::Parallel_if_available_tag>(order.begin(), order.end(),
                                                 [&](std::size_t i, std::size_t j) { return key(i) < key(j); });
  for(std::size_t k = 0; k < order.size(); ++k)
    first[order[k]] = k > 0 && p[order[k]] == p[order[k - 1]] ? first[order[k - 1]] : order[k];
  return first;
}

// Normalizes `input` and removes isolated far outliers (rules above).
// Throws std::invalid_argument naming the first point with a NaN or
// infinite coordinate.
template <class Kernel, class PointRange>
Normalized_input<Kernel> normalize_input(const PointRange& input,
                                         const Input_hygiene_options& options = Input_hygiene_options())
{
  typedef typename Kernel::Point_3 Point;
  using hygiene_detail::median;
  Normalized_input<Kernel> result;
  std::vector<Point> p(input.begin(), input.end());
  check_coordinates(p, "", false);
  result.is_outlier.assign(p.size(), false);
  // the copies of a point are merged into its first: the rest sees each point once
  const std::vector<std::size_t> first = first_copies(p);
  std::vector<std::size_t> distinct;  // distinct point -> input index
  for(std::size_t i = 0; i < p.size(); ++i)
    if(first[i] == i)
      distinct.push_back(i);
  for(std::size_t j = 0; j < distinct.size(); ++j)
    p[j] = p[distinct[j]];
  p.resize(distinct.size());
  const std::size_t n = p.size();

  std::vector<std::size_t> all(n);
  for(std::size_t i = 0; i < n; ++i)
    all[i] = i;
  std::vector<bool> is_outlier(n, false);  // by distinct point

  const unsigned int k = (std::max)(options.k, 1u);
  if(options.remove_outliers && n >= 2 * (std::size_t(k) + 1))
  {
    // a first normalization on all points, for the distances
    result.center = hygiene_detail::median_center(p, all);
    result.size_exponent = hygiene_detail::size_exponent(p, all, result.center);
    // the points tested by distances, with their indices, in the spatial
    // order of the points: the tree's leaves and the searches then read
    // memory in order (in the order of the input, which may be any, the
    // time per point tripled from 100,000 to 3,000,000 points)
    typedef std::pair<Point, std::size_t> Point_and_index;
    std::vector<Point_and_index> tested;
    for(std::size_t i = 0; i < n; ++i)
    {
      const Point x = result.to_normalized(p[i]);
      const double r = (std::max)({std::abs(x.x()), std::abs(x.y()), std::abs(x.z())});
      if(r > 1e50)
        is_outlier[i] = true;
      else
        tested.emplace_back(x, i);
    }
    CGAL::spatial_sort<CGAL::Parallel_if_available_tag>(tested.begin(), tested.end(),
                       CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::First_of_pair_property_map<Point_and_index> >());
    std::vector<Point> q;
    std::vector<std::size_t> near;  // input index of q[i]
    q.reserve(tested.size());
    near.reserve(tested.size());
    for(const Point_and_index& t : tested)
    {
      q.push_back(t.first);
      near.push_back(t.second);
    }
    std::vector<Point_and_index>().swap(tested);

    // distance to the k-th nearest other point, and the k neighbors
    typedef CGAL::Search_traits_3<Kernel> Base_traits;
    typedef typename CGAL::Pointer_property_map<Point>::const_type Point_map;
    typedef CGAL::Search_traits_adapter<std::size_t, Point_map, Base_traits> Traits;
    typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
    typedef typename Search::Tree Tree;
    typedef typename Search::Distance Distance;
    std::vector<double> dk(q.size(), 0);
    std::vector<std::size_t> neighbors(q.size() * k);
    if(q.size() > k)
    {
      const std::vector<Point>& const_q = q;
      const Point_map point_map = CGAL::make_property_map(const_q);
      std::vector<std::size_t> ids(q.size());
      for(std::size_t i = 0; i < q.size(); ++i)
        ids[i] = i;
      Tree tree(ids.begin(), ids.end(), typename Tree::Splitter(), Traits(point_map));
      tree.template build<CGAL::Parallel_if_available_tag>();
      const Distance distance(point_map);
      // the searches only read the tree: one per point, on any thread
      for_each_index<CGAL::Parallel_if_available_tag>(q.size(), []() { return 0; }, [&](std::size_t i, int) {
        Search search(tree, q[i], k + 1, 0, true, distance);
        std::size_t found = 0;
        bool self_skipped = false;
        for(const auto& hit : search)
        {
          if(!self_skipped && hit.first == i)
          {
            self_skipped = true;
            continue;
          }
          if(found < k)
          {
            neighbors[i * k + found++] = hit.first;
            dk[i] = std::sqrt(hit.second);
          }
        }
        for(; found < k; ++found)  // fewer than k others
          neighbors[i * k + found] = i;
      });
      std::vector<double> positive;
      for(double d : dk)
        if(d > 0)
          positive.push_back(d);
      if(positive.size() * 2 >= dk.size())
      {
        const double m = median(positive);
        std::vector<double> around(k);
        for(std::size_t i = 0; i < q.size(); ++i)
        {
          if(!(dk[i] > options.isolation_factor * m))
            continue;
          for(unsigned int j = 0; j < k; ++j)
            around[j] = dk[neighbors[i * k + j]];
          if(dk[i] > options.isolation_factor * median(around))
            is_outlier[near[i]] = true;
        }
      }
    }
  }

  std::vector<std::size_t> kept;  // distinct points
  for(std::size_t j = 0; j < n; ++j)
    if(is_outlier[j])
      result.is_outlier[distinct[j]] = true;
    else
      kept.push_back(j);
  for(std::size_t i = 0; i < first.size(); ++i)
  {
    result.is_outlier[i] = result.is_outlier[first[i]];
    if(result.is_outlier[i])
      result.outliers.push_back(i);
    else if(first[i] != i)
      result.copies.emplace_back(i, first[i]);
  }
  result.number_of_copies = first.size() - n;

  // the final normalization, on the kept points only
  result.center = hygiene_detail::median_center(p, kept);
  result.size_exponent = hygiene_detail::size_exponent(p, kept, result.center);
  result.points.reserve(kept.size());
  result.input_index.reserve(kept.size());
  for(std::size_t j : kept)
  {
    result.points.push_back(result.to_normalized(p[j]));
    result.input_index.push_back(distinct[j]);
  }
  return result;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_INPUT_HYGIENE_H
