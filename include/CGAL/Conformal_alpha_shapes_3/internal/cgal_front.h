// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CGAL_FRONT_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CGAL_FRONT_H

// The advancing front of CGAL's Advancing_front_surface_reconstruction with
// the conformal priority: the reference that the library's own front
// (conformal_front.h) reproduces, kept for the tests and the benchmark that
// compare the two; the library does not use it.

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/front_priority.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/triangle_soup.h>

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Advancing_front_surface_reconstruction_cell_base_3.h>
#include <CGAL/Advancing_front_surface_reconstruction_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The shape's cell that an advancing-front cell copies, whose facets' values
// the front reads on demand (a handle instead of four values: 32 bytes less
// per cell at the front's memory peak); the cells the front creates while
// removing a vertex copy none and are never a candidate.
template <class Shape_cell_handle>
struct Copied_cell
{
  Shape_cell_handle shape_cell{};
};

// The conformal value of facet `i` of a front cell copying `shape_cell`
// (the copy keeps the shape's vertex order in each cell).
template <class Cas>
double copied_facet_value(const Cas& cas, typename Cas::Cell_handle shape_cell, int i)
{
  return shape_cell == typename Cas::Cell_handle() ? std::numeric_limits<double>::infinity()
                                                   : double(cas.conformal_alpha(shape_cell, i));
}

// The front's priority: the conformal value of a facet (infinite facets and
// the cells the front creates have an infinite value: never taken); no seed
// is taken once seeding has stopped. The front calls it for every candidate
// facet, on the thread that runs it: where it may be interrupted.
template <class Cas>
struct Conformal_priority
{
  const Cas* shape;
  Front_seeding* seeding;
  Interruption_point* interruption;
  std::size_t* calls;

  template <class AdvancingFront, class Cell_handle>
  double operator()(const AdvancingFront& front, Cell_handle& c, const int& i) const
  {
    if(++*calls % 1024 == 0)
      interruption->throw_if_stopped();
    const double value = copied_facet_value(*shape, c->info().shape_cell, i);
    const bool seed = c->vertex((i + 1) & 3)->is_exterior() && c->vertex((i + 2) & 3)->is_exterior()
                      && c->vertex((i + 3) & 3)->is_exterior();
    if(seed && !seeding->may_seed(front))
      return std::numeric_limits<double>::infinity();
    return tie_broken_value(value, c->vertex((i + 1) & 3)->id(), c->vertex((i + 2) & 3)->id(),
                            c->vertex((i + 3) & 3)->id());
  }
};

// Fills `triangulation` (empty) with a combinatorial copy of the shape's
// triangulation, cells and vertices in the shape's order (the front visits
// them in that order), whose cells carry the shape's cell they copy and
// whose vertices carry the shape's vertex indices (`no_vertex` for the
// infinite one). CGAL's `copy_tds()` maps handles through hash
// tables; the shape's dense indices make that a look-up, and cells are
// linked in parallel (the manual's Performance section has the figures).
template <class Cas, class FrontTriangulation>
void copy_triangulation(const Cas& cas, FrontTriangulation& triangulation, std::size_t no_vertex)
{
  typedef typename FrontTriangulation::Triangulation_data_structure Front_tds;
  typedef typename Front_tds::Vertex_handle Front_vertex_handle;
  typedef typename Front_tds::Cell_handle Front_cell_handle;

  Front_tds& tds = triangulation.tds();
  tds.clear();
  tds.set_dimension(3);
  std::vector<Front_vertex_handle> vertex_copy(cas.number_of_vertices());
  Front_vertex_handle infinite_copy;
  for(auto v = cas.tds().vertices_begin(); v != cas.tds().vertices_end(); ++v)
  {
    const Front_vertex_handle w = tds.create_vertex(typename Front_tds::Vertex(v->point()));
    if(v == cas.infinite_vertex())
    {
      w->id() = no_vertex;
      infinite_copy = w;
    }
    else
    {
      w->id() = v->vertex_index();
      vertex_copy[v->vertex_index()] = w;
    }
  }
  auto copy_of = [&](typename Cas::Vertex_handle v) {
    return v == cas.infinite_vertex() ? infinite_copy : vertex_copy[v->vertex_index()];
  };

  std::vector<Front_cell_handle> cell_copy(cas.number_of_cells());
  std::vector<typename Cas::Cell_handle> shape_cell(cas.number_of_cells());
  for(auto c = cas.tds().cells_begin(); c != cas.tds().cells_end(); ++c)
  {
    cell_copy[c->cell_index()] = tds.create_cell();
    shape_cell[c->cell_index()] = c;
  }
  for(auto v = cas.tds().vertices_begin(); v != cas.tds().vertices_end(); ++v)
    copy_of(v)->set_cell(cell_copy[v->cell()->cell_index()]);
  for_each_index<Parallel_if_available_tag>(shape_cell.size(), []() { return 0; }, [&](std::size_t k, int&) {
    const typename Cas::Cell_handle c = shape_cell[k];
    const Front_cell_handle d = cell_copy[k];
    for(int i = 0; i < 4; ++i)
    {
      d->set_vertex(i, copy_of(c->vertex(i)));
      d->set_neighbor(i, cell_copy[c->neighbor(i)->cell_index()]);
    }
    d->info().shape_cell = c;
  });
  triangulation.set_infinite_vertex(infinite_copy);
}

