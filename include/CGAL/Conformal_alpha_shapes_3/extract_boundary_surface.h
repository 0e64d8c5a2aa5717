// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_EXTRACT_BOUNDARY_SURFACE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_EXTRACT_BOUNDARY_SURFACE_H

#include <CGAL/Conformal_alpha_shapes_3/internal/solid_labeling.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_counts.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <array>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/// \ingroup PkgConformalAlphaShapes3Surface
/// What `extract_boundary_surface()` did.
struct Boundary_surface_report : Surface_counts
{
  /// finite facets that are `REGULAR` or `SINGULAR` at the scale
  std::size_t number_of_candidate_facets = 0;
  /// candidate facets left out of the surface
  std::size_t number_of_dropped_facets = 0;
  /// cells the manifold repair moved into the solid
  std::size_t number_of_filled_cells = 0;
  /// cells the manifold repair removed from the solid
  std::size_t number_of_carved_cells = 0;
  /// cells removed from the solid to bring vertices onto the surface
  std::size_t number_of_sculpted_cells = 0;
  /// vertices where the surface pinches, written once per umbrella of faces
  std::size_t number_of_pinched_vertices = 0;
};

namespace internal {

// The number of input points whose vertex is not on the boundary of the solid.
template <class Cas>
std::size_t number_of_points_off_boundary(const Cas& cas, const Solid_labeling<Cas>& solid)
{
  return number_of_points_off(cas, solid.boundary_vertex_marks());
}

} // namespace internal

