// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_VERTICES_BY_INDEX_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_VERTICES_BY_INDEX_H

#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The finite vertices of a triangulation whose vertices carry their
// `vertex_index()` (from 0 to the number of vertices), by that index: the
// passes that index their values by vertex reach the vertices through it.
template <class Triangulation>
std::vector<typename Triangulation::Vertex_handle> vertices_by_index(const Triangulation& t)
{
  std::vector<typename Triangulation::Vertex_handle> by_index(t.number_of_vertices());
  for(const typename Triangulation::Vertex_handle v : t.finite_vertex_handles())
    by_index[v->vertex_index()] = v;
  return by_index;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_VERTICES_BY_INDEX_H
