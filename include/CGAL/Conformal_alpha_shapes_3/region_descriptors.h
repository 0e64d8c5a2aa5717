// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_REGION_DESCRIPTORS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_REGION_DESCRIPTORS_H

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/shape_index.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Matching
Descriptors of regions of a surface, from `region_descriptors()`: one row
of values per centre point, each row a concatenation of normalised
histograms (each sums to 1, or is all zeros for an empty ring). Per ring,
from the innermost: per curvature layer the shape index bins then the
curvedness bins, then (with normals) the bins of the normals' cosines and
those of the heights.
*/
struct Region_descriptors
{
  std::vector<std::size_t> centers;                 ///< the centres' point indices
  std::vector<std::array<double, 3> > center_points; ///< the centres' positions
  std::vector<double> rings;                        ///< the rings' outer radii
  int shape_index_bins = 0;                         ///< per shape index histogram
  int curvedness_bins = 0;                          ///< per curvedness histogram
  /// the bins, weight (in `histogram_distances()`) and kind of each
  /// histogram of a row, in order; the kind says what the histogram counts
  /// whatever its ring: 2k and 2k+1 layer k's shape index and curvedness,
  /// then the normals' cosines and the heights
  std::vector<int> histogram_bins;
  std::vector<double> histogram_weights;            ///< see `histogram_bins`
  std::vector<int> histogram_kinds;                 ///< see `histogram_bins`
  std::size_t width = 0;                            ///< values per row
  std::vector<double> values;                       ///< the rows, one after another

  /// the number of regions
  std::size_t size() const { return centers.size(); }
  /// the `width` values of region `i`
  const double* row(std::size_t i) const { return values.data() + i * width; }
  /// whether the rows of `this` and of `other` compare histogram by histogram
  bool same_layout(const Region_descriptors& other) const
  {
    return width == other.width && rings == other.rings && shape_index_bins == other.shape_index_bins
           && curvedness_bins == other.curvedness_bins && histogram_bins == other.histogram_bins
           && histogram_weights == other.histogram_weights && histogram_kinds == other.histogram_kinds;
  }
};

namespace internal {

// A value's linear weights at the two nearest bin centres of `bins` over
// [low, high] (the ends clamped), so that a small change of the value moves
// a little weight rather than all of it.
struct Soft_bin
{
  int first, second;
  double first_weight, second_weight;
};

inline Soft_bin soft_bin(double value, double low, double high, int bins)
{
  double t = ((std::min)((std::max)(value, low), high) - low) / (high - low) * bins - 0.5;
  t = (std::min)((std::max)(t, 0.0), double(bins - 1));
  const int first = int(std::floor(t));
  const double w = t - first;
  return {first, (std::min)(first + 1, bins - 1), 1 - w, w};
}

template <class Point>
bool finite_point(const Point& p)
{
  return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y()))
         && std::isfinite(CGAL::to_double(p.z()));
}

template <class NamedParameters>
std::vector<double> ring_radii_of(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  std::vector<double> rings =
    choose_parameter(get_parameter(np, internal_np_cas3::ring_radii), std::vector<double>{3.0, 6.0, 10.0});
  bool increasing = !rings.empty() && rings[0] > 0;
  for(std::size_t k = 1; k < rings.size(); ++k)
    increasing = increasing && rings[k] > rings[k - 1];
  if(!increasing || !std::isfinite(rings.back()))
    throw std::invalid_argument("region_descriptors: rings must be increasing radii > 0");
  return rings;
}

} // namespace internal

