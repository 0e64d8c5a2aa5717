// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_AUTOMATIC_RADIUS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_AUTOMATIC_RADIUS_H

// The automatic neighborhood of the curvature fit (the manual,
// "Neighborhoods"): one of several candidate radii per vertex, chosen from
// the data alone.

#include <CGAL/Conformal_alpha_shapes_3/internal/curvature_fits.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// How many of the smallest candidate radii measure the noise from the
// fits' residuals (when the sample's noise is not known)...
constexpr std::size_t noise_measuring_radii = 4;
// ... and by how much that noise is raised: the pipeline smooths noisy
// points (`denoise()`, jets of 24 to 64 neighbors) before the surface is
// built, which hides most of the noise from the residuals but not from the
// curvature at radii larger than the jets (the manual, "Neighborhoods").
constexpr double residual_noise_factor = 7;
// The bias of the fits grows as r^2: the quadric's correction for the
// fourth order (`quadric_fit()`) leaves the part due to the curvature's
// variation, whose leading term is its second derivatives times r^2 (the
// manual compares r^2, r^3 and r^4).
constexpr double bias_growth_power = 2;
// A fit whose residuals exceed this many times the noise is not a height
// polynomial any more at its radius (the neighborhood wraps around a thin
// part, or holds detail of its own): it and the larger radii are left out,
// which keeps the choice off radii that wrap around a thin tube (the
// manual, section Neighborhoods).
constexpr double polynomial_residual_limit = 3;

// A fit at one of the candidate radii of the automatic rule.
struct Candidate_fit
{
  Local_curvature curvature;
  Quadric_fit_error error;
  double radius;
};

// A straight line y = intercept + slope x fitted by weighted least squares,
// its sums accumulated one point at a time.
struct Weighted_line_fit
{
  double w0 = 0, w1 = 0, w2 = 0, y0 = 0, y1 = 0;  // sums of w, w x, w x^2, w y, w y x

  void add(double x, double y, double w)
  {
    w0 += w;
    w1 += w * x;
    w2 += w * x * x;
    y0 += w * y;
    y1 += w * y * x;
  }
  double determinant() const { return w0 * w2 - w1 * w1; }
  double intercept() const { return (y0 * w2 - y1 * w1) / determinant(); }
  double slope() const { return (w0 * y1 - w1 * y0) / determinant(); }
};

// The noise of the heights around the vertex from the fits' residual
// variances at the smallest candidate radii, s^2(r) = sigma^2 + beta r^10
// (the noise, and the terms that the fit misses), fitted by least squares
// weighted by their inverse variances (degrees of freedom / s^4), sigma^2
// kept between 0 and the widest of these variances.
inline double residual_noise(const std::vector<Candidate_fit>& fits)
{
  const std::size_t measuring = (std::min)(fits.size(), noise_measuring_radii);
  Weighted_line_fit line;
  for(std::size_t i = 0; i < measuring; ++i)
  {
    const Quadric_fit_error& e = fits[i].error;
    if(!(e.degrees_of_freedom >= 1) || !std::isfinite(e.noise))
      continue;
    const double s2 = e.noise * e.noise;
    line.add(std::pow(fits[i].radius / fits[0].radius, 10), s2,
             e.degrees_of_freedom / (s2 * s2 + (std::numeric_limits<double>::min)()));
  }
  const double widest = fits[measuring - 1].error.noise * fits[measuring - 1].error.noise;
  double noise2 = line.determinant() > 0 ? line.intercept() : widest;
  noise2 = std::isfinite(widest) ? (std::min)((std::max)(noise2, 0.), widest) : (std::max)(noise2, 0.);
  return std::sqrt(noise2);
}

// How many of the fits the choice below weighs: those before the first
// whose residuals exceed `polynomial_residual_limit` times the noise.
inline std::size_t weighed_candidates(const std::vector<Candidate_fit>& fits, double sample_noise)
{
  const double residual_limit = polynomial_residual_limit * (std::max)(sample_noise, residual_noise(fits));
  for(std::size_t i = 1; i < fits.size(); ++i)
    if(fits[i].error.noise > residual_limit)
      return i;
  return fits.size();
}

// Whether the choice among `fits` is the choice among any list that starts
// with them (the fits at the larger radii then do not matter): they hold
// the fits that measure the noise, and one past those the choice weighs.
inline bool choice_is_settled(const std::vector<Candidate_fit>& fits, double sample_noise)
{
  return fits.size() >= noise_measuring_radii && weighed_candidates(fits, sample_noise) < fits.size();
}

// The automatic neighborhood, by least expected squared error of the mean
// curvature (a plug-in rule). Each fit's standard error is the noise through
// the fit (`Quadric_fit_error::per_noise`); the noise is the sample's,
// measured before denoising (`sample_noise`, model units), or else the
// residuals' raised by `residual_noise_factor`. The bias is modeled as
// H(r) = H0 + c r^2, c fitted to the fits' mean curvatures by least squares
// weighted by their inverse squared standard errors, and c^2 taken less
// its variance (a c that is noise alone must not read as bias: that would
// keep small, noisy radii). The radius kept minimizes c^2 r^4 + se(r)^2
// (the manual, "Neighborhoods", measures it against the alternatives).
// `fits` holds the defined fits, by increasing radius; at least one.
inline const Candidate_fit& choose_by_least_squared_error(const std::vector<Candidate_fit>& fits,
                                                          double sample_noise = 0)
{
  const double noise = sample_noise > 0 ? sample_noise : residual_noise_factor * residual_noise(fits);
  const std::size_t count = weighed_candidates(fits, sample_noise);

  const double r_max = fits[count - 1].radius;
  std::vector<double> se(count), x(count);
  double w0 = 0, w1 = 0, w2 = 0, h0 = 0, h1 = 0;
  for(std::size_t i = 0; i < count; ++i)
  {
    se[i] = noise * fits[i].error.per_noise;
    x[i] = std::pow(fits[i].radius / r_max, bias_growth_power);
    const double H = (fits[i].curvature.k1 + fits[i].curvature.k2) / 2;
    if(!(se[i] > 0) || !std::isfinite(se[i]) || !std::isfinite(H))
      continue;
    const double w = 1 / (se[i] * se[i]);
    w0 += w;
    w1 += w * x[i];
    w2 += w * x[i] * x[i];
    h0 += w * H;
    h1 += w * H * x[i];
  }
  const double det = w0 * w2 - w1 * w1;
  if(!(det > 0))
    return fits.front();  // no noise measured: the least biased
  const double c = (w0 * h1 - w1 * h0) / det;
  const double c2 = (std::max)(0., c * c - w0 / det);
  std::size_t best = count - 1;
  double least = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < count; ++i)
  {
    const double squared_error = c2 * x[i] * x[i] + se[i] * se[i];
    if(squared_error < least)  // false for an undefined standard error
    {
      least = squared_error;
      best = i;
    }
  }
  return fits[best];
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_AUTOMATIC_RADIUS_H
