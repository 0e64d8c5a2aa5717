// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_OUTSIDE_WALK_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_OUTSIDE_WALK_H

#include <CGAL/Conformal_alpha_shapes_3/internal/flood_fill.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/solid_cells.h>

#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// Step 1 of the solid labeling, the outside walk: starting from the infinite
// cells, takes out of the solid every cell reached by crossing facets that
// are not in the complex at `alpha` (value > alpha, or NaN). Infinite facets
// are never in the complex (as `classify()` says), whatever `alpha`: at
// `alpha = +infinity` their value, `+infinity`, would otherwise let them
// stand, leave infinite cells in the solid and its boundary outside the
// finite cells (the fuzz finding `solid_labeling_id_of_out_of_range`). The
// cells never reached remain the solid: the `INTERIOR` cells and the pockets
// that the `REGULAR` and `SINGULAR` facets enclose.
template <class Cas>
void walk_from_outside(const Cas& cas, double alpha, Solid_cells<Cas>& solid)
{
  typedef typename Cas::Cell_handle Cell_handle;
  std::vector<Cell_handle> work(1, cas.infinite_cell());
  solid.set_solid(work.back(), false);
  // which cells are reached does not depend on the order
  flood_fill(work, Flood_order::depth_first, [&](Cell_handle c, auto&& reach) {
    for(int i = 0; i < 4; ++i)
    {
      const Cell_handle n = c->neighbor(i);
      if(solid.is_solid(n) && (cas.is_infinite(c, i) || !(cas.conformal_alpha(c, i) <= alpha)))
      {
        solid.set_solid(n, false);
        reach(n);
      }
    }
  });
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_OUTSIDE_WALK_H
