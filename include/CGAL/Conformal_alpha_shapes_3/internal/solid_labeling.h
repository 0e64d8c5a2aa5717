// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_LABELING_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_LABELING_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The solid bounded by the conformal alpha shape's surface at scale `a`, as
// a labelling of the triangulation's cells (indexed by `c->cell_index()`),
// and its boundary facets:
//
// 1. Outside walk. Starting from the infinite cells, a walk crosses every
//    facet that is not in the complex at `a` (value > a). The cells it never
//    reaches are the solid: the INTERIOR cells, and the pockets that the
//    REGULAR and SINGULAR facets enclose (on a surface sample, the whole
//    volume inside the shell of SINGULAR facets). Facets between reached and
//    unreached cells are REGULAR or SINGULAR; the others are dropped.
//
// 2. Manifold repair. The boundary of a union of tetrahedra is a 2-manifold
//    exactly when, at every vertex, the solid cells of its star are connected
//    through facets incident to the vertex, so are the other cells, and every
//    edge has 0 or 2 boundary facets. When few vertices fail this (at most
//    1% of the boundary's: a surface that has formed), each is mended by
//    relabelling cells of its star: carving away all but the largest solid
//    component, filling all but the largest outside component (infinite
//    cells are never filled), or carving or filling the smaller runs of
//    cells around a bad edge, whichever flips fewer cells. Each cell is
//    relabelled at most once, so the repair terminates; a vertex that would
//    need a cell twice is left to step 4. (Below the scale at which the
//    surface closes, the solid is a sponge of small pockets, most of whose
//    vertices fail: relabelling would erode it cell by cell, slowly.)
//
// 3. Sculpting. A solid cell with a single boundary facet, whose opposite
//    vertex is not on the boundary and whose other three facets are in the
//    complex at `a`, is carved: the boundary then reaches that vertex through
//    facets of the complex. This keeps the boundary's manifold vertices
//    manifold (a facet is replaced by a fan of three around a vertex that
//    was not on it), and brings onto the surface the points that noise put
//    just inside it.
//
// 4. Splitting. The boundary facets around a vertex that is still not a
//    manifold are grouped into umbrellas: around each edge, the two facets
//    that bound the same wedge of solid cells are neighbours. Each umbrella
//    becomes a vertex of its own. An umbrella may pass an edge twice (both
//    wedges of a bad edge); when the umbrella at the edge's other end does
//    too, the two copies would share four faces: the solid star of that
//    vertex is carved, and the splitting starts again (carving only shrinks
//    the solid, so this ends). The surface is then a manifold.
template <class Cas>
class Solid_labeling
{
public:
  typedef typename Cas::Vertex_handle Vertex_handle;
  typedef typename Cas::Cell_handle   Cell_handle;

  // A boundary facet, as (solid cell, index of the vertex opposite to it).
  typedef typename Cas::Facet Facet;
  // A boundary facet's vertices, ordered so that its normal points out of
  // the solid.
  typedef std::array<Vertex_handle, 3> Triangle;

  Solid_labeling(const Cas& cas, double alpha)
    : m_cas(cas), m_solid(cas.number_of_cells(), 1), m_relabelled(cas.number_of_cells(), 0),
      m_star_position(cas.number_of_cells(), -1)
  {
    walk_from_outside(alpha);
    collect_boundary();
    std::vector<Vertex_handle> bad = non_manifold_vertices();
    if(!bad.empty())
    {
      repair(bad);
      if(m_filled + m_carved > 0)
      {
        collect_boundary();
        bad = non_manifold_vertices();
      }
    }
    // sculpting neither mends nor breaks a vertex: `bad` stays exact
    if(sculpt(alpha) > 0)
      collect_boundary();
    if(bad.empty())
      return;
    // an umbrella that passes an edge twice is resolved by carving
    for(std::vector<Vertex_handle> pinched = split(bad); !pinched.empty(); pinched = split(bad))
    {
      for(Vertex_handle v : pinched)
        carve_star(v);
      m_queue.clear();
      collect_boundary();
      bad = non_manifold_vertices();
    }
  }

