// Tests of Conformal_alpha_shape_cell_base_3.h: a cell stores its alpha,
// four independent encroachment flags and a 32-bit index, keeps them through
// the triangulation's rebind, and the shape stores in them the circumradius,
// the encroachments and a dense numbering of its cells.
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shape_cell_base_3.h>

#include "cas3_rebound_base.h"
#include "cas3_test_shapes.h"
#include "cas3_test_types.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_conformal_alpha_shape_cell_base_3 {

using namespace cas3_test_types;
typedef Tds::Cell Cell;

static_assert(cas3_test::is_rebound<CGAL::Conformal_alpha_shape_cell_base_3, K, Cell,
                                    CGAL::Triangulation_ds_cell_base_3<Tds> >(),
              "the triangulation's cell is the cell base rebound to it");

BOOST_AUTO_TEST_SUITE(conformal_alpha_shape_cell_base_3)

BOOST_AUTO_TEST_CASE(a_cell_stores_its_values)
{
  Cell c;
  BOOST_TEST(c.alpha() == 0.0);
  BOOST_TEST(c.cell_index() == 0u);
  for(int i = 0; i < 4; ++i)
    BOOST_TEST(!c.encroaches_facet(i));

  c.set_alpha(2.5);
  BOOST_TEST(c.alpha() == 2.5);
  const std::size_t largest = std::numeric_limits<std::uint32_t>::max();
  c.set_cell_index(largest);
  BOOST_TEST(c.cell_index() == largest);

  // each flag is set and cleared alone
  c.set_encroaches_facet(0, true);
  c.set_encroaches_facet(3, true);
  BOOST_TEST((c.encroaches_facet(0) && !c.encroaches_facet(1) && !c.encroaches_facet(2) && c.encroaches_facet(3)));
  c.set_encroaches_facet(0, false);
  c.set_encroaches_facet(3, true);
  BOOST_TEST((!c.encroaches_facet(0) && !c.encroaches_facet(1) && !c.encroaches_facet(2) && c.encroaches_facet(3)));
  BOOST_TEST(c.alpha() == 2.5);
  BOOST_TEST(c.cell_index() == largest);
}

BOOST_AUTO_TEST_CASE(the_shape_stores_circumradii_encroachments_and_indices)
{
  const std::vector<Point> pts = cas3_test::ellipsoid_sample<Point>(300, 1.0, 0.7, 0.4, 0.01);
  const Cas cas(pts.begin(), pts.end());
  std::vector<int> seen(cas.number_of_cells(), 0);
  std::size_t checked = 0;
  for(Cas::Cell_handle c : cas.all_cell_handles())
  {
    BOOST_REQUIRE(c->cell_index() < seen.size());
    ++seen[c->cell_index()];
    if(cas.is_infinite(c))
      continue;
    const Point center = CGAL::circumcenter(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                            c->vertex(3)->point());
    BOOST_REQUIRE(std::abs(c->alpha() - std::sqrt(CGAL::squared_distance(center, c->vertex(0)->point())))
                  <= 1e-12 * c->alpha());
    for(int i = 0; i < 4; ++i)
    {
      // vertex i against the smallest ball through the opposite facet
      const Point& a = c->vertex((i + 1) & 3)->point();
      const Point& b = c->vertex((i + 2) & 3)->point();
      const Point& d = c->vertex((i + 3) & 3)->point();
      const Point facet_center = CGAL::circumcenter(a, b, d);
      const double r2 = CGAL::squared_distance(facet_center, a);
      const double d2 = CGAL::squared_distance(facet_center, c->vertex(i)->point());
      if(std::abs(d2 - r2) <= 1e-9 * r2)
        continue;  // too near the ball's sphere for double
      BOOST_REQUIRE(c->encroaches_facet(i) == (d2 < r2));
      ++checked;
    }
  }
  for(int count : seen)
    BOOST_REQUIRE(count == 1);
  BOOST_TEST(checked > 4 * cas.number_of_finite_cells() / 2);
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_conformal_alpha_shape_cell_base_3
