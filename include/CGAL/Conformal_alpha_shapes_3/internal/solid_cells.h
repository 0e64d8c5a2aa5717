// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_CELLS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_CELLS_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// What the four steps of the solid labeling (solid_labeling.h) share: which
// cells of the triangulation are in the solid (by `c->cell_index()`; every
// cell starts in it, and the infinite cells are never left in it), and the
// solid's boundary facets as last collected.
template <class Cas>
class Solid_cells
{
public:
  typedef typename Cas::Vertex_handle Vertex_handle;
  typedef typename Cas::Cell_handle   Cell_handle;

  // A boundary facet, as (solid cell, index of the vertex opposite to it).
  typedef typename Cas::Facet Facet;
  // A boundary facet's vertices, ordered so that its normal points out of
  // the solid.
  typedef std::array<Vertex_handle, 3> Triangle;

  explicit Solid_cells(const Cas& cas) : m_cas(cas), m_solid(cas.number_of_cells(), 1) {}

  const Cas& shape() const { return m_cas; }

  bool is_solid(Cell_handle c) const { return m_solid[c->cell_index()] != 0; }

  // Whether facet (c, i) separates the solid from the outside.
  bool is_boundary(Cell_handle c, int i) const { return is_solid(c) != is_solid(c->neighbor(i)); }

  // Puts `c` into the solid or out of it; returns whether its label changed.
  bool set_solid(Cell_handle c, bool solid)
  {
    if(is_solid(c) == solid)
      return false;
    m_solid[c->cell_index()] = solid ? 1 : 0;
    return true;
  }

  // The boundary facets, as collected last, grouped by cell in the order of
  // the finite cells.
  const std::vector<Facet>& boundary() const { return m_boundary; }

  void collect_boundary()
  {
    m_boundary.clear();
    for(Cell_handle c : m_cas.finite_cell_handles())
      if(is_solid(c))
        for(int i = 0; i < 4; ++i)
          if(!is_solid(c->neighbor(i)))
            m_boundary.push_back(Facet(c, i));
  }

  static Triangle outward_triangle(const Facet& f)
  {
    // CGAL's vertex triple of facet i is oriented towards vertex i, into the
    // solid cell: reversed, it points out
    return Triangle{f.first->vertex(Cas::vertex_triple_index(f.second, 0)),
                    f.first->vertex(Cas::vertex_triple_index(f.second, 2)),
                    f.first->vertex(Cas::vertex_triple_index(f.second, 1))};
  }

  // By vertex index: 1 for the vertices of the boundary facets, else 0.
  std::vector<char> boundary_vertex_marks() const
  {
    std::vector<char> on(m_cas.number_of_vertices(), 0);
    for(const Facet& f : m_boundary)
      for(int k = 1; k < 4; ++k)
        on[f.first->vertex((f.second + k) & 3)->vertex_index()] = 1;
    return on;
  }

  // The vertices where the boundary is not a manifold, found from the
  // boundary triangles alone: a manifold vertex has no outgoing edge twice
  // and its triangles form a single fan.
  std::vector<Vertex_handle> non_manifold_vertices() const
  {
    const std::size_t nv = m_cas.number_of_vertices();
    std::vector<std::size_t> first(nv + 1, 0);
    for(const Facet& f : m_boundary)
      for(int k = 1; k < 4; ++k)
        ++first[f.first->vertex((f.second + k) & 3)->vertex_index() + 1];
    for(std::size_t k = 0; k < nv; ++k)
      first[k + 1] += first[k];
    // around each vertex v, the corners (next, previous) of its triangles
    std::vector<std::pair<Vertex_handle, Vertex_handle> > corners(first[nv]);
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(const Facet& f : m_boundary)
    {
      const Triangle t = outward_triangle(f);
      for(int k = 0; k < 3; ++k)
        corners[fill[t[k]->vertex_index()]++] = std::make_pair(t[(k + 1) % 3], t[(k + 2) % 3]);
    }

    std::vector<Vertex_handle> bad;
    for(Vertex_handle v : m_cas.finite_vertex_handles())
    {
      const auto begin = corners.begin() + std::ptrdiff_t(first[v->vertex_index()]);
      const auto end = corners.begin() + std::ptrdiff_t(first[v->vertex_index() + 1]);
      if(begin == end)
        continue;
      // walk the fan: the triangle after (v, n, p) is the one whose next is p
      std::size_t length = 0;
      auto current = begin;
      do
      {
        const Vertex_handle p = current->second;
        current = std::find_if(begin, end, [&](const std::pair<Vertex_handle, Vertex_handle>& c) {
          return c.first == p;
        });
        ++length;
      } while(current != end && current != begin && length <= std::size_t(end - begin));
      if(current != begin || length != std::size_t(end - begin))
        bad.push_back(v);
    }
    return bad;
  }

private:
  const Cas& m_cas;
  std::vector<unsigned char> m_solid;  // by cell index
  std::vector<Facet> m_boundary;
};

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_CELLS_H
