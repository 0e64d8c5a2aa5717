// What the solid-boundary tests (test_extract_surface.cpp,
// test_suggest_scale.cpp) check of a surface that extract_surface() gives
// with SOLID_BOUNDARY: its report, topology, volume and faces.
#ifndef CAS3_SOLID_BOUNDARY_FACTS_H
#define CAS3_SOLID_BOUNDARY_FACTS_H

#include <CGAL/Conformal_alpha_shapes_3/extract_surface.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <set>
#include <vector>

namespace cas3_test {

struct Surface_facts
{
  CGAL::Conformal_alpha_shapes_3::Surface_report report;
  std::size_t components = 0;
  long euler = 0;
  double volume = 0;
  bool valid_closed_triangle_mesh = false;
  std::set<std::array<std::size_t, 3> > faces;  // by the sorted input indices of their vertices
};

// The solid boundary of `cas` at `alpha` as a `Mesh`, whose vertices must
// be the input points `pts` of `cas`.
template <class Mesh, class Shape, class Point>
Surface_facts extract(const Shape& cas, double alpha, const std::vector<Point>& pts)
{
  namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
  namespace PMP = CGAL::Polygon_mesh_processing;
  Mesh mesh;
  auto input_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  Surface_facts facts;
  facts.report = CAS3::extract_surface(cas, alpha, mesh, CAS3::parameters::surface_extraction(
    CAS3::SOLID_BOUNDARY, CAS3::parameters::vertex_input_index_map(input_index)));
  BOOST_TEST(facts.report.number_of_faces == num_faces(mesh));
  BOOST_TEST(facts.report.number_of_vertices == num_vertices(mesh));
  // every mesh vertex is its input point
  std::size_t wrong_index = 0;
  for(auto v : vertices(mesh))
    if(get(input_index, v) >= pts.size() || get(CGAL::vertex_point, mesh, v) != pts[get(input_index, v)])
      ++wrong_index;
  BOOST_TEST(wrong_index == 0u);
  facts.valid_closed_triangle_mesh =
    CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_closed(mesh) && CGAL::is_triangle_mesh(mesh);
  for(auto f : faces(mesh))
  {
    std::array<std::size_t, 3> triangle;
    std::size_t k = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      triangle[k++ % 3] = get(input_index, v);
    std::sort(triangle.begin(), triangle.end());
    facts.faces.insert(triangle);
  }
  if(num_faces(mesh) > 0)
  {
    auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
    facts.components = PMP::connected_components(mesh, component);
    facts.volume = PMP::volume(mesh);
  }
  facts.euler = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
  return facts;
}

} // namespace cas3_test

#endif // CAS3_SOLID_BOUNDARY_FACTS_H
