// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_AUTOMATIC_RADIUS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_AUTOMATIC_RADIUS_H

// The automatic neighborhood of the curvature fit (the manual,
// "Neighborhoods"): one of several candidate radii per vertex, chosen from
// the fits' residuals alone.

#include <CGAL/Conformal_alpha_shapes_3/internal/curvature_fits.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The half-width
// of the intervals of the mean curvature, in standard errors computed as if
// the heights' errors were independent. Wide, because they are not: the
// pipeline smooths noisy points (`denoise()`, jets of 24 to 64 neighbors)
// before the surface is built, which leaves errors correlated over about
// that many points (about 7 times the independent standard error) and hides
// them from the residuals. Measured on the ellipsoid and torus at 20k points
// with noise 0.1 spacing (evaluate_surfaces): with 2 the median radius is 4
// spacings and the median H error 15% and 8% (best fixed radius: 4.2%,
// 4.1%); 8 to 14 gives 5.2% to 5.6%; 25 and above grow too far. The cost:
// clean bumps about 6 spacings wide read as noise and are smoothed away.
constexpr double mean_curvature_interval_width = 10;
// ... and how many of the smallest candidate radii measure the noise.
constexpr std::size_t noise_measuring_radii = 4;

// A fit at one of the candidate radii of the automatic rule.
struct Candidate_fit
{
  Local_curvature curvature;
  Quadric_fit_error error;
  double radius;
};

// The automatic neighborhood: the vertex's noise is measured from the
// residual variances of the fits at the smallest candidate radii,
// s^2(r) = sigma^2 + beta r^6 (the noise, and the cubic terms that a
// quadric misses), fitted by least squares weighted by their inverse
// variances (degrees of freedom / s^4), sigma^2 kept between 0 and the
// widest of these variances (clean samples read about 0: their residuals
// grow as r^3); then the largest radius is kept whose confidence interval
// of the mean curvature (that noise through each fit) still meets those of
// all smaller ones (the intersection of confidence intervals rule): beyond
// it the fit's bias outgrows its noise. `fits` holds the defined fits, by
// increasing radius; at least one.
inline const Candidate_fit& choose_by_confidence_intervals(const std::vector<Candidate_fit>& fits)
{
  const std::size_t measuring = (std::min)(fits.size(), noise_measuring_radii);
  double s00 = 0, s01 = 0, s11 = 0, t0 = 0, t1 = 0;
  for(std::size_t i = 0; i < measuring; ++i)
  {
    const Quadric_fit_error& e = fits[i].error;
    if(!(e.degrees_of_freedom >= 1) || !std::isfinite(e.noise))
      continue;
    const double s2 = e.noise * e.noise;
    const double x = std::pow(fits[i].radius / fits[0].radius, 6);
    const double w = e.degrees_of_freedom / (s2 * s2 + (std::numeric_limits<double>::min)());
    s00 += w;
    s01 += w * x;
    s11 += w * x * x;
    t0 += w * s2;
    t1 += w * s2 * x;
  }
  const double det = s00 * s11 - s01 * s01;
  const double widest = fits[measuring - 1].error.noise * fits[measuring - 1].error.noise;
  double noise2 = det > 0 ? (t0 * s11 - t1 * s01) / det : widest;
  noise2 = std::isfinite(widest) ? (std::min)((std::max)(noise2, 0.), widest) : (std::max)(noise2, 0.);
  const double noise = std::sqrt(noise2);
  std::size_t chosen = 0;
  double low = -std::numeric_limits<double>::infinity(), high = -low;
  for(std::size_t i = 0; i < fits.size(); ++i)
  {
    const double H = (fits[i].curvature.k1 + fits[i].curvature.k2) / 2;
    const double se = noise * fits[i].error.per_noise;
    low = (std::max)(low, H - mean_curvature_interval_width * se);
    high = (std::min)(high, H + mean_curvature_interval_width * se);
    if(i > 0 && !(low <= high))
      break;
    chosen = i;
  }
  return fits[chosen];
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_AUTOMATIC_RADIUS_H
