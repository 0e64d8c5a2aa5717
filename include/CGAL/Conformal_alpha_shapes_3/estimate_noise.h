// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_NOISE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_NOISE_H

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/order_free.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// What `estimate_noise()` measured.
struct Noise_estimate
{
  /// the mean distance from a point to its 6 nearest neighbors, measured
  /// in the local tangent plane (so that noise does not inflate it), in model units
  double spacing = 0;
  /// the standard deviation of the points' offsets from a local cubic
  /// surface fitted to 16 neighbors, as a multiple of `spacing`
  double noise = 0;
  /// the same with 24 neighbors: noise reads the same at both sizes,
  /// surface detail that the sampling does not resolve grows with the size
  double noise_24 = 0;

  /// Whether the reading grows by more than 30% from 16 to 24 neighbors:
  /// what it measures is then mostly surface detail that the sampling does
  /// not resolve, not noise (a reading that is not a number counts as such).
  bool shows_unresolved_detail() const { return !(noise_24 <= 1.3 * noise); }

  /// Whether automatic denoising smooths the points: the noise exceeds
  /// 0.02 (below it the interpolating surface does not fold; clean samples
  /// read 0.011 or less, even with detail) and is not unresolved detail
  /// (`shows_unresolved_detail()`).
  bool calls_for_denoising() const { return noise > 0.02 && !shows_unresolved_detail(); }
};

namespace internal {

// The most points whose fits make the estimate: all of a cloud up to this
// size, so that the estimate is a function of the points alone (no sample
// to choose); above, a sample this large leaves it within about 0.2% of
// the estimate on any other sample.
constexpr std::size_t noise_sample_size = 100000;

// The median of a chi-squared variable with `nu` degrees of freedom over
// `nu` (Wilson-Hilferty): dividing the median residual variance by it makes
// the estimate unbiased for Gaussian noise.
inline double chi_squared_median_ratio(double nu)
{
  const double t = 1.0 - 2.0 / (9.0 * nu);
  return t * t * t;
}

// The residual variance of a least-squares cubic height function over the
// first `k` (at most 32) of `neighbors` (the query point first, then by distance), in
// the PCA frame of those points, and the mean tangential distance to the
// 6 nearest. Returns false on a degenerate neighborhood.
inline bool cubic_fit_residual(const std::vector<Eigen::Vector3d>& neighbors, int k,
                               double& variance, double& spacing)
{
  const int coefficients = 10;
  if(int(neighbors.size()) < k || k <= coefficients || k > 32)
    return false;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  for(int i = 0; i < k; ++i)
    center += neighbors[i];
  center /= double(k);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(int i = 0; i < k; ++i)
    covariance += (neighbors[i] - center) * (neighbors[i] - center).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> frame(covariance);  // ascending eigenvalues
  const Eigen::Vector3d n = frame.eigenvectors().col(0), u = frame.eigenvectors().col(2),
                        v = frame.eigenvectors().col(1);
  double size = 0;
  for(int i = 0; i < k; ++i)
    size = (std::max)(size, (neighbors[i] - neighbors[0]).norm());
  if(!(size > 0))
    return false;
  // least squares by the fixed-size normal equations: the coordinates are
  // scaled into [-1, 1], where cubic monomials are well enough conditioned
  typedef Eigen::Matrix<double, 10, 1> Monomials;
  std::array<Monomials, 32> rows;
  Eigen::Matrix<double, 10, 10> normal = Eigen::Matrix<double, 10, 10>::Zero();
  Monomials right = Monomials::Zero();
  std::array<double, 32> height;
  for(int i = 0; i < k; ++i)
  {
    const Eigen::Vector3d d = (neighbors[i] - neighbors[0]) / size;
    const double x = d.dot(u), y = d.dot(v);
    height[i] = d.dot(n);
    rows[i] << 1, x, y, x * x, x * y, y * y, x * x * x, x * x * y, x * y * y, y * y * y;
    normal.selfadjointView<Eigen::Lower>().rankUpdate(rows[i]);
    right += height[i] * rows[i];
  }
  const Monomials coefficients_fitted = normal.selfadjointView<Eigen::Lower>().ldlt().solve(right);
  double squared_residual = 0;
  for(int i = 0; i < k; ++i)
    squared_residual += CGAL::square(rows[i].dot(coefficients_fitted) - height[i]);
  variance = squared_residual * size * size / double(k - coefficients);
  spacing = 0;
  for(int i = 1; i <= 6; ++i)
  {
    const Eigen::Vector3d d = neighbors[i] - neighbors[0];
    spacing += std::hypot(d.dot(u), d.dot(v));
  }
  spacing /= 6;
  return true;
}

} // namespace internal

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