/*!
\ingroup PkgConformalAlphaShapes3Surface

Writes into `pmesh` the boundary surface of the conformal alpha shape `cas` at
scale `alpha`: a consistently oriented, closed 2-manifold triangle mesh whose
faces are facets of the triangulation, oriented outwards.

The candidate facets are those `REGULAR` or `SINGULAR` at `alpha`; together
they are in general not a manifold. The surface is the boundary of a solid:
a walk from the infinite cells crosses every facet that is not in the
complex at `alpha`, and the cells it never reaches (the `INTERIOR` cells and
whatever the candidate facets enclose) form the solid. Candidate facets
that do not separate the solid from the walked space (dangling sheets,
facets inside the volume) are dropped. When few vertices of the solid's
boundary are not manifold, each is mended by moving a few cells of its star
into or out of the solid (the cheapest of the two, each cell at most once).
Solid cells with a single boundary facet whose opposite vertex is off the
surface, and whose other facets are in the complex, are then removed, which
brings onto the surface the points that noise put just inside it. Where the
surface still pinches, each umbrella of faces around the vertex gets a
vertex of its own (`number_of_pinched_vertices`). The result is therefore
always a closed 2-manifold, possibly with several components (small pockets
below the scale at which the surface closes); where the data has a hole
wider than the scale, the walk enters the volume and that part of the
surface is missing (it is not bridged by a surface with border). The manual
details each step and its measured effect.

Faces and vertices are added to `pmesh`, which is usually empty. When `alpha`
is below every facet value (or NaN), when the candidate facets enclose
nothing, or when `cas` is empty, nothing is added and the report says so.

\tparam ConformalAlphaShape a `Conformal_alpha_shape_3`
\tparam PolygonMesh a model of `MutableFaceGraph`
\tparam NamedParameters a sequence of named parameters

\param cas the conformal alpha shape
\param alpha the scale `a`, a value of the spectrum of `cas` or any value
\param pmesh the output mesh
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the positions of the vertices of `pmesh`}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and a point type constructible from three `double` as value}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, pmesh)`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_input_index_map}
    \cgalParamDescription{output: for each vertex added to `pmesh`, the index of its input point (the smallest one when duplicates collapsed into the vertex; the same for the copies of a pinched vertex)}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `std::size_t` as value}
    \cgalParamDefault{not written}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Boundary_surface_report`: faces written, candidate facets dropped,
cells the repair moved, and input points not on the surface.
*/
template <class ConformalAlphaShape, class PolygonMesh,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Boundary_surface_report extract_boundary_surface(const ConformalAlphaShape& cas, double alpha,
                                                 PolygonMesh& pmesh,
                                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef ConformalAlphaShape Cas;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NamedParameters>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Mesh_point;
  typedef CGAL::Constant_property_map<vertex_descriptor, std::size_t> Default_index_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
    internal_np_cas3::vertex_input_index_map_t, NamedParameters, Default_index_map>::type Index_map;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_property_map(CGAL::vertex_point, pmesh));
  Index_map input_index = choose_parameter(get_parameter(np, internal_np_cas3::vertex_input_index_map),
                                           Default_index_map());

  Boundary_surface_report report;
  report.number_of_input_points = cas.number_of_input_points();
  report.number_of_points_off_surface = cas.number_of_input_points();
  if(cas.dimension() < 3)
    return report;

  const internal::Solid_labeling<Cas> solid(cas, alpha);
  report.number_of_filled_cells = solid.number_of_filled_cells();
  report.number_of_carved_cells = solid.number_of_carved_cells();
  report.number_of_sculpted_cells = solid.number_of_sculpted_cells();

  // one mesh vertex per umbrella of faces around a vertex of the shape, at
  // mesh_vertex[first_umbrella[v] + umbrella]
  const vertex_descriptor null_vertex = boost::graph_traits<PolygonMesh>::null_vertex();
  std::vector<std::size_t> first_umbrella(cas.number_of_vertices() + 1, 0);
  for(typename Cas::Vertex_handle v : cas.finite_vertex_handles())
    first_umbrella[v->vertex_index() + 1] = std::size_t(solid.number_of_umbrellas(v));
  std::partial_sum(first_umbrella.begin(), first_umbrella.end(), first_umbrella.begin());
  std::vector<vertex_descriptor> mesh_vertex(first_umbrella.back(), null_vertex);
  auto mesh_vertex_of = [&](typename Cas::Vertex_handle v, int umbrella) {
    vertex_descriptor& mv = mesh_vertex[first_umbrella[v->vertex_index()] + std::size_t(umbrella)];
    if(mv == null_vertex)
    {
      mv = add_vertex(pmesh);
      const typename Cas::Point& p = v->point();
      put(vpm, mv, Mesh_point(p.x(), p.y(), p.z()));
      put(input_index, mv, *cas.input_indices(v).begin());
      ++report.number_of_vertices;
      report.number_of_pinched_vertices += umbrella == 1 ? 1 : 0;
    }
    return mv;
  };

  // a closed triangle mesh has 3/2 edges per face and about half as many vertices
  const std::size_t faces = solid.boundary().size();
  reserve(pmesh, num_vertices(pmesh) + faces / 2 + 2, num_edges(pmesh) + 3 * faces / 2, num_faces(pmesh) + faces);
  for(std::size_t id = 0; id < faces; ++id)
  {
    const auto triangle = internal::Solid_labeling<Cas>::outward_triangle(solid.boundary()[id]);
    const std::array<vertex_descriptor, 3> face = {mesh_vertex_of(triangle[0], solid.umbrella(id, 0)),
                                                   mesh_vertex_of(triangle[1], solid.umbrella(id, 1)),
                                                   mesh_vertex_of(triangle[2], solid.umbrella(id, 2))};
    CGAL_assertion_code(const auto added =) CGAL::Euler::add_face(face, pmesh);
    CGAL_assertion(added != boost::graph_traits<PolygonMesh>::null_face());
    ++report.number_of_faces;
  }

  // candidate facets: in the complex, not between two INTERIOR cells (the
  // facet's value is checked first: on most facets it already says no)
  std::size_t kept = 0;
  for(const typename Cas::Facet& f : cas.finite_facets())
  {
    if(!(cas.conformal_alpha(f) <= alpha))
      continue;
    const typename Cas::Cell_handle n = f.first->neighbor(f.second);
    if(cas.conformal_alpha(f.first) <= alpha && cas.conformal_alpha(n) <= alpha)
      continue;
    ++report.number_of_candidate_facets;
    kept += solid.is_boundary(f.first, f.second) ? 1 : 0;
  }
  report.number_of_dropped_facets = report.number_of_candidate_facets - kept;
  report.number_of_points_off_surface = internal::number_of_points_off_boundary(cas, solid);
  return report;
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_EXTRACT_BOUNDARY_SURFACE_H
