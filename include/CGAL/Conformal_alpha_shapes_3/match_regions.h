// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_MATCH_REGIONS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_MATCH_REGIONS_H

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/region_descriptors.h>

#include <CGAL/Random.h>
#include <CGAL/tags.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Matching
A rigid motion `x -> R x + t` (a proper rotation `R`, row by row, and a
translation `t`).
*/
struct Rigid_motion
{
  std::array<std::array<double, 3>, 3> rotation{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  ///< `R`
  std::array<double, 3> translation{{0, 0, 0}};                                      ///< `t`

  /// `R p + t`
  std::array<double, 3> operator()(const std::array<double, 3>& p) const
  {
    std::array<double, 3> q;
    for(int r = 0; r < 3; ++r)
      q[r] = rotation[r][0] * p[0] + rotation[r][1] * p[1] + rotation[r][2] * p[2] + translation[r];
    return q;
  }
};

/*!
\ingroup PkgConformalAlphaShapes3Matching
A robust rigid registration: the motion, and which pairs agree with it.
*/
struct Registration
{
  Rigid_motion motion;        ///< places the source points onto the target points
  std::vector<bool> inliers;  ///< per pair: whether the motion places it within the tolerance
};

/*!
\ingroup PkgConformalAlphaShapes3Matching
What `match_regions()` finds: for each region of A its best candidates
among B's regions, and the registration of B onto A that they give.
*/
struct Region_matches
{
  std::vector<std::size_t> centers;     ///< A's centre point indices
  std::size_t top = 0;                  ///< candidates per centre
  /// per centre, `top` of B's centre point indices, best first by `histogram_distances()`
  std::vector<std::size_t> candidates;
  std::vector<double> scores;           ///< their distances (0: identical; smaller is better)
  /// per centre, `top` of B's centre point indices re-ranked by the
  /// registration: among the centre's pool of best candidates, those that
  /// the motion places within the tolerance of the centre first, then the
  /// others, each group in the order of the descriptors
  std::vector<std::size_t> reranked;
  Rigid_motion motion;                  ///< places B onto A
  std::vector<bool> inliers;            ///< per centre: whether its best candidate agrees with `motion`
  double consistent = 0;                ///< the share of the inliers
};

namespace internal {

inline double squared_gap(const std::array<double, 3>& p, const std::array<double, 3>& q)
{
  return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
}

// The median of `values` (the mean of the two middle ones for an even count).
inline double median(std::vector<double> values)
{
  const std::size_t half = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(half), values.end());
  const double upper = values[half];
  if(values.size() % 2 == 1)
    return upper;
  return (*std::max_element(values.begin(), values.begin() + std::ptrdiff_t(half)) + upper) / 2;
}

// The rows of `r` as running sums of each histogram, weighted so that the
// L1 distance between two rows is the weighted mean earth mover's distance.
inline std::vector<double> cumulative_rows(const Region_descriptors& r)
{
  std::vector<double> out(r.values.size());
  double total_weight = 0;
  for(double w : r.histogram_weights)
    total_weight += w;
  for(std::size_t i = 0; i < r.size(); ++i)
  {
    std::size_t column = i * r.width;
    for(std::size_t h = 0; h < r.histogram_bins.size(); ++h)
    {
      const double scale = r.histogram_weights[h] / r.histogram_bins[h] / total_weight;
      double sum = 0;
      for(int k = 0; k < r.histogram_bins[h]; ++k, ++column)
      {
        sum += r.values[column];
        out[column] = sum * scale;
      }
    }
  }
  return out;
}

} // namespace internal