The noise of a point sample of a surface, relative to its spacing (the
manual, "Noise"). At every point (points written more than once counted
once; above 100,000 points, at 100,000 of them chosen by their coordinates,
so that any order of the same points gives the same estimate), a cubic
height function is fitted by least squares to the 16 (and 24) nearest
points in their principal frame; the median residual
variance, made unbiased for Gaussian noise, gives the noise. A cubic
follows curvature and its variation, so clean samples of smooth surfaces
read near 0, detailed ones (fine bumps a few spacings wide) 0.011 or less;
Gaussian noise of standard deviation `r` times the spacing reads `r`
within 3% for `r` up to 0.5 (it saturates near 0.7 above). All zero for
fewer than 25 distinct points.
*/
template <class PointRange>
Noise_estimate estimate_noise(const PointRange& points)
{
  typedef typename PointRange::value_type Point;
  typedef typename Kernel_traits<Point>::Kernel Kernel;
  typedef CGAL::Search_traits_3<Kernel> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  const int small = 16, large = 24;
  Noise_estimate estimate;
  // points written more than once are one point of the surface
  std::vector<Point> all(points.begin(), points.end());
  internal::sort_distinct<CGAL::Parallel_if_available_tag>(all.begin(), all.end(), [](const Point& p, const Point& q) {
    return std::make_tuple(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()))
           < std::make_tuple(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
  });
  all.erase(std::unique(all.begin(), all.end()), all.end());
  if(all.size() <= std::size_t(large))
    return estimate;
  typename Search::Tree tree(all.begin(), all.end());
  // built on TBB's threads: the same tree as a serial build
  tree.template build<CGAL::Parallel_if_available_tag>();
  // every point up to noise_sample_size, in the order of their keys (the
  // sums then do not depend on the input's order); above, the points of
  // the smallest keys
  const std::vector<std::size_t> sample = all.size() <= internal::noise_sample_size
                                            ? internal::order_free_permutation(all)
                                            : internal::order_free_sample(all, internal::noise_sample_size);
  struct Fit
  {
    double variance_small = 0, variance_large = 0, spacing = 0;
    bool defined = false;
  };
  std::vector<Fit> fits(sample.size());
  struct Workspace
  {
    std::vector<std::pair<double, Eigen::Vector3d> > hits;  // squared distance, point
    std::vector<Eigen::Vector3d> neighbors;
  };
  internal::for_each_index<CGAL::Parallel_if_available_tag>(sample.size(), []() { return Workspace(); },
                                                            [&](std::size_t i, Workspace& ws) {
    const Point& p = all[sample[i]];
    ws.hits.clear();
    bool self_skipped = false;
    for(const auto& hit : Search(tree, p, large))
    {
      if(!self_skipped && hit.first == p)
      {
        self_skipped = true;
        continue;
      }
      ws.hits.emplace_back(CGAL::to_double(hit.second),
                           Eigen::Vector3d(CGAL::to_double(hit.first.x()), CGAL::to_double(hit.first.y()),
                                           CGAL::to_double(hit.first.z())));
    }
    // neighbors at equal distance in the order of their coordinates, not
    // in the order the tree (built from the input order) gives them
    std::sort(ws.hits.begin(), ws.hits.end(), [](const auto& a, const auto& b) {
      return std::make_tuple(a.first, a.second.x(), a.second.y(), a.second.z())
             < std::make_tuple(b.first, b.second.x(), b.second.y(), b.second.z());
    });
    ws.neighbors.assign(1, Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
    for(const auto& hit : ws.hits)
      ws.neighbors.push_back(hit.second);
    Fit& f = fits[i];
    double ignored = 0;
    f.defined = internal::cubic_fit_residual(ws.neighbors, small, f.variance_small, f.spacing)
                && internal::cubic_fit_residual(ws.neighbors, large, f.variance_large, ignored);
  });
  std::vector<double> variances_small, variances_large;
  double spacing_sum = 0;
  for(const Fit& f : fits)
    if(f.defined)
    {
      variances_small.push_back(f.variance_small);
      variances_large.push_back(f.variance_large);
      spacing_sum += f.spacing;
    }
  if(variances_small.empty() || !(spacing_sum > 0))
    return estimate;
  estimate.spacing = spacing_sum / double(variances_small.size());
  auto sigma = [](std::vector<double>& variances, int k) {
    std::nth_element(variances.begin(), variances.begin() + std::ptrdiff_t(variances.size() / 2), variances.end());
    return std::sqrt(variances[variances.size() / 2] / internal::chi_squared_median_ratio(double(k - 10)));
  };
  estimate.noise = sigma(variances_small, small) / estimate.spacing;
  estimate.noise_24 = sigma(variances_large, large) / estimate.spacing;
  return estimate;
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_NOISE_H
