// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_DENOISE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_DENOISE_H

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>

#include <CGAL/Euclidean_distance.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <CGAL/number_utils.h>

#include <Eigen/Dense>


#include <algorithm>
#include <type_traits>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// Whether the points are smoothed before the shape is built.
enum Denoising
{
  AUTOMATIC_DENOISING,  ///< when `Noise_estimate::calls_for_denoising()`
  ALWAYS_DENOISE,
  NEVER_DENOISE
};

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// What `estimate_noise()` measured.
struct Noise_estimate
{
  /// the mean distance from a point to its 6 nearest neighbours, measured
  /// in the local tangent plane (so that noise does not inflate it), in model units
  double spacing = 0;
  /// the standard deviation of the points' offsets from a local cubic
  /// surface fitted to 16 neighbours, as a multiple of `spacing`
  double noise = 0;
  /// the same with 24 neighbours: noise reads the same at both sizes,
  /// surface detail that the sampling does not resolve grows with the size
  double noise_24 = 0;

  /// Whether automatic denoising smooths the points: the noise exceeds
  /// 0.02 (below it the interpolating surface does not fold; clean samples
  /// read 0.011 or less, even with detail) and does not grow by more than
  /// 30% from 16 to 24 neighbours (which would mark unresolved detail).
  bool calls_for_denoising() const { return noise > 0.02 && noise_24 <= 1.3 * noise; }
};

