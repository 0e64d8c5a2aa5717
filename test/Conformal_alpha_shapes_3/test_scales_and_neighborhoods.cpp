// Tests of scales_and_neighborhoods.h: each factory gives its kind and
// value, the automatic candidates grow as documented, and the defaults are
// the automatic scale and the automatic neighborhood then 2, 4, 8 and 16
// spacings. (The program's parsing of these: test_conformal_curvature_program.cpp.)
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/scales_and_neighborhoods.h>

#include <cmath>
#include <cstddef>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_scales_and_neighborhoods {

using CGAL::Conformal_alpha_shapes_3::Neighborhood;
using CGAL::Conformal_alpha_shapes_3::Scale;

BOOST_AUTO_TEST_SUITE(scales_and_neighborhoods)

BOOST_AUTO_TEST_CASE(a_scale_keeps_its_kind_and_value)
{
  BOOST_TEST(Scale::absolute(0.3).kind() == Scale::ABSOLUTE);
  BOOST_TEST(Scale::absolute(0.3).value() == 0.3);
  BOOST_TEST(Scale::quantile(0.25).kind() == Scale::QUANTILE);
  BOOST_TEST(Scale::quantile(0.25).value() == 0.25);
  BOOST_TEST(Scale::automatic().kind() == Scale::AUTOMATIC);
}

BOOST_AUTO_TEST_CASE(a_neighborhood_keeps_its_kind_and_value)
{
  BOOST_TEST(Neighborhood::rings(2).kind() == Neighborhood::RINGS);
  BOOST_TEST(Neighborhood::rings(2).value() == 2.0);
  BOOST_TEST(Neighborhood::radius(0.05).kind() == Neighborhood::RADIUS);
  BOOST_TEST(Neighborhood::radius(0.05).value() == 0.05);
  BOOST_TEST(Neighborhood::spacings(8).kind() == Neighborhood::SPACINGS);
  BOOST_TEST(Neighborhood::spacings(8).value() == 8.0);
  BOOST_TEST(Neighborhood::automatic().kind() == Neighborhood::AUTOMATIC);
}

// 2 to 11.3 spacings by factors of sqrt(2), then to 22.6 by factors of 2^(1/4),
// to the two digits they are written with.
BOOST_AUTO_TEST_CASE(automatic_radii_grow_by_the_documented_factors)
{
  const std::vector<double> radii = Neighborhood::automatic_radii();
  BOOST_REQUIRE(radii.size() == 10u);
  BOOST_TEST(radii.front() == 2.0);
  BOOST_TEST(radii.back() == 22.6);
  for(std::size_t i = 1; i < radii.size(); ++i)
  {
    const double factor = radii[i - 1] < 11 ? std::sqrt(2.0) : std::pow(2.0, 0.25);
    BOOST_TEST(radii[i] / radii[i - 1] == factor, boost::test_tools::tolerance(0.005));
  }
}

BOOST_AUTO_TEST_CASE(the_defaults)
{
  const std::vector<Scale> scales = CGAL::Conformal_alpha_shapes_3::default_scales();
  BOOST_REQUIRE(scales.size() == 1u);
  BOOST_TEST(scales.front().kind() == Scale::AUTOMATIC);

  const std::vector<Neighborhood> neighborhoods = CGAL::Conformal_alpha_shapes_3::default_neighborhoods();
  BOOST_REQUIRE(neighborhoods.size() == 5u);
  BOOST_TEST(neighborhoods.front().kind() == Neighborhood::AUTOMATIC);
  const double spacings[] = {2, 4, 8, 16};
  for(std::size_t i = 0; i < 4; ++i)
  {
    BOOST_TEST(neighborhoods[i + 1].kind() == Neighborhood::SPACINGS);
    BOOST_TEST(neighborhoods[i + 1].value() == spacings[i]);
  }
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_scales_and_neighborhoods