/*!
\ingroup PkgConformalAlphaShapes3Matching
The rotation `R` and translation `t` minimising the sum of
`weights[i] |R source[i] + t - target[i]|^2` (Kabsch's least squares, a
proper rotation, by Eigen's singular value decomposition); all weights 1
when `weights` is empty.
\throws std::invalid_argument when the ranges' sizes differ or there is no pair.
*/
inline Rigid_motion fit_rigid(const std::vector<std::array<double, 3> >& source,
                              const std::vector<std::array<double, 3> >& target,
                              const std::vector<double>& weights = std::vector<double>())
{
  if(source.size() != target.size() || source.empty() || (!weights.empty() && weights.size() != source.size()))
    throw std::invalid_argument("fit_rigid: as many source and target points (and weights), at least one");
  double total = 0;
  for(std::size_t i = 0; i < source.size(); ++i)
    total += weights.empty() ? 1.0 : weights[i];
  Eigen::Vector3d cs = Eigen::Vector3d::Zero(), ct = Eigen::Vector3d::Zero();
  for(std::size_t i = 0; i < source.size(); ++i)
  {
    const double w = (weights.empty() ? 1.0 : weights[i]) / total;
    cs += w * Eigen::Vector3d(source[i][0], source[i][1], source[i][2]);
    ct += w * Eigen::Vector3d(target[i][0], target[i][1], target[i][2]);
  }
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for(std::size_t i = 0; i < source.size(); ++i)
  {
    const double w = (weights.empty() ? 1.0 : weights[i]) / total;
    h += w * (Eigen::Vector3d(source[i][0], source[i][1], source[i][2]) - cs)
         * (Eigen::Vector3d(target[i][0], target[i][1], target[i][2]) - ct).transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1 : 1;
  const Eigen::Matrix3d r = svd.matrixV() * d * svd.matrixU().transpose();
  const Eigen::Vector3d t = ct - r * cs;
  Rigid_motion motion;
  for(int i = 0; i < 3; ++i)
  {
    for(int j = 0; j < 3; ++j)
      motion.rotation[std::size_t(i)][std::size_t(j)] = r(i, j);
    motion.translation[std::size_t(i)] = t(i);
  }
  return motion;
}

/*!
\ingroup PkgConformalAlphaShapes3Matching
A rigid motion placing the points `source` onto their points `target`,
robust to wrong pairs. RANSAC: random triples of pairs (`CGAL::Random` of
the seed) whose mutual distances agree within the tolerance on both sides,
each at least the tolerance, give candidate motions (`fit_rigid()`); the
one under which most pairs land within the tolerance wins (the first
drawn of ties), then is refitted by least squares on those pairs, twice.
Without any such triple, the fit of all the pairs is the start. The same
result on every run.

\cgalNamedParamsBegin
  \cgalParamNBegin{inlier_tolerance}
    \cgalParamDescription{the distance within which a pair agrees with a motion, in the points' units}
    \cgalParamType{`double`}
    \cgalParamDefault{3}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the triples drawn}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{2000}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the draws}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{0}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument with fewer than 3 pairs, or sizes that differ.
*/
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
Registration register_correspondences(const std::vector<std::array<double, 3> >& source,
                                      const std::vector<std::array<double, 3> >& target,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double tolerance = choose_parameter(get_parameter(np, internal_np_cas3::inlier_tolerance), 3.0);
  const std::size_t iterations =
    choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(2000));
  const unsigned int seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  const std::size_t n = source.size();
  if(n < 3 || target.size() != n)
    throw std::invalid_argument("register_correspondences: fewer than 3 pairs, or not as many sources as targets");
  if(!(tolerance > 0))
    throw std::invalid_argument("register_correspondences: the tolerance must be > 0");
  const double tolerance2 = tolerance * tolerance;
  auto agree = [&](const Rigid_motion& m, std::size_t i) {
    return internal::squared_gap(m(source[i]), target[i]) < tolerance2;
  };

  CGAL::Random random(seed);
  Rigid_motion best = fit_rigid(source, target);
  std::size_t best_count = 0;
  for(std::size_t iteration = 0; iteration < iterations; ++iteration)
  {
    const std::size_t t[3] = {std::size_t(random.get_int(0, int(n))), std::size_t(random.get_int(0, int(n))),
                              std::size_t(random.get_int(0, int(n)))};
    if(t[0] == t[1] || t[0] == t[2] || t[1] == t[2])
      continue;
    bool spread_and_alike = true;
    for(const auto& e : {std::make_pair(0, 1), std::make_pair(0, 2), std::make_pair(1, 2)})
    {
      const double ds = std::sqrt(internal::squared_gap(source[t[e.first]], source[t[e.second]]));
      const double dt = std::sqrt(internal::squared_gap(target[t[e.first]], target[t[e.second]]));
      spread_and_alike = spread_and_alike && std::abs(ds - dt) <= tolerance && ds >= tolerance;
    }
    if(!spread_and_alike)
      continue;
    const Rigid_motion m = fit_rigid({source[t[0]], source[t[1]], source[t[2]]},
                                     {target[t[0]], target[t[1]], target[t[2]]});
    std::size_t count = 0;
    for(std::size_t i = 0; i < n; ++i)
      count += agree(m, i) ? 1 : 0;
    if(count > best_count)
    {
      best = m;
      best_count = count;
    }
  }
  Registration out{best, std::vector<bool>(n)};
  for(int refit = 0; refit <= 2; ++refit)
  {
    std::vector<std::array<double, 3> > s, t;
    for(std::size_t i = 0; i < n; ++i)
    {
      out.inliers[i] = agree(out.motion, i);
      if(out.inliers[i])
      {
        s.push_back(source[i]);
        t.push_back(target[i]);
      }
    }
    if(refit == 2 || s.size() < 3)
      break;
    out.motion = fit_rigid(s, t);
  }
  return out;
}

