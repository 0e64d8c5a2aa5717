// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_DENOISE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_DENOISE_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/jet_smooth_point_set.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// Whether the points are smoothed before the shape is built.
enum Denoising
{
  AUTOMATIC_DENOISING,  ///< when `estimate_noise()` exceeds `noise_threshold()`
  ALWAYS_DENOISE,
  NEVER_DENOISE
};

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// The noise level, relative to the sample spacing, above which automatic
/// denoising smooths the points: above it the interpolating surface folds
/// (the manual, "Noise").
inline double noise_threshold() { return 0.03; }

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// The number of neighbours of the jet fit that smooths the points.
inline unsigned int default_denoising_neighbors() { return 32; }

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

The noise of a point sample of a surface, as a multiple of its spacing: the
median, over up to 4096 points spread over the sample, of the residual of a
least-squares quadric height function fitted to the 16 nearest neighbours
(corrected for the 6 fitted coefficients), divided by the local spacing
`sqrt(pi r^2 / 16)`, `r` being the distance to the 16th neighbour (the
spacing `sqrt(area / n)` of a uniform sample). A quadric follows the
surface's curvature, so a clean sample reads near 0 however curved; Gaussian
noise of standard deviation `s` times the spacing reads about `s`.
Returns 0 for fewer than 17 points.
*/
template <class PointRange>
double estimate_noise(const PointRange& points)
{
  typedef typename PointRange::value_type Point;
  typedef typename Kernel_traits<Point>::Kernel Kernel;
  typedef CGAL::Search_traits_3<Kernel> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  const unsigned int k = 16;
  const std::size_t n = std::size_t(std::distance(points.begin(), points.end()));
  if(n <= k)
    return 0;
  const typename Search::Tree tree(points.begin(), points.end());
  const std::size_t samples = std::min<std::size_t>(n, 4096);
  std::vector<double> ratios;
  ratios.reserve(samples);
  std::vector<Eigen::Vector3d> neighbors;
  for(std::size_t s = 0; s < samples; ++s)
  {
    const Point& p = *std::next(points.begin(), std::ptrdiff_t(s * n / samples));
    neighbors.clear();
    double farthest = 0;
    for(const auto& hit : Search(tree, p, k))
    {
      neighbors.emplace_back(hit.first.x(), hit.first.y(), hit.first.z());
      farthest = (std::max)(farthest, hit.second);
    }
    if(neighbors.size() < k || !(farthest > 0))
      continue;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for(const Eigen::Vector3d& q : neighbors)
      centre += q;
    centre /= double(k);
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for(const Eigen::Vector3d& q : neighbors)
      covariance += (q - centre) * (q - centre).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> frame(covariance);
    // height along the smallest eigenvector, as a quadric in the other two
    Eigen::Matrix<double, Eigen::Dynamic, 6> design(k, 6);
    Eigen::VectorXd height(k);
    for(unsigned int i = 0; i < k; ++i)
    {
      const Eigen::Vector3d d = neighbors[i] - centre;
      const double u = d.dot(frame.eigenvectors().col(2)), v = d.dot(frame.eigenvectors().col(1));
      design.row(i) << 1, u, v, u * u, u * v, v * v;
      height(i) = d.dot(frame.eigenvectors().col(0));
    }
    const Eigen::VectorXd residual = height - design * design.colPivHouseholderQr().solve(height);
    const double sigma = std::sqrt(residual.squaredNorm() / double(k - 6));
    const double spacing = std::sqrt(M_PI * farthest / double(k));  // `farthest` is a squared distance
    ratios.push_back(sigma / spacing);
  }
  if(ratios.empty())
    return 0;
  std::nth_element(ratios.begin(), ratios.begin() + std::ptrdiff_t(ratios.size() / 2), ratios.end());
  return ratios[ratios.size() / 2];
}

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// Smooths `points` in place by projecting each onto a jet (a quadric) fitted
/// to its `neighbors` nearest neighbours (CGAL's `jet_smooth_point_set()`).
template <class PointRange>
void denoise(PointRange& points, unsigned int neighbors = default_denoising_neighbors())
{
  if(std::size_t(std::distance(points.begin(), points.end())) > neighbors)
    CGAL::jet_smooth_point_set<CGAL::Sequential_tag>(points, neighbors);
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_DENOISE_H
