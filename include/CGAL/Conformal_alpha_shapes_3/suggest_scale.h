// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_SUGGEST_SCALE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_SUGGEST_SCALE_H

#include <CGAL/Conformal_alpha_shapes_3/internal/advancing_front_facets.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// `suggest_scale()` from the soup grown with no bound: the `coverage`
// quantile over its vertices of the largest value among their faces.
inline double suggest_scale(const Advancing_front_soup& soup, double coverage)
{
  std::vector<double> closing(soup.shape_vertex.size(), 0.0);
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
    for(std::size_t s : soup.triangles[t])
      closing[s] = (std::max)(closing[s], soup.values[t]);
  if(closing.empty())
    return std::numeric_limits<double>::infinity();
  const std::size_t k = std::min(closing.size() - 1, std::size_t(coverage * double(closing.size())));
  std::nth_element(closing.begin(), closing.begin() + std::ptrdiff_t(k), closing.end());
  return closing[k];
}

} // namespace internal

/*!
\ingroup PkgConformalAlphaShapes3Surface

The automatic scale of `extract_surface()`: the smallest `a` at which the
surface covers the points. The surface is first grown with no bound on the
scale; each of its vertices then needs the largest conformal value among its
faces for its whole umbrella to be in the complex, and the scale returned is
the `coverage` quantile of those values over the vertices. At that scale,
that share of the surface's vertices has its full umbrella, and the rest (a
border that would need larger facets, gaps in the sampling) is left as a
border rather than bridged. On samples of closed or open surfaces, clean or
noisy (after denoising), the surface at this scale holds over 99% of the
points (the manual gives the measurements). It fails where the sample does
not describe a surface at all (a volume of points, scattered noise): then
the surface grown without bound is itself poor, and so is the scale.

\param cas a `Conformal_alpha_shape_3` of dimension 3
\param coverage the share of vertices whose umbrella must be complete, in `(0, 1]`
\throws std::invalid_argument when `cas` has dimension below 3 or `coverage` is outside `(0, 1]`
*/
template <class ConformalAlphaShape>
double suggest_scale(const ConformalAlphaShape& cas, double coverage = 0.99)
{
  if(cas.dimension() < 3)
    throw std::invalid_argument("suggest_scale: the shape has dimension below 3");
  if(!(coverage > 0 && coverage <= 1))
    throw std::invalid_argument("suggest_scale: coverage must be in (0, 1]");
  return internal::suggest_scale(internal::advancing_front_soup(cas), coverage);
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_SUGGEST_SCALE_H
