// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CRITICAL_VALUES_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CRITICAL_VALUES_H

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The three values at which a simplex of a `Conformal_alpha_shape_3`
// changes class, as in Alpha_shape_3: it enters the complex at `own`, gets a
// coface in it at `mid`, and all its cells are in it at `max` (never, when
// it lies on the convex hull).
template <class FT>
struct Critical_values
{
  FT own, mid, max;
  bool on_hull;
};

template <class Cas>
Critical_values<typename Cas::FT> facet_status(const Cas& cas, typename Cas::Cell_handle c, int i)
{
  typedef typename Cas::FT FT;
  typedef typename Cas::Cell_handle Cell_handle;
  const Cell_handle n = c->neighbor(i);
  const FT a = cas.conformal_alpha(c), b = cas.conformal_alpha(n);
  return Critical_values<FT>{cas.conformal_alpha(c, i), (std::min)(a, b), (std::max)(a, b),
                         cas.is_infinite(c) || cas.is_infinite(n)};
}

// An edge is Gabriel when no vertex of an incident cell lies strictly
// inside its diametral ball; otherwise it is attached to its smallest
// incident facet.
template <class Cas>
typename Cas::FT edge_ordinary_alpha(const Cas& cas, typename Cas::Cell_handle c, typename Cas::Vertex_handle p,
                                     typename Cas::Vertex_handle q)
{
  typedef typename Cas::FT FT;
  typedef typename Cas::Cell_handle Cell_handle;
  typedef typename Cas::Vertex_handle Vertex_handle;
  typename Cas::Geom_traits::Side_of_bounded_sphere_3 side = cas.geom_traits().side_of_bounded_sphere_3_object();
  bool gabriel = true;
  FT smallest_facet = std::numeric_limits<FT>::infinity();
  typename Cas::Cell_circulator cc = cas.incident_cells(c, c->index(p), c->index(q)), done = cc;
  do
  {
    const int i = cc->index(p), j = cc->index(q);
    for(int k = 0; k < 4; ++k)
    {
      if(k == i || k == j)
        continue;
      const Vertex_handle s = cc->vertex(k);
      if(cas.is_infinite(s))
        continue;
      if(gabriel && side(p->point(), q->point(), s->point()) == ON_BOUNDED_SIDE)
        gabriel = false;
      // the facet opposite to the other vertex holds p, q and s
      smallest_facet = (std::min)(smallest_facet, cas.ordinary_alpha(Cell_handle(cc), 6 - i - j - k));
    }
  } while(++cc != done);
  if(gabriel)
    return std::sqrt(cas.geom_traits().compute_squared_radius_3_object()(p->point(), q->point()));
  return smallest_facet;
}

template <class Cas>
Critical_values<typename Cas::FT> edge_status(const Cas& cas, typename Cas::Cell_handle c, int i, int j)
{
  typedef typename Cas::FT FT;
  typedef typename Cas::Cell_handle Cell_handle;
  typedef typename Cas::Vertex_handle Vertex_handle;
  const Vertex_handle p = c->vertex(i), q = c->vertex(j);
  Critical_values<FT> s{edge_ordinary_alpha(cas, c, p, q) / (std::min)(p->local_feature_size(), q->local_feature_size()),
                    std::numeric_limits<FT>::infinity(), FT(0), false};
  typename Cas::Cell_circulator cc = cas.incident_cells(c, i, j), done = cc;
  do
  {
    if(cas.is_infinite(cc))
    {
      s.on_hull = true;
    }
    else
    {
      s.max = (std::max)(s.max, cas.conformal_alpha(Cell_handle(cc)));
      for(int k = 0; k < 4; ++k)
        if(cc->vertex(k) != p && cc->vertex(k) != q)
          s.mid = (std::min)(s.mid, cas.conformal_alpha(Cell_handle(cc), k));
    }
  } while(++cc != done);
  return s;
}

template <class Cas>
Critical_values<typename Cas::FT> vertex_status(const Cas& cas, typename Cas::Vertex_handle v)
{
  typedef typename Cas::FT FT;
  typedef typename Cas::Cell_handle Cell_handle;
  Critical_values<FT> s{FT(0), std::numeric_limits<FT>::infinity(), FT(0), false};
  std::vector<Cell_handle> cells;
  cas.incident_cells(v, std::back_inserter(cells));
  for(Cell_handle c : cells)
  {
    if(cas.is_infinite(c))
    {
      s.on_hull = true;
      continue;
    }
    s.max = (std::max)(s.max, cas.conformal_alpha(c));
  }
  std::vector<typename Cas::Edge> edges;
  cas.finite_incident_edges(v, std::back_inserter(edges));
  for(const typename Cas::Edge& e : edges)
    s.mid = (std::min)(s.mid, cas.conformal_alpha(e));
  return s;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CRITICAL_VALUES_H
