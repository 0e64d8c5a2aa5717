// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_UMBRELLA_SPLITTING_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_UMBRELLA_SPLITTING_H

#include <CGAL/Conformal_alpha_shapes_3/internal/solid_cells.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// Step 4 of the solid labeling, splitting: the boundary facets around a
// vertex that is still not a manifold are grouped into umbrellas: around
// each edge, the two facets that bound the same wedge of solid cells are
// neighbors. Each umbrella becomes a vertex of its own. An umbrella may pass
// an edge twice (both wedges of a bad edge); when the umbrella at the edge's
// other end does too, the two copies would share four faces: the solid star
// of that vertex is carved, and the splitting starts again (carving only
// shrinks the solid, so this ends). The surface is then a manifold.
template <class Cas>
class Umbrella_splitting
{
public:
  typedef typename Cas::Vertex_handle Vertex_handle;
  typedef typename Cas::Cell_handle   Cell_handle;
  typedef typename Solid_cells<Cas>::Facet    Facet;
  typedef typename Solid_cells<Cas>::Triangle Triangle;

  explicit Umbrella_splitting(Solid_cells<Cas>& solid)
    : m_cas(solid.shape()), m_solid(solid), m_first_boundary_facet(m_cas.number_of_cells(), -1)
  {}

  // Splits the vertices `bad` (the non-manifold vertices of the boundary last
  // collected), carving where it must.
  void run(std::vector<Vertex_handle> bad)
  {
    if(bad.empty())
      return;
    for(std::vector<Vertex_handle> pinched = split(bad); !pinched.empty(); pinched = split(bad))
    {
      for(Vertex_handle v : pinched)
        carve_star(v);
      m_solid.collect_boundary();
      bad = m_solid.non_manifold_vertices();
    }
  }

  // Cells carved where an edge stayed doubled.
  std::size_t number_of_carved_cells() const { return m_carved; }

  // The umbrella of corner k (0, 1, 2 as in `outward_triangle()`) of
  // boundary facet `id` around its vertex: 0 at a manifold vertex, else one
  // of 0, 1, ... per umbrella of that vertex.
  int umbrella(std::size_t id, int k) const
  {
    return m_umbrellas.empty() ? 0 : m_umbrellas[id][std::size_t(k)];
  }

  // The number of umbrellas of a boundary vertex: 1 unless the surface
  // pinches there.
  int number_of_umbrellas(Vertex_handle v) const
  {
    return m_umbrellas_at.empty() ? 1 : (std::max)(1, m_umbrellas_at[v->vertex_index()]);
  }

private:
  static Triangle outward_triangle(const Facet& f) { return Solid_cells<Cas>::outward_triangle(f); }

  void carve_star(Vertex_handle v)
  {
    std::vector<Cell_handle> cells;
    m_cas.incident_cells(v, std::back_inserter(cells));
    for(Cell_handle c : cells)
      m_carved += m_solid.set_solid(c, false) ? 1 : 0;
  }

  // The boundary facet that bounds, with (c, j), the same wedge of solid
  // cells around the edge (a, b) of facet (c, j).
  Facet wedge_neighbor(Cell_handle c, int j, Vertex_handle a, Vertex_handle b) const
  {
    for(;;)
    {
      const int l = 6 - c->index(a) - c->index(b) - j;  // c's other facet on (a, b)
      const Cell_handle n = c->neighbor(l);
      if(!m_solid.is_solid(n))
        return Facet(c, l);
      j = n->index(c);
      c = n;
    }
  }

  // The index of a boundary facet in `m_solid.boundary()`.
  std::size_t id_of(const Facet& f) const
  {
    const std::vector<Facet>& boundary = m_solid.boundary();
    // a boundary facet's cell is finite, and so was collected
    CGAL_assertion(m_first_boundary_facet[f.first->cell_index()] >= 0);
    std::size_t id = std::size_t(m_first_boundary_facet[f.first->cell_index()]);
    while(boundary[id].second != f.second)
      ++id;
    return id;
  }

