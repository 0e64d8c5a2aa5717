// Tests of surface_report.h: a report's counts start at 0 and its
// agreement NaN, the derived counts follow the stored ones, the points off
// the surface count duplicates, and extract_surface() fills the counts of
// the mesh it writes. (The counts of each extraction method's steps:
// test_extract_surface.cpp.)
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/extract_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/suggest_scale.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_report.h>

#include <CGAL/boost/graph/helpers.h>

#include "cas3_test_shapes.h"
#include "cas3_test_types.h"

#include <cmath>
#include <cstddef>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_surface_report {

using namespace cas3_test_types;

BOOST_AUTO_TEST_SUITE(surface_report)

BOOST_AUTO_TEST_CASE(a_report_starts_empty)
{
  const CAS3::Surface_report r;
  BOOST_TEST(r.empty());
  BOOST_TEST(r.number_of_faces == 0u);
  BOOST_TEST(r.number_of_vertices == 0u);
  BOOST_TEST(r.number_of_points_off_surface == 0u);
  BOOST_TEST(r.number_of_input_points == 0u);
  BOOST_TEST(r.number_of_parts == 0u);
  BOOST_TEST(r.number_of_open_parts() == 0u);
  BOOST_TEST(r.number_of_reversed_parts == 0u);
  BOOST_TEST(!r.oriented_by_reference_normals);
  BOOST_TEST(r.number_of_sheets_with_inconsistent_normals == 0u);
  BOOST_TEST(std::isnan(r.reference_normal_agreement));
  BOOST_TEST(r.number_of_candidate_facets == 0u);
  BOOST_TEST(r.number_of_dropped_facets == 0u);
  BOOST_TEST(r.number_of_filled_cells == 0u);
  BOOST_TEST(r.number_of_carved_cells == 0u);
  BOOST_TEST(r.number_of_sculpted_cells == 0u);
  BOOST_TEST(r.number_of_pinched_vertices == 0u);
  // no input points: none on the surface, without dividing by zero
  BOOST_TEST(r.fraction_of_points_on_surface() == 0.0);
}

BOOST_AUTO_TEST_CASE(derived_counts_follow_the_stored_ones)
{
  CAS3::Surface_report r;
  r.number_of_faces = 1;
  r.number_of_parts = 5;
  r.number_of_closed_parts = 2;
  r.number_of_input_points = 8;
  r.number_of_points_off_surface = 2;
  BOOST_TEST(!r.empty());
  BOOST_TEST(r.number_of_open_parts() == 3u);
  BOOST_TEST(r.fraction_of_points_on_surface() == 0.75);
}

// A point given three times counts three times off the surface.
BOOST_AUTO_TEST_CASE(points_off_the_surface_count_duplicates)
{
  std::vector<Point> pts = cas3_test::ellipsoid_sample<Point>(200, 1, 1, 1);
  pts.push_back(pts.front());
  pts.push_back(pts.front());
  const Cas cas(pts.begin(), pts.end());
  BOOST_REQUIRE(cas.number_of_vertices() == 200u);
  std::vector<char> on(cas.number_of_vertices(), 1);
  BOOST_TEST(CAS3::internal::number_of_points_off(cas, on) == 0u);
  on[cas.input_vertex(0)->vertex_index()] = 0;
  BOOST_TEST(CAS3::internal::number_of_points_off(cas, on) == 3u);
  on.assign(on.size(), 0);
  BOOST_TEST(CAS3::internal::number_of_points_off(cas, on) == pts.size());
}

BOOST_AUTO_TEST_CASE(extract_surface_counts_its_mesh)
{
  const std::vector<Point> pts = cas3_test::ellipsoid_sample<Point>(2000, 1.0, 0.7, 0.4);
  const Cas cas(pts.begin(), pts.end());
  for(CAS3::Surface_extraction method : {CAS3::ADVANCING_FRONT, CAS3::SOLID_BOUNDARY})
  {
    BOOST_TEST_INFO("method " << int(method));
    Surface_mesh mesh;
    const auto np = CAS3::parameters::surface_extraction(method);
    const CAS3::Surface_report r = CAS3::extract_surface(cas, CAS3::suggest_scale(cas, np), mesh, np);
    BOOST_TEST(r.number_of_faces == num_faces(mesh));
    BOOST_TEST(r.number_of_vertices == num_vertices(mesh));
    BOOST_TEST(r.number_of_input_points == pts.size());
    BOOST_TEST(r.number_of_parts >= 1u);
    BOOST_TEST(r.number_of_closed_parts <= r.number_of_parts);
    BOOST_TEST(r.fraction_of_points_on_surface() > 0.9);
    // each method leaves the other's step counts at 0
    if(method == CAS3::ADVANCING_FRONT)
      BOOST_TEST(r.number_of_candidate_facets == 0u);
    else
      BOOST_TEST(r.number_of_reversed_parts == 0u);
  }
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_surface_report