/*!
\ingroup PkgConformalAlphaShapes3Matching
The distances between the regions of `a` and those of `b`, row by row (`a.size()` rows of
`b.size()` values): per histogram the earth mover's distance as a share of
its range (the L1 distance of the running sums over the bins' count),
weighted by the histograms' weights. The bins are ordered (a shape index of
0.9 is near 1.0, far from -1.0), so a shape shifted by a bin stays near.

With `balance` (the default), the weighted sum over each kind of histogram
(one layer's shape index, one layer's curvedness, the normals' cosines, the
heights; all rings) is divided by its median over all the pairs of regions,
and the kinds averaged: every kind then weighs alike however spread its
values, and a distance of 1 is a typical one. Without it, the weighted
mean over all the histograms, in [0, 1].

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_if_available_tag`
        (the rows on TBB's threads; the same results)
\throws std::invalid_argument when `a` and `b` were described with different layouts.
*/
template <class ConcurrencyTag = CGAL::Sequential_tag>
std::vector<double> histogram_distances(const Region_descriptors& a, const Region_descriptors& b, bool balance = true)
{
  if(!a.same_layout(b))
    throw std::invalid_argument("histogram_distances: the regions were described with different layouts");
  const std::vector<double> x = internal::cumulative_rows(a), y = internal::cumulative_rows(b);
  // the columns grouped by kind, so that each kind's distance is a sum over a span
  std::vector<int> column_kind;
  for(std::size_t h = 0; h < a.histogram_bins.size(); ++h)
    column_kind.insert(column_kind.end(), std::size_t(a.histogram_bins[h]), balance ? a.histogram_kinds[h] : 0);
  std::vector<std::size_t> columns(a.width);
  std::iota(columns.begin(), columns.end(), std::size_t(0));
  std::stable_sort(columns.begin(), columns.end(), [&](std::size_t i, std::size_t j) {
    return column_kind[i] < column_kind[j];
  });
  std::vector<std::size_t> span_end;
  for(std::size_t k = 1; k <= columns.size(); ++k)
    if(k == columns.size() || column_kind[columns[k]] != column_kind[columns[k - 1]])
      span_end.push_back(k);
  auto regroup = [&](const std::vector<double>& rows, std::size_t count) {
    std::vector<double> out(rows.size());
    for(std::size_t i = 0; i < count; ++i)
      for(std::size_t k = 0; k < columns.size(); ++k)
        out[i * a.width + k] = rows[i * a.width + columns[k]];
    return out;
  };
  const std::vector<double> xs = regroup(x, a.size()), ys = regroup(y, b.size());
  const std::size_t kinds = span_end.size(), pairs = a.size() * b.size();
  std::vector<double> by_kind(kinds * pairs);
  internal::for_each_index<ConcurrencyTag>(a.size(), [] { return 0; }, [&](std::size_t i, int) {
    const double* row = xs.data() + i * a.width;
    for(std::size_t j = 0; j < b.size(); ++j)
    {
      const double* other = ys.data() + j * a.width;
      std::size_t k = 0;
      for(std::size_t kind = 0; kind < kinds; ++kind)
      {
        double sum = 0;
        for(; k < span_end[kind]; ++k)
          sum += std::abs(row[k] - other[k]);
        by_kind[kind * pairs + i * b.size() + j] = sum;
      }
    }
  });
  if(!balance)
    return by_kind;
  std::vector<double> out(pairs, 0.0);
  for(std::size_t kind = 0; kind < kinds; ++kind)
  {
    const auto first = by_kind.begin() + std::ptrdiff_t(kind * pairs);
    const double m = internal::median(std::vector<double>(first, first + std::ptrdiff_t(pairs)));
    for(std::size_t p = 0; p < pairs; ++p)
      out[p] += (m > 0 ? first[std::ptrdiff_t(p)] / m : first[std::ptrdiff_t(p)]) / double(kinds);
  }
  return out;
}

