// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_SHAPE_INDEX_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_SHAPE_INDEX_H

#include <cmath>
#include <limits>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Curvature

Koenderink's shape index of a surface point from its principal curvatures:
\f$ S = \frac{2}{\pi} \arctan \frac{k_1 + k_2}{k_1 - k_2} \f$ with
\f$ k_1 \ge k_2 \f$ (the two are sorted here), in \f$ [-1, 1] \f$.

The curvatures follow the package's sign convention: positive where the
surface bends away from its outward normal (a sphere with outward normals
has \f$ k_1 = k_2 = 1/r \f$). So \f$ S = 1 \f$ on a convex cap (a bump),
\f$ -1 \f$ on a concave cup (a pit), \f$ 1/2 \f$ on a ridge (a convex
cylinder), \f$ -1/2 \f$ on a rut, \f$ 0 \f$ on a symmetric saddle.
Umbilic points (\f$ k_1 = k_2 \ne 0 \f$) get \f$ \pm 1 \f$ by their sign.
Flat points (\f$ k_1 = k_2 = 0 \f$) have no shape index: the result is
NaN, as it is when a curvature is NaN. The shape index does not depend on
the size of the shape: a sphere of any radius has \f$ S = 1 \f$.

J. J. Koenderink and A. J. van Doorn, "Surface shape and curvature
scales", Image and Vision Computing 10(8), 1992, 557-564.

\tparam FT a floating-point number type
*/
template <typename FT>
FT shape_index(FT k1, FT k2)
{
  if(std::isnan(k1) || std::isnan(k2) || (k1 == FT(0) && k2 == FT(0)))
    return std::numeric_limits<FT>::quiet_NaN();
  const FT hi = k1 < k2 ? k2 : k1;
  const FT lo = k1 < k2 ? k1 : k2;
  return FT(2) / FT(3.14159265358979323846) * std::atan2(hi + lo, hi - lo);
}

/*!
\ingroup PkgConformalAlphaShapes3Curvature

Koenderink's curvedness of a surface point from its principal curvatures:
\f$ C = \sqrt{(k_1^2 + k_2^2) / 2} \ge 0 \f$, in inverse units of the
points: \f$ 1/r \f$ on a sphere of radius \f$ r \f$, 0 on a plane. It says
how much the surface bends, whatever its shape (`shape_index()`); NaN in,
NaN out.

\tparam FT a floating-point number type
*/
template <typename FT>
FT curvedness(FT k1, FT k2)
{
  return std::sqrt((k1 * k1 + k2 * k2) / FT(2));
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_SHAPE_INDEX_H
