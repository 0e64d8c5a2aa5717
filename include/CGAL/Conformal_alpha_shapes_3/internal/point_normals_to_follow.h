// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_POINT_NORMALS_TO_FOLLOW_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_POINT_NORMALS_TO_FOLLOW_H

#include <CGAL/Conformal_alpha_shapes_3/internal/orient_surface_parts.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Origin.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// By kept point, the reference normal its values follow (`reference_normals`
// by kept point, `kept_index` by input index): its own where the reference
// normals of its sheet (a connected part of `surface`) are consistent, as
// extract_surface() decides it (at least 3/4 of its vertices agree with the
// sheet), else none (a null vector); a point off the surface follows its
// own when most of the surface's vertices do.
template <class Point, class Vector>
std::vector<Vector> point_normals_to_follow(const CGAL::Surface_mesh<Point>& surface,
                                            const std::vector<Vector>& reference_normals,
                                            const std::vector<std::size_t>& kept_index)
{
  typedef CGAL::Surface_mesh<Point> Surface;
  typedef typename Surface::Vertex_index Surface_vertex;
  if(reference_normals.empty())
    return {};
  const auto input_index = surface.template property_map<Surface_vertex, std::size_t>("v:input_index").first;
  std::vector<std::size_t> root(surface.num_vertices());
  for(std::size_t v = 0; v < root.size(); ++v)
    root[v] = v;
  auto find = [&](std::size_t v) {
    while(root[v] != v)
      v = root[v] = root[root[v]];
    return v;
  };
  std::vector<Vector> oriented(surface.num_vertices(), Vector(CGAL::NULL_VECTOR));
  for(typename Surface::Face_index f : surface.faces())
  {
    const typename Surface::Halfedge_index h = surface.halfedge(f);
    const Surface_vertex a = surface.source(h), b = surface.target(h), c = surface.target(surface.next(h));
    const Vector area_normal = CGAL::cross_product(surface.point(b) - surface.point(a),
                                                   surface.point(c) - surface.point(a));
    for(Surface_vertex v : {a, b, c})
      oriented[v.idx()] = oriented[v.idx()] + area_normal;
    root[find(a.idx())] = find(b.idx());
    root[find(b.idx())] = find(c.idx());
  }
  std::vector<std::size_t> agree(root.size(), 0), count(root.size(), 0);
  for(Surface_vertex v : surface.vertices())
  {
    const std::size_t r = find(v.idx());
    agree[r] += oriented[v.idx()] * reference_normals[kept_index[input_index[v]]] > 0 ? 1 : 0;
    ++count[r];
  }
  std::vector<Vector> follow(reference_normals.size(), Vector(CGAL::NULL_VECTOR));
  std::size_t following = 0;
  std::vector<bool> on_surface(reference_normals.size(), false);
  for(Surface_vertex v : surface.vertices())
  {
    const std::size_t r = find(v.idx()), k = kept_index[input_index[v]];
    on_surface[k] = true;
    if(double(agree[r]) >= consistent_share * double(count[r]))
    {
      follow[k] = reference_normals[k];
      ++following;
    }
  }
  if(2 * following > surface.number_of_vertices())
    for(std::size_t k = 0; k < follow.size(); ++k)
      if(!on_surface[k])
        follow[k] = reference_normals[k];
  return follow;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_POINT_NORMALS_TO_FOLLOW_H
