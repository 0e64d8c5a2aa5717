// Tests of curvature_estimator.h: each estimator finds the curvature of a
// sphere, QUADRIC_FIT is the default, its normal is the fitted surface's
// and it alone gives uncertainties. (Each estimator's accuracy on the
// manual's meshes: test_estimate_vertex_curvatures.cpp.)
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/curvature_estimator.h>
#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "cas3_test_meshes.h"

#include <cmath>
#include <cstring>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_curvature_estimator {

namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef std::vector<CAS3::Vertex_curvature<K> > Curvatures;

const double sphere_radius = 2;

// The estimates on an icosphere of radius 2 with 2-ring neighborhoods.
template <class NamedParameters>
Curvatures on_sphere(const NamedParameters& np)
{
  Mesh mesh;
  cas3_test::icosphere<Mesh, K::Point_3>(3, sphere_radius, mesh);
  return CAS3::estimate_vertex_curvatures(mesh, {CAS3::Neighborhood::rings(2)}, np).front();
}

BOOST_AUTO_TEST_SUITE(curvature_estimator)

BOOST_AUTO_TEST_CASE(every_estimator_finds_the_curvature_of_a_sphere)
{
  for(CAS3::Curvature_estimator e : {CAS3::PAPER_EULER_FIT, CAS3::EULER_LEAST_SQUARES_FIT, CAS3::QUADRIC_FIT})
  {
    const Curvatures c = on_sphere(CAS3::parameters::estimator(e));
    BOOST_TEST_INFO("estimator " << int(e));
    BOOST_REQUIRE(!c.empty());
    for(const CAS3::Vertex_curvature<K>& v : c)
    {
      BOOST_REQUIRE(v.is_defined());
      BOOST_REQUIRE(std::abs(v.mean_curvature() * sphere_radius - 1) < 0.05);
      BOOST_REQUIRE(std::abs(v.gaussian_curvature() * sphere_radius * sphere_radius - 1) < 0.1);
      BOOST_REQUIRE(std::abs(v.normal.squared_length() - 1) < 1e-9);
    }
  }
}

BOOST_AUTO_TEST_CASE(quadric_fit_is_the_default)
{
  const Curvatures given = on_sphere(CAS3::parameters::estimator(CAS3::QUADRIC_FIT));
  const Curvatures by_default = on_sphere(CGAL::parameters::default_values());
  BOOST_REQUIRE(given.size() == by_default.size());
  for(std::size_t i = 0; i < given.size(); ++i)
  {
    BOOST_REQUIRE(given[i].mean_curvature() == by_default[i].mean_curvature());
    BOOST_REQUIRE(given[i].normal == by_default[i].normal);
  }
}

// The fitted surface's normal is not the Chen-Wu normal of the Euler
// estimators, though both are radial on a sphere.
BOOST_AUTO_TEST_CASE(the_quadric_normal_is_the_fitted_surfaces)
{
  Mesh mesh;
  cas3_test::icosphere<Mesh, K::Point_3>(3, sphere_radius, mesh);
  const Curvatures quadric = on_sphere(CAS3::parameters::estimator(CAS3::QUADRIC_FIT));
  const Curvatures euler = on_sphere(CAS3::parameters::estimator(CAS3::EULER_LEAST_SQUARES_FIT));
  std::size_t differ = 0;
  for(Mesh::Vertex_index v : mesh.vertices())
  {
    const K::Vector_3 radial = (mesh.point(v) - CGAL::ORIGIN) / sphere_radius;
    BOOST_REQUIRE(quadric[v].normal * radial > 1 - 1e-4);
    BOOST_REQUIRE(euler[v].normal * radial > 1 - 1e-3);
    differ += quadric[v].normal == euler[v].normal ? 0 : 1;
  }
  BOOST_TEST(differ > 0u);
}

BOOST_AUTO_TEST_CASE(only_the_quadric_fit_gives_uncertainties)
{
  for(const CAS3::Vertex_curvature<K>& v : on_sphere(CAS3::parameters::estimator(CAS3::QUADRIC_FIT)))
  {
    BOOST_REQUIRE(std::isfinite(v.uncertainty.mean_curvature));
    BOOST_REQUIRE(std::isfinite(v.uncertainty.normal_degrees));
  }
  for(CAS3::Curvature_estimator e : {CAS3::PAPER_EULER_FIT, CAS3::EULER_LEAST_SQUARES_FIT})
    for(const CAS3::Vertex_curvature<K>& v : on_sphere(CAS3::parameters::estimator(e)))
    {
      BOOST_REQUIRE(std::isnan(v.uncertainty.mean_curvature));
      BOOST_REQUIRE(std::isnan(v.uncertainty.gaussian_curvature));
      BOOST_REQUIRE(std::isnan(v.uncertainty.normal_degrees));
    }
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_curvature_estimator
