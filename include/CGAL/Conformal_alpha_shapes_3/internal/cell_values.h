// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CELL_VALUES_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CELL_VALUES_H

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>

#include <CGAL/determinant.h>
#include <CGAL/tags.h>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The kernel's circumcenter of a cell and squared radius of a facet divide
// by a determinant of coordinate differences, computed in double. A
// tetrahedron or triangle flat to rounding (which the exact predicates may
// still see as non-degenerate, e.g. at wildly different scales) makes it 0:
// the construction is then undefined (NaN, or an assertion in debug
// builds). The same determinants, computed the same way, tell beforehand:
// the circumcenter of (p, q, r, s) divides by det(q - p, r - p, s - p), the
// squared radius of the facet (a, b, c) by det(a - c, b - c, (a - c) x (b - c)),
// with the facet opposite to vertex i taken as (i + 1, i + 2, i + 3) as in
// ordinary_alpha().
template <class Dt>
bool constructions_are_defined(typename Dt::Cell_handle c)
{
  typedef typename Dt::Point Point;
  auto usable = [](double d) { return d != 0 && std::isfinite(d); };
  const Point& p = c->vertex(0)->point();
  const Point& q = c->vertex(1)->point();
  const Point& r = c->vertex(2)->point();
  const Point& s = c->vertex(3)->point();
  if(!usable(CGAL::determinant(q.x() - p.x(), q.y() - p.y(), q.z() - p.z(),
                               r.x() - p.x(), r.y() - p.y(), r.z() - p.z(),
                               s.x() - p.x(), s.y() - p.y(), s.z() - p.z())))
    return false;
  for(int i = 0; i < 4; ++i)
  {
    const Point& a = c->vertex((i + 1) & 3)->point();
    const Point& b = c->vertex((i + 2) & 3)->point();
    const Point& o = c->vertex((i + 3) & 3)->point();
    const double ax = a.x() - o.x(), ay = a.y() - o.y(), az = a.z() - o.z();
    const double bx = b.x() - o.x(), by = b.y() - o.y(), bz = b.z() - o.z();
    const double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
    if(!usable(CGAL::determinant(ax, ay, az, bx, by, bz, nx, ny, nz)))
      return false;
  }
  return true;
}

// One pass over the cells (by index) stores each cell's radius and which
// of its facets its vertices encroach, and writes the circumcenters
// (indexed by cell index) into `centers`, for the poles. The vertex opposite to a facet
// lies strictly inside the facet's smallest circumscribing ball exactly
// when the cell's circumcenter lies strictly beyond the facet's plane: the
// centers of the balls through the facet's circle lie on one line, and
// the opposite vertex's power changes sign with the center's side. This
// is a filtered orientation test, much cheaper than
// Side_of_bounded_sphere_3.
// Returns false, with some cells unset, when a circumcenter or radius is not
// finite (or the radius is 0): the later predicates would run on NaN or
// infinity.
template <class Dt>
bool store_cell_values(const Dt& dt, const std::vector<typename Dt::Cell_handle>& cells,
                       std::vector<typename Dt::Point>& centers)
{
  typedef typename Dt::Geom_traits Gt;
  typedef typename Dt::Point Point;
  typedef typename Dt::Cell_handle Cell_handle;
  const Gt& gt = dt.geom_traits();
  typename Gt::Construct_circumcenter_3 circumcenter = gt.construct_circumcenter_3_object();
  typename Gt::Compute_squared_distance_3 squared_distance = gt.compute_squared_distance_3_object();
  typename Gt::Orientation_3 orientation = gt.orientation_3_object();

  // each cell's values are its own: computed on TBB's threads when
  // available, with the same results
  centers.clear();
  centers.resize(cells.size());
  std::atomic<bool> undefined(false);
  for_each_index<Parallel_if_available_tag>(
    cells.size(), []() { return 0; }, [&](std::size_t index, int) {
      const Cell_handle c = cells[index];
      if(dt.is_infinite(c))
      {
        c->set_alpha(std::numeric_limits<double>::infinity());
        for(int i = 0; i < 4; ++i)
          c->set_encroaches_facet(i, false);
        return;
      }
      if(!constructions_are_defined<Dt>(c))
      {
        undefined = true;
        return;
      }
      const Point& center = centers[index] =
        circumcenter(c->vertex(0)->point(), c->vertex(1)->point(),
                     c->vertex(2)->point(), c->vertex(3)->point());
      const double radius = std::sqrt(squared_distance(center, c->vertex(0)->point()));
      if(!(std::isfinite(center.x()) && std::isfinite(center.y()) && std::isfinite(center.z())
           && std::isfinite(radius) && radius > 0))
      {
        undefined = true;
        return;
      }
      c->set_alpha(radius);
      for(int i = 0; i < 4; ++i)
      {
        // (v[i+1], v[i+2], v[i+3], v[i]) is a cyclic shift of a positive cell
        const Orientation vertex_side = (i % 2 == 0) ? NEGATIVE : POSITIVE;
        const Orientation center_side = orientation(c->vertex((i + 1) & 3)->point(),
                                                    c->vertex((i + 2) & 3)->point(),
                                                    c->vertex((i + 3) & 3)->point(), center);
        c->set_encroaches_facet(i, center_side == -vertex_side);
      }
    });
  return !undefined;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CELL_VALUES_H