/*!
\ingroup PkgConformalAlphaShapes3Matching
The indices of `n` points of `points` chosen greedily, each the farthest
from those chosen before, starting from the first one: a spread-out sample,
the same on every run (of ties, the smallest index). All the indices, in
order, when `n` is at least the number of points.

\tparam PointRange a model of `ConstRange`

\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{the position of each element of `points`}
    \cgalParamType{a model of `ReadablePropertyMap` with the range's value type as key and `GT::Point_3` as value}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{first_point_index}
    \cgalParamDescription{the index of the first point chosen}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{0}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument when the first index is not a point's, or a
coordinate is NaN or infinite.
*/
template <class PointRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<std::size_t> farthest_point_sample(const PointRange& points, std::size_t n,
                                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto point_map = choose_parameter<CGAL::Identity_property_map<typename PointRange::value_type> >(
    get_parameter(np, CGAL::internal_np::point_map));
  std::vector<std::array<double, 3> > xyz;
  for(const auto& element : points)
  {
    const auto& p = get(point_map, element);
    if(!internal::finite_point(p))
      throw std::invalid_argument("farthest_point_sample: a point's coordinate is NaN or infinite");
    xyz.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  const std::size_t first = choose_parameter(get_parameter(np, internal_np_cas3::first_point_index), std::size_t(0));
  std::vector<std::size_t> chosen;
  if(n >= xyz.size())
  {
    for(std::size_t i = 0; i < xyz.size(); ++i)
      chosen.push_back(i);
    return chosen;
  }
  if(first >= xyz.size())
    throw std::invalid_argument("farthest_point_sample: the first index is not a point's");
  std::vector<double> distance(xyz.size(), std::numeric_limits<double>::infinity());
  for(std::size_t c = first; chosen.size() < n;)
  {
    chosen.push_back(c);
    std::size_t farthest = 0;
    for(std::size_t i = 0; i < xyz.size(); ++i)
    {
      const double dx = xyz[i][0] - xyz[c][0], dy = xyz[i][1] - xyz[c][1], dz = xyz[i][2] - xyz[c][2];
      distance[i] = (std::min)(distance[i], dx * dx + dy * dy + dz * dz);
      if(distance[i] > distance[farthest])
        farthest = i;
    }
    c = farthest;
  }
  return chosen;
}

/*!
\ingroup PkgConformalAlphaShapes3Matching

Descriptors of the surface around chosen centre points, at every
curvature scale, in rings. For each centre, the points within each ring of
distance (0 to `rings[0]`, then `rings[0]` to `rings[1]`, ...) are
summarised, for each curvature layer, by a histogram of their shape index
(over [-1, 1], `shape_index()`) and one of their curvedness times the
layer's fit radius (over [0, `curvedness_range`], the last bin taking
larger values). Each histogram is soft (a value shares its weight between
the two nearest bins) and normalised to sum 1. Points without a shape
index (flat, or NaN) count in neither histogram. With normals, each ring
also gets a histogram of the cosines between the centre's normal and the
points' normals, and one of the points' heights over the centre's tangent
plane over the ring's radius (both over [-1, 1]; a NaN normal counts in
neither). Distances are Euclidean,
so the rings suit surfaces whose sheets are farther apart than the
largest ring's width. The rings' points are found in kd-trees
(`CGAL::Kd_tree`).

Beyond `dense_radius` from the centre only one point in `thinning` (those
whose index is a multiple of it) counts: the outer rings hold thousands of
points, whose normalised histograms a third of them gives nearly as well in
half the time (the manual, "Matching Surface Regions").

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_if_available_tag`
        (the centres on TBB's threads; the same results)
\tparam PointRange a model of `ConstRange`
\tparam LayerRange a range of curvature layers; each layer a range holding,
        for every point of `points` in order, a value `v` with
        `v.principal.max_curvature`, `v.principal.min_curvature` and
        `v.radius` (as `Point_curvature`, e.g. `Curvature_layer::points`)
\tparam CenterRange a range of point indices (`farthest_point_sample()`)

\cgalNamedParamsBegin
  \cgalParamNBegin{point_map}
    \cgalParamDescription{the position of each element of `points`}
    \cgalParamType{a model of `ReadablePropertyMap` with the range's value type as key and `GT::Point_3` as value}
    \cgalParamDefault{`CGAL::Identity_property_map`}
  \cgalParamNEnd
  \cgalParamNBegin{normal_map}
    \cgalParamDescription{the outward normal of each point (any length but 0); without it, no normal and height histograms}
    \cgalParamType{a model of `ReadablePropertyMap` with the range's value type as key and `GT::Vector_3` as value}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{center_normal_map}
    \cgalParamDescription{the normal giving a centre's tangent plane: a layer's fitted normal at a few sample spacings is steadier than a sample's own}
    \cgalParamType{as `normal_map`}
    \cgalParamDefault{`normal_map`}
  \cgalParamNEnd
  \cgalParamNBegin{ring_radii}
    \cgalParamDescription{the rings' outer radii, increasing}
    \cgalParamType{`std::vector<double>`}
    \cgalParamDefault{{3, 6, 10}}
  \cgalParamNEnd
  \cgalParamNBegin{ring_weights}
    \cgalParamDescription{the weight of each ring's histograms in `histogram_distances()`; the default, proportional to the outer radius, lets the outer rings' context tell apart regions alike at the centre}
    \cgalParamType{`std::vector<double>`, one value >= 0 per ring}
    \cgalParamDefault{each ring's radius over the rings' mean radius}
  \cgalParamNEnd
  \cgalParamNBegin{shape_index_bins, curvedness_bins, geometry_bins}
    \cgalParamDescription{the bins of the shape index, curvedness, and normal and height histograms}
    \cgalParamType{`int`}
    \cgalParamDefault{10, 6 and 8}
  \cgalParamNEnd
  \cgalParamNBegin{curvedness_range}
    \cgalParamDescription{the end of the last curvedness bin, for the curvedness times the fit's radius}
    \cgalParamType{`double`}
    \cgalParamDefault{2}
  \cgalParamNEnd
  \cgalParamNBegin{dense_radius, thinning}
    \cgalParamDescription{every point counts within `dense_radius`, one in `thinning` beyond}
    \cgalParamType{`double` and `std::size_t`}
    \cgalParamDefault{4 and 3}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument on a NaN or infinite coordinate, rings that do not increase, weights that
are not one value >= 0 per ring, a layer whose size is not the number of
points, no layer, a centre that is not a point's index, fewer than 2 shape
index or geometry bins or 1 curvedness bin, `thinning` < 1 or
`dense_radius` <= 0.
*/
template <class ConcurrencyTag = CGAL::Sequential_tag, class PointRange, class LayerRange, class CenterRange,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Region_descriptors region_descriptors(const PointRange& points, const LayerRange& layers, const CenterRange& centers,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef typename PointRange::value_type Element;
  typedef CGAL::Identity_property_map<Element> Default_point_map;
  const auto point_map = choose_parameter<Default_point_map>(get_parameter(np, CGAL::internal_np::point_map));
  typedef typename Kernel_traits<std::decay_t<decltype(get(point_map, *std::begin(points)))> >::Kernel GT;
  typedef typename GT::Point_3 Point;
  typedef typename GT::Vector_3 Vector;
  constexpr bool with_normals = !is_default_parameter<NamedParameters, CGAL::internal_np::normal_t>::value;

  const std::vector<double> rings = internal::ring_radii_of(np);
  std::vector<double> ring_weights = choose_parameter(get_parameter(np, internal_np_cas3::ring_weights),
                                                      std::vector<double>());
  if(is_default_parameter<NamedParameters, internal_np_cas3::ring_weights_t>::value)
  {
    double mean = 0;
    for(double r : rings)
      mean += r / double(rings.size());
    for(double r : rings)
      ring_weights.push_back(r / mean);
  }
  if(ring_weights.size() != rings.size()
     || std::any_of(ring_weights.begin(), ring_weights.end(), [](double w) { return !(w >= 0); }))
    throw std::invalid_argument("region_descriptors: ring_weights must be one value >= 0 per ring");
  const int shape_bins = choose_parameter(get_parameter(np, internal_np_cas3::shape_index_bins), 10);
  const int curvedness_bins = choose_parameter(get_parameter(np, internal_np_cas3::curvedness_bins), 6);
  const int geometry_bins = choose_parameter(get_parameter(np, internal_np_cas3::geometry_bins), 8);
  const double curvedness_range = choose_parameter(get_parameter(np, internal_np_cas3::curvedness_range), 2.0);
  const double dense_radius = choose_parameter(get_parameter(np, internal_np_cas3::dense_radius), 4.0);
  const std::size_t thinning = choose_parameter(get_parameter(np, internal_np_cas3::thinning), std::size_t(3));
  if(shape_bins < 2 || curvedness_bins < 1 || geometry_bins < 2 || !(curvedness_range > 0))
    throw std::invalid_argument(
      "region_descriptors: at least 2 shape index and geometry bins and 1 curvedness bin, and a curvedness range > 0");
  if(thinning < 1 || !(dense_radius > 0))
    throw std::invalid_argument("region_descriptors: thinning must be an integer >= 1 and dense_radius > 0");

  std::vector<Point> xyz;
  for(const Element& element : points)
  {
    xyz.push_back(get(point_map, element));
    if(!internal::finite_point(xyz.back()))
      throw std::invalid_argument("region_descriptors: a point's coordinate is NaN or infinite");
  }
  const std::size_t n = xyz.size();
  std::vector<Vector> normals, center_normals;
  if constexpr(with_normals)
  {
    const auto normal_map = get_parameter(np, CGAL::internal_np::normal_map);
    const auto center_map = choose_parameter(get_parameter(np, internal_np_cas3::center_normal_map), normal_map);
    auto unit = [](const Vector& v) { return v / (std::max)(std::sqrt(CGAL::to_double(v.squared_length())), 1e-300); };
    for(const Element& element : points)
    {
      normals.push_back(unit(get(normal_map, element)));
      center_normals.push_back(unit(get(center_map, element)));
    }
  }

  // each point's four (bin, weight) pairs per layer, as offsets in a ring's block of values
  const std::size_t n_layers = std::size_t(std::distance(std::begin(layers), std::end(layers)));
  if(n_layers == 0)
    throw std::invalid_argument("region_descriptors: no curvature layer");
  const int per_layer = shape_bins + curvedness_bins;
  const std::size_t geometry = with_normals ? std::size_t(2 * geometry_bins) : 0;
  const std::size_t per_ring = n_layers * std::size_t(per_layer) + geometry;
  std::vector<std::pair<int, double> > contributions(n * n_layers * 4);
  std::size_t layer_index = 0;
  for(const auto& layer : layers)
  {
    const std::size_t size = std::size_t(std::distance(std::begin(layer), std::end(layer)));
    if(size != n)
      throw std::invalid_argument("region_descriptors: " + std::to_string(n) + " points but " + std::to_string(size)
                                  + " values per layer");
    std::size_t i = 0;
    for(const auto& value : layer)
    {
      const double k1 = value.principal.max_curvature, k2 = value.principal.min_curvature;
      const double s = shape_index(k1, k2), c = curvedness(k1, k2) * value.radius;
      const bool defined = std::isfinite(s) && std::isfinite(c);
      const internal::Soft_bin bs = internal::soft_bin(defined ? s : 0.0, -1.0, 1.0, shape_bins);
      const internal::Soft_bin bc = internal::soft_bin(defined ? c : 0.0, 0.0, curvedness_range, curvedness_bins);
      const int offset = int(layer_index) * per_layer;
      std::pair<int, double>* out = &contributions[(i++ * n_layers + layer_index) * 4];
      out[0] = {offset + bs.first, defined ? bs.first_weight : 0.0};
      out[1] = {offset + bs.second, defined ? bs.second_weight : 0.0};
      out[2] = {offset + shape_bins + bc.first, defined ? bc.first_weight : 0.0};
      out[3] = {offset + shape_bins + bc.second, defined ? bc.second_weight : 0.0};
    }
    ++layer_index;
  }

  Region_descriptors out;
  out.rings = rings;
  out.shape_index_bins = shape_bins;
  out.curvedness_bins = curvedness_bins;
  for(std::size_t ring = 0; ring < rings.size(); ++ring)
  {
    for(std::size_t layer = 0; layer < n_layers; ++layer)
      for(int k = 0; k < 2; ++k)
      {
        out.histogram_bins.push_back(k == 0 ? shape_bins : curvedness_bins);
        out.histogram_kinds.push_back(int(2 * layer) + k);
      }
    for(std::size_t k = 0; geometry != 0 && k < 2; ++k)
    {
      out.histogram_bins.push_back(geometry_bins);
      out.histogram_kinds.push_back(int(2 * n_layers + k));
    }
    out.histogram_weights.resize(out.histogram_bins.size(), ring_weights[ring]);
  }
  out.width = rings.size() * per_ring;
  for(const auto& c : centers)
  {
    const std::size_t index = std::size_t(c);  // a negative index wraps beyond n
    if(index >= n)
      throw std::invalid_argument("region_descriptors: centers must be point indices");
    out.centers.push_back(index);
    out.center_points.push_back({CGAL::to_double(xyz[index].x()), CGAL::to_double(xyz[index].y()),
                                 CGAL::to_double(xyz[index].z())});
  }
  out.values.assign(out.centers.size() * out.width, 0.0);

  // every point within the dense radius, the kept ones (one in `thinning`) out to the last ring
  typedef CGAL::Search_traits_adapter<std::size_t, typename CGAL::Pointer_property_map<Point>::type,
                                      CGAL::Search_traits_3<GT> > Traits;
  typedef CGAL::Kd_tree<Traits> Tree;
  const double outer2 = rings.back() * rings.back();
  const double dense2 = thinning > 1 ? (std::min)(dense_radius * dense_radius, outer2) : outer2;
  std::vector<std::size_t> all(n), kept;
  for(std::size_t i = 0; i < n; ++i)
  {
    all[i] = i;
    if(i % thinning == 0)
      kept.push_back(i);
  }
  Tree dense_tree(all.begin(), all.end(), typename Tree::Splitter(), Traits(CGAL::make_property_map(xyz)));
  Tree far_tree(kept.begin(), kept.end(), typename Tree::Splitter(), Traits(CGAL::make_property_map(xyz)));
  dense_tree.build();
  far_tree.build();
  std::vector<double> rings2;
  for(double r : rings)
    rings2.push_back(r * r);

  internal::for_each_index<ConcurrencyTag>(
    out.centers.size(), [] { return std::vector<std::size_t>(); },
    [&](std::size_t row, std::vector<std::size_t>& found) {
      const std::size_t c = out.centers[row];
      const Point& center = xyz[c];
      double* values = out.values.data() + row * out.width;
      auto add = [&](std::size_t j, double d2) {
        const std::size_t ring = std::size_t(std::lower_bound(rings2.begin(), rings2.end(), d2) - rings2.begin());
        double* block = values + ring * per_ring;
        for(std::size_t k = j * n_layers * 4; k < (j + 1) * n_layers * 4; ++k)
          block[contributions[k].first] += contributions[k].second;
        if constexpr(with_normals)
        {
          const double cosine = CGAL::to_double(normals[j] * center_normals[c]);
          const double height = CGAL::to_double((xyz[j] - center) * center_normals[c]) / rings[ring];
          double* geometry_block = block + n_layers * std::size_t(per_layer);
          for(const double v : {cosine, height})
          {
            if(std::isfinite(v))  // a NaN normal counts in neither histogram
            {
              const internal::Soft_bin b = internal::soft_bin(v, -1.0, 1.0, geometry_bins);
              geometry_block[b.first] += b.first_weight;
              geometry_block[b.second] += b.second_weight;
            }
            geometry_block += geometry_bins;
          }
        }
      };
      for(int pass = 0; pass < (dense2 < outer2 ? 2 : 1); ++pass)
      {
        found.clear();
        const double radius = std::sqrt(pass == 0 ? dense2 : outer2);
        const Tree& tree = pass == 0 ? dense_tree : far_tree;
        // the query is the centre's index, read through the trees' map
        tree.search(std::back_inserter(found), CGAL::Fuzzy_sphere<Traits>(c, radius, 0.0, tree.traits()));
        for(const std::size_t j : found)
        {
          const double d2 = CGAL::to_double((xyz[j] - center).squared_length());
          if(pass == 0 ? d2 <= dense2 : (d2 > dense2 && d2 <= outer2))
            add(j, d2);
        }
      }
      // each histogram normalised to sum 1
      for(const int bins : out.histogram_bins)
      {
        double total = 0;
        for(int k = 0; k < bins; ++k)
          total += values[k];
        for(int k = 0; total > 0 && k < bins; ++k)
          values[k] /= total;
        values += bins;
      }
    });
  return out;
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_REGION_DESCRIPTORS_H
