// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SCULPTING_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SCULPTING_H

#include <CGAL/Conformal_alpha_shapes_3/internal/flood_fill.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/solid_cells.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// Step 3 of the solid labeling, sculpting: a solid cell with a single
// boundary facet, whose opposite vertex is not on the boundary and whose
// other three facets are in the complex at `alpha`, is carved: the boundary
// then reaches that vertex through facets of the complex. This keeps the
// boundary's manifold vertices manifold (a facet is replaced by a fan of
// three around a vertex that was not on it), and brings onto the surface the
// points that noise put just inside it. Starts from the cells of the
// boundary last collected in `solid` (which it does not collect again);
// returns the number of cells carved.
template <class Cas>
std::size_t sculpt(const Cas& cas, double alpha, Solid_cells<Cas>& solid)
{
  typedef typename Cas::Cell_handle Cell_handle;
  std::vector<int> degree(cas.number_of_vertices(), 0);  // boundary facets per vertex
  std::vector<Cell_handle> work;
  for(const typename Cas::Facet& f : solid.boundary())
  {
    for(int k = 1; k < 4; ++k)
      ++degree[f.first->vertex((f.second + k) & 3)->vertex_index()];
    work.push_back(f.first);
  }
  std::size_t sculpted = 0;
  // depth first: a carved cell's neighbors are tried next (which cells are
  // carved depends on the order)
  flood_fill(work, Flood_order::depth_first, [&](Cell_handle c, auto&& reach) {
    if(!solid.is_solid(c))
      return;
    int boundary_facets = 0, facet = 0;
    for(int i = 0; i < 4; ++i)
      if(!solid.is_solid(c->neighbor(i)))
      {
        ++boundary_facets;
        facet = i;
      }
    if(boundary_facets != 1 || degree[c->vertex(facet)->vertex_index()] > 0)
      return;
    for(int i = 0; i < 4; ++i)
      if(i != facet && !(cas.conformal_alpha(c, i) <= alpha))
        return;
    solid.set_solid(c, false);
    ++sculpted;
    for(int i = 0; i < 4; ++i)
      degree[c->vertex(i)->vertex_index()] += (i == facet) ? 3 : 1;  // -1 for the old facet, +2 for the new ones; 3 for the apex
    for(int i = 0; i < 4; ++i)
      if(i != facet)
        reach(c->neighbor(i));
  });
  return sculpted;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SCULPTING_H
