// Tests of named_parameters.h: each parameter starts a pack and extends one
// (of its own, of CGAL's), CGAL's members chain after it, the last value
// given for a parameter wins, combine() joins two packs (the first pack's
// value winning), an absent parameter reads as the default the caller gives,
// and CGAL's own functions accept packs holding the package's parameters.
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <string>
#include <type_traits>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_named_parameters {

namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
namespace NP = CGAL::Conformal_alpha_shapes_3::internal_np_cas3;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::is_default_parameter;

// is_default_parameter<>::value is a static const bool without a definition:
// read it as a prvalue before Boost.Test takes it by reference.
template <typename Tag, typename NP_pack>
bool is_default(const NP_pack&)
{
  return bool(is_default_parameter<NP_pack, Tag>::value);
}

BOOST_AUTO_TEST_SUITE(named_parameters)

BOOST_AUTO_TEST_CASE(a_parameter_starts_a_pack)
{
  const auto np = CAS3::parameters::ring_size(3);
  static_assert(std::is_same<std::decay_t<decltype(np)>,
                             CGAL::Named_function_parameters<int, NP::ring_size_t> >::value,
                "a pack of one parameter is CGAL's Named_function_parameters");
  BOOST_TEST(choose_parameter(get_parameter(np, NP::ring_size), 1) == 3);
  BOOST_TEST(!is_default<NP::ring_size_t>(np));
  BOOST_TEST(is_default<NP::coverage_t>(np));

  // the helper that tells packs from other arguments
  BOOST_TEST(bool(CAS3::internal::Is_named_function_parameters<std::decay_t<decltype(np)> >::value));
  BOOST_TEST(!bool(CAS3::internal::Is_named_function_parameters<int>::value));
}

