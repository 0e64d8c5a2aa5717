// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_BOUNDARY_SURFACE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_BOUNDARY_SURFACE_H

#include <CGAL/Conformal_alpha_shapes_3/internal/solid_labeling.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/surface_output_maps.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_report.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <array>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The number of input points whose vertex is not on the boundary of the solid.
template <class Cas>
std::size_t number_of_points_off_boundary(const Cas& cas, const Solid_labeling<Cas>& solid)
{
  return number_of_points_off(cas, solid.boundary_vertex_marks());
}

// `extract_surface()` with `SOLID_BOUNDARY`: the boundary of the solid that
// the facets of the complex at `a` enclose (the manual, "The Solid
// Boundary"), closed and outward by construction.
template <class ConformalAlphaShape, class PolygonMesh, class NamedParameters>
Surface_report extract_solid_boundary(const ConformalAlphaShape& cas, double a, PolygonMesh& pmesh,
                                      const NamedParameters& np)
{
  typedef ConformalAlphaShape Cas;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  const Surface_output_maps<PolygonMesh, NamedParameters> output(pmesh, np);

  Surface_report report;
  report.number_of_input_points = cas.number_of_input_points();
  report.number_of_points_off_surface = cas.number_of_input_points();
  if(cas.dimension() < 3)
    return report;

  const Solid_labeling<Cas> solid(cas, a);
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
      mv = output.new_vertex(pmesh, v->point(), *cas.input_indices(v).begin());
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
    const auto triangle = Solid_labeling<Cas>::outward_triangle(solid.boundary()[id]);
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
    if(!(cas.conformal_alpha(f) <= a))
      continue;
    const typename Cas::Cell_handle n = f.first->neighbor(f.second);
    if(cas.conformal_alpha(f.first) <= a && cas.conformal_alpha(n) <= a)
      continue;
    ++report.number_of_candidate_facets;
    kept += solid.is_boundary(f.first, f.second) ? 1 : 0;
  }
  report.number_of_dropped_facets = report.number_of_candidate_facets - kept;
  report.number_of_points_off_surface = number_of_points_off_boundary(cas, solid);
  auto part = get(CGAL::dynamic_face_property_t<std::size_t>(), pmesh);
  report.number_of_parts = CGAL::Polygon_mesh_processing::connected_components(pmesh, part);
  report.number_of_closed_parts = report.number_of_parts;  // the boundary of a solid is closed
  return report;
}

} // namespace internal

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOLID_BOUNDARY_SURFACE_H
