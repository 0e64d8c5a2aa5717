// Multi-scale curvature of a point cloud: for each scale and neighborhood,
// where the points' values come from and the median mean curvature.
//   multiscale_curvatures_example [points.xyz]   (default: the bundled bunny)
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>

#include "cas3_layer_names.h"

#include <algorithm>
#include <cmath>
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
  // the automatic scale and the default neighborhoods (automatic, then 2 to
  // 16 sample spacings), and the paper's 25% quantile with 2-rings
  std::vector<CAS3::Curvature_layer<K> > layers = CAS3::multiscale_curvatures(points);
  const std::vector<CAS3::Curvature_layer<K> > paper = CAS3::multiscale_curvatures(
    points, CAS3::parameters::scales(std::vector<CAS3::Scale>{CAS3::Scale::quantile(0.25)},
            CAS3::parameters::neighborhoods(std::vector<CAS3::Neighborhood>{CAS3::Neighborhood::rings(2)})));
  layers.insert(layers.end(), paper.begin(), paper.end());

  std::printf("scale  neighborhood  a           own vertex  nearest facet  no value  median H\n");
  for(const CAS3::Curvature_layer<K>& layer : layers)
  {
    std::vector<double> H;
    std::size_t count[3] = {0, 0, 0};
    for(const CAS3::Point_curvature<K>& p : layer.points)
    {
      ++count[p.source];
      if(std::isfinite(p.mean_curvature))
        H.push_back(p.mean_curvature);
    }
    std::nth_element(H.begin(), H.begin() + std::ptrdiff_t(H.size() / 2), H.end());
    std::printf("%-6s %-14s %-11.4g %10zu %14zu %9zu %9.4g\n", cas3::scale_text(layer.scale).c_str(),
                cas3::neighborhood_label(layer.neighborhood).c_str(), layer.a, count[CAS3::SURFACE_VERTEX],
                count[CAS3::NEAREST_SURFACE_POINT], count[CAS3::NO_VALUE], H.empty() ? 0.0 : H[H.size() / 2]);
  }
  return EXIT_SUCCESS;
}