BOOST_AUTO_TEST_CASE(a_parameter_extends_a_pack)
{
  const std::vector<double> radii{2., 4., 8.};
  const auto np = CAS3::parameters::neighborhood_radii(
    radii, CAS3::parameters::coverage(0.9, CAS3::parameters::ring_size(2)));
  BOOST_TEST(choose_parameter(get_parameter(np, NP::ring_size), 1) == 2);
  BOOST_TEST(choose_parameter(get_parameter(np, NP::coverage), 0.99) == 0.9);
  const std::vector<double> got =
    choose_parameter(get_parameter(np, NP::neighborhood_radii), std::vector<double>());
  BOOST_TEST(got == radii, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(every_parameter_keeps_its_value)
{
  const auto np = CAS3::parameters::orient_each_point(false,
                  CAS3::parameters::noise_level(0.25,
                  CAS3::parameters::sample_spacing(0.5,
                  CAS3::parameters::neighborhood_radius(6.,
                  CAS3::parameters::denoising_neighbors(24,
                  CAS3::parameters::scales(std::vector<double>{0.1, 0.25},
                  CAS3::parameters::estimator(std::string("jet"))))))));
  BOOST_TEST(choose_parameter(get_parameter(np, NP::orient_each_point), true) == false);
  BOOST_TEST(choose_parameter(get_parameter(np, NP::noise_level), 0.) == 0.25);
  BOOST_TEST(choose_parameter(get_parameter(np, NP::sample_spacing), 0.) == 0.5);
  BOOST_TEST(choose_parameter(get_parameter(np, NP::neighborhood_radius), 0.) == 6.);
  BOOST_TEST(choose_parameter(get_parameter(np, NP::denoising_neighbors), 0) == 24);
  BOOST_TEST(choose_parameter(get_parameter(np, NP::scales), std::vector<double>()).size() == 2u);
  BOOST_TEST(choose_parameter(get_parameter(np, NP::estimator), std::string()) == "jet");
}

BOOST_AUTO_TEST_CASE(an_absent_parameter_reads_as_its_default)
{
  const auto none = CGAL::parameters::default_values();
  BOOST_TEST(choose_parameter(get_parameter(none, NP::ring_size), 1) == 1);
  BOOST_TEST(choose_parameter(get_parameter(none, NP::orient_each_point), true) == true);
  BOOST_TEST(is_default<NP::ring_size_t>(none));
  BOOST_TEST(is_default<NP::vertex_mean_curvature_map_t>(none));

  // a pack that holds other parameters only
  const auto other = CAS3::parameters::coverage(0.5);
  BOOST_TEST(choose_parameter(get_parameter(other, NP::ring_size), 1) == 1);

  // the type of an absent parameter is the default's
  typedef CGAL::Constant_property_map<int, double> Default_map;
  typedef CGAL::internal_np::Lookup_named_param_def<NP::vertex_mean_curvature_map_t, decltype(other),
                                                    Default_map>::type Absent;
  static_assert(std::is_same<Absent, Default_map>::value, "an absent map has the default's type");
  typedef CGAL::internal_np::Lookup_named_param_def<NP::coverage_t, decltype(other), Default_map>::type Present;
  static_assert(std::is_same<Present, double>::value, "a given parameter has its own type");
}

BOOST_AUTO_TEST_CASE(the_last_value_given_wins)
{
  const auto np = CAS3::parameters::ring_size(5, CAS3::parameters::ring_size(2));
  BOOST_TEST(choose_parameter(get_parameter(np, NP::ring_size), 1) == 5);
}

BOOST_AUTO_TEST_CASE(cgal_members_chain_after_a_pack)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef CGAL::Identity_property_map<K::Point_3> Point_map;
  const auto np = CAS3::parameters::ring_size(2).vertex_point_map(Point_map()).geom_traits(K());
  BOOST_TEST(choose_parameter(get_parameter(np, NP::ring_size), 1) == 2);
  BOOST_TEST(!is_default<CGAL::internal_np::vertex_point_t>(np));
  BOOST_TEST(!is_default<CGAL::internal_np::geom_traits_t>(np));
  typedef CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::vertex_point_t, decltype(np),
                                                    int>::type Vpm;
  static_assert(std::is_same<Vpm, Point_map>::value, "the point map is found under CGAL's tag");

  // and a package parameter extends a pack of CGAL's own
  const auto np2 = CAS3::parameters::coverage(0.8, CGAL::parameters::vertex_point_map(Point_map()));
  BOOST_TEST(choose_parameter(get_parameter(np2, NP::coverage), 0.99) == 0.8);
  BOOST_TEST(!is_default<CGAL::internal_np::vertex_point_t>(np2));
}

BOOST_AUTO_TEST_CASE(combine_joins_two_packs)
{
  const auto np1 = CAS3::parameters::ring_size(3, CAS3::parameters::coverage(0.5));
  const auto np2 = CAS3::parameters::noise_level(0.2, CAS3::parameters::ring_size(7));
  const auto np = CAS3::parameters::combine(np1, np2);
  BOOST_TEST(choose_parameter(get_parameter(np, NP::coverage), 0.99) == 0.5);
  BOOST_TEST(choose_parameter(get_parameter(np, NP::noise_level), 0.) == 0.2);
  // held by both: the first pack's value
  BOOST_TEST(choose_parameter(get_parameter(np, NP::ring_size), 1) == 3);
  BOOST_TEST(is_default<NP::scales_t>(np));

  // a pack of one, and a pack of CGAL's own parameters
  typedef CGAL::Identity_property_map<CGAL::Simple_cartesian<double>::Point_3> Point_map;
  const auto np3 = CAS3::parameters::combine(CAS3::parameters::orient_each_point(false),
                                             CGAL::parameters::vertex_point_map(Point_map()));
  BOOST_TEST(choose_parameter(get_parameter(np3, NP::orient_each_point), true) == false);
  BOOST_TEST(!is_default<CGAL::internal_np::vertex_point_t>(np3));

  // the result is a pack: CGAL's members chain after it
  const auto np4 = CAS3::parameters::combine(np1, np2).vertex_point_map(Point_map());
  BOOST_TEST(choose_parameter(get_parameter(np4, NP::ring_size), 1) == 3);
  BOOST_TEST(!is_default<CGAL::internal_np::vertex_point_t>(np4));
}

BOOST_AUTO_TEST_CASE(cgal_functions_ignore_the_package_parameters)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  Mesh mesh;
  mesh.add_face(mesh.add_vertex(K::Point_3(0, 0, 0)), mesh.add_vertex(K::Point_3(2, 0, 0)),
                mesh.add_vertex(K::Point_3(0, 3, 0)));
  const auto np = CAS3::parameters::ring_size(2, CAS3::parameters::coverage(0.5))
                    .vertex_point_map(get(CGAL::vertex_point, mesh)).geom_traits(K());
  BOOST_TEST(CGAL::Polygon_mesh_processing::area(mesh, np) == 3., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(CGAL::Polygon_mesh_processing::area(mesh, CAS3::parameters::combine(
                                                           CAS3::parameters::ring_size(2), np)) == 3.,
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_named_parameters
