#define BOOST_TEST_MODULE test_shape_index
#include <CGAL/Conformal_alpha_shapes_3/shape_index.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

namespace CAS = CGAL::Conformal_alpha_shapes_3;

BOOST_AUTO_TEST_SUITE(shape_index)

BOOST_AUTO_TEST_CASE(koenderink_shapes)
{
  // outward normals: a sphere has positive curvatures
  BOOST_TEST(CAS::shape_index(0.5, 0.5) == 1.0);            // cap (umbilic, convex)
  BOOST_TEST(CAS::shape_index(-0.5, -0.5) == -1.0);         // cup (umbilic, concave)
  BOOST_TEST(CAS::shape_index(0.5, 0.0) == 0.5, boost::test_tools::tolerance(1e-15));   // ridge
  BOOST_TEST(CAS::shape_index(0.0, -0.5) == -0.5, boost::test_tools::tolerance(1e-15)); // rut
  BOOST_TEST(CAS::shape_index(0.5, -0.5) == 0.0);           // symmetric saddle
  BOOST_TEST(CAS::shape_index(0.2, -0.5) < 0.0);            // a saddle bending more inward
  // the order of the principal curvatures does not matter, nor the size
  BOOST_TEST(CAS::shape_index(0.0, 0.5) == CAS::shape_index(0.5, 0.0));
  BOOST_TEST(CAS::shape_index(3.0, 1.0) == CAS::shape_index(0.3, 0.1), boost::test_tools::tolerance(1e-14));
  BOOST_TEST(CAS::shape_index(1.0f, 1.0f) == 1.0f);
}

BOOST_AUTO_TEST_CASE(flat_and_undefined)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  BOOST_TEST(std::isnan(CAS::shape_index(0.0, 0.0)));
  BOOST_TEST(std::isnan(CAS::shape_index(nan, 0.5)));
  BOOST_TEST(std::isnan(CAS::shape_index(0.5, nan)));
  BOOST_TEST(CAS::curvedness(0.0, 0.0) == 0.0);
  BOOST_TEST(std::isnan(CAS::curvedness(nan, 0.5)));
}

BOOST_AUTO_TEST_CASE(curvedness_values)
{
  BOOST_TEST(CAS::curvedness(0.5, 0.5) == 0.5);    // a sphere of radius 2
  BOOST_TEST(CAS::curvedness(-0.5, -0.5) == 0.5);  // its inside
  BOOST_TEST(CAS::curvedness(1.0, -1.0) == 1.0);
  BOOST_TEST(CAS::curvedness(2.0, 0.0) == std::sqrt(2.0), boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()
