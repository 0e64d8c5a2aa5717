// The pipeline's values at the input points in the tests that compare runs
// (test_surface_front.cpp, test_transfer_to_points.cpp,
// test_multiscale_curvatures.cpp) and that orient sheets
// (test_extract_surface.cpp).
#ifndef CAS3_POINT_VALUES_H
#define CAS3_POINT_VALUES_H

#include <CGAL/Conformal_alpha_shapes_3/transfer_to_points.h>

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

} // namespace cas3_test

#endif // CAS3_POINT_VALUES_H
