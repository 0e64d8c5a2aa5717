// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SURFACE_FEET_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SURFACE_FEET_H

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/shape_vertex_table.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// Where a vertex of the shape without a value of its own meets the surface:
// the nearest point of the surface, on `face`; `face` is null when the
// vertex is farther than `far_from_surface()` local spacings.
template <class Point, class Face>
struct Surface_foot
{
  std::size_t shape_vertex;  // vertex index
  Point point;
  Face face;
  double distance;
};

// The faces of `pmesh` that may hold a point within `reach[k]` of
// `queries[k]` for some k, in the order of `all` (the faces of `pmesh`):
// every face whose bounding box meets a grid cell that a query's ball's box
// meets, and every face across many cells: a superset; all of them when a
// reach is not finite.
template <class ConcurrencyTag, class Point, class PolygonMesh, class VertexPointMap>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>
faces_within_reach(const PolygonMesh& pmesh, const VertexPointMap& vpm,
                   const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& all,
                   const CGAL::Bbox_3& box, const std::vector<Point>& queries, const std::vector<double>& reach)
{
  double largest = 0;
  for(double r : reach)
    largest = (std::max)(largest, r);
  if(!std::isfinite(largest))
    return all;
  // cells as wide as the largest reach, at most 256 along the box's longest side
  const double extent = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  const double cell = (std::max)({largest, extent / 256, (std::numeric_limits<double>::min)()});
  int size[3];
  for(int i = 0; i < 3; ++i)
    size[i] = int(std::floor((box.max(i) - box.min(i)) / cell)) + 1;
  auto cell_of = [&](double x, int i) {  // clamped before the conversion, which could overflow
    return int((std::min)(double(size[i] - 1), (std::max)(0., std::floor((x - box.min(i)) / cell))));
  };
  auto at = [&](int x, int y, int z) {
    return (std::size_t(x) * std::size_t(size[1]) + std::size_t(y)) * std::size_t(size[2]) + std::size_t(z);
  };
  std::vector<char> marked(std::size_t(size[0]) * std::size_t(size[1]) * std::size_t(size[2]), 0);
  for(std::size_t k = 0; k < queries.size(); ++k)
  {
    const CGAL::Bbox_3 q = queries[k].bbox();
    for(int x = cell_of(q.xmin() - reach[k], 0); x <= cell_of(q.xmax() + reach[k], 0); ++x)
      for(int y = cell_of(q.ymin() - reach[k], 1); y <= cell_of(q.ymax() + reach[k], 1); ++y)
        for(int z = cell_of(q.zmin() - reach[k], 2); z <= cell_of(q.zmax() + reach[k], 2); ++z)
          marked[at(x, y, z)] = 1;
  }
  std::vector<char> kept(all.size(), 0);
  for_each_index<ConcurrencyTag>(all.size(), []() { return 0; }, [&](std::size_t f, int) {
    CGAL::Bbox_3 b;
    for(auto v : CGAL::vertices_around_face(halfedge(all[f], pmesh), pmesh))
      b += get(vpm, v).bbox();
    const int from[3] = {cell_of(b.xmin(), 0), cell_of(b.ymin(), 1), cell_of(b.zmin(), 2)};
    const int to[3] = {cell_of(b.xmax(), 0), cell_of(b.ymax(), 1), cell_of(b.zmax(), 2)};
    // a face across many cells is kept unchecked
    kept[f] = (to[0] - from[0] + 1) * (to[1] - from[1] + 1) * (to[2] - from[2] + 1) > 64;
    for(int x = from[0]; x <= to[0] && !kept[f]; ++x)
      for(int y = from[1]; y <= to[1] && !kept[f]; ++y)
        for(int z = from[2]; z <= to[2] && !kept[f]; ++z)
          kept[f] = marked[at(x, y, z)];
  });
  std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> within;
  for(std::size_t f = 0; f < all.size(); ++f)
    if(kept[f])
      within.push_back(all[f]);
  return within;
}

