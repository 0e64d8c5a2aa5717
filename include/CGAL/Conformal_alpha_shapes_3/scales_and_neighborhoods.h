// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_SCALES_AND_NEIGHBORHOODS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_SCALES_AND_NEIGHBORHOODS_H

// The vocabulary of a layer of multi-scale curvature: the scale `a` of the
// surface and the neighborhood of the fit.

#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
A requested internal scale `a`: an absolute value, a quantile of the facet
values (the paper's "10%, 25%, 35%, 50%", see
`Conformal_alpha_shape_3::alpha_at_quantile()`), or automatic
(`suggest_scale()`, or `suggest_alpha()` for the solid boundary).
*/
class Scale
{
public:
  enum Kind { ABSOLUTE, QUANTILE, AUTOMATIC };

  static Scale absolute(double a) { return Scale(ABSOLUTE, a); }
  static Scale quantile(double q) { return Scale(QUANTILE, q); }
  static Scale automatic() { return Scale(AUTOMATIC, 0); }

  Kind kind() const { return m_kind; }
  /// the absolute value or the quantile in `[0, 1]`
  double value() const { return m_value; }

private:
  Scale(Kind kind, double value) : m_kind(kind), m_value(value) {}
  Kind m_kind;
  double m_value;
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
The neighborhood of the curvature fit (see `estimate_vertex_curvatures()`):
a ring size, a radius in model units, a radius in multiples of the
measured sample spacing (`Noise_estimate::spacing`), or automatic: per
point, one of the radii `automatic_radii()` times the spacing, chosen from
the data alone.
*/
class Neighborhood
{
public:
  enum Kind { RINGS, RADIUS, SPACINGS, AUTOMATIC };

  static Neighborhood rings(int k) { return Neighborhood(RINGS, k); }
  static Neighborhood radius(double r) { return Neighborhood(RADIUS, r); }
  static Neighborhood spacings(double m) { return Neighborhood(SPACINGS, m); }
  static Neighborhood automatic() { return Neighborhood(AUTOMATIC, 0); }

  /// The candidates of the automatic choice, in spacings: 2 to 11.3 by
  /// factors of the square root of 2, then to 22.6 by factors of its
  /// square root: the larger radii, where noisy samples are fitted, are
  /// sampled more finely (the manual, section Neighborhoods, compares the
  /// steps).
  static std::vector<double> automatic_radii() { return {2, 2.83, 4, 5.66, 8, 11.3, 13.45, 16, 19, 22.6}; }

  Kind kind() const { return m_kind; }
  /// the ring size, the radius or the number of spacings
  double value() const { return m_value; }

private:
  Neighborhood(Kind kind, double value) : m_kind(kind), m_value(value) {}
  Kind m_kind;
  double m_value;
};

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// The scales of `multiscale_curvatures()` and of the program when none are
/// named: the automatic one (see the manual for why coarser conformal scales
/// are not in the default: above the automatic scale the advancing front
/// gives nearly the same surface; the neighborhood radius is what coarsens).
inline std::vector<Scale> default_scales() { return {Scale::automatic()}; }

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// The neighborhoods of `multiscale_curvatures()` and of the program when
/// none are named: the automatic one, then radii of 2, 4, 8 and 16 sample
/// spacings, from the finest detail to a summary of larger regions.
inline std::vector<Neighborhood> default_neighborhoods()
{
  return {Neighborhood::automatic(), Neighborhood::spacings(2), Neighborhood::spacings(4),
          Neighborhood::spacings(8), Neighborhood::spacings(16)};
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_SCALES_AND_NEIGHBORHOODS_H
