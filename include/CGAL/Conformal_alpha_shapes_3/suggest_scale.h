// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_SUGGEST_SCALE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_SUGGEST_SCALE_H

#include <CGAL/Conformal_alpha_shapes_3/internal/solid_scale.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_front.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_report.h>

#include <CGAL/Named_function_parameters.h>

#include <stdexcept>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Surface

The automatic scale of `extract_surface()` with the same
`surface_extraction`: the smallest `a` at which its surface covers the
share `coverage` of the sample.
- `ADVANCING_FRONT`: `Surface_front::suggest_scale()`: `coverage` is the
  share of the front's vertices around which the complex holds a closed fan
  of facets (default 0.99).
- `SOLID_BOUNDARY`: `coverage` is the share of the input points on one
  connected part of the solid's boundary (default 0.9): below the scale at
  which the surface first closes, the walk enters the volume and what is
  left are small closed pockets, each holding few points; at that scale the
  share jumps to nearly all points, so the smallest scale reaching
  `coverage` is the first closed surface. For a sample of several separate
  objects, lower it below the share of the largest object. The scale is
  found among the values of `cas.boundary_facet_alphas()`, by their
  quantiles 5%, 10%, ..., 100% then a bisection to 0.1%; when no quantile
  reaches `coverage`, the one whose surface holds the most points.

The paper's convention, a fixed quantile of the facet values, is
`cas.alpha_at_quantile(q)`.

\cgalNamedParamsBegin
  \cgalParamNBegin{surface_extraction}
    \cgalParamDescription{the method of the surface}
    \cgalParamType{`Surface_extraction`}
    \cgalParamDefault{`ADVANCING_FRONT`}
  \cgalParamNEnd
  \cgalParamNBegin{coverage}
    \cgalParamDescription{the share of the sample the surface must cover (see above)}
    \cgalParamType{`double` in `(0, 1]`}
    \cgalParamDefault{0.99 with `ADVANCING_FRONT`, 0.9 with `SOLID_BOUNDARY`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument when `cas` has dimension below 3 or
`coverage` is outside `(0, 1]` (NaN included).
*/
template <class ConformalAlphaShape, class NamedParameters = CGAL::parameters::Default_named_parameters>
double suggest_scale(const ConformalAlphaShape& cas, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Surface_extraction method = choose_parameter(get_parameter(np, internal_np_cas3::surface_extraction),
                                                     ADVANCING_FRONT);
  const double coverage = choose_parameter(get_parameter(np, internal_np_cas3::coverage),
                                           method == SOLID_BOUNDARY ? 0.9 : 0.99);
  if(cas.dimension() < 3)
    throw std::invalid_argument("suggest_scale: the shape has dimension below 3");
  if(!(coverage > 0 && coverage <= 1))
    throw std::invalid_argument("suggest_scale: coverage must be in (0, 1]");
  if(method == SOLID_BOUNDARY)
    return internal::suggest_solid_scale(cas, coverage);
  return Surface_front<ConformalAlphaShape>(cas).suggest_scale(coverage);
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_SUGGEST_SCALE_H