// The feet on `pmesh` of the shape's vertices that `needs` flags, sorted by
// vertex (the far ones are dropped by drop_far_feet()); none when `pmesh`
// is empty. A vertex's foot does not depend on which others are searched
// with it, but for which of several faces equally near it names. The
// search tree is built over the faces within `reach` (by flagged vertex,
// in the same order; infinite for the whole surface) of the vertices, and
// again with twice the reach for those whose nearest face there is
// farther: a point nearer than the reach is on a face within it. A few
// points off a large surface then do not pay for a tree over all of it;
// the search tree is freed on return.
template <class ConcurrencyTag, class GT, class PolygonMesh, class VertexPointMap>
std::vector<Surface_foot<typename GT::Point_3, typename boost::graph_traits<PolygonMesh>::face_descriptor> >
surface_feet(const Shape_vertex_table<typename GT::Point_3>& table, const PolygonMesh& pmesh,
             const VertexPointMap& vpm, const std::vector<bool>& needs, std::vector<double> reach)
{
  typedef typename GT::Point_3 Point;
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  typedef Surface_foot<Point, face_descriptor> Foot;
  std::vector<std::size_t> footless;
  for(std::size_t v = 0; v < needs.size(); ++v)
    if(needs[v])
      footless.push_back(v);
  CGAL_precondition(reach.size() == footless.size());
  const std::vector<face_descriptor> all(faces(pmesh).first, faces(pmesh).second);
  if(footless.empty() || all.empty())
    return std::vector<Foot>();
  CGAL::Bbox_3 box;
  for(auto v : vertices(pmesh))
    box += get(vpm, v).bbox();
  const double smallest_reach =
    (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()}) / 256;
  std::vector<Foot> feet(footless.size());
  std::vector<std::size_t> pending(footless.size());
  for(std::size_t k = 0; k < pending.size(); ++k)
    pending[k] = k;
  while(!pending.empty())
  {
    std::vector<Point> queries;
    std::vector<double> pending_reach;
    for(std::size_t k : pending)
    {
      queries.push_back(table.points[footless[k]]);
      pending_reach.push_back(reach[k]);
    }
    const std::vector<face_descriptor> within =
      faces_within_reach<ConcurrencyTag>(pmesh, vpm, all, box, queries, pending_reach);
    const bool whole_surface = within.size() == all.size();
    std::vector<char> found(pending.size(), 0);
    if(!within.empty())
    {
      typedef CGAL::AABB_face_graph_triangle_primitive<PolygonMesh, VertexPointMap> Primitive;
      CGAL::AABB_tree<CGAL::AABB_traits<GT, Primitive> > tree;
      tree.insert(within.begin(), within.end(), pmesh, vpm);
      // the search tree of the faces in their order, then the hierarchy,
      // which sorts them: where several faces are nearest, the one found
      // depends on that order
      tree.accelerate_distance_queries();
      tree.build();
      for_each_index<ConcurrencyTag>(pending.size(), []() { return 0; }, [&](std::size_t j, int&) {
        const auto nearest = tree.closest_point_and_primitive(queries[j]);
        const double distance = std::sqrt(CGAL::to_double(CGAL::squared_distance(queries[j], nearest.first)));
        if(whole_surface || distance <= pending_reach[j])
        {
          feet[pending[j]] = Foot{footless[pending[j]], nearest.first, nearest.second, distance};
          found[j] = 1;
        }
      });
    }
    std::vector<std::size_t> farther;
    for(std::size_t j = 0; j < pending.size(); ++j)
      if(!found[j])
      {
        farther.push_back(pending[j]);
        reach[pending[j]] = (std::max)(2 * reach[pending[j]], smallest_reach);
      }
    pending.swap(farther);
  }
  return feet;
}

// Makes none the feet (from surface_feet()) beyond their vertex's distance
// in `far` (from far_distances(), of the same vertices).
template <class Foot>
void drop_far_feet(std::vector<Foot>& feet, const std::vector<double>& far)
{
  for(std::size_t k = 0; k < feet.size(); ++k)
    if(feet[k].distance > far[k])
      feet[k].face = decltype(feet[k].face)();
}

// Adds to `feet` (sorted by vertex) the feet of the vertices that `needs`
// flags and that have none yet: vertices of the surface without a value in
// some layer, whose feet are on the surface, never far; their search
// starts with no reach, which surface_feet() widens until it finds a face.
template <class ConcurrencyTag, class GT, class PolygonMesh, class VertexPointMap, class Foot>
void add_feet_on_surface(const Shape_vertex_table<typename GT::Point_3>& table, const PolygonMesh& pmesh,
                         const VertexPointMap& vpm, std::vector<bool> needs, std::vector<Foot>& feet)
{
  for(const Foot& foot : feet)
    needs[foot.shape_vertex] = false;
  const std::size_t count = std::size_t(std::count(needs.begin(), needs.end(), true));
  const std::vector<Foot> on_surface =
    surface_feet<ConcurrencyTag, GT>(table, pmesh, vpm, needs, std::vector<double>(count, 0.));
  const std::size_t off_surface = feet.size();
  feet.insert(feet.end(), on_surface.begin(), on_surface.end());
  std::inplace_merge(feet.begin(), feet.begin() + std::ptrdiff_t(off_surface), feet.end(),
                     [](const Foot& x, const Foot& y) { return x.shape_vertex < y.shape_vertex; });
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SURFACE_FEET_H
