// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_POINT_CURVATURE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_POINT_CURVATURE_H

// What `transfer_to_points()` gives each input point, in a header of its
// own so that the internal headers that make these values can include it.

#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>

#include <limits>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
Where the values of an input point at one scale come from.
*/
enum Point_source
{
  /// the fit at the point's own vertex of the surface
  SURFACE_VERTEX,
  /// the values of the surface at its point nearest to the input point,
  /// interpolated over the facet there: the point is not a vertex of the
  /// surface, or its own fit is undefined
  NEAREST_SURFACE_POINT,
  /// none: the point is farther from the surface than
  /// `far_from_surface()` local spacings, or the surface
  /// near it has no defined values; every number is NaN
  NO_VALUE
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
The curvature of the surface at one input point, at one scale and
neighborhood; every number is NaN where `source` is `NO_VALUE`.
*/
template <class Kernel>
struct Point_curvature
{
  Point_source source = NO_VALUE;
  /// from the (smoothed) point to the surface point whose values these are
  /// (0 on its own vertex; NaN when the surface is empty)
  double distance = std::numeric_limits<double>::quiet_NaN();
  /// the radius of the neighborhood of the fit (for rings: the farthest
  /// neighbor used); interpolated like the values
  double radius = std::numeric_limits<double>::quiet_NaN();
  typename Kernel::Vector_3 normal = typename Kernel::Vector_3(std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
  typename Kernel::FT mean_curvature = std::numeric_limits<double>::quiet_NaN();
  typename Kernel::FT gaussian_curvature = std::numeric_limits<double>::quiet_NaN();
  /// `max_curvature` is `k1`, `max_direction` `d1`; `min_curvature` is `k2`
  Principal_curvatures_and_directions<Kernel> principal;
  /// the standard uncertainties of `H`, `K` and the normal: those of the
  /// vertex, or interpolated like the values and grown with `distance` (the
  /// manual, section "Uncertainty")
  Curvature_uncertainty<Kernel> uncertainty;

  /// whether the values are the point's own vertex's
  bool on_surface() const { return source == SURFACE_VERTEX; }
};

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// How far, in local spacings, an input point may be from the surface and
/// still take its values in `transfer_to_points()`; the local spacing of a
/// point is the length of its vertex's third-shortest Delaunay edge.
constexpr double far_from_surface() { return 4; }

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_POINT_CURVATURE_H
