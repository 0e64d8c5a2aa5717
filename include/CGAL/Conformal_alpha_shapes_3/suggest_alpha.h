// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_SUGGEST_ALPHA_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_SUGGEST_ALPHA_H

#include <CGAL/Conformal_alpha_shapes_3/extract_boundary_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/flood_fill.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/solid_labeling.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The number of input points on the boundary of the largest connected part
// of the solid (cells connected through facets), counted by points.
template <class Cas>
std::size_t number_of_points_on_largest_part(const Cas& cas, const Solid_labeling<Cas>& solid)
{
  typedef typename Cas::Cell_handle Cell_handle;
  std::vector<int> part(cas.number_of_cells(), -1);
  std::vector<std::size_t> points;         // per part
  std::vector<std::size_t> stamp(cas.number_of_vertices(), std::size_t(-1));
  std::vector<Cell_handle> work;
  for(const typename Cas::Facet& f : solid.boundary())
  {
    if(part[f.first->cell_index()] >= 0)
      continue;
    const int id = int(points.size());
    points.push_back(0);
    part[f.first->cell_index()] = id;
    work.assign(1, f.first);
    // the count does not depend on the order
    flood_fill(work, Flood_order::depth_first, [&](Cell_handle c, auto&& reach) {
      for(int i = 0; i < 4; ++i)
      {
        const Cell_handle n = c->neighbor(i);
        if(solid.is_solid(n))
        {
          if(part[n->cell_index()] < 0)
          {
            part[n->cell_index()] = id;
            reach(n);
          }
          continue;
        }
        for(int k = 1; k < 4; ++k)  // a boundary facet: count its new vertices
        {
          const typename Cas::Vertex_handle v = c->vertex((i + k) & 3);
          if(stamp[v->vertex_index()] != std::size_t(id))
          {
            stamp[v->vertex_index()] = std::size_t(id);
            points.back() += std::size_t(cas.input_indices(v).size());
          }
        }
      }
    });
  }
  return points.empty() ? 0 : *std::max_element(points.begin(), points.end());
}

} // namespace internal

/*!
\ingroup PkgConformalAlphaShapes3Surface

An automatic scale for `extract_boundary_surface()`: the smallest `a` among
the values written by `cas.boundary_facet_alphas()` at which one connected
part of the extracted surface (the boundary of one facet-connected part of
the solid) holds at least the fraction `f` (`minimum_fraction_on_surface`)
of the input points.

Below the scale at which the surface first closes, the outside walk enters
the volume and what is left are small closed pockets, each holding few
points; at that scale the share jumps to nearly all points, and it then
slowly decreases as larger cells cover points. The smallest scale reaching
`f` is therefore the first closed surface: the finest one that represents
the whole sample. For a sample of several separate objects, lower `f`
below the share of the largest object. It is found by a
scan of the quantiles 5%, 10%, ..., 100% of the facet values, then a
bisection on their ranks inside the first bracket that reaches `f` (to 0.1%
of the value). When no quantile reaches `f`, the quantile whose surface
holds the most points is returned.

The paper's convention, a fixed quantile of the same values, is
`cas.alpha_at_quantile(q)`.

\tparam ConformalAlphaShape a `Conformal_alpha_shape_3`
\tparam NamedParameters a sequence of named parameters

\param cas the conformal alpha shape, of dimension 3
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{minimum_fraction_on_surface}
    \cgalParamDescription{the share `f` of the input points the surface must hold}
    \cgalParamType{`double` in `[0, 1]`}
    \cgalParamDefault{0.9}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument when `cas` is empty (dimension below 3), or
when `f` is not in `[0, 1]` (NaN included).
*/
template <class ConformalAlphaShape,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
double suggest_alpha(const ConformalAlphaShape& cas,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef ConformalAlphaShape Cas;
  const double minimum_fraction = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np_cas3::minimum_fraction_on_surface), 0.9);
  if(cas.dimension() < 3)
    throw std::invalid_argument("suggest_alpha: the conformal alpha shape is empty");
  if(!(minimum_fraction >= 0 && minimum_fraction <= 1))
    throw std::invalid_argument("suggest_alpha: minimum_fraction_on_surface must be in [0, 1]");

  std::vector<double> values;
  cas.boundary_facet_alphas(std::back_inserter(values));
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  CGAL_assertion(!values.empty());

  const double n = double(cas.number_of_input_points());
  auto share = [&](std::size_t rank) {
    const internal::Solid_labeling<Cas> solid(cas, values[rank]);
    return double(internal::number_of_points_on_largest_part(cas, solid)) / n;
  };
  auto rank_at = [&](double q) { return std::size_t(q * double(values.size() - 1) + 0.5); };

  std::size_t below = 0, best = 0;
  double best_share = -1;
  for(int step = 1; step <= 20; ++step)
  {
    const std::size_t rank = rank_at(0.05 * step);
    const double s = share(rank);
    if(s >= minimum_fraction)
    {
      // bisection: share(below) < f <= share(above)
      std::size_t above = rank;
      while(above - below > 1 && values[above] > values[below] * (1 + 1e-3))
      {
        const std::size_t middle = below + (above - below) / 2;
        (share(middle) >= minimum_fraction ? above : below) = middle;
      }
      return values[above];
    }
    if(s > best_share)
    {
      best_share = s;
      best = rank;
    }
    below = rank;
  }
  return values[best];
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_SUGGEST_ALPHA_H
