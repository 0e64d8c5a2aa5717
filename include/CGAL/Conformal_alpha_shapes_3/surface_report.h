// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_SURFACE_REPORT_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_SURFACE_REPORT_H

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/// \ingroup PkgConformalAlphaShapes3Surface
/// How `extract_surface()` chooses a surface among the facets of the complex
/// (named parameter `surface_extraction`).
enum Surface_extraction
{
  /// one sheet per part of the sampled surface, grown facet by facet
  /// (`Surface_front`), closed or with a border: the default
  ADVANCING_FRONT,
  /// the boundary of the solid the facets enclose, closed by construction
  SOLID_BOUNDARY
};

/// \ingroup PkgConformalAlphaShapes3Surface
/// What `extract_surface()` did. The counts of a step that the extraction
/// method does not have stay 0.
struct Surface_report
{
  /// faces written to the mesh
  std::size_t number_of_faces = 0;
  /// vertices written to the mesh
  std::size_t number_of_vertices = 0;
  /// input points whose vertex is not on the surface (duplicates counted)
  std::size_t number_of_points_off_surface = 0;
  /// input points of the shape
  std::size_t number_of_input_points = 0;

  /// connected sheets of the surface
  std::size_t number_of_parts = 0;
  /// sheets without border
  std::size_t number_of_closed_parts = 0;

  /// \name Advancing front
  /// @{
  /// pieces grown separately that were turned to follow the orientation
  /// rule (from the canonical orientation in which the front is kept)
  std::size_t number_of_reversed_parts = 0;
  /// whether reference normals were given
  bool oriented_by_reference_normals = false;
  /// sheets whose reference normals are not consistent (about as many
  /// point to one side as to the other: random signs), oriented as
  /// without reference normals
  std::size_t number_of_sheets_with_inconsistent_normals = 0;
  /// the share of the surface's vertices whose reference normal points to
  /// the side their sheet faces (NaN without reference normals)
  double reference_normal_agreement = std::numeric_limits<double>::quiet_NaN();
  /// @}

  /// \name Solid boundary
  /// @{
  /// facets `REGULAR` or `SINGULAR` at the scale
  std::size_t number_of_candidate_facets = 0;
  /// candidate facets that do not bound the solid (dangling, or inside it)
  std::size_t number_of_dropped_facets = 0;
  /// cells moved into the solid to mend non-manifold vertices
  std::size_t number_of_filled_cells = 0;
  /// cells moved out of the solid to mend non-manifold vertices
  std::size_t number_of_carved_cells = 0;
  /// cells removed to bring points just inside the surface onto it
  std::size_t number_of_sculpted_cells = 0;
  /// vertices given a copy per umbrella where the surface still pinches
  std::size_t number_of_pinched_vertices = 0;
  /// @}

  /// `true` when the surface has no face (for example, below every facet value)
  bool empty() const { return number_of_faces == 0; }
  /// sheets with a border
  std::size_t number_of_open_parts() const { return number_of_parts - number_of_closed_parts; }
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

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_SURFACE_REPORT_H
