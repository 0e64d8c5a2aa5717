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
`S = (2 / pi) atan((k1 + k2) / (k1 - k2))` with
`k1 >= k2` (the two are sorted here), in `[-1, 1]`.

The curvatures follow the package's sign convention: positive where the
surface bends away from its outward normal (a sphere with outward normals
has `k1 = k2 = 1 / r`). So `S = 1` on a convex cap (a bump),
-1 on a concave cup (a pit), 1/2 on a ridge (a convex
cylinder), -1/2 on a rut, 0 on a symmetric saddle.
Umbilic points (`k1 = k2 != 0`) get +1 or -1 by their sign.
Flat points (`k1 = k2 = 0`) have no shape index: the result is
NaN, as it is when a curvature is NaN. The shape index does not depend on
the size of the shape: a sphere of any radius has `S = 1`.

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
`C = sqrt((k1^2 + k2^2) / 2) >= 0`, in inverse units of the
points: `1 / r` on a sphere of radius `r`, 0 on a plane. It says
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