  // Returns the vertices of the edges that umbrellas pass twice at both ends.
  std::vector<Vertex_handle> split(const std::vector<Vertex_handle>& bad)
  {
    const std::vector<Facet>& boundary = m_solid.boundary();
    m_umbrellas.clear();
    m_umbrellas_at.clear();
    if(bad.empty())
      return bad;
    m_umbrellas_at.assign(m_cas.number_of_vertices(), 0);
    for(Vertex_handle v : bad)
      m_umbrellas_at[v->vertex_index()] = -1;  // not counted yet
    auto is_bad = [&](Vertex_handle v) { return m_umbrellas_at[v->vertex_index()] != 0; };
    // the boundary facets of a cell are consecutive in the boundary, by index
    for(std::size_t id = boundary.size(); id-- > 0;)
      m_first_boundary_facet[boundary[id].first->cell_index()] = int(id);
    m_umbrellas.assign(boundary.size(), std::array<int, 3>{{0, 0, 0}});
    for(std::size_t id = 0; id < boundary.size(); ++id)
    {
      const Triangle t = outward_triangle(boundary[id]);
      for(std::size_t k = 0; k < 3; ++k)
        if(is_bad(t[k]))
          m_umbrellas[id][k] = -1;
    }
    for(Vertex_handle v : bad)
      m_umbrellas_at[v->vertex_index()] = 0;
    std::vector<std::pair<std::size_t, int> > corners;
    for(std::size_t start = 0; start < boundary.size(); ++start)
      for(int k0 = 0; k0 < 3; ++k0)
      {
        if(m_umbrellas[start][std::size_t(k0)] >= 0)
          continue;
        const Vertex_handle v = outward_triangle(boundary[start])[std::size_t(k0)];
        // turn around v: across the edge (v, next vertex) to the wedge
        // neighbor, until back
        corners.clear();
        std::size_t id = start;
        int k = k0;
        do
        {
          const Facet& f = boundary[id];
          corners.emplace_back(id, k);
          const Vertex_handle next = outward_triangle(f)[std::size_t((k + 1) % 3)];
          const Facet g = wedge_neighbor(f.first, f.second, v, next);
          id = id_of(g);
          const Triangle t = outward_triangle(g);
          k = int(std::find(t.begin(), t.end(), v) - t.begin());
        } while(id != start || k != k0);
        const int umbrella = m_umbrellas_at[v->vertex_index()]++;
        for(const auto& corner : corners)
          m_umbrellas[corner.first][std::size_t(corner.second)] = umbrella;
      }
    for(const Facet& f : boundary)
      m_first_boundary_facet[f.first->cell_index()] = -1;

    // an umbrella may pass an edge twice (both wedges of a bad edge): that
    // is harmless unless the umbrella at the edge's other end does too, and
    // the edge between the two copies then has four faces
    typedef std::tuple<Vertex_handle, int, Vertex_handle, int> Copy_edge;  // (vertex, umbrella) twice
    std::vector<Copy_edge> copy_edges;
    for(std::size_t id = 0; id < boundary.size(); ++id)
    {
      const Triangle t = outward_triangle(boundary[id]);
      for(std::size_t k = 0; k < 3; ++k)
        if(is_bad(t[k]) && is_bad(t[(k + 1) % 3]))
          copy_edges.emplace_back(t[k], m_umbrellas[id][k], t[(k + 1) % 3], m_umbrellas[id][(k + 1) % 3]);
    }
    std::sort(copy_edges.begin(), copy_edges.end());
    std::vector<Vertex_handle> doubled_edge_ends;
    for(std::size_t k = 1; k < copy_edges.size(); ++k)
      if(copy_edges[k] == copy_edges[k - 1])
        doubled_edge_ends.push_back(std::get<0>(copy_edges[k]));
    return doubled_edge_ends;
  }

  const Cas& m_cas;
  Solid_cells<Cas>& m_solid;
  std::vector<int> m_first_boundary_facet;       // by cell index: its first facet in the boundary, or -1
  std::vector<std::array<int, 3> > m_umbrellas;  // by boundary facet id; empty when all are 0
  std::vector<int> m_umbrellas_at;               // by vertex index; empty when all are 1
  std::size_t m_carved = 0;
};

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_UMBRELLA_SPLITTING_H
