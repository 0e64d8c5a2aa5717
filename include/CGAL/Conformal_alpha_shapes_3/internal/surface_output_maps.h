// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SURFACE_OUTPUT_MAPS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SURFACE_OUTPUT_MAPS_H

#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cstddef>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The named parameters `vertex_point_map` and `vertex_input_index_map` of
// `extract_surface()`, which every extraction writes for each vertex it adds,
// and `face_orientation_group_map`, which the advancing front writes for each
// face it adds.
template <class PolygonMesh, class NamedParameters>
class Surface_output_maps
{
public:
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;

  Surface_output_maps(PolygonMesh& pmesh, const NamedParameters& np)
    : m_points(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                  get_property_map(CGAL::vertex_point, pmesh))),
      m_input_index(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np_cas3::vertex_input_index_map), Default_index_map())),
      m_face_group(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np_cas3::face_orientation_group_map), Default_group_map()))
  {}

  // A new vertex of `pmesh` at `p`, standing for the input point `input_index`.
  template <class Point>
  vertex_descriptor new_vertex(PolygonMesh& pmesh, const Point& p, std::size_t input_index) const
  {
    const vertex_descriptor v = add_vertex(pmesh);
    put(m_points, v, Mesh_point(p.x(), p.y(), p.z()));
    put(m_input_index, v, input_index);
    return v;
  }

  // Face `f` belongs to the orientation group `group`.
  void set_face_group(face_descriptor f, std::size_t group) const { put(m_face_group, f, group); }

private:
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NamedParameters>::type Point_map;
  typedef typename boost::property_traits<Point_map>::value_type Mesh_point;
  typedef CGAL::Constant_property_map<vertex_descriptor, std::size_t> Default_index_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np_cas3::vertex_input_index_map_t,
                                                             NamedParameters, Default_index_map>::type Index_map;
  typedef CGAL::Constant_property_map<face_descriptor, std::size_t> Default_group_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np_cas3::face_orientation_group_map_t,
                                                             NamedParameters, Default_group_map>::type Group_map;
  Point_map m_points;
  Index_map m_input_index;
  Group_map m_face_group;
};

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SURFACE_OUTPUT_MAPS_H
