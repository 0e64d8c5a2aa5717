// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_VERTEX_CLOSING_VALUE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_VERTEX_CLOSING_VALUE_H

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The buffers of `vertex_closing_value()`, kept by a thread from vertex to vertex.
template <class Shape>
struct Closing_workspace
{
  struct Link_edge
  {
    double value;
    std::size_t a, b; // positions in `link`
  };
  std::vector<typename Shape::Cell_handle> cells;
  std::vector<typename Shape::Facet> facets;
  std::vector<Link_edge> edges;
  std::vector<typename Shape::Vertex_handle> link;
  std::vector<double> angle;     // of each link vertex about the axis
  std::vector<std::size_t> parent;
  std::vector<double> turn;      // angle from the vertex to its parent, unwrapped
};

// The finite facets incident to `v` into ws.facets, each once: a walk over
// the cells around `v` that keeps its visited cells in the workspace (a
// star holds a few dozen), where the triangulation's thread-safe walk
// allocates a hash set of cells per vertex, whose allocations cost more
// than the walk.
template <class Shape>
void finite_facets_around(const Shape& shape, typename Shape::Vertex_handle v, Closing_workspace<Shape>& ws)
{
  typedef typename Shape::Cell_handle Cell_handle;
  ws.facets.clear();
  ws.cells.clear();
  ws.cells.push_back(v->cell());
  for(std::size_t head = 0; head < ws.cells.size(); ++head)
  {
    const Cell_handle c = ws.cells[head];
    for(int i = 0; i < 4; ++i)
    {
      if(c->vertex(i) == v)
        continue;
      const Cell_handle next = c->neighbor(i);
      if(c < next && !shape.is_infinite(c, i))
        ws.facets.emplace_back(c, i);
      if(std::find(ws.cells.begin(), ws.cells.end(), next) == ws.cells.end())
        ws.cells.push_back(next);
    }
  }
}

// The closing value of `v`: the smallest conformal value at which the finite
// facets of the complex around `v` hold a fan that turns once around it,
// seen along the axis from `v` to its pole; NaN when no fan of finite
// facets does (a vertex of the convex hull with its outside open).
// It reads the star of `v` only, so a piece of the cloud with a halo gives
// its core the values of the whole cloud, and, as a threshold over a set of
// facets, it does not depend on the order of facets of equal value.
// The facets are added by increasing value to a union-find over the link's
// vertices that carries each vertex's angle from its root (unwrapped along
// the tree): an edge joining two vertices of one tree closes a cycle whose
// total turn is that edge's wrapped angle plus the tree's path, a multiple
// of a full turn; a nonzero multiple is a fan around `v`.
template <class Shape>
double vertex_closing_value(const Shape& shape, typename Shape::Vertex_handle v, Closing_workspace<Shape>& ws)
{
  typedef typename Shape::Geom_traits::Vector_3 Vector;
  ws.edges.clear();
  ws.link.clear();
  ws.angle.clear();
  finite_facets_around(shape, v, ws);

  const auto& p = v->point();
  Vector axis = shape.pole(v) - p;
  axis = axis / std::sqrt(CGAL::to_double(axis.squared_length()));
  Vector e1 = CGAL::cross_product(axis, std::abs(CGAL::to_double(axis.x())) < 0.6 ? Vector(1, 0, 0) : Vector(0, 1, 0));
  e1 = e1 / std::sqrt(CGAL::to_double(e1.squared_length()));
  const Vector e2 = CGAL::cross_product(axis, e1);
  auto position = [&](typename Shape::Vertex_handle w) {
    const auto found = std::find(ws.link.begin(), ws.link.end(), w);
    if(found != ws.link.end())
      return std::size_t(found - ws.link.begin());
    const Vector d = w->point() - p;
    ws.link.push_back(w);
    ws.angle.push_back(std::atan2(CGAL::to_double(d * e2), CGAL::to_double(d * e1)));
    return ws.link.size() - 1;
  };
  for(const typename Shape::Facet& f : ws.facets)
  {
    std::size_t ends[2], k = 0;
    for(int j = 1; j < 4; ++j)
      if(f.first->vertex((f.second + j) & 3) != v)
        ends[k++] = position(f.first->vertex((f.second + j) & 3));
    ws.edges.push_back({double(shape.conformal_alpha(f)), ends[0], ends[1]});
  }
  std::sort(ws.edges.begin(), ws.edges.end(),
            [](const auto& x, const auto& y) { return x.value < y.value; });

  ws.parent.resize(ws.link.size());
  ws.turn.assign(ws.link.size(), 0.0);
  for(std::size_t k = 0; k < ws.link.size(); ++k)
    ws.parent[k] = k;
  // the root of x, with turn[x] made the angle from the root to x
  auto find = [&](std::size_t x) {
    std::size_t root = x;
    double total = 0;
    while(ws.parent[root] != root)
    {
      total += ws.turn[root];
      root = ws.parent[root];
    }
    while(ws.parent[x] != root)
    {
      const std::size_t next = ws.parent[x];
      const double rest = total - ws.turn[x];
      ws.turn[x] = total;
      ws.parent[x] = root;
      x = next;
      total = rest;
    }
    return root;
  };
  for(const auto& e : ws.edges)
  {
    double step = ws.angle[e.b] - ws.angle[e.a];
    if(step > CGAL_PI)
      step -= 2 * CGAL_PI;
    else if(step <= -CGAL_PI)
      step += 2 * CGAL_PI;
    const std::size_t ra = find(e.a), rb = find(e.b);
    if(ra != rb)
    {
      ws.parent[rb] = ra;
      ws.turn[rb] = ws.turn[e.a] + step - ws.turn[e.b];
    }
    else if(std::abs(ws.turn[e.a] + step - ws.turn[e.b]) > CGAL_PI)
      return e.value;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_VERTEX_CLOSING_VALUE_H
