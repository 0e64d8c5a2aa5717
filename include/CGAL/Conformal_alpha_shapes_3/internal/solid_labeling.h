// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_LABELING_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_LABELING_H

// The four steps, one header each, in the order they run:
#include <CGAL/Conformal_alpha_shapes_3/internal/outside_walk.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/manifold_repair.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/sculpting.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/umbrella_splitting.h>

#include <CGAL/Conformal_alpha_shapes_3/internal/solid_cells.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The solid bounded by the conformal alpha shape's surface at scale `a`, as
// a labeling of the triangulation's cells (indexed by `c->cell_index()`),
// and its boundary facets (the manual, section "The Solid Boundary"):
//
// 1. Outside walk (outside_walk.h): the cells that a walk from the infinite
//    cells does not reach through facets outside the complex at `a`.
// 2. Manifold repair (manifold_repair.h): when few boundary vertices are not
//    manifold, each is mended by relabeling a few cells of its star.
// 3. Sculpting (sculpting.h): solid cells that hide a vertex just below the
//    boundary are carved.
// 4. Splitting (umbrella_splitting.h): each umbrella of boundary facets
//    around a vertex that is still not a manifold becomes a vertex of its
//    own. The boundary is then a manifold.
template <class Cas>
class Solid_labeling
{
public:
  typedef typename Cas::Vertex_handle Vertex_handle;
  typedef typename Cas::Cell_handle   Cell_handle;
  typedef typename Solid_cells<Cas>::Facet    Facet;
  typedef typename Solid_cells<Cas>::Triangle Triangle;

  Solid_labeling(const Cas& cas, double alpha) : m_cells(cas), m_splitting(m_cells)
  {
    walk_from_outside(cas, alpha, m_cells);
    m_cells.collect_boundary();
    std::vector<Vertex_handle> bad = m_cells.non_manifold_vertices();
    if(!bad.empty())
    {
      const Manifold_repair<Cas> repair(m_cells, bad);
      m_filled = repair.number_of_filled_cells();
      m_carved = repair.number_of_carved_cells();
      if(m_filled + m_carved > 0)
      {
        m_cells.collect_boundary();
        bad = m_cells.non_manifold_vertices();
      }
    }
    // sculpting neither mends nor breaks a vertex: `bad` stays exact
    m_sculpted = sculpt(cas, alpha, m_cells);
    if(m_sculpted > 0)
      m_cells.collect_boundary();
    m_splitting.run(bad);
    m_carved += m_splitting.number_of_carved_cells();
  }

  Solid_labeling(const Solid_labeling&) = delete;  // m_splitting refers to m_cells
  Solid_labeling& operator=(const Solid_labeling&) = delete;

  // The boundary facets, grouped by cell.
  const std::vector<Facet>& boundary() const { return m_cells.boundary(); }

  static Triangle outward_triangle(const Facet& f) { return Solid_cells<Cas>::outward_triangle(f); }

  bool is_solid(Cell_handle c) const { return m_cells.is_solid(c); }

  // Whether facet (c, i) separates the solid from the outside.
  bool is_boundary(Cell_handle c, int i) const { return m_cells.is_boundary(c, i); }

  // By vertex index: 1 for the vertices of the boundary, else 0.
  std::vector<char> boundary_vertex_marks() const { return m_cells.boundary_vertex_marks(); }

  // Cells relabeled: filled (outside to solid) by the repair, carved by the
  // repair and the splitting; cells carved by sculpting.
  std::size_t number_of_filled_cells() const { return m_filled; }
  std::size_t number_of_carved_cells() const { return m_carved; }
  std::size_t number_of_sculpted_cells() const { return m_sculpted; }

  // The umbrella of corner k (0, 1, 2 as in `outward_triangle()`) of
  // boundary facet `id` around its vertex: 0 at a manifold vertex, else one
  // of 0, 1, ... per umbrella of that vertex.
  int umbrella(std::size_t id, int k) const { return m_splitting.umbrella(id, k); }

  // The number of umbrellas of a boundary vertex: 1 unless the surface
  // pinches there.
  int number_of_umbrellas(Vertex_handle v) const { return m_splitting.number_of_umbrellas(v); }

private:
  Solid_cells<Cas> m_cells;
  Umbrella_splitting<Cas> m_splitting;
  std::size_t m_filled = 0, m_carved = 0, m_sculpted = 0;
};

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_LABELING_H