  const std::vector<Facet>& boundary() const { return m_boundary; }

  static Triangle outward_triangle(const Facet& f)
  {
    // CGAL's vertex triple of facet i is oriented towards vertex i, into the
    // solid cell: reversed, it points out
    return Triangle{f.first->vertex(Cas::vertex_triple_index(f.second, 0)),
                    f.first->vertex(Cas::vertex_triple_index(f.second, 2)),
                    f.first->vertex(Cas::vertex_triple_index(f.second, 1))};
  }

  bool is_solid(Cell_handle c) const { return m_solid[c->cell_index()] != 0; }

  // Whether facet (c, i) separates the solid from the outside.
  bool is_boundary(Cell_handle c, int i) const { return is_solid(c) != is_solid(c->neighbor(i)); }

  // Cells relabelled by the repair: filled (outside to solid) and carved;
  // cells carved by sculpting.
  std::size_t number_of_filled_cells() const { return m_filled; }
  std::size_t number_of_carved_cells() const { return m_carved; }
  std::size_t number_of_sculpted_cells() const { return m_sculpted; }

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
  void walk_from_outside(double alpha)
  {
    std::vector<Cell_handle> stack(1, m_cas.infinite_cell());
    m_solid[stack.back()->cell_index()] = 0;
    while(!stack.empty())
    {
      const Cell_handle c = stack.back();
      stack.pop_back();
      for(int i = 0; i < 4; ++i)
      {
        const Cell_handle n = c->neighbor(i);
        if(m_solid[n->cell_index()] && !(m_cas.conformal_alpha(c, i) <= alpha))
        {
          m_solid[n->cell_index()] = 0;
          stack.push_back(n);
        }
      }
    }
  }

  // The star of a vertex split into facet-connected components of equal
  // label, and the edges of the vertex with more than two boundary facets.
  struct Star
  {
    std::vector<Cell_handle> cells;
    std::vector<int> component;                  // per cell
    std::vector<std::vector<std::size_t> > solid_components, outside_components;
    std::vector<Vertex_handle> bad_edge_ends;    // the other end of each bad edge
  };

  void analyse(Vertex_handle v, Star& s)
  {
    s.cells.clear();
    s.solid_components.clear();
    s.outside_components.clear();
    s.bad_edge_ends.clear();
    m_cas.incident_cells(v, std::back_inserter(s.cells));
    s.component.assign(s.cells.size(), -1);
    for(std::size_t k = 0; k < s.cells.size(); ++k)
      m_star_position[s.cells[k]->cell_index()] = int(k);
    std::vector<std::pair<Vertex_handle, int> > edge_counts;  // boundary facets per edge (v, w)
    for(std::size_t k = 0; k < s.cells.size(); ++k)
    {
      const Cell_handle c = s.cells[k];
      for(int i = 0; i < 4; ++i)
      {
        if(c->vertex(i) == v || !is_boundary(c, i) || !is_solid(c))
          continue;
        for(int j = 0; j < 4; ++j)
        {
          if(j == i || c->vertex(j) == v)
            continue;
          auto it = std::find_if(edge_counts.begin(), edge_counts.end(),
                                 [&](const std::pair<Vertex_handle, int>& e) { return e.first == c->vertex(j); });
          if(it == edge_counts.end())
            edge_counts.emplace_back(c->vertex(j), 1);
          else
            ++it->second;
        }
      }
      if(s.component[k] >= 0)
        continue;
      const bool solid = is_solid(c);
      auto& components = solid ? s.solid_components : s.outside_components;
      components.emplace_back(1, k);
      s.component[k] = int(components.size() - 1);
      for(std::size_t head = 0; head < components.back().size(); ++head)
      {
        const Cell_handle d = s.cells[components.back()[head]];
        for(int i = 0; i < 4; ++i)
        {
          if(d->vertex(i) == v)
            continue;  // the facet opposite to v does not contain v
          const Cell_handle n = d->neighbor(i);
          if(is_solid(n) != solid)
            continue;
          const std::size_t m = std::size_t(m_star_position[n->cell_index()]);
          if(s.component[m] < 0)
          {
            s.component[m] = int(components.size() - 1);
            components.back().push_back(m);
          }
        }
      }
    }
    for(const auto& e : edge_counts)
      if(e.second > 2)
        s.bad_edge_ends.push_back(e.first);
    for(Cell_handle c : s.cells)
      m_star_position[c->cell_index()] = -1;
  }

