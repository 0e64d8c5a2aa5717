// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_DENOISE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_DENOISE_H

#include <CGAL/Conformal_alpha_shapes_3/estimate_noise.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/jet_smoothing.h>

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
  AUTOMATIC_DENOISING,  ///< when `Noise_estimate::calls_for_denoising()`
  ALWAYS_DENOISE,
  NEVER_DENOISE
};

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// How the points are smoothed: `passes` projections of every point onto a
/// degree 2 jet fitted to it and its `neighbors` nearest neighbors (what
/// CGAL's `jet_smooth_point_set()` does with its default degrees, by the
/// package's own faster fit: see `denoise()`); no smoothing when `passes` is 0.
struct Denoising_plan
{
  unsigned int neighbors = 0;
  int passes = 0;
  /// The radius, in sample spacings, over which the passes average the
  /// noise (0 without smoothing): `0.78 sqrt(neighbors)` for one pass,
  /// growing as the fourth root of the passes, both measured on analytic
  /// surfaces under noise by the calibration of the uncertainties (the
  /// manual, "Uncertainty"). Times the spacing, what the named parameter
  /// `smoothing_radius` of `estimate_vertex_curvatures()` takes.
  double smoothing_radius_in_spacings() const
  {
    return passes > 0 ? 0.78 * std::sqrt(double(neighbors)) * std::pow(double(passes), 0.25) : 0.;
  }
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
The smoothing for a noise level `noise` (relative to the spacing): one
pass with `max(24, 500 noise)` neighbors up to 64 neighbors, then two
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
The smoothing that `mode` asks for on points whose noise is `estimate`:
none with `NEVER_DENOISE`, or with `AUTOMATIC_DENOISING` when
`estimate.calls_for_denoising()` is false; otherwise
`denoising_plan(estimate.noise)` with at least one pass, and `neighbors`
neighbors when it is not 0, else at least 24.
*/
inline Denoising_plan denoising_plan(const Noise_estimate& estimate, Denoising mode, unsigned int neighbors = 0)
{
  if(mode == NEVER_DENOISE || (mode == AUTOMATIC_DENOISING && !estimate.calls_for_denoising()))
    return Denoising_plan();
  Denoising_plan plan = denoising_plan(estimate.noise);
  plan.passes = (std::max)(plan.passes, 1);
  plan.neighbors = neighbors != 0 ? neighbors : (std::max)(plan.neighbors, 24u);
  return plan;
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
neighbors coincident, on a line, or on one conic of their plane) stays
where it is; nothing moves when there are no more distinct points than
neighbors.
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
