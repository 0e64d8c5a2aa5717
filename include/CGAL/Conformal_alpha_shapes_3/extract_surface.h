// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_EXTRACT_SURFACE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_EXTRACT_SURFACE_H

#include <CGAL/Conformal_alpha_shapes_3/internal/advancing_front_facets.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/orient_surface_parts.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_counts.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/// \ingroup PkgConformalAlphaShapes3Surface
/// How a surface is chosen among the facets of the complex.
enum Surface_extraction
{
  /// one sheet per part of the sampled surface, grown facet by facet
  /// (`extract_surface()`), the default
  ADVANCING_FRONT,
  /// the boundary of the solid the facets enclose
  /// (`extract_boundary_surface()`), closed by construction
  SOLID_BOUNDARY
};

/// \ingroup PkgConformalAlphaShapes3Surface
/// What `extract_surface()` did.
struct Surface_report : Surface_counts
{
  /// connected sheets of the surface
  std::size_t number_of_parts = 0;
  /// sheets without border
  std::size_t number_of_closed_parts = 0;
  /// pieces grown separately that were turned to follow the orientation
  /// rule (from the canonical orientation in which the advancing front's
  /// surface is kept)
  std::size_t number_of_reversed_parts = 0;
  /// whether reference normals decided the orientation
  bool oriented_by_reference_normals = false;

  /// sheets with a border
  std::size_t number_of_open_parts() const { return number_of_parts - number_of_closed_parts; }
};

namespace internal {

// `extract_surface()` of a soup of `cas` (`advancing_front_soup()`, cut
// at the scale by `pruned_soup()`): its parts joined into sheets and
// oriented, written into `pmesh`.
template <class ConformalAlphaShape, class PolygonMesh, class NamedParameters>
Surface_report surface_of_soup(const ConformalAlphaShape& cas, Advancing_front_soup soup, PolygonMesh& pmesh,
                               const NamedParameters& np)
{
  typedef ConformalAlphaShape Cas;
  typedef typename Cas::Geom_traits::Vector_3 Vector;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NamedParameters>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Mesh_point;
  typedef CGAL::Constant_property_map<vertex_descriptor, std::size_t> Default_index_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
    internal_np_cas3::vertex_input_index_map_t, NamedParameters, Default_index_map>::type Index_map;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;

  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_property_map(CGAL::vertex_point, pmesh));
  Index_map input_index = choose_parameter(get_parameter(np, internal_np_cas3::vertex_input_index_map),
                                           Default_index_map());
  const std::vector<Vector> no_normals;
  const auto& reference_normals = choose_parameter(get_parameter_reference(np, internal_np_cas3::reference_normals),
                                                   no_normals);

  Surface_report report;
  report.number_of_input_points = cas.number_of_input_points();
  report.number_of_points_off_surface = cas.number_of_input_points();
  if(cas.dimension() < 3)
    return report;

  std::vector<typename Cas::Vertex_handle> shape_vertex(cas.number_of_vertices());
  for(typename Cas::Vertex_handle v : cas.finite_vertex_handles())
    shape_vertex[v->vertex_index()] = v;
  auto point = [&](std::size_t s) { return shape_vertex[soup.shape_vertex[s]]->point(); };
  const bool has_reference = !reference_normals.empty();
  auto reference = [&](std::size_t s) {
    return Vector(reference_normals[*cas.input_indices(shape_vertex[soup.shape_vertex[s]]).begin()]);
  };
  if(has_reference)
    internal::cut_at_reference_folds<Vector>(soup, point, reference);
  const internal::Soup_parts parts = internal::soup_parts(soup);
  const internal::Soup_sheets sheets = internal::soup_sheets(soup, parts);
  const internal::Sheet_groups groups = has_reference
    ? internal::Sheet_groups::one_per_sheet(sheets.size())
    : internal::join_open_sheets_across_gaps<Vector>(soup, parts, sheets, point);
  const std::vector<char> reverse =
    internal::parts_to_reverse<Vector>(soup, parts, sheets, groups, point, reference, has_reference);

  report.number_of_parts = sheets.size();
  for(std::size_t s = 0; s < sheets.size(); ++s)
    report.number_of_closed_parts += sheets.closed[s] ? 1 : 0;
  for(std::size_t p = 0; p < parts.size(); ++p)
    report.number_of_reversed_parts += reverse[p] ? 1 : 0;
  report.oriented_by_reference_normals = has_reference;

