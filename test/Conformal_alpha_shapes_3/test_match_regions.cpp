// Tests of match_regions.h: Kabsch's fit, the robust registration of
// pairs with wrong ones among them, the histogram distances, and the
// matching of a surface against an identical copy and against a rotated,
// translated copy (each region's best candidate, the registration
// recovering the motion), the same with and without TBB.
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/match_regions.h>
#include <CGAL/Conformal_alpha_shapes_3/point_curvature.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace test_match_regions {

namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef std::array<double, 3> Xyz;
typedef std::pair<Point, Vector> Point_with_normal;
typedef std::vector<std::vector<CAS3::Point_curvature<K> > > Layers;

// a rotation by `angle` about the axis (1, 2, 2) / 3, then a translation
CAS3::Rigid_motion known_motion(double angle, const Xyz& t)
{
  const double x = 1 / 3.0, y = 2 / 3.0, z = 2 / 3.0, c = std::cos(angle), s = std::sin(angle), C = 1 - c;
  CAS3::Rigid_motion m;
  m.rotation = {{{c + x * x * C, x * y * C - z * s, x * z * C + y * s},
                 {y * x * C + z * s, c + y * y * C, y * z * C - x * s},
                 {z * x * C - y * s, z * y * C + x * s, c + z * z * C}}};
  m.translation = t;
  return m;
}

double largest_difference(const CAS3::Rigid_motion& a, const CAS3::Rigid_motion& b)
{
  double d = 0;
  for(int i = 0; i < 3; ++i)
  {
    for(int j = 0; j < 3; ++j)
      d = (std::max)(d, std::abs(a.rotation[i][j] - b.rotation[i][j]));
    d = (std::max)(d, std::abs(a.translation[i] - b.translation[i]));
  }
  return d;
}

// A bumpy closed surface: a sphere of radius 20 whose points carry
// curvature values that vary with the place (as a bumpy surface's would),
// each point's values its own wherever the surface is moved.
struct Surface
{
  std::vector<Point_with_normal> points;
  Layers layers;
};

Surface bumpy_surface(std::size_t n, const CAS3::Rigid_motion& motion)
{
  Surface s;
  s.layers.resize(2);
  const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
  for(std::size_t i = 0; i < n; ++i)
  {
    const double z = 1 - (2 * double(i) + 1) / double(n), r = std::sqrt(1 - z * z);
    const Xyz u{r * std::cos(golden * double(i)), r * std::sin(golden * double(i)), z};
    const Xyz p = motion({20 * u[0], 20 * u[1], 20 * u[2]});
    const Xyz q = motion({21 * u[0], 21 * u[1], 21 * u[2]});
    s.points.emplace_back(Point(p[0], p[1], p[2]), Vector(q[0] - p[0], q[1] - p[1], q[2] - p[2]));
    for(std::size_t k = 0; k < 2; ++k)
    {
      CAS3::Point_curvature<K> v;
      v.principal.max_curvature = 0.3 * std::sin(9 * u[0] + 7 * u[1] * double(k + 1)) + 0.05;
      v.principal.min_curvature = 0.3 * std::cos(8 * u[1] - 11 * u[2]) * std::sin(6 * u[0] + double(k));
      v.radius = 2.0 * double(k + 1);
      s.layers[k].push_back(v);
    }
  }
  return s;
}

template <class ConcurrencyTag = CGAL::Sequential_tag>
CAS3::Region_descriptors describe(const Surface& s, const std::vector<std::size_t>& centers)
{
  return CAS3::region_descriptors<ConcurrencyTag>(
    s.points, s.layers, centers,
    CAS3::parameters::ring_radii(std::vector<double>{2.0, 4.0, 6.0, 8.0})
      .point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
      .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>()));
}

std::vector<Point> positions(const Surface& s)
{
  std::vector<Point> out;
  for(const auto& p : s.points)
    out.push_back(p.first);
  return out;
}

BOOST_AUTO_TEST_SUITE(match_regions)

