// The curvature of a Polyhedron_3 with the paper's estimator and with the
// default quadric fit, written into external property maps.
//   curvature_polyhedron_example [mesh.off]   (default: a torus R = 1, r = 0.4)
#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/generators.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef boost::graph_traits<Polyhedron>::vertex_descriptor Vertex;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;

int main(int argc, char* argv[])
{
  Polyhedron mesh;
  if(argc > 1)
  {
    if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "cannot read a triangle mesh from " << argv[1] << "\n";
      return EXIT_FAILURE;
    }
  }
  else
  {
    // a triangulated torus: a quad grid on (u, v), each quad split in two
    const double R = 1.0, r = 0.4;
    CGAL::make_grid(120, 48, mesh, [&](int i, int j) {
      const double u = 2 * M_PI * i / 120, v = 2 * M_PI * j / 48;
      return K::Point_3((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }, true);
  }

  std::map<Vertex, double> mean_paper, mean_quadric;
  CAS3::estimate_vertex_curvatures(mesh, CAS3::parameters::vertex_mean_curvature_map(
    boost::make_assoc_property_map(mean_paper), CAS3::parameters::estimator(CAS3::PAPER_EULER_FIT)));
  CAS3::estimate_vertex_curvatures(mesh, CAS3::parameters::vertex_mean_curvature_map(
    boost::make_assoc_property_map(mean_quadric), CAS3::parameters::ring_size(2)));

  const Vertex v = *vertices(mesh).begin();
  std::cout << "vertex at " << v->point() << ": H = " << mean_paper[v] << " (paper, 1-ring), "
            << mean_quadric[v] << " (quadric fit, 2-ring)\n";
  return EXIT_SUCCESS;
}
