// Mean and Gaussian curvature, principal curvatures and directions of a
// triangle mesh, at 1-ring and 2-ring scale, into Surface_mesh properties.
//   curvature_surface_mesh_example [mesh.off]   (default: a sphere of radius 2)
#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/point_generators_3.h>

#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;

int main(int argc, char* argv[])
{
  Mesh mesh;
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
    // an irregular triangulation of the sphere of radius 2: H = 0.5, K = 0.25
    CGAL::Random seed(1);
    CGAL::Random_points_on_sphere_3<K::Point_3> random(2.0, seed);
    std::vector<K::Point_3> points;
    std::copy_n(random, 2000, std::back_inserter(points));
    CGAL::convex_hull_3(points.begin(), points.end(), mesh);
  }

  auto mean = mesh.add_property_map<Vertex, double>("v:mean_curvature").first;
  auto gaussian = mesh.add_property_map<Vertex, double>("v:gaussian_curvature").first;
  auto principal = mesh.add_property_map<Vertex, CAS3::Principal_curvatures_and_directions<K> >("v:principal").first;
  for(int rings : {1, 2})
  {
    const std::size_t undefined = CAS3::estimate_vertex_curvatures(
      mesh, CAS3::parameters::vertex_mean_curvature_map(mean,
            CAS3::parameters::vertex_Gaussian_curvature_map(gaussian,
            CAS3::parameters::vertex_principal_curvatures_and_directions_map(principal,
            CAS3::parameters::ring_size(rings)))));
    const Vertex v = *mesh.vertices().begin();
    std::cout << rings << "-ring: at vertex " << v << " H = " << mean[v] << ", K = " << gaussian[v]
              << ", k1 = " << principal[v].max_curvature << " along (" << principal[v].max_direction << ")"
              << ", k2 = " << principal[v].min_curvature << "; " << undefined << " vertices undefined\n";
  }
  return EXIT_SUCCESS;
}