  std::vector<vertex_descriptor> mesh_vertex(soup.shape_vertex.size());
  for(std::size_t s = 0; s < soup.shape_vertex.size(); ++s)
  {
    mesh_vertex[s] = add_vertex(pmesh);
    const typename Cas::Point& p = point(s);
    put(vpm, mesh_vertex[s], Mesh_point(p.x(), p.y(), p.z()));
    put(input_index, mesh_vertex[s], *cas.input_indices(shape_vertex[soup.shape_vertex[s]]).begin());
  }
  report.number_of_vertices = soup.shape_vertex.size();

  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const std::array<std::size_t, 3>& tri = soup.triangles[t];
    const bool flip = reverse[parts.part_of_triangle[t]] != 0;
    const std::array<vertex_descriptor, 3> face = {mesh_vertex[tri[0]], mesh_vertex[flip ? tri[2] : tri[1]],
                                                   mesh_vertex[flip ? tri[1] : tri[2]]};
    if(CGAL::Euler::add_face(face, pmesh) != boost::graph_traits<PolygonMesh>::null_face())
      ++report.number_of_faces;
  }

  std::vector<char> on(cas.number_of_vertices(), 0);
  for(std::size_t s : soup.shape_vertex)
    on[s] = 1;
  report.number_of_points_off_surface = internal::number_of_points_off(cas, on);
  return report;
}

} // namespace internal

/*!
\ingroup PkgConformalAlphaShapes3Surface

Writes into `pmesh` the surface of the conformal alpha shape `cas` at scale
`a`: one oriented 2-manifold sheet per part of the sampled surface, closed
where the sample is closed and with a border where it stops (a single view,
a facade), whose faces are facets of the triangulation.

The sheet is grown facet by facet from the smallest conformal value, as
CGAL's `Advancing_front_surface_reconstruction` grows a surface, over the
Delaunay facets with no bound on the scale. (Facets between two cells of
the complex are candidates too: under noise, the flat cells along the
sampled surface enter the complex before the surface closes, and the
facets between them are the surface.) The front only grows where the
surface stays a manifold, so a noisy layer gives one sheet, not a shell
with an inner wall, and an open scan one sheet with a border, not a
two-sided slab. The surface at `a` is that sheet less its faces whose
conformal value exceeds `a`: their neighbors get a border there, and
pieces of fewer than 8 faces left on their own are dropped. Vertices the
front cannot attach, or whose faces all exceed `a`, are left off the
surface (`number_of_points_off_surface`); so are pockets too small to
carry curvature once they are all the front finds (the manual, "The
Advancing Front"). The front is grown anew at each call: to extract
several scales of one shape, `Multiscale_curvatures` grows it once.

Orientation (the manual, "Orientation"): with `reference_normals`, every
sheet faces the side that the majority of the reference normals at its
vertices point to; without, a closed sheet points out of the volume it
encloses and an open sheet away from the center of the surface's vertices.
Parts that the front grew separately but that meet along border edges are
one sheet, oriented alike, so that the pieces of one scan agree. Without
reference normals, open sheets that continue each other across a gap the
front did not bridge (border vertices within 8 local spacings of each
other, the gap within 45 degrees of their tangent planes, their normals
within 45 degrees of parallel: a strip the scan missed, a step whose riser
it did not sample) face alike too, and point away from the center
together; sheets offset along their normals (the two faces of a thin wall)
are not joined, nor are closed sheets. An open sheet that nearly closes
round its own center (a blob with a small hole) is not joined either, and
points out of that center, as a closed sheet does.

Faces and vertices are added to `pmesh`, which is usually empty.

\tparam ConformalAlphaShape a `Conformal_alpha_shape_3`
\tparam PolygonMesh a model of `MutableFaceGraph`
\tparam NamedParameters a sequence of named parameters

\param cas the conformal alpha shape
\param a the scale
\param pmesh the output mesh
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the positions of the vertices of `pmesh`}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and a point type constructible from three `double` as value}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, pmesh)`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_input_index_map}
    \cgalParamDescription{output: for each vertex added to `pmesh`, the index of its input point (the smallest one when duplicates collapsed into the vertex)}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `std::size_t` as value}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{reference_normals}
    \cgalParamDescription{a normal per input point (a scanner's), or an empty range}
    \cgalParamType{a random access range of `Vector_3`, indexed by input point}
    \cgalParamDefault{empty}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Surface_report`: faces, parts, and input points not on the surface.
*/
template <class ConformalAlphaShape, class PolygonMesh,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Surface_report extract_surface(const ConformalAlphaShape& cas, double a, PolygonMesh& pmesh,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::surface_of_soup(cas, internal::pruned_soup(internal::advancing_front_soup(cas), a), pmesh, np);
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_EXTRACT_SURFACE_H
