// Tests of suggest_scale() with SOLID_BOUNDARY: at the suggested scale,
// closed oriented manifolds of the right genus and volume on analytic
// samples, nearly every point on the surface of noisy samples, and the
// shares of the manual's table on real scans. (The advancing front's scale
// is tested with its surfaces, in test_extract_surface.cpp; coverage out of
// range in test_conformal_alpha_shape_3.cpp.)
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shape_3.h>
#include <CGAL/Conformal_alpha_shapes_3/extract_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/suggest_scale.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include "cas3_solid_boundary_facts.h"
#include "cas3_test_data.h"
#include "cas3_test_shapes.h"
#include "cas3_test_types.h"

#include <boost/mpl/list.hpp>

#include <cmath>
#include <string>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_suggest_scale {

using namespace cas3_test_types;
using cas3_test::Surface_facts;
using cas3_test::extract;
using cas3_test::closed_points;
using cas3_test::noisy_points;

BOOST_AUTO_TEST_SUITE(suggest_scale)

// Noiseless samples: at the suggested scale, one closed outward manifold of
// the right genus through every point, enclosing the analytic volume.
BOOST_AUTO_TEST_CASE_TEMPLATE(closed_surfaces_of_the_right_genus_and_volume, Mesh, Mesh_types)
{
  struct Case { const char* name; std::vector<Point> pts; long euler; double volume; };
  const double a = 1.0, b = 0.7, c = 0.4, R = 1.0, r = 0.35;
  const double ellipsoid_volume = 4.0 / 3.0 * M_PI * a * b * c, torus_volume = 2 * M_PI * M_PI * R * r * r;
  const std::vector<Case> cases = {
    {"ellipsoid", cas3_test::ellipsoid_sample<Point>(closed_points, a, b, c), 2, ellipsoid_volume},
    {"torus", cas3_test::torus_sample<Point>(closed_points, R, r), 0, torus_volume},
    {"ellipsoid, 30x density gradient", cas3_test::graded_ellipsoid_sample<Point>(closed_points, a, b, c, 30), 2,
     ellipsoid_volume},
    {"torus, 30x density gradient", cas3_test::torus_sample<Point>(closed_points, R, r, 0, 2, 30), 0, torus_volume},
  };
  for(const Case& k : cases)
  {
    const Cas cas(k.pts.begin(), k.pts.end());
    const Surface_facts s = extract<Mesh>(cas, CAS3::suggest_scale(cas, CAS3::parameters::surface_extraction(CAS3::SOLID_BOUNDARY)), k.pts);
    BOOST_TEST_INFO(k.name);
    BOOST_TEST(s.valid_closed_triangle_mesh);
    BOOST_TEST(s.components == 1u);
    BOOST_TEST(s.euler == k.euler);
    BOOST_TEST(s.report.number_of_points_off_surface == 0u);
    BOOST_TEST(s.report.number_of_pinched_vertices == 0u);
    BOOST_TEST(s.volume > 0);  // outward
    BOOST_TEST(s.volume == k.volume, boost::test_tools::tolerance(0.03));
  }
  // a torus whose density follows a 7x range of feature size (see below)
  const auto pts = cas3_test::lfs_torus_sample<Point>(closed_points, 1.0, 0.8);
  const Cas cas(pts.begin(), pts.end());
  const Surface_facts s = extract<Mesh>(cas, CAS3::suggest_scale(cas, CAS3::parameters::surface_extraction(CAS3::SOLID_BOUNDARY)), pts);
  BOOST_TEST(s.valid_closed_triangle_mesh);
  BOOST_TEST(s.components == 1u);
  BOOST_TEST(s.euler == 0);
  BOOST_TEST(s.report.number_of_points_off_surface == 0u);
  BOOST_TEST(s.volume == 2 * M_PI * M_PI * 0.64, boost::test_tools::tolerance(0.03));
}

// Radial noise: the surface stays a closed oriented manifold and holds
// nearly every point, with either local feature size.
BOOST_AUTO_TEST_CASE(noisy_samples_stay_manifold)
{
  for(double noise : {1e-4, 1e-3})
    for(CAS3::Local_feature_size_estimator estimator : {CAS3::PAPER_POLE_DISTANCE, CAS3::NOISE_ROBUST_POLE_DISTANCE})
    {
      const auto pts = cas3_test::ellipsoid_sample<Point>(noisy_points, 1.0, 0.7, 0.4, noise);
      const Cas cas(pts.begin(), pts.end(), CAS3::parameters::local_feature_size_estimator(estimator));
      const Surface_facts s = extract<Surface_mesh>(cas, CAS3::suggest_scale(cas, CAS3::parameters::surface_extraction(CAS3::SOLID_BOUNDARY)), pts);
      BOOST_TEST_MESSAGE("noise " << noise << " estimator " << int(estimator) << ": "
                         << s.report.fraction_of_points_on_surface() << " of the points on the surface");
      BOOST_TEST_INFO("noise " << noise << " estimator " << int(estimator));
      BOOST_TEST(s.valid_closed_triangle_mesh);
      BOOST_TEST(s.components == 1u);
      BOOST_TEST(s.euler == 2);
      BOOST_TEST(s.report.fraction_of_points_on_surface() >= 0.99);
    }
}

// Real scans (libcgal-demo's, and the bundled bunny) at the suggested scale:
// the shares of points on the surface of the manual's table ("Measured",
// solid boundary; 0.5 point of margin) on a closed surface of the right
// genus where the scan is closed.
BOOST_AUTO_TEST_CASE(real_scans)
{
  struct Case { std::string file; double share; long euler; };
  const Case cases[] = {{cas3_test::test_data_file("kitten.xyz"), 1.0, 0},  // genus 1 (the tail)
                        {cas3_test::test_data_file("bunny00.off"), 1.0, 2},
                        {CAS3_BUNNY_XYZ, 0.975, 0},
                        {cas3_test::test_data_file("bunny_1000.xyz"), 0.985, 0}};
  for(const Case& k : cases)
  {
    const auto pts = cas3_test::read_points<Point>(k.file);
    const Cas cas(pts.begin(), pts.end());
    const Surface_facts s = extract<Polyhedron>(cas, CAS3::suggest_scale(cas, CAS3::parameters::surface_extraction(CAS3::SOLID_BOUNDARY)), pts);
    BOOST_TEST_MESSAGE(k.file << ": " << s.report.fraction_of_points_on_surface() << " of the points on the surface, "
                       << s.components << " components, Euler characteristic " << s.euler);
    BOOST_TEST_CONTEXT(k.file)
    {
      BOOST_TEST(s.valid_closed_triangle_mesh);
      BOOST_TEST(s.volume > 0);
      BOOST_TEST(s.report.fraction_of_points_on_surface() >= k.share - 0.005);
      if(k.share == 1.0)
      {
        BOOST_TEST(s.components == 1u);
        BOOST_TEST(s.euler == k.euler);
      }
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_suggest_scale
