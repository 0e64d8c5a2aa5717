// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_POLES_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_POLES_H

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The pole of a vertex p and its distance (the manual, section "Poles and
// Local Scales").
// `u` is p+ - p (p+ the farthest Voronoi vertex) on a bounded Voronoi cell
// and the mean outward normal of the incident hull facets on an unbounded one.
// The pole is the farthest Voronoi vertex on the side opposite to `u` (the
// Amenta-Bern negative pole); without one, the farthest Voronoi vertex.
template <class Cell_handle>
struct Pole
{
  Cell_handle cell;          // the cell whose circumcenter is the pole
  double      distance = 0;  // |p - pole|, the circumradius of that cell
};

// Computes the pole of every finite vertex, indexed by `v->vertex_index()`,
// from the circumcenters of the finite cells (indexed by `c->cell_index()`).
// Precondition: dimension 3 and every finite cell's circumradius stored with
// `set_alpha()`: the distance from a vertex to the circumcenter of an incident
// cell is that cell's circumradius.
template <class Dt>
std::vector<Pole<typename Dt::Cell_handle> >
compute_poles(const Dt& dt, const std::vector<typename Dt::Geom_traits::Point_3>& centers)
{
  typedef typename Dt::Geom_traits   Gt;
  typedef typename Dt::Cell_handle   Cell_handle;
  typedef typename Dt::Vertex_handle Vertex_handle;
  typedef typename Gt::Point_3       Point;
  typedef typename Gt::Vector_3      Vector;

  const std::size_t nv = dt.number_of_vertices();
  std::vector<Pole<Cell_handle> > farthest(nv), opposite(nv);
  std::vector<Vector> u(nv, Vector(0, 0, 0));
  std::vector<bool> on_hull(nv, false);

  for(Cell_handle c : dt.finite_cell_handles())
    for(int k = 0; k < 4; ++k)
    {
      Pole<Cell_handle>& f = farthest[c->vertex(k)->vertex_index()];
      if(f.cell == Cell_handle() || c->alpha() > f.distance)
        f = Pole<Cell_handle>{c, c->alpha()};
    }

  // unbounded Voronoi cells: mean outward normal of the incident hull facets
  typename Gt::Construct_cross_product_vector_3 cross_product =
    dt.geom_traits().construct_cross_product_vector_3_object();
  std::vector<Cell_handle> infinite_cells;
  dt.incident_cells(dt.infinite_vertex(), std::back_inserter(infinite_cells));
  for(Cell_handle c : infinite_cells)
  {
    const int i = c->index(dt.infinite_vertex());
    const Vertex_handle a = c->vertex((i + 1) & 3), b = c->vertex((i + 2) & 3),
                        d = c->vertex((i + 3) & 3);
    Vector n = cross_product(b->point() - a->point(), d->point() - a->point());
    const Cell_handle inside = c->neighbor(i);
    const Point& e = inside->vertex(inside->index(c))->point();
    if(n * (e - a->point()) > 0)
      n = -n;
    const double len = std::sqrt(CGAL::to_double(n.squared_length()));
    if(len > 0)
      n = n / len;
    for(Vertex_handle v : {a, b, d})
    {
      on_hull[v->vertex_index()] = true;
      u[v->vertex_index()] = u[v->vertex_index()] + n;
    }
  }

  for(Vertex_handle v : dt.finite_vertex_handles())
    if(!on_hull[v->vertex_index()])
      u[v->vertex_index()] = centers[farthest[v->vertex_index()].cell->cell_index()] - v->point();

  for(Cell_handle c : dt.finite_cell_handles())
  {
    const Point& center = centers[c->cell_index()];
    for(int k = 0; k < 4; ++k)
    {
      const Vertex_handle v = c->vertex(k);
      Pole<Cell_handle>& o = opposite[v->vertex_index()];
      if((center - v->point()) * u[v->vertex_index()] < 0 &&
         (o.cell == Cell_handle() || c->alpha() > o.distance))
        o = Pole<Cell_handle>{c, c->alpha()};
    }
  }

  for(std::size_t id = 0; id < nv; ++id)
    if(opposite[id].cell == Cell_handle())
      opposite[id] = farthest[id];
  return opposite;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_POLES_H
