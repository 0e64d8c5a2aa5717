// Extracts the surface of a point cloud's conformal alpha shape into a
// Surface_mesh: the default advancing-front surface at its automatic scale,
// then the solid boundary (the earlier extraction) at its own.
//   surface_example [points.xyz]   (default: the bundled bunny)
#include <CGAL/Conformal_alpha_shape_3.h>
#include <CGAL/Conformal_alpha_shapes_3/extract_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/suggest_scale.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_data_structure_3<CGAL::Conformal_alpha_shape_vertex_base_3<K>,
                                             CGAL::Conformal_alpha_shape_cell_base_3<K> > Tds;
typedef CGAL::Conformal_alpha_shape_3<CGAL::Delaunay_triangulation_3<K, Tds> > Conformal_alpha_shape;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;

int main(int argc, char* argv[])
{
  const char* filename = argc > 1 ? argv[1] : CGAL_CAS3_DEFAULT_INPUT;
  std::vector<K::Point_3> points;
  if(!CGAL::IO::read_points(filename, std::back_inserter(points)))
  {
    std::cerr << "cannot read points from " << filename << "\n";
    return EXIT_FAILURE;
  }
  const Conformal_alpha_shape cas(points.begin(), points.end());

  // one oriented sheet per part of the sampled surface
  Mesh sheet;
  // which input point each mesh vertex is
  Mesh::Property_map<Mesh::Vertex_index, std::size_t> input_index =
    sheet.add_property_map<Mesh::Vertex_index, std::size_t>("v:input_index").first;
  const double a = CAS3::suggest_scale(cas);
  const CAS3::Surface_report report =
    CAS3::extract_surface(cas, a, sheet, CAS3::parameters::vertex_input_index_map(input_index));
  std::cout << "surface, a = " << a << ": " << report.number_of_faces << " faces, "
            << report.number_of_parts << " parts (" << report.number_of_closed_parts << " closed), "
            << 100 * report.fraction_of_points_on_surface() << "% of the points on it\n";
  if(sheet.number_of_vertices() > 0)
  {
    const Mesh::Vertex_index v = *sheet.vertices().begin();
    std::cout << "  its first vertex is input point " << input_index[v] << ": " << sheet.point(v) << "\n";
  }

  // the closed boundary of the solid that the facets enclose
  Mesh solid;
  const auto solid_boundary = CAS3::parameters::surface_extraction(CAS3::SOLID_BOUNDARY);
  const double solid_a = CAS3::suggest_scale(cas, solid_boundary);
  const CAS3::Surface_report solid_report = CAS3::extract_surface(cas, solid_a, solid, solid_boundary);
  std::cout << "solid boundary, a = " << solid_a << ": " << solid_report.number_of_faces << " faces, "
            << 100 * solid_report.fraction_of_points_on_surface() << "% of the points on it, "
            << solid_report.number_of_pinched_vertices << " pinched vertices\n";
  return EXIT_SUCCESS;
}
