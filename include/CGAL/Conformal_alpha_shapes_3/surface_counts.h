// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_SURFACE_COUNTS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_SURFACE_COUNTS_H

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/// \ingroup PkgConformalAlphaShapes3Surface
/// What any surface extraction reports: its size and the input points it covers.
struct Surface_counts
{
  /// faces written to the mesh
  std::size_t number_of_faces = 0;
  /// vertices written to the mesh
  std::size_t number_of_vertices = 0;
  /// input points whose vertex is not on the surface (duplicates counted)
  std::size_t number_of_points_off_surface = 0;
  /// input points of the shape
  std::size_t number_of_input_points = 0;

  /// `true` when the surface has no face (for example, below every facet value)
  bool empty() const { return number_of_faces == 0; }
  /// the share of input points on the surface, in `[0, 1]`
  double fraction_of_points_on_surface() const
  {
    return number_of_input_points == 0
             ? 0.0
             : double(number_of_input_points - number_of_points_off_surface) / double(number_of_input_points);
  }
};

namespace internal {

// The number of input points whose vertex is not marked in `on` (indexed by
// `vertex_index()`).
template <class Cas>
std::size_t number_of_points_off(const Cas& cas, const std::vector<char>& on)
{
  std::size_t off = 0;
  for(typename Cas::Vertex_handle v : cas.finite_vertex_handles())
    if(!on[v->vertex_index()])
      off += std::size_t(cas.input_indices(v).size());
  return off;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_SURFACE_COUNTS_H
