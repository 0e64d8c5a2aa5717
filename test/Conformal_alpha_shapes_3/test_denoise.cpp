// Tests of denoise(): its agreement with CGAL's jet_smooth_point_set(), and
// the neighborhoods it leaves in place.
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/denoise.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/jet_smooth_point_set.h>

#include "cas3_test_shapes.h"
#include "cas3_test_types.h"

#include <algorithm>
#include <cmath>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_denoise {

using namespace cas3_test_types;

BOOST_AUTO_TEST_SUITE(denoise)

// denoise() smooths as CGAL's jet_smooth_point_set() with degree 2 jets
// (its own fit, the same meaning): on a noisy sphere, one and two passes
// agree to rounding.
BOOST_AUTO_TEST_CASE(denoise_matches_cgal_jet_smoothing)
{
  const std::vector<Point> noisy = cas3_test::ellipsoid_sample<Point>(4000, 1, 0.8, 0.6, 0.01, 3, 1e-4);
  const double spacing = std::sqrt(4 * M_PI * 0.8 / 4000.0);
  for(unsigned int k : {24u, 50u})
    for(int passes : {1, 2})
    {
      std::vector<Point> ours = noisy, cgal = noisy;
      CAS3::denoise(ours, CAS3::Denoising_plan{k, passes});
      for(int i = 0; i < passes; ++i)
        CGAL::jet_smooth_point_set<CGAL::Sequential_tag>(cgal, k);
      double largest = 0, moved = 0;
      for(std::size_t i = 0; i < noisy.size(); ++i)
      {
        largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(ours[i], cgal[i])));
        moved = (std::max)(moved, std::sqrt(CGAL::squared_distance(ours[i], noisy[i])));
      }
      BOOST_TEST_MESSAGE("k " << k << ", " << passes << " pass(es): largest difference to CGAL "
                         << largest / spacing << " spacings, largest move " << moved / spacing);
      BOOST_TEST(moved > 0.05 * spacing);
      BOOST_TEST(largest < 1e-9 * spacing);
    }
#ifdef CGAL_LINKED_WITH_TBB
  // in parallel, the serial result bit for bit
  std::vector<Point> serial = noisy, parallel = noisy;
  CAS3::internal::jet_smooth_points<CGAL::Sequential_tag>(serial, 40, 2);
  CAS3::internal::jet_smooth_points<CGAL::Parallel_tag>(parallel, 40, 2);
  BOOST_TEST((serial == parallel));
#endif
}

// Neighborhoods whose quadratic is not determined leave their points in
// place (never NaN): coincident points (smoothed once, as one: the fuzz
// finding denoise_jet_fit_on_duplicates), points on a line, points on one
// circle, an exact plane (the fit is exact: nothing moves).
BOOST_AUTO_TEST_CASE(denoise_leaves_degenerate_neighborhoods_in_place)
{
  const CAS3::Denoising_plan plan{24, 2};
  auto finite = [](const std::vector<Point>& p) {
    return std::all_of(p.begin(), p.end(), [](const Point& q) {
      return std::isfinite(q.x()) && std::isfinite(q.y()) && std::isfinite(q.z());
    });
  };
  // mostly copies of one point, and a few grid points (as the fuzz seed)
  std::vector<Point> copies(40, Point(0.25, 0.5, 0.75));
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j)
      copies.push_back(Point(i, j, (i + j) % 2));
  std::vector<Point> smoothed = copies;
  CAS3::denoise(smoothed, plan);  // 17 distinct points: fewer than 24 neighbors, nothing moves
  BOOST_TEST((smoothed == copies));
  for(int i = 0; i < 6; ++i)
    for(int j = 0; j < 6; ++j)
      copies.push_back(Point(i + 0.5, j + 0.25, 0.125 * ((i * j) % 3)));
  smoothed = copies;
  CAS3::denoise(smoothed, plan);
  BOOST_TEST(finite(smoothed));
  BOOST_TEST(std::all_of(smoothed.begin(), smoothed.begin() + 40, [&](const Point& q) { return q == smoothed[0]; }));
  // on a line
  std::vector<Point> line;
  for(int i = 0; i < 100; ++i)
    line.push_back(Point(0.1 * i, 0.2 * i, -0.3 * i));
  smoothed = line;
  CAS3::denoise(smoothed, plan);
  BOOST_TEST((smoothed == line));
  // on one circle: every neighborhood lies on a conic of its plane
  std::vector<Point> circle;
  for(int i = 0; i < 100; ++i)
    circle.push_back(Point(std::cos(0.0628 * i), std::sin(0.0628 * i), 0.5));
  smoothed = circle;
  CAS3::denoise(smoothed, plan);
  BOOST_TEST((smoothed == circle));
  // an exact plane, tilted
  std::vector<Point> plane;
  for(int i = 0; i < 30; ++i)
    for(int j = 0; j < 30; ++j)
      plane.push_back(Point(i, j, 0.5 * i - 0.25 * j + 3));
  smoothed = plane;
  CAS3::denoise(smoothed, plan);
  BOOST_TEST(finite(smoothed));
  double largest = 0;
  for(std::size_t i = 0; i < plane.size(); ++i)
    largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(smoothed[i], plane[i])));
  BOOST_TEST(largest < 1e-12);
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_denoise