// The triangles of `cgal_front_soup()`, with their values, in the
// order the front's surface holds them; their neighbors are left to
// `pair_neighbors()`, once the front is freed.
//
// The advancing front removes the vertices it cannot attach from the
// triangulation it works on, so it runs on a copy of the shape's
// triangulation (a combinatorial copy: no predicate is evaluated again) whose
// cells point to the shape's cells they copy.
template <class Cas>
Advancing_front_soup cgal_front_triangles(const Cas& cas)
{
  typedef typename Cas::Geom_traits Gt;
  typedef Advancing_front_surface_reconstruction_vertex_base_3<Gt> Vb;
  typedef Advancing_front_surface_reconstruction_cell_base_3<
    Gt, Triangulation_cell_base_with_info_3<Copied_cell<typename Cas::Cell_handle>, Gt, Delaunay_triangulation_cell_base_3<Gt> > > Cb;
  typedef Delaunay_triangulation_3<Gt, Triangulation_data_structure_3<Vb, Cb> > Front_triangulation;
  typedef Advancing_front_surface_reconstruction<Front_triangulation, Conformal_priority<Cas> > Front;

  Advancing_front_soup soup;
  if(cas.dimension() < 3)
    return soup;

  const std::size_t no_vertex = std::size_t(-1);
  Front_triangulation triangulation(cas.geom_traits());
  copy_triangulation(cas, triangulation, no_vertex);
  Front_seeding seeding(cas.number_of_vertices());
  Interruption_point interruption;
  std::size_t calls = 0;
  Front front(triangulation, Conformal_priority<Cas>{&cas, &seeding, &interruption, &calls});
  front.run();

  // CGAL's surface holds its faces in the order it created them (a fresh
  // container, nothing erased), which is the order its adjacency was
  // paired in; `pair_neighbors()` relies on it
  const typename Front::Triangulation_data_structure_2& tds = front.triangulation_data_structure_2();
  soup.triangles.reserve(tds.number_of_faces());
  soup.values.reserve(tds.number_of_faces());
  soup.shape_vertex.reserve(tds.number_of_vertices());
  std::vector<std::size_t> soup_vertex(cas.number_of_vertices(), Advancing_front_soup::no_neighbor);
  for(auto f = tds.faces_begin(); f != tds.faces_end(); ++f)
  {
    if(!f->is_on_surface())
      continue;
    std::array<std::size_t, 3> triangle;
    for(int k = 0; k < 3; ++k)
      triangle[k] = soup_vertex_of(soup, soup_vertex, f->vertex(k)->vertex_3()->id());
    soup.triangles.push_back(triangle);
    soup.values.push_back(copied_facet_value(cas, f->facet().first->info().shape_cell, f->facet().second));
  }
  return soup;
}

// The soup of `conformal_front_soup()` grown by CGAL's front on a copy of
// the shape's triangulation: the same triangles, neighbors and values.
template <class Cas>
Advancing_front_soup cgal_front_soup(const Cas& cas)
{
  // paired and ordered once the front and its copy of the triangulation
  // are freed, so that the ordering's arrays do not add to the front's
  // memory peak
  Interruption_point interruption;
  Advancing_front_soup soup = cgal_front_triangles(cas);
  interruption.throw_if_stopped();
  pair_neighbors(soup);
  interruption.throw_if_stopped();
  put_in_canonical_order(soup);
  return soup;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CGAL_FRONT_H
