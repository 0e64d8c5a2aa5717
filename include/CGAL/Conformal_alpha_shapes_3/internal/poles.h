// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_POLES_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_POLES_H

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>

#include <CGAL/tags.h>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The pole of a vertex p and its distance (the manual, section "Poles and
// Local Feature Sizes").
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
// from `cells` (every cell of `dt`, by `c->cell_index()`) and the
// circumcenters of the finite ones (indexed the same way).
// Precondition: dimension 3 and every finite cell's circumradius stored with
// `set_alpha()`: the distance from a vertex to the circumcenter of an incident
// cell is that cell's circumradius.
// Of cells at the same distance, the one of smallest index is taken, so
// that the passes over the cells can run in chunks on TBB's threads (when
// available) and be merged with the same result.
template <class Dt>
std::vector<Pole<typename Dt::Cell_handle> >
compute_poles(const Dt& dt, const std::vector<typename Dt::Cell_handle>& cells,
              const std::vector<typename Dt::Geom_traits::Point_3>& centers)
{
  typedef typename Dt::Geom_traits   Gt;
  typedef typename Dt::Cell_handle   Cell_handle;
  typedef typename Dt::Vertex_handle Vertex_handle;
  typedef typename Gt::Point_3       Point;
  typedef typename Gt::Vector_3      Vector;
  typedef std::vector<Pole<Cell_handle> > Poles;

  const std::size_t nv = dt.number_of_vertices();
  auto farther = [](const Pole<Cell_handle>& candidate, const Pole<Cell_handle>& pole) {
    return pole.cell == Cell_handle() || candidate.distance > pole.distance
           || (candidate.distance == pole.distance && candidate.cell->cell_index() < pole.cell->cell_index());
  };
  // the farthest pole of each vertex among the cells around it for which
  // `counts(cell, vertex)`
  auto farthest_cells = [&](auto counts) {
    std::vector<Poles> partial = partial_results_in_chunks<Parallel_if_available_tag>(
      cells.size(), [&]() { return Poles(nv); },
      [&](std::size_t begin, std::size_t end, Poles& poles) {
        for(std::size_t index = begin; index < end; ++index)
        {
          const Cell_handle c = cells[index];
          if(dt.is_infinite(c))
            continue;
          const Pole<Cell_handle> candidate{c, c->alpha()};
          for(int k = 0; k < 4; ++k)
          {
            Pole<Cell_handle>& pole = poles[c->vertex(k)->vertex_index()];
            if(counts(c, c->vertex(k)) && farther(candidate, pole))
              pole = candidate;
          }
        }
      });
    Poles& poles = partial.front();
    for(std::size_t k = 1; k < partial.size(); ++k)
      for(std::size_t v = 0; v < nv; ++v)
        if(partial[k][v].cell != Cell_handle() && farther(partial[k][v], poles[v]))
          poles[v] = partial[k][v];
    return std::move(poles);
  };

  const Poles farthest = farthest_cells([](Cell_handle, Vertex_handle) { return true; });

  // unbounded Voronoi cells: mean outward normal of the incident hull facets
  std::vector<Vector> u(nv, Vector(0, 0, 0));
  std::vector<bool> on_hull(nv, false);
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

  Poles opposite = farthest_cells([&](Cell_handle c, Vertex_handle v) {
    return (centers[c->cell_index()] - v->point()) * u[v->vertex_index()] < 0;
  });
  for(std::size_t id = 0; id < nv; ++id)
    if(opposite[id].cell == Cell_handle())
      opposite[id] = farthest[id];
  return opposite;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_POLES_H
