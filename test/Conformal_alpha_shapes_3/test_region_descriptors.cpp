// Tests of region_descriptors.h: the farthest-point sample, the rings'
// points (by their histograms), the shape index of a sphere, thinning
// beyond the dense radius, the layout, bad arguments, and the same values
// with and without TBB.
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/point_curvature.h>
#include <CGAL/Conformal_alpha_shapes_3/region_descriptors.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace test_region_descriptors {

namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CAS3::Point_curvature<K> Value;
typedef std::vector<std::vector<Value> > Layers;

// n points spread over a sphere of radius r about the origin
std::vector<Point> fibonacci_sphere(std::size_t n, double r)
{
  std::vector<Point> points;
  const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
  for(std::size_t i = 0; i < n; ++i)
  {
    const double z = 1 - (2 * double(i) + 1) / double(n), s = std::sqrt(1 - z * z);
    points.emplace_back(r * s * std::cos(golden * double(i)), r * s * std::sin(golden * double(i)), r * z);
  }
  return points;
}

Value value(double k1, double k2, double radius)
{
  Value v;
  v.principal.max_curvature = k1;
  v.principal.min_curvature = k2;
  v.radius = radius;
  return v;
}

BOOST_AUTO_TEST_SUITE(region_descriptors)

BOOST_AUTO_TEST_CASE(farthest_points)
{
  std::vector<Point> line;
  for(int i = 0; i < 10; ++i)
    line.emplace_back(i, 0, 0);
  // 0, then the far end, then the middle (of the tie 4 and 5, the smaller index)
  BOOST_TEST(CAS3::farthest_point_sample(line, 3) == (std::vector<std::size_t>{0, 9, 4}),
             boost::test_tools::per_element());
  BOOST_TEST(CAS3::farthest_point_sample(line, 2, CAS3::parameters::first_point_index(std::size_t(3)))
               == (std::vector<std::size_t>{3, 9}), boost::test_tools::per_element());
  BOOST_TEST(CAS3::farthest_point_sample(line, 20).size() == 10u);
  BOOST_CHECK_THROW(CAS3::farthest_point_sample(line, 2, CAS3::parameters::first_point_index(std::size_t(10))),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(sphere_has_shape_index_one)
{
  // a sphere of radius 2 with outward normals: k1 = k2 = 1/2, fitted at radius 1
  const std::vector<Point> points = fibonacci_sphere(3000, 2.0);
  std::vector<std::pair<Point, Vector> > with_normals;
  for(const Point& p : points)
    with_normals.emplace_back(p, p - CGAL::ORIGIN);
  const Layers layers(1, std::vector<Value>(points.size(), value(0.5, 0.5, 1.0)));
  const std::vector<std::size_t> centers = CAS3::farthest_point_sample(points, 20);
  const CAS3::Region_descriptors r = CAS3::region_descriptors(
    with_normals, layers, centers,
    CAS3::parameters::ring_radii(std::vector<double>{1.0, 2.0, 3.0})
      .point_map(CGAL::First_of_pair_property_map<std::pair<Point, Vector> >())
      .normal_map(CGAL::Second_of_pair_property_map<std::pair<Point, Vector> >()));
  BOOST_TEST(r.size() == 20u);
  // per ring: shape index (10 bins), curvedness (6), cosines (8), heights (8)
  BOOST_TEST(r.width == 3u * 32u);
  BOOST_TEST(r.histogram_bins == (std::vector<int>{10, 6, 8, 8, 10, 6, 8, 8, 10, 6, 8, 8}),
             boost::test_tools::per_element());
  BOOST_TEST(r.histogram_kinds == (std::vector<int>{0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3}),
             boost::test_tools::per_element());
  BOOST_TEST(r.histogram_weights[0] == 0.5, boost::test_tools::tolerance(1e-15));  // radius over the mean radius
  for(std::size_t i = 0; i < r.size(); ++i)
    for(std::size_t ring = 0; ring < 3; ++ring)
    {
      const double* h = r.row(i) + ring * 32;
      BOOST_TEST(h[9] == 1.0, boost::test_tools::tolerance(1e-12));  // all of the shape index in its last bin
      // curvedness x radius = 0.5: between the bins centred at 1/6 and 1/2
      BOOST_TEST(h[10 + 1] == 1.0, boost::test_tools::tolerance(1e-12));
      // the heights over the tangent plane of a sphere are all below it, at most 0 (between bins 3 and 4)
      BOOST_TEST(h[24 + 5] + h[24 + 6] + h[24 + 7] == 0.0);
    }
}

// A centre at the origin and points at known distances, each ring's points
// with their own shape index: 1 within 2, -1 from 2 to 4, 0 from 4 to 6.
struct Rings_fixture
{
  std::vector<Point> points{Point(0, 0, 0), Point(2, 0, 0), Point(0, 3, 0), Point(0, 0, 4.5), Point(5.5, 0, 0),
                            Point(0, 5, 0), Point(9, 0, 0)};
  Layers layers{{value(1, 1, 1), value(1, 1, 1), value(-1, -1, 1), value(1, -1, 1), value(1, -1, 1),
                 value(0, 0, 1), value(1, 1, 1)}};
  CAS3::Region_descriptors describe(std::size_t thinning) const
  {
    return CAS3::region_descriptors(points, layers, std::vector<std::size_t>{0},
                                    CAS3::parameters::dense_radius(4.0, CAS3::parameters::thinning(
                                      thinning, CAS3::parameters::ring_radii(std::vector<double>{2.0, 4.0, 6.0}))));
  }
};

BOOST_AUTO_TEST_CASE(points_fall_in_their_rings)
{
  const Rings_fixture f;
  const CAS3::Region_descriptors r = f.describe(1);
  BOOST_TEST(r.width == 3u * 16u);
  const double* v = r.row(0);
  // ring 0 (the centre and the point at exactly 2): shape index 1, bin 9
  BOOST_TEST(v[9] == 1.0);
  // ring 1: -1, bin 0
  BOOST_TEST(v[16 + 0] == 1.0);
  // ring 2: two saddles (0, between bins 4 and 5) and a flat point, which counts in neither histogram
  BOOST_TEST(v[32 + 4] == 0.5, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(v[32 + 5] == 0.5, boost::test_tools::tolerance(1e-12));
  // the point at 9 is beyond the last ring
  double total = 0;
  for(std::size_t k = 0; k < r.width; ++k)
    total += v[k];
  BOOST_TEST(total == 6.0, boost::test_tools::tolerance(1e-12));  // three rings, two histograms each
}

BOOST_AUTO_TEST_CASE(thinning_beyond_the_dense_radius)
{
  const Rings_fixture f;
  // one point in 3 beyond 4: of ring 2's points 3, 4 and 5 only 3 counts
  const CAS3::Region_descriptors three = f.describe(3);
  const double* v = three.row(0);
  BOOST_TEST(v[32 + 4] == 0.5, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(v[32 + 5] == 0.5, boost::test_tools::tolerance(1e-12));
  // one in 5: of ring 2 only the flat point 5, which counts in neither histogram: an empty ring
  const CAS3::Region_descriptors five = f.describe(5);
  double ring2 = 0;
  for(std::size_t k = 32; k < 48; ++k)
    ring2 += five.row(0)[k];
  BOOST_TEST(ring2 == 0.0);
  BOOST_TEST(five.row(0)[9] == 1.0);  // within the dense radius every point counts
}

BOOST_AUTO_TEST_CASE(bad_arguments)
{
  const Rings_fixture f;
  const std::vector<std::size_t> c{0};
  BOOST_CHECK_THROW(CAS3::region_descriptors(f.points, f.layers, c,
                                             CAS3::parameters::ring_radii(std::vector<double>{3.0, 2.0})),
                    std::invalid_argument);
  BOOST_CHECK_THROW(CAS3::region_descriptors(f.points, f.layers, std::vector<std::size_t>{7}), std::invalid_argument);
  BOOST_CHECK_THROW(CAS3::region_descriptors(f.points, Layers(), c), std::invalid_argument);
  Layers short_layer = f.layers;
  short_layer[0].pop_back();
  BOOST_CHECK_THROW(CAS3::region_descriptors(f.points, short_layer, c), std::invalid_argument);
  BOOST_CHECK_THROW(CAS3::region_descriptors(f.points, f.layers, c, CAS3::parameters::thinning(std::size_t(0))),
                    std::invalid_argument);
  BOOST_CHECK_THROW(CAS3::region_descriptors(f.points, f.layers, c,
                                             CAS3::parameters::ring_weights(std::vector<double>{1.0})),
                    std::invalid_argument);
  BOOST_CHECK_THROW(CAS3::region_descriptors(f.points, f.layers, c, CAS3::parameters::shape_index_bins(1)),
                    std::invalid_argument);
  std::vector<Point> with_nan = f.points;
  with_nan[3] = Point(0, std::numeric_limits<double>::quiet_NaN(), 0);
  BOOST_CHECK_THROW(CAS3::region_descriptors(with_nan, f.layers, c), std::invalid_argument);
  BOOST_CHECK_THROW(CAS3::farthest_point_sample(with_nan, 2), std::invalid_argument);
}

#ifdef CGAL_LINKED_WITH_TBB
BOOST_AUTO_TEST_CASE(parallel_gives_the_serial_values)
{
  const std::vector<Point> points = fibonacci_sphere(4000, 10.0);
  std::vector<Value> values;
  for(const Point& p : points)
    values.push_back(value(std::sin(p.x()), std::cos(p.y()), 1.0 + 0.1 * p.z()));
  const Layers layers(2, values);
  const std::vector<std::size_t> centers = CAS3::farthest_point_sample(points, 500);
  const auto serial = CAS3::region_descriptors<CGAL::Sequential_tag>(points, layers, centers);
  const auto parallel = CAS3::region_descriptors<CGAL::Parallel_tag>(points, layers, centers);
  BOOST_TEST(serial.values == parallel.values, boost::test_tools::per_element());
}
#endif

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_region_descriptors
