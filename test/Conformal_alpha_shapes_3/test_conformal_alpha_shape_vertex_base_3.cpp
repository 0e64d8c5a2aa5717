// Tests of Conformal_alpha_shape_vertex_base_3.h: a vertex stores its local
// feature size, its pole's cell and its index, keeps them through the
// triangulation's rebind, and the shape stores in them a dense numbering of
// its vertices, an incident pole cell, and the local feature sizes given.
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shape_vertex_base_3.h>

#include "cas3_rebound_base.h"
#include "cas3_test_shapes.h"
#include "cas3_test_types.h"

#include <cstddef>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_conformal_alpha_shape_vertex_base_3 {

using namespace cas3_test_types;
typedef Tds::Vertex Vertex;

static_assert(cas3_test::is_rebound<CGAL::Conformal_alpha_shape_vertex_base_3, K, Vertex,
                                    CGAL::Triangulation_ds_vertex_base_3<Tds> >(),
              "the triangulation's vertex is the vertex base rebound to it");

BOOST_AUTO_TEST_SUITE(conformal_alpha_shape_vertex_base_3)

BOOST_AUTO_TEST_CASE(a_vertex_stores_its_values)
{
  Vertex v(Point(1, 2, 3));
  BOOST_TEST(v.point() == Point(1, 2, 3));
  BOOST_TEST(v.local_feature_size() == 0.0);
  BOOST_TEST((v.pole_cell() == Tds::Cell_handle()));
  BOOST_TEST(v.vertex_index() == 0u);

  v.set_local_feature_size(0.125);
  v.set_vertex_index(7);
  BOOST_TEST(v.local_feature_size() == 0.125);
  BOOST_TEST(v.vertex_index() == 7u);
  BOOST_TEST(v.point() == Point(1, 2, 3));
}

BOOST_AUTO_TEST_CASE(the_shape_stores_indices_poles_and_sizes)
{
  const std::vector<Point> pts = cas3_test::ellipsoid_sample<Point>(300, 1.0, 0.7, 0.4, 0.01);
  std::vector<double> sizes;
  for(std::size_t i = 0; i < pts.size(); ++i)
    sizes.push_back(0.01 + 0.001 * double(i));
  const Cas cas(pts.begin(), pts.end(), CAS3::parameters::local_feature_sizes(sizes));
  BOOST_REQUIRE(cas.number_of_vertices() == pts.size());
  std::vector<int> seen(cas.number_of_vertices(), 0);
  for(Cas::Vertex_handle v : cas.finite_vertex_handles())
  {
    BOOST_REQUIRE(v->vertex_index() < seen.size());
    ++seen[v->vertex_index()];
    BOOST_REQUIRE(v->pole_cell() != Cas::Cell_handle());
    BOOST_REQUIRE(!cas.is_infinite(v->pole_cell()));
    BOOST_REQUIRE(v->pole_cell()->has_vertex(v));
  }
  for(int count : seen)
    BOOST_REQUIRE(count == 1);
  for(std::size_t i = 0; i < pts.size(); ++i)
    BOOST_REQUIRE(cas.input_vertex(i)->local_feature_size() == sizes[i]);
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_conformal_alpha_shape_vertex_base_3
