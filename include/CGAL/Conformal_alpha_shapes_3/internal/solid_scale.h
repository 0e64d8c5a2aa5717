// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_SCALE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_SCALE_H

#include <CGAL/Conformal_alpha_shapes_3/internal/flood_fill.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/solid_labeling.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
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

// `suggest_scale()` with `SOLID_BOUNDARY`: the smallest `a` among the
// values of `cas.boundary_facet_alphas()` at which one part of the solid's
// boundary holds the share `coverage` of the input points (the first closed
// surface; the pockets below it hold few points each), found by a scan of
// the quantiles 5%, 10%, ..., 100% of those values and a bisection on their
// ranks inside the first bracket that reaches it, to 0.1% of the value; the
// quantile holding the most points when none reaches it.
template <class ConformalAlphaShape>
double suggest_solid_scale(const ConformalAlphaShape& cas, double coverage)
{
  typedef ConformalAlphaShape Cas;
  std::vector<double> values;
  cas.boundary_facet_alphas(std::back_inserter(values));
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  CGAL_assertion(!values.empty());

  const double n = double(cas.number_of_input_points());
  auto share = [&](std::size_t rank) {
    const Solid_labeling<Cas> solid(cas, values[rank]);
    return double(number_of_points_on_largest_part(cas, solid)) / n;
  };
  auto rank_at = [&](double q) { return std::size_t(q * double(values.size() - 1) + 0.5); };

  std::size_t below = 0, best = 0;
  double best_share = -1;
  for(int step = 1; step <= 20; ++step)
  {
    const std::size_t rank = rank_at(0.05 * step);
    const double s = share(rank);
    if(s >= coverage)
    {
      // bisection: share(below) < coverage <= share(above)
      std::size_t above = rank;
      while(above - below > 1 && values[above] > values[below] * (1 + 1e-3))
      {
        const std::size_t middle = below + (above - below) / 2;
        (share(middle) >= coverage ? above : below) = middle;
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

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_SCALE_H
