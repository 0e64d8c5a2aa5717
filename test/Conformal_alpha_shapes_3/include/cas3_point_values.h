// The pipeline's values at the input points in the tests that compare runs
// (test_surface_front.cpp, test_transfer_to_points.cpp,
// test_multiscale_curvatures.cpp), that orient sheets
// (test_extract_surface.cpp) and that take points off the surface
// (test_transfer_to_points.cpp, test_point_curvature.cpp).
#ifndef CAS3_POINT_VALUES_H
#define CAS3_POINT_VALUES_H

#include <CGAL/Conformal_alpha_shapes_3/transfer_to_points.h>

#include "cas3_test_meshes.h"
#include "cas3_test_shapes.h"
#include "cas3_test_types.h"

#include <cstddef>
#include <cstring>
#include <vector>

namespace cas3_test {

// Whether two estimates hold the same bits in every value.
template <class Kernel>
bool same_bits(const CGAL::Conformal_alpha_shapes_3::Point_curvature<Kernel>& p,
               const CGAL::Conformal_alpha_shapes_3::Point_curvature<Kernel>& q)
{
  auto values = [](const CGAL::Conformal_alpha_shapes_3::Point_curvature<Kernel>& c) {
    return std::vector<double>{double(c.source), c.distance, c.radius, c.normal.x(), c.normal.y(), c.normal.z(),
                               c.mean_curvature, c.gaussian_curvature, c.principal.max_curvature,
                               c.principal.min_curvature, c.principal.max_direction.x(),
                               c.principal.max_direction.y(), c.principal.max_direction.z(),
                               c.principal.min_direction.x(), c.principal.min_direction.y(),
                               c.principal.min_direction.z()};
  };
  const std::vector<double> a = values(p), b = values(q);
  return std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// A sample of the unit sphere through the pipeline, its surface at the
// automatic scale with the cap above z = 0.8 cut off, and the points' values
// with 2-ring neighborhoods: the cap's points are off the surface, those of
// its rim near it, those of its center far.
struct Pipeline_without_cap
{
  typedef cas3_test_types::Analysis Analysis;
  std::vector<cas3_test_types::Point> pts = ellipsoid_sample<cas3_test_types::Point>(4000, 1, 1, 1);
  const Analysis analysis{pts.begin(), pts.end()};
  Analysis::Surface surface;
  std::vector<CGAL::Conformal_alpha_shapes_3::Point_curvature<cas3_test_types::K> > values;

  Pipeline_without_cap()
  {
    namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
    analysis.surface(analysis.scale_value(CAS3::Scale::automatic()), surface);
    remove_cap_above(surface, 0.8);
    values = analysis.estimate_curvatures(surface, {CAS3::Neighborhood::rings(2)}).front();
  }
};

} // namespace cas3_test

#endif // CAS3_POINT_VALUES_H
