// Multi-scale curvature of a point cloud: for each scale and ring size, the
// share of the points on the surface and the median mean curvature there.
//   multiscale_curvatures_example [points.xyz]   (default: the bundled bunny)
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
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
  const std::vector<CAS3::Curvature_layer<K> > layers = CAS3::multiscale_curvatures(
    points, CAS3::parameters::scales(std::vector<CAS3::Scale>{CAS3::Scale::quantile(0.25), CAS3::Scale::automatic(),
                                                              CAS3::Scale::quantile(0.50)},
            CAS3::parameters::ring_sizes(std::vector<int>{1, 2, 3})));

  std::printf("scale   alpha_hat  rings  on surface  median H\n");
  for(const CAS3::Curvature_layer<K>& layer : layers)
  {
    std::vector<double> H;
    for(const CAS3::Point_curvature<K>& p : layer.points)
      if(p.on_surface && p.mean_curvature == p.mean_curvature)
        H.push_back(p.mean_curvature);
    std::nth_element(H.begin(), H.begin() + std::ptrdiff_t(H.size() / 2), H.end());
    std::printf("%-6s %10.4g %6d %10.1f%% %9.4g\n", layer.scale.label().c_str(), layer.alpha, layer.ring_size,
                100 * layer.surface.fraction_of_points_on_surface(), H.empty() ? 0.0 : H[H.size() / 2]);
  }
  return EXIT_SUCCESS;
}
