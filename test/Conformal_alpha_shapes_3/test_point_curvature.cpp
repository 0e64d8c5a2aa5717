// Tests of point_curvature.h: a Point_curvature is NaN and without a source
// until set, on_surface() holds for its own vertex's values only, and the
// points of a sphere without its cap have no value exactly when they are
// farther than far_from_surface() local spacings from the surface. (The
// values themselves: test_transfer_to_points.cpp.)
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/internal/sample_spacing.h>
#include <CGAL/Conformal_alpha_shapes_3/point_curvature.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cas3_point_values.h"
#include "cas3_test_types.h"

#include <cmath>
#include <cstddef>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_point_curvature {

using namespace cas3_test_types;

// whether every number of `c` but the distance is NaN
bool all_nan(const CAS3::Point_curvature<K>& c)
{
  return std::isnan(c.radius) && std::isnan(c.normal.x()) && std::isnan(c.normal.y()) && std::isnan(c.normal.z())
         && std::isnan(c.mean_curvature) && std::isnan(c.gaussian_curvature)
         && std::isnan(c.principal.max_curvature) && std::isnan(c.principal.min_curvature)
         && std::isnan(c.principal.max_direction.x()) && std::isnan(c.principal.min_direction.x())
         && std::isnan(c.uncertainty.mean_curvature) && std::isnan(c.uncertainty.gaussian_curvature)
         && std::isnan(c.uncertainty.normal_degrees);
}

BOOST_AUTO_TEST_SUITE(point_curvature)

BOOST_AUTO_TEST_CASE(a_point_curvature_has_no_value_until_set)
{
  CAS3::Point_curvature<K> c;
  BOOST_TEST(c.source == CAS3::NO_VALUE);
  BOOST_TEST(!c.on_surface());
  BOOST_TEST(std::isnan(c.distance));
  BOOST_TEST(all_nan(c));
  c.source = CAS3::NEAREST_SURFACE_POINT;
  BOOST_TEST(!c.on_surface());
  c.source = CAS3::SURFACE_VERTEX;
  BOOST_TEST(c.on_surface());
}

BOOST_AUTO_TEST_CASE(far_from_surface_is_four_local_spacings)
{
  static_assert(CAS3::far_from_surface() == 4, "a constant expression, as documented");
}

// The unit sphere without its cap: the cap's points are off the surface,
// those near its rim take values, those near its center none.
BOOST_AUTO_TEST_CASE(points_farther_than_far_from_surface_have_no_value)
{
  const cas3_test::Pipeline_without_cap sphere;
  const std::vector<Point>& pts = sphere.pts;
  const Analysis& analysis = sphere.analysis;
  const std::vector<CAS3::Point_curvature<K> >& c = sphere.values;
  BOOST_REQUIRE(c.size() == pts.size());

  typedef CAS3::internal::Local_feature_size_policy Policy;
  std::size_t own = 0, nearest = 0, none = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    const double spacing = CAS3::internal::kth_shortest_edge_length<Policy::spacing_edge_rank>(
      analysis.shape(), analysis.shape().input_vertex(i));
    BOOST_TEST_INFO("point " << i << " at distance " << c[i].distance << ", local spacing " << spacing);
    BOOST_REQUIRE(c[i].on_surface() == (c[i].source == CAS3::SURFACE_VERTEX));
    switch(c[i].source)
    {
      case CAS3::SURFACE_VERTEX:
        ++own;
        BOOST_REQUIRE(c[i].distance == 0);
        BOOST_REQUIRE(!all_nan(c[i]));
        break;
      case CAS3::NEAREST_SURFACE_POINT:
        ++nearest;
        BOOST_REQUIRE(c[i].distance <= CAS3::far_from_surface() * spacing);
        BOOST_REQUIRE(!all_nan(c[i]));
        break;
      case CAS3::NO_VALUE:
        ++none;
        BOOST_REQUIRE(c[i].distance > CAS3::far_from_surface() * spacing);
        BOOST_REQUIRE(all_nan(c[i]));
        break;
    }
  }
  BOOST_TEST(own > 3000u);
  BOOST_TEST(nearest > 50u);
  BOOST_TEST(none > 50u);
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_point_curvature
