// Tests of interruption.h: a check that asks to stop stops the construction,
// the front and the per-vertex passes with Interrupted; a check that never
// does changes nothing; the check is called on the calling thread only.
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/interruption.h>
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cas3_test_shapes.h"
#include "cas3_test_types.h"

#include <cstddef>
#include <functional>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_interruption {

using namespace cas3_test_types;

// Large enough for the loops to reach their checks; smaller under the sanitizers.
const std::vector<Point>& sample()
{
#ifdef CAS3_SANITIZED
  const std::size_t n = 4000;
#else
  const std::size_t n = 20000;
#endif
  static const std::vector<Point> points = cas3_test::ellipsoid_sample<Point>(n, 1.5, 1.0, 0.75, 0.002);
  return points;
}

// A check that asks to stop at its `stop_at`-th call, recording its threads.
struct Counting_check
{
  explicit Counting_check(std::size_t stop) : stop_at(stop) {}

  std::size_t stop_at;
  std::size_t calls = 0;
  std::set<std::thread::id> threads;
  std::mutex mutex;

  std::function<bool()> function()
  {
    return [this] {
      std::lock_guard<std::mutex> lock(mutex);
      threads.insert(std::this_thread::get_id());
      return ++calls >= stop_at;
    };
  }
};

BOOST_AUTO_TEST_SUITE(interruption)

BOOST_AUTO_TEST_CASE(a_stop_at_the_first_check_stops_the_construction_and_empties_the_shape)
{
  Counting_check check(1);
  Analysis::Shape shape;
  {
    const CAS3::Scoped_interruption_check scope(check.function());
    BOOST_CHECK_THROW(shape.make_conformal_alpha_shape(sample().begin(), sample().end()), CAS3::Interrupted);
  }
  BOOST_CHECK_EQUAL(check.calls, 1u);
  BOOST_CHECK_EQUAL(shape.number_of_vertices(), 0u);
  BOOST_CHECK_EQUAL(shape.number_of_input_points(), 0u);
  // out of the scope, nothing is checked
  BOOST_CHECK_EQUAL(shape.make_conformal_alpha_shape(sample().begin(), sample().end()), sample().size());
  BOOST_CHECK_EQUAL(check.calls, 1u);
}

BOOST_AUTO_TEST_CASE(the_front_and_the_curvature_passes_stop)
{
  Analysis::Shape shape(sample().begin(), sample().end());
  {
    Counting_check check(1);
    const CAS3::Scoped_interruption_check scope(check.function());
    BOOST_CHECK_THROW(CAS3::Surface_front<Analysis::Shape> front(shape), CAS3::Interrupted);
  }
  const CAS3::Surface_front<Analysis::Shape> front(shape);
  Analysis::Surface surface;
  front.extract_surface(front.suggest_scale(), surface);
  Counting_check check(1);
  const CAS3::Scoped_interruption_check scope(check.function());
  BOOST_CHECK_THROW(CAS3::estimate_vertex_curvatures<CGAL::Parallel_if_available_tag>(
                      surface, std::vector<CAS3::Neighborhood>{CAS3::Neighborhood::rings(2)}),
                    CAS3::Interrupted);
}

BOOST_AUTO_TEST_CASE(a_check_that_never_stops_changes_nothing_and_runs_on_the_calling_thread)
{
  const std::vector<CAS3::Curvature_layer<K> > plain = CAS3::multiscale_curvatures(sample());
  Counting_check check(std::size_t(-1));
  std::vector<CAS3::Curvature_layer<K> > checked;
  {
    const CAS3::Scoped_interruption_check scope(check.function());
    checked = CAS3::multiscale_curvatures(sample());
  }
  BOOST_CHECK_GT(check.calls, 0u);
  BOOST_CHECK(check.threads == std::set<std::thread::id>{std::this_thread::get_id()});
  BOOST_REQUIRE_EQUAL(plain.size(), checked.size());
  for(std::size_t k = 0; k < plain.size(); ++k)
    for(std::size_t i = 0; i < sample().size(); ++i)
    {
      const CAS3::Point_curvature<K>&a = plain[k].points[i], &b = checked[k].points[i];
      BOOST_REQUIRE(a.source == b.source);
      BOOST_REQUIRE((a.mean_curvature == b.mean_curvature) || (a.mean_curvature != a.mean_curvature));
      BOOST_REQUIRE(a.normal == b.normal || a.source == CAS3::NO_VALUE);
    }
}

BOOST_AUTO_TEST_CASE(checks_nest)
{
  Counting_check outer(std::size_t(-1)), inner(1);
  const CAS3::Scoped_interruption_check outer_scope(outer.function());
  {
    const CAS3::Scoped_interruption_check inner_scope(inner.function());
    BOOST_CHECK_THROW(Analysis(sample().begin(), sample().end()), CAS3::Interrupted);
  }
  BOOST_CHECK_EQUAL(outer.calls, 0u);
  const Analysis analysis(sample().begin(), sample().end());
  BOOST_CHECK_GT(outer.calls, 0u);
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_interruption