namespace internal {

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
// 6 nearest. Returns false on a degenerate neighbourhood.
inline bool cubic_fit_residual(const std::vector<Eigen::Vector3d>& neighbors, int k,
                               double& variance, double& spacing)
{
  const int coefficients = 10;
  if(int(neighbors.size()) < k || k <= coefficients || k > 32)
    return false;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for(int i = 0; i < k; ++i)
    centre += neighbors[i];
  centre /= double(k);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(int i = 0; i < k; ++i)
    covariance += (neighbors[i] - centre) * (neighbors[i] - centre).transpose();
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

// Degree-2 jet smoothing of one point, the meaning of CGAL's
// `jet_smooth_point_set()` with degree 2 jets and degree 2 Monge forms:
// `offsets` are the query point's nearest points (itself included) less the
// query point; in their principal frame (the normal along the smallest
// eigenvalue of their covariance) a quadratic height function
// z = a0 + a1 x + a2 y + a3 x^2 + a4 x y + a5 y^2 is fitted by least
// squares, and the query point moves to the fitted surface above it, by a0
// along the normal (the Monge origin). Fixed-size normal equations on the
// moments of x, y scaled by their root mean square (the monomials are then
// of order 1). Returns false, leaving `shift` alone, when the fit is
// degenerate: coincident or collinear points, or points on one conic of the
// tangent plane (the quadratic not determined).
inline bool quadratic_jet_shift(const Eigen::Vector3d* offsets, std::size_t count, Eigen::Vector3d& shift)
{
  if(count < 6)
    return false;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for(std::size_t i = 0; i < count; ++i)
    mean += offsets[i];
  mean /= double(count);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(std::size_t i = 0; i < count; ++i)
  {
    const Eigen::Vector3d d = offsets[i] - mean;
    covariance.noalias() += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> frame;
  frame.computeDirect(covariance);  // ascending eigenvalues, as CGAL's diagonalization
  const Eigen::Vector3d& values = frame.eigenvalues();
  if(!(values(2) > 0) || !(values(1) > 1e-12 * values(2)) || !std::isfinite(values(2)))
    return false;  // coincident or collinear: no tangent plane
  const Eigen::Vector3d n = frame.eigenvectors().col(0), u = frame.eigenvectors().col(2),
                        v = frame.eigenvectors().col(1);
  double tangential = 0;
  for(std::size_t i = 0; i < count; ++i)
    tangential += CGAL::square(offsets[i].dot(u)) + CGAL::square(offsets[i].dot(v));
  if(!(tangential > 0))
    return false;
  const double scale = 1.0 / std::sqrt(tangential / double(count));
  // moments x^a y^b (a + b <= 4) and z x^a y^b (a + b <= 2)
  double m00 = 0, m10 = 0, m01 = 0, m20 = 0, m11 = 0, m02 = 0, m30 = 0, m21 = 0, m12 = 0, m03 = 0,
         m40 = 0, m31 = 0, m22 = 0, m13 = 0, m04 = 0;
  double z00 = 0, z10 = 0, z01 = 0, z20 = 0, z11 = 0, z02 = 0;
  for(std::size_t i = 0; i < count; ++i)
  {
    const double x = offsets[i].dot(u) * scale, y = offsets[i].dot(v) * scale, z = offsets[i].dot(n);
    const double xx = x * x, xy = x * y, yy = y * y;
    m00 += 1; m10 += x; m01 += y; m20 += xx; m11 += xy; m02 += yy;
    m30 += xx * x; m21 += xx * y; m12 += x * yy; m03 += yy * y;
    m40 += xx * xx; m31 += xx * xy; m22 += xx * yy; m13 += xy * yy; m04 += yy * yy;
    z00 += z; z10 += z * x; z01 += z * y; z20 += z * xx; z11 += z * xy; z02 += z * yy;
  }
  // monomials 1, x, y, x^2, x y, y^2
  Eigen::Matrix<double, 6, 6> normal;
  normal << m00, m10, m01, m20, m11, m02,
            m10, m20, m11, m30, m21, m12,
            m01, m11, m02, m21, m12, m03,
            m20, m30, m21, m40, m31, m22,
            m11, m21, m12, m31, m22, m13,
            m02, m12, m03, m22, m13, m04;
  Eigen::Matrix<double, 6, 1> right;
  right << z00, z10, z01, z20, z11, z02;
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(normal);
  const Eigen::Matrix<double, 6, 1> pivots = solver.vectorD();
  if(solver.info() != Eigen::Success || !(pivots.minCoeff() > 1e-10 * pivots.maxCoeff()))
    return false;  // the quadratic is not determined by these points
  const double height = solver.solve(right)(0);
  if(!std::isfinite(height))
    return false;
  shift = height * n;
  return true;
}

// One pass of degree-2 jet smoothing: `smoothed[i]` is `points[i]` (which
// must be distinct) moved onto the jet fitted to its `k` nearest neighbours
// and itself (CGAL's convention: `k + 1` points), or left in place when that
// fit is degenerate. Each result depends only on `points`: the parallel
// run (with TBB) gives the serial run's result bit for bit. Neighbours from a
// kd-tree (`Orthogonal_k_neighbor_search`); the points should be in a
// spatial order (queries in that order hit the cache).
template <class ConcurrencyTag, class Point>
void jet_smooth_pass(const std::vector<Point>& points, unsigned int k, std::vector<Point>& smoothed)
{
  typedef typename Kernel_traits<Point>::Kernel Kernel;
  typedef CGAL::Search_traits_3<Kernel> Traits;
  typedef CGAL::Sliding_midpoint<Traits> Splitter;
  typedef CGAL::Kd_tree<Traits, Splitter, CGAL::Tag_true, CGAL::Tag_true> Tree;
  typedef CGAL::Euclidean_distance<Traits> Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance, Splitter, Tree> Search;
  smoothed = points;
  if(points.size() <= std::size_t(k))
    return;
  Tree tree(points.begin(), points.end(), Splitter(16));  // buckets of 16: a little faster than 10 at k = 24..64
  tree.build();
  internal::for_each_index<ConcurrencyTag>(points.size(),
    [k]() {
      std::vector<Eigen::Vector3d> offsets;
      offsets.reserve(std::size_t(k) + 1);
      return offsets;
    },
    [&](std::size_t i, std::vector<Eigen::Vector3d>& offsets) {
      const Point& p = points[i];
      const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y()), pz = CGAL::to_double(p.z());
      offsets.clear();
      // unsorted (the sort took a quarter of the search): the hits come in
      // the search's own order, the same on every run
      const Search search(tree, p, k + 1, 0, true, Distance(), false);
      for(const auto& hit : search)
        offsets.emplace_back(CGAL::to_double(hit.first.x()) - px, CGAL::to_double(hit.first.y()) - py,
                             CGAL::to_double(hit.first.z()) - pz);
      Eigen::Vector3d shift;
      if(quadratic_jet_shift(offsets.data(), offsets.size(), shift))
        smoothed[i] = Point(px + shift(0), py + shift(1), pz + shift(2));
    });
}

// `passes` passes of `jet_smooth_pass()` over `points` (distinct), in
// place; the points are visited in Hilbert order (found once: the
// results do not depend on the order, the time does).
template <class ConcurrencyTag, class Point>
void jet_smooth_points(std::vector<Point>& points, unsigned int k, int passes)
{
  typedef typename Kernel_traits<Point>::Kernel Kernel;
  typedef CGAL::Spatial_sort_traits_adapter_3<Kernel, typename CGAL::Pointer_property_map<Point>::type>
    Sort_traits;
  if(passes <= 0 || points.size() <= std::size_t(k))
    return;
  std::vector<std::size_t> order(points.size());
  for(std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  CGAL::hilbert_sort(order.begin(), order.end(), Sort_traits(CGAL::make_property_map(points)));
  std::vector<Point> current(points.size()), smoothed;
  for(std::size_t i = 0; i < order.size(); ++i)
    current[i] = points[order[i]];
  for(int pass = 0; pass < passes; ++pass)
  {
    jet_smooth_pass<ConcurrencyTag>(current, k, smoothed);
    current.swap(smoothed);
  }
  for(std::size_t i = 0; i < order.size(); ++i)
    points[order[i]] = current[i];
}

} // namespace internal

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

The noise of a point sample of a surface, relative to its spacing (the
manual, "Noise"). At up to 2000 points spread over the sample, a cubic
height function is fitted by least squares to the 16 (and 24) nearest
points in their principal frame; the median residual variance, made
unbiased for Gaussian noise, gives the noise. A cubic follows curvature and
its variation, so clean samples of smooth surfaces read near 0, detailed
ones (fine bumps a few spacings wide) 0.011 or less; Gaussian noise of
standard deviation `r` times the spacing reads `r` within 3% for `r` up to
0.5 (it saturates near 0.7 above). All zero for fewer than 25 points.
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
  const std::vector<Point> all(points.begin(), points.end());
  if(all.size() <= std::size_t(large))
    return estimate;
  const typename Search::Tree tree(all.begin(), all.end());
  const std::size_t samples = (std::min)(all.size(), std::size_t(2000));
  std::vector<double> variances_small, variances_large;
  double spacing_sum = 0;
  std::vector<Eigen::Vector3d> neighbors;
  for(std::size_t s = 0; s < samples; ++s)
  {
    const Point& p = all[s * all.size() / samples];
    neighbors.assign(1, Eigen::Vector3d(p.x(), p.y(), p.z()));
    bool self_skipped = false;
    for(const auto& hit : Search(tree, p, large))
    {
      if(!self_skipped && hit.first == p)
      {
        self_skipped = true;
        continue;
      }
      neighbors.emplace_back(hit.first.x(), hit.first.y(), hit.first.z());
    }
    double variance_small = 0, variance_large = 0, spacing = 0, ignored = 0;
    if(!internal::cubic_fit_residual(neighbors, small, variance_small, spacing)
       || !internal::cubic_fit_residual(neighbors, large, variance_large, ignored))
      continue;
    variances_small.push_back(variance_small);
    variances_large.push_back(variance_large);
    spacing_sum += spacing;
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

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// How the points are smoothed: `passes` projections of every point onto a
/// degree 2 jet fitted to it and its `neighbors` nearest neighbours (what
/// CGAL's `jet_smooth_point_set()` does with its default degrees, by the
/// package's own faster fit: see `denoise()`); no smoothing when `passes` is 0.
struct Denoising_plan
{
  unsigned int neighbors = 0;
  int passes = 0;
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
The smoothing for a noise level `noise` (relative to the spacing): one
pass with `max(24, 500 noise)` neighbours up to 64 neighbours, then two
passes with `max(24, 200 noise)`, then three with 64. After one pass the
remaining roughness is about `5 noise / neighbors` times the spacing, after
two about `2 noise / neighbors`: the plan keeps it near 0.01, below the
0.02 at which the surface folds, with the largest single pass first (it
keeps detail better than repeating a small one).
*/
inline Denoising_plan denoising_plan(double noise)
{
  Denoising_plan plan;
  if(!(noise > 0))
    return plan;
  if(500 * noise <= 64)
    return Denoising_plan{(std::max)(24u, (unsigned int)std::ceil(500 * noise)), 1};
  if(200 * noise <= 64)
    return Denoising_plan{(std::max)(24u, (unsigned int)std::ceil(200 * noise)), 2};
  return Denoising_plan{64, 3};
}

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
Smooths `points` in place as `plan` says. Each pass moves every point onto
the degree 2 jet (a quadratic height function over the principal plane,
fitted by least squares) of itself and its `plan.neighbors` nearest
points, to the jet's point above it, from the positions of the previous
pass: the meaning of CGAL's `jet_smooth_point_set()` with degree 2 jets and
Monge forms (the same points to rounding, about 1e-12 spacings), computed
by fixed-size normal equations instead of its general jet fitting, with
unsorted kd-tree searches in Hilbert order: 8 to 10 times less processor
time (the manual, "Noise"). With TBB (`CGAL_LINKED_WITH_TBB`) the points of
a pass are smoothed in parallel, with the serial result bit for bit.
Coincident points are smoothed once, as one (a jet fitted to copies of one
point is undefined); a point whose fit is degenerate anyway (its
neighbours coincident, on a line, or on one conic of their plane) stays
where it is; nothing moves when there are no more distinct points than
neighbours.
*/
template <class PointRange>
void denoise(PointRange& points, const Denoising_plan& plan)
{
  typedef typename PointRange::value_type Point;
  std::vector<Point> distinct(points.begin(), points.end());
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if(plan.passes == 0 || distinct.size() <= plan.neighbors)
    return;
  std::vector<Point> smoothed = distinct;
  internal::jet_smooth_points<CGAL::Parallel_if_available_tag>(smoothed, plan.neighbors, plan.passes);
  for(Point& p : points)
  {
    const std::size_t i = std::size_t(std::lower_bound(distinct.begin(), distinct.end(), p) - distinct.begin());
    const Point& q = smoothed[i];
    if(std::isfinite(q.x()) && std::isfinite(q.y()) && std::isfinite(q.z()))
      p = q;
  }
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_DENOISE_H