  static bool is_manifold(const Star& s)
  {
    return s.solid_components.size() <= 1 && s.outside_components.size() <= 1 && s.bad_edge_ends.empty();
  }

  void carve_star(Vertex_handle v)
  {
    std::vector<Cell_handle> cells;
    m_cas.incident_cells(v, std::back_inserter(cells));
    for(Cell_handle c : cells)
      set_label(c, false);
  }

  // Relabels the cells, unless one of them was relabelled before.
  void relabel_once(const std::vector<Cell_handle>& cells, bool solid)
  {
    for(Cell_handle c : cells)
      if(m_relabelled[c->cell_index()] || (solid && m_cas.is_infinite(c)))
        return;
    for(Cell_handle c : cells)
    {
      m_relabelled[c->cell_index()] = 1;
      set_label(c, solid);
    }
  }

  void set_label(Cell_handle c, bool solid)
  {
    if(is_solid(c) == solid)
      return;
    m_solid[c->cell_index()] = solid ? 1 : 0;
    ++(solid ? m_filled : m_carved);
    for(int i = 0; i < 4; ++i)
      if(!m_cas.is_infinite(c->vertex(i)))
        m_queue.push_back(c->vertex(i));
  }

  // All components but the largest, as cells.
  std::vector<Cell_handle> all_but_largest(const Star& s, const std::vector<std::vector<std::size_t> >& comps) const
  {
    std::size_t largest = 0;
    for(std::size_t k = 1; k < comps.size(); ++k)
      if(comps[k].size() > comps[largest].size())
        largest = k;
    std::vector<Cell_handle> cells;
    for(std::size_t k = 0; k < comps.size(); ++k)
      if(k != largest)
        for(std::size_t m : comps[k])
          cells.push_back(s.cells[m]);
    return cells;
  }

  // Around the edge (v, w): the runs of equal label except the largest one
  // of each label; returns the cheaper of carving the extra solid runs and
  // filling the extra outside runs.
  std::pair<std::vector<Cell_handle>, bool> mend_edge(Vertex_handle v, Vertex_handle w) const
  {
    Cell_handle c;
    int i = 0, j = 0;
    m_cas.is_edge(v, w, c, i, j);
    std::vector<Cell_handle> ring;
    typename Cas::Cell_circulator cc = m_cas.incident_cells(c, i, j), done = cc;
    do ring.push_back(cc); while(++cc != done);
    // rotate so that the ring starts at a label change
    std::size_t start = 0;
    while(start < ring.size() && is_solid(ring[start]) == is_solid(ring[(start + ring.size() - 1) % ring.size()]))
      ++start;
    std::rotate(ring.begin(), ring.begin() + std::ptrdiff_t(start % ring.size()), ring.end());
    std::vector<std::vector<Cell_handle> > runs[2];
    for(std::size_t k = 0; k < ring.size(); ++k)
    {
      const int label = is_solid(ring[k]) ? 1 : 0;
      if(k == 0 || is_solid(ring[k - 1]) != bool(label))
        runs[label].emplace_back();
      runs[label].back().push_back(ring[k]);
    }
    std::vector<Cell_handle> extra[2];
    for(int label = 0; label < 2; ++label)
    {
      std::size_t largest = 0;
      for(std::size_t k = 1; k < runs[label].size(); ++k)
        if(runs[label][k].size() > runs[label][largest].size())
          largest = k;
      for(std::size_t k = 0; k < runs[label].size(); ++k)
        if(k != largest)
          extra[label].insert(extra[label].end(), runs[label][k].begin(), runs[label][k].end());
    }
    const bool fill_possible = std::none_of(extra[0].begin(), extra[0].end(),
                                            [&](Cell_handle d) { return m_cas.is_infinite(d); });
    if(fill_possible && extra[0].size() < extra[1].size())
      return {extra[0], true};
    return {extra[1], false};
  }