BOOST_AUTO_TEST_CASE(kabsch_fit)
{
  const CAS3::Rigid_motion m = known_motion(0.8, {3, -4, 5});
  std::vector<Xyz> source{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {1, 1, 1}}, target;
  for(const Xyz& p : source)
    target.push_back(m(p));
  BOOST_TEST(largest_difference(CAS3::fit_rigid(source, target), m) < 1e-12);
  BOOST_CHECK_THROW(CAS3::fit_rigid(source, std::vector<Xyz>()), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(registration_recovers_a_known_motion)
{
  // 40 pairs, of which every fourth is wrong
  const CAS3::Rigid_motion m = known_motion(2.0, {10, 20, -30});
  std::vector<Xyz> source, target;
  for(int i = 0; i < 40; ++i)
  {
    const Xyz p{10 * std::sin(1.3 * i), 10 * std::cos(0.7 * i), 0.5 * i};
    source.push_back(p);
    target.push_back(i % 4 == 3 ? Xyz{p[0] + 50, p[1], p[2] - 40} : m(p));
  }
  const CAS3::Registration r = CAS3::register_correspondences(source, target);
  BOOST_TEST(largest_difference(r.motion, m) < 1e-9);
  for(int i = 0; i < 40; ++i)
    BOOST_TEST(r.inliers[std::size_t(i)] == (i % 4 != 3));
  // the same on every run
  const CAS3::Registration again = CAS3::register_correspondences(source, target);
  BOOST_TEST(largest_difference(r.motion, again.motion) == 0.0);
  BOOST_CHECK_THROW(CAS3::register_correspondences(std::vector<Xyz>(2), std::vector<Xyz>(2)), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(identical_copy_matches_itself)
{
  const Surface a = bumpy_surface(6000, CAS3::Rigid_motion());
  const std::vector<std::size_t> centers = CAS3::farthest_point_sample(positions(a), 60);
  const CAS3::Region_descriptors r = describe(a, centers);
  const std::vector<double> d = CAS3::histogram_distances(r, r, false);
  for(std::size_t i = 0; i < r.size(); ++i)
    BOOST_TEST(d[i * r.size() + i] == 0.0);
  const CAS3::Region_matches m = CAS3::match_regions(r, r);
  BOOST_TEST(m.top == 10u);
  for(std::size_t i = 0; i < r.size(); ++i)
  {
    BOOST_TEST(m.candidates[i * m.top] == centers[i]);
    BOOST_TEST(m.scores[i * m.top] == 0.0);
    BOOST_TEST(m.reranked[i * m.top] == centers[i]);
  }
  BOOST_TEST(m.consistent == 1.0);
  BOOST_TEST(largest_difference(m.motion, CAS3::Rigid_motion()) < 1e-9);
}

BOOST_AUTO_TEST_CASE(rotated_translated_copy)
{
  // B is A moved; B's candidates are sampled from another first point, so they are not A's centres
  const CAS3::Rigid_motion motion = known_motion(1.1, {25, -40, 13});
  const Surface a = bumpy_surface(6000, CAS3::Rigid_motion()), b = bumpy_surface(6000, motion);
  const std::vector<std::size_t> centers = CAS3::farthest_point_sample(positions(a), 60);
  const std::vector<std::size_t> candidates =
    CAS3::farthest_point_sample(positions(b), 1500, CAS3::parameters::first_point_index(std::size_t(1234)));
  const CAS3::Region_descriptors ra = describe(a, centers), rb = describe(b, candidates);
  const CAS3::Region_matches m = CAS3::match_regions(ra, rb);
  std::size_t hits = 0, reranked_hits = 0;
  for(std::size_t i = 0; i < ra.size(); ++i)
  {
    const Xyz truth = motion(ra.center_points[i]);
    auto hit = [&](std::size_t j) {
      const Point& p = b.points[j].first;
      return CAS3::internal::squared_gap({p.x(), p.y(), p.z()}, truth) <= 9.0;
    };
    hits += hit(m.candidates[i * m.top]) ? 1 : 0;
    reranked_hits += hit(m.reranked[i * m.top]) ? 1 : 0;
  }
  BOOST_TEST(hits >= 54u);  // 0.9
  BOOST_TEST(reranked_hits == ra.size());
  BOOST_TEST(m.consistent >= 0.9);
  // B onto A: the inverse motion, to the candidates' spacing (about 1.5)
  for(const Xyz& p : {Xyz{0, 0, 20}, Xyz{20, 0, 0}, Xyz{0, -20, 0}})
    BOOST_TEST(std::sqrt(CAS3::internal::squared_gap(m.motion(motion(p)), p)) < 1.0);
}

BOOST_AUTO_TEST_CASE(layouts_must_agree)
{
  const Surface a = bumpy_surface(500, CAS3::Rigid_motion());
  const std::vector<std::size_t> centers{0, 10, 20};
  const CAS3::Region_descriptors r = describe(a, centers);
  const CAS3::Region_descriptors other =
    CAS3::region_descriptors(positions(a), a.layers, centers, CAS3::parameters::ring_radii(std::vector<double>{2.0}));
  BOOST_CHECK_THROW(CAS3::match_regions(r, other), std::invalid_argument);
  BOOST_CHECK_THROW(CAS3::histogram_distances(r, other), std::invalid_argument);
  BOOST_CHECK_THROW(CAS3::match_regions(r, CAS3::Region_descriptors()), std::invalid_argument);
}

#ifdef CGAL_LINKED_WITH_TBB
BOOST_AUTO_TEST_CASE(parallel_gives_the_serial_matches)
{
  const Surface a = bumpy_surface(6000, CAS3::Rigid_motion()), b = bumpy_surface(6000, known_motion(0.5, {1, 2, 3}));
  const auto ra = describe<CGAL::Parallel_tag>(a, CAS3::farthest_point_sample(positions(a), 300));
  const auto rb = describe<CGAL::Parallel_tag>(b, CAS3::farthest_point_sample(positions(b), 400));
  const CAS3::Region_matches serial = CAS3::match_regions<CGAL::Sequential_tag>(ra, rb);
  const CAS3::Region_matches parallel = CAS3::match_regions<CGAL::Parallel_tag>(ra, rb);
  BOOST_TEST(serial.candidates == parallel.candidates, boost::test_tools::per_element());
  BOOST_TEST(serial.scores == parallel.scores, boost::test_tools::per_element());
  BOOST_TEST(serial.reranked == parallel.reranked, boost::test_tools::per_element());
  BOOST_TEST(largest_difference(serial.motion, parallel.motion) == 0.0);
}
#endif

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_match_regions