/*!
\ingroup PkgConformalAlphaShapes3Matching

The best candidates among the regions of `b` for each region of `a` (by
`histogram_distances()`), the registration of B onto A from each region's
best candidate (`register_correspondences()`, with at least 3 regions in
`a`; else the identity and no inliers), and the candidates re-ranked by
their agreement with it. `a` and `b` must be described with the same
layout: the same rings, bins, weights and layers (the same radii, in the
same units).

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_if_available_tag`
        (the same results)

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_candidates}
    \cgalParamDescription{the candidates kept per region of `a` (at most `b.size()`)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{10}
  \cgalParamNEnd
  \cgalParamNBegin{candidate_pool}
    \cgalParamDescription{the best candidates per region that the re-ranking chooses from (at least `number_of_candidates`)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{50}
  \cgalParamNEnd
  \cgalParamNBegin{inlier_tolerance, number_of_iterations, random_seed}
    \cgalParamDescription{as for `register_correspondences()`}
  \cgalParamNEnd
  \cgalParamNBegin{balance_kinds}
    \cgalParamDescription{the `balance` of `histogram_distances()`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument when `a` or `b` is empty or their layouts differ.
*/
template <class ConcurrencyTag = CGAL::Sequential_tag, class NamedParameters = CGAL::parameters::Default_named_parameters>
Region_matches match_regions(const Region_descriptors& a, const Region_descriptors& b,
                             const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(a.size() == 0 || b.size() == 0)
    throw std::invalid_argument("match_regions: no region");
  if(!a.same_layout(b))
    throw std::invalid_argument("match_regions: the regions were described with different layouts");
  const double tolerance = choose_parameter(get_parameter(np, internal_np_cas3::inlier_tolerance), 3.0);
  if(!(tolerance > 0))
    throw std::invalid_argument("match_regions: the tolerance must be > 0");
  const std::vector<double> distances = histogram_distances<ConcurrencyTag>(
    a, b, choose_parameter(get_parameter(np, internal_np_cas3::balance_kinds), true));
  Region_matches out;
  out.centers = a.centers;
  out.top = (std::min)(choose_parameter(get_parameter(np, internal_np_cas3::number_of_candidates), std::size_t(10)),
                       b.size());
  const std::size_t pool = (std::min)(
    (std::max)(choose_parameter(get_parameter(np, internal_np_cas3::candidate_pool), std::size_t(50)), out.top),
    b.size());
  // per centre its pool of best regions of b, in the order of a stable sort
  std::vector<std::size_t> order(a.size() * pool);
  internal::for_each_index<ConcurrencyTag>(a.size(), [] { return std::vector<std::size_t>(); },
                                           [&](std::size_t i, std::vector<std::size_t>& all) {
    const double* d = distances.data() + i * b.size();
    all.resize(b.size());
    std::iota(all.begin(), all.end(), std::size_t(0));
    std::partial_sort(all.begin(), all.begin() + std::ptrdiff_t(pool), all.end(), [d](std::size_t p, std::size_t q) {
      return d[p] < d[q] || (d[p] == d[q] && p < q);
    });
    std::copy(all.begin(), all.begin() + std::ptrdiff_t(pool), order.begin() + std::ptrdiff_t(i * pool));
  });
  for(std::size_t i = 0; i < a.size(); ++i)
    for(std::size_t k = 0; k < out.top; ++k)
    {
      out.candidates.push_back(b.centers[order[i * pool + k]]);
      out.scores.push_back(distances[i * b.size() + order[i * pool + k]]);
    }
  if(a.size() >= 3)
  {
    std::vector<std::array<double, 3> > best;
    for(std::size_t i = 0; i < a.size(); ++i)
      best.push_back(b.center_points[order[i * pool]]);
    Registration r = register_correspondences(best, a.center_points, np);
    out.motion = r.motion;
    out.inliers = std::move(r.inliers);
  }
  else
    out.inliers.assign(a.size(), false);
  out.consistent = double(std::count(out.inliers.begin(), out.inliers.end(), true)) / double(a.size());
  // the registration's verdict on each candidate of the pool; a stable partition keeps the descriptors' order
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    std::vector<std::size_t> pooled(order.begin() + std::ptrdiff_t(i * pool), order.begin() + std::ptrdiff_t((i + 1) * pool));
    std::stable_partition(pooled.begin(), pooled.end(), [&](std::size_t j) {
      return internal::squared_gap(out.motion(b.center_points[j]), a.center_points[i]) < tolerance * tolerance;
    });
    for(std::size_t k = 0; k < out.top; ++k)
      out.reranked.push_back(b.centers[pooled[k]]);
  }
  return out;
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_MATCH_REGIONS_H