  void mend(Vertex_handle v, const Star& s)
  {
    if(s.solid_components.size() > 1)
      relabel_once(all_but_largest(s, s.solid_components), false);
    else if(s.outside_components.size() > 1)
      relabel_once(all_but_largest(s, s.outside_components), true);
    else
    {
      const auto cells_and_label = mend_edge(v, s.bad_edge_ends.front());
      relabel_once(cells_and_label.first, cells_and_label.second);
    }
  }

  void collect_boundary()
  {
    m_boundary.clear();
    for(Cell_handle c : m_cas.finite_cell_handles())
      if(is_solid(c))
        for(int i = 0; i < 4; ++i)
          if(!is_solid(c->neighbor(i)))
            m_boundary.push_back(Facet(c, i));
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

  void repair(const std::vector<Vertex_handle>& bad)
  {
    std::size_t on_boundary = 0;
    std::vector<char> on(m_cas.number_of_vertices(), 0);
    for(const Facet& f : m_boundary)
      for(int k = 1; k < 4; ++k)
      {
        char& mark = on[f.first->vertex((f.second + k) & 3)->vertex_index()];
        on_boundary += mark ? 0 : 1;
        mark = 1;
      }
    if(100 * bad.size() > on_boundary)
      return;
    m_queue = bad;
    Star star;
    while(!m_queue.empty())
    {
      const Vertex_handle v = m_queue.back();
      m_queue.pop_back();
      analyse(v, star);
      if(!is_manifold(star))
        mend(v, star);
    }
  }

  // The boundary facet that bounds, with (c, j), the same wedge of solid
  // cells around the edge (a, b) of facet (c, j).
  Facet wedge_neighbour(Cell_handle c, int j, Vertex_handle a, Vertex_handle b) const
  {
    for(;;)
    {
      const int l = 6 - c->index(a) - c->index(b) - j;  // c's other facet on (a, b)
      const Cell_handle n = c->neighbor(l);
      if(!is_solid(n))
        return Facet(c, l);
      j = n->index(c);
      c = n;
    }
  }

  // Step 4; returns the vertices of the edges that umbrellas pass twice at
  // both ends.
  std::vector<Vertex_handle> split(const std::vector<Vertex_handle>& bad)
  {
    m_umbrellas.clear();
    m_umbrellas_at.clear();
    if(bad.empty())
      return bad;
    m_umbrellas_at.assign(m_cas.number_of_vertices(), 0);
    for(Vertex_handle v : bad)
      m_umbrellas_at[v->vertex_index()] = -1;  // not counted yet
    auto is_bad = [&](Vertex_handle v) { return m_umbrellas_at[v->vertex_index()] != 0; };
    // the boundary facets of a cell are consecutive in m_boundary, by index
    for(std::size_t id = m_boundary.size(); id-- > 0;)
      m_star_position[m_boundary[id].first->cell_index()] = int(id);
    auto id_of = [&](const Facet& f) {
      std::size_t id = std::size_t(m_star_position[f.first->cell_index()]);
      while(m_boundary[id].second != f.second)
        ++id;
      return id;
    };
    m_umbrellas.assign(m_boundary.size(), std::array<int, 3>{{0, 0, 0}});
    for(std::size_t id = 0; id < m_boundary.size(); ++id)
    {
      const Triangle t = outward_triangle(m_boundary[id]);
      for(std::size_t k = 0; k < 3; ++k)
        if(is_bad(t[k]))
          m_umbrellas[id][k] = -1;
    }
    for(Vertex_handle v : bad)
      m_umbrellas_at[v->vertex_index()] = 0;
    std::vector<std::pair<std::size_t, int> > corners;
    for(std::size_t start = 0; start < m_boundary.size(); ++start)
      for(int k0 = 0; k0 < 3; ++k0)
      {
        if(m_umbrellas[start][std::size_t(k0)] >= 0)
          continue;
        const Vertex_handle v = outward_triangle(m_boundary[start])[std::size_t(k0)];
        // turn around v: across the edge (v, next vertex) to the wedge
        // neighbour, until back
        corners.clear();
        std::size_t id = start;
        int k = k0;
        do
        {
          const Facet& f = m_boundary[id];
          corners.emplace_back(id, k);
          const Vertex_handle next = outward_triangle(f)[std::size_t((k + 1) % 3)];
          const Facet g = wedge_neighbour(f.first, f.second, v, next);
          id = id_of(g);
          const Triangle t = outward_triangle(g);
          k = int(std::find(t.begin(), t.end(), v) - t.begin());
        } while(id != start || k != k0);
        const int umbrella = m_umbrellas_at[v->vertex_index()]++;
        for(const auto& corner : corners)
          m_umbrellas[corner.first][std::size_t(corner.second)] = umbrella;
      }
    for(const Facet& f : m_boundary)
      m_star_position[f.first->cell_index()] = -1;

    // an umbrella may pass an edge twice (both wedges of a bad edge): that
    // is harmless unless the umbrella at the edge's other end does too, and
    // the edge between the two copies then has four faces
    typedef std::tuple<Vertex_handle, int, Vertex_handle, int> Copy_edge;  // (vertex, umbrella) twice
    std::vector<Copy_edge> copy_edges;
    for(std::size_t id = 0; id < m_boundary.size(); ++id)
    {
      const Triangle t = outward_triangle(m_boundary[id]);
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

  // Step 3; returns the number of cells carved.
  std::size_t sculpt(double alpha)
  {
    std::vector<int> degree(m_cas.number_of_vertices(), 0);  // boundary facets per vertex
    std::vector<Cell_handle> stack;
    for(const Facet& f : m_boundary)
    {
      for(int k = 1; k < 4; ++k)
        ++degree[f.first->vertex((f.second + k) & 3)->vertex_index()];
      stack.push_back(f.first);
    }
    std::size_t sculpted = 0;
    while(!stack.empty())
    {
      const Cell_handle c = stack.back();
      stack.pop_back();
      if(!is_solid(c))
        continue;
      int boundary_facets = 0, facet = 0;
      for(int i = 0; i < 4; ++i)
        if(!is_solid(c->neighbor(i)))
        {
          ++boundary_facets;
          facet = i;
        }
      if(boundary_facets != 1 || degree[c->vertex(facet)->vertex_index()] > 0)
        continue;
      bool admissible = true;
      for(int i = 0; i < 4 && admissible; ++i)
        admissible = i == facet || m_cas.conformal_alpha(c, i) <= alpha;
      if(!admissible)
        continue;
      m_solid[c->cell_index()] = 0;
      ++sculpted;
      for(int i = 0; i < 4; ++i)
        degree[c->vertex(i)->vertex_index()] += (i == facet) ? 3 : 1;  // -1 for the old facet, +2 for the new ones; 3 for the apex
      for(int i = 0; i < 4; ++i)
        if(i != facet)
          stack.push_back(c->neighbor(i));
    }
    m_sculpted = sculpted;
    return sculpted;
  }

  const Cas& m_cas;
  std::vector<unsigned char> m_solid;       // per cell index
  std::vector<unsigned char> m_relabelled;  // per cell index
  std::vector<int> m_star_position;         // per cell index: its place in the star analysed, or -1
  std::vector<Facet> m_boundary;
  std::vector<std::array<int, 3> > m_umbrellas;  // by boundary facet id; empty when all are 0
  std::vector<int> m_umbrellas_at;               // by vertex index; empty when all are 1
  std::vector<Vertex_handle> m_queue;
  std::size_t m_filled = 0, m_carved = 0, m_sculpted = 0;
};

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_LABELING_H
