// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_MANIFOLD_REPAIR_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_MANIFOLD_REPAIR_H

#include <CGAL/Conformal_alpha_shapes_3/internal/flood_fill.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/solid_cells.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// Step 2 of the solid labeling, the manifold repair. The boundary of a union
// of tetrahedra is a 2-manifold exactly when, at every vertex, the solid
// cells of its star are connected through facets incident to the vertex, so
// are the other cells, and every edge has 0 or 2 boundary facets. When few
// vertices fail this (a surface that has formed), each is mended by
// relabeling cells of its star: carving away all but the largest solid
// component, filling all but the largest outside component (infinite cells
// are never filled), or carving or filling the smaller runs of cells around
// a bad edge, whichever flips fewer cells. Each cell is relabeled at most
// once, so the repair terminates; a vertex that would need a cell twice is
// left to the splitting (step 4). Below the scale at which the surface
// closes, the solid is a sponge of small pockets, most of whose vertices
// fail: relabeling would erode it cell by cell, slowly, so the repair is
// skipped there.
template <class Cas>
class Manifold_repair
{
public:
  typedef typename Cas::Vertex_handle Vertex_handle;
  typedef typename Cas::Cell_handle   Cell_handle;

  // The repair runs when at most one boundary vertex in this many fails.
  static constexpr std::size_t boundary_vertices_per_bad_vertex = 100;

  // Mends the vertices `bad` (the non-manifold vertices of the boundary last
  // collected in `solid`) and those whose stars the mending changes.
  Manifold_repair(Solid_cells<Cas>& solid, const std::vector<Vertex_handle>& bad)
    : m_cas(solid.shape()), m_solid(solid),
      m_relabeled(m_cas.number_of_cells(), 0), m_star_position(m_cas.number_of_cells(), -1)
  {
    const std::vector<char> on = solid.boundary_vertex_marks();
    const std::size_t on_boundary = std::size_t(std::count(on.begin(), on.end(), char(1)));
    if(boundary_vertices_per_bad_vertex * bad.size() > on_boundary)
      return;
    m_queue = bad;
    Star star;
    while(!m_queue.empty())
    {
      const Vertex_handle v = m_queue.back();
      m_queue.pop_back();
      analyze(v, star);
      if(!is_manifold(star))
        mend(v, star);
    }
  }

  // Cells moved into the solid, and out of it.
  std::size_t number_of_filled_cells() const { return m_filled; }
  std::size_t number_of_carved_cells() const { return m_carved; }

private:
  // The star of a vertex split into facet-connected components of equal
  // label, and the edges of the vertex with more than two boundary facets.
  struct Star
  {
    std::vector<Cell_handle> cells;
    std::vector<int> component;                  // per cell
    std::vector<std::vector<std::size_t> > solid_components, outside_components;
    std::vector<Vertex_handle> bad_edge_ends;    // the other end of each bad edge
  };

  bool is_solid(Cell_handle c) const { return m_solid.is_solid(c); }

  void analyze(Vertex_handle v, Star& s)
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
      if(is_solid(c))
        count_boundary_edges(v, c, edge_counts);
      if(s.component[k] >= 0)
        continue;
      const bool solid = is_solid(c);
      auto& components = solid ? s.solid_components : s.outside_components;
      components.emplace_back(1, k);
      const int id = int(components.size() - 1);
      s.component[k] = id;
      // breadth first: the order of a component's cells is the order in
      // which mending relabels them, and so queues their vertices
      flood_fill(components.back(), Flood_order::breadth_first, [&](std::size_t m, auto&& reach) {
        const Cell_handle d = s.cells[m];
        for(int i = 0; i < 4; ++i)
        {
          if(d->vertex(i) == v)
            continue;  // the facet opposite to v does not contain v
          const Cell_handle n = d->neighbor(i);
          if(is_solid(n) != solid)
            continue;
          const std::size_t position = std::size_t(m_star_position[n->cell_index()]);
          if(s.component[position] < 0)
          {
            s.component[position] = id;
            reach(position);
          }
        }
      });
    }
    for(const auto& e : edge_counts)
      if(e.second > 2)
        s.bad_edge_ends.push_back(e.first);
    for(Cell_handle c : s.cells)
      m_star_position[c->cell_index()] = -1;
  }

  // Counts, for each edge (v, w) of the boundary facets of the solid cell
  // `c` that contain v, one more boundary facet.
  void count_boundary_edges(Vertex_handle v, Cell_handle c,
                            std::vector<std::pair<Vertex_handle, int> >& edge_counts) const
  {
    for(int i = 0; i < 4; ++i)
    {
      if(c->vertex(i) == v || is_solid(c->neighbor(i)))
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
  }

  static bool is_manifold(const Star& s)
  {
    return s.solid_components.size() <= 1 && s.outside_components.size() <= 1 && s.bad_edge_ends.empty();
  }

  // Relabels the cells, unless one of them was relabeled before.
  void relabel_once(const std::vector<Cell_handle>& cells, bool solid)
  {
    for(Cell_handle c : cells)
      if(m_relabeled[c->cell_index()] || (solid && m_cas.is_infinite(c)))
        return;
    for(Cell_handle c : cells)
    {
      m_relabeled[c->cell_index()] = 1;
      if(!m_solid.set_solid(c, solid))
        continue;
      ++(solid ? m_filled : m_carved);
      for(int i = 0; i < 4; ++i)
        if(!m_cas.is_infinite(c->vertex(i)))
          m_queue.push_back(c->vertex(i));
    }
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

  const Cas& m_cas;
  Solid_cells<Cas>& m_solid;
  std::vector<unsigned char> m_relabeled;  // by cell index
  std::vector<int> m_star_position;        // by cell index: its place in the star analyzed, or -1
  std::vector<Vertex_handle> m_queue;      // vertices to analyze
  std::size_t m_filled = 0, m_carved = 0;
};

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_MANIFOLD_REPAIR_H
