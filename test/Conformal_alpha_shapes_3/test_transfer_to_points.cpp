// Tests of transfer_to_points(), through Multiscale_curvatures: the values
// of the points off the surface (those of the nearest surface point, or
// none when far) and of points whose given normal faces the other side.
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/extract_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>
#include <CGAL/Conformal_alpha_shapes_3/suggest_scale.h>
#include <CGAL/Conformal_alpha_shapes_3/transfer_to_points.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include "cas3_point_values.h"
#include "cas3_test_meshes.h"
#include "cas3_test_shapes.h"
#include "cas3_test_types.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cmath>
#include <limits>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_transfer_to_points {

using namespace cas3_test_types;
using cas3_test::same_bits;

BOOST_AUTO_TEST_SUITE(transfer_to_points)

// Points that are not vertices take the values of the nearest surface point:
// on a unit sphere whose surface lost a cap, H = 1 and the normal is radial
// there too; points farther than the documented multiple of the spacing
// have no value.
BOOST_AUTO_TEST_CASE(points_off_the_surface_take_the_nearest_surface_values)
{
  cas3_test::Pipeline_without_cap sphere;
  const std::vector<Point>& pts = sphere.pts;
  const std::vector<CAS3::Point_curvature<K> >& c = sphere.values;
#ifdef CGAL_LINKED_WITH_TBB
  {
    // on one thread, the same bits: the points on their own vertex are
    // filled in parallel, the others serially
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    const std::vector<CAS3::Point_curvature<K> > serial =
      sphere.analysis.estimate_curvatures(sphere.surface, {CAS3::Neighborhood::rings(2)}).front();
    std::size_t differing = 0;
    for(std::size_t i = 0; i < c.size(); ++i)
      differing += same_bits(c[i], serial[i]) ? 0 : 1;
    BOOST_TEST(differing == 0u);
  }
#endif
  std::size_t own = 0, nearest = 0, none = 0;
  const double spacing = std::sqrt(4 * M_PI / 4000);
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    const K::Vector_3 radial = (pts[i] - CGAL::ORIGIN) / std::sqrt((pts[i] - CGAL::ORIGIN).squared_length());
    BOOST_TEST_INFO("point " << i << " at z = " << pts[i].z() << ", distance " << c[i].distance);
    switch(c[i].source)
    {
      case CAS3::SURFACE_VERTEX:
        ++own;
        BOOST_REQUIRE(c[i].distance == 0);
        break;
      case CAS3::NEAREST_SURFACE_POINT:
        ++nearest;
        BOOST_REQUIRE(pts[i].z() > 0.75);
        // the distance to the rim of the cut surface, about 1 - z's height
        BOOST_REQUIRE(c[i].distance > 0);
        BOOST_REQUIRE(std::abs(c[i].mean_curvature - 1) < 0.03);
        BOOST_REQUIRE(std::abs(c[i].gaussian_curvature - 1) < 0.06);
        // the normal of the nearest surface point: radial there, at an
        // angle of about the distance from the point's own radial direction
        BOOST_TEST_INFO("normal . radial " << c[i].normal * radial << ", H " << c[i].mean_curvature);
        BOOST_REQUIRE(c[i].normal * radial > std::cos(c[i].distance) - 0.01);
        BOOST_REQUIRE(std::abs(c[i].principal.max_direction * c[i].normal) < 1e-9);
        break;
      case CAS3::NO_VALUE:
        ++none;
        BOOST_REQUIRE(pts[i].z() > 0.8);
        BOOST_REQUIRE(c[i].distance > 2 * spacing);  // far: at least a few spacings
        BOOST_REQUIRE(std::isnan(c[i].mean_curvature));
        break;
    }
  }
  BOOST_TEST_MESSAGE("own vertex " << own << ", nearest surface point " << nearest << ", no value " << none);
  BOOST_TEST(nearest > 50u);
  BOOST_TEST(none > 50u);  // the cap's center is about 12 spacings from its rim
}

// With given normals, a point whose normal points to the other side of its
// sheet gets the values seen from that side; the sheet keeps the majority's
// orientation.
BOOST_AUTO_TEST_CASE(each_point_follows_its_given_normal)
{
  const std::vector<Point> points = cas3_test::ellipsoid_sample<Point>(4000, 1, 1, 1);
  std::vector<Vector> given;
  std::vector<bool> flipped;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    flipped.push_back(i % 10 == 3);
    const Vector outward = points[i] - CGAL::ORIGIN;
    given.push_back(flipped.back() ? -outward : outward);
  }
  const Analysis analysis(points.begin(), points.end(), CAS3::parameters::reference_normals(given));
  Analysis::Surface surface;
  analysis.surface(analysis.scale_value(CAS3::Scale::automatic()), surface);
  const auto values = analysis.estimate_curvatures(surface, {CAS3::Neighborhood::spacings(4)}).front();
  auto index = surface.property_map<Analysis::Surface_vertex, std::size_t>("v:input_index").first;
  auto normal = surface.property_map<Analysis::Surface_vertex, Vector>("v:normal").first;
  std::size_t outward_sheet = 0;
  for(Analysis::Surface_vertex v : surface.vertices())
    outward_sheet += normal[v] * (points[index[v]] - CGAL::ORIGIN) > 0 ? 1 : 0;
  BOOST_TEST(outward_sheet == surface.number_of_vertices());
  std::size_t checked = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const CAS3::Point_curvature<K>& c = values[i];
    if(!c.on_surface())
      continue;
    ++checked;
    const double side = flipped[i] ? -1 : 1;
    BOOST_TEST_INFO("point " << i);
    BOOST_REQUIRE(c.normal * given[i] > 0);
    BOOST_REQUIRE(std::abs(c.mean_curvature - side) < 0.05);
    BOOST_REQUIRE(std::abs(c.gaussian_curvature - 1) < 0.1);
    BOOST_REQUIRE(c.principal.max_curvature >= c.principal.min_curvature);
    const Vector d1_x_d2 = CGAL::cross_product(c.principal.max_direction, c.principal.min_direction);
    BOOST_REQUIRE(d1_x_d2 * c.normal > 0.99);
  }
  BOOST_TEST(checked >= points.size() * 99 / 100);
}

// Where the corners of the nearest facet have normals that cancel (a fold
// of a degenerate surface: fuzzing found 40 grid points, many repeated,
// whose 12-face surface gave a point 16 units away the zero normal), the
// point takes a corner's value: a unit normal, never the zero vector.
BOOST_AUTO_TEST_CASE(corner_normals_that_cancel_give_a_corner_value)
{
  const std::vector<Point> pts{
    {0, 64, 0},   {0, 0, 0},  {0, 10, 0},  {-14, 0, 0}, {0, 0, 0},   {0, 0, 0},   {0, 0, 64},   {0, 0, 0},
    {0, 0, 10},   {0, -14, 0}, {0, 0, 0},  {0, 0, 0},   {0, 0, 0},   {0, 0, 0},   {0, 0, 0},    {0, 0, 0},
    {0, 10, 10},  {10, 0, 0}, {10, 0, 25}, {10, 10, 10}, {1, 64, 0},  {0, 0, 0},   {10, 0, -14}, {4, 0, 0},
    {0, 10, 10},  {10, 0, 0}, {0, 0, 0},   {0, 0, 0},   {0, 0, 0},   {0, 10, 10}, {10, 0, 0},   {10, 0, 25},
    {10, 10, 10}, {1, 64, 0}, {0, 0, 0},   {10, 0, -14}, {0, 0, 10}, {10, 10, 0}, {0, 10, 0},   {25, 10, 10}};
  // many copies of a few points: too few distinct points to estimate a spacing, so one is given
  const Analysis analysis(pts.begin(), pts.end(), CAS3::parameters::noise_estimate(CAS3::Noise_estimate{8, 0, 0}));
  std::size_t nearest = 0;
  for(const CAS3::Scale& scale : {CAS3::Scale::automatic(), CAS3::Scale::quantile(0.5)})
  {
    Analysis::Surface surface;
    analysis.surface(analysis.scale_value(scale), surface);
    for(const CAS3::Neighborhood& n : {CAS3::Neighborhood::spacings(4), CAS3::Neighborhood::automatic()})
    {
      const std::vector<CAS3::Point_curvature<K> > c = analysis.estimate_curvatures(surface, {n}).front();
      for(std::size_t i = 0; i < c.size(); ++i)
        if(c[i].source != CAS3::NO_VALUE)
        {
          nearest += c[i].source == CAS3::NEAREST_SURFACE_POINT;
          BOOST_TEST_INFO("point " << i << ", source " << int(c[i].source) << ", distance " << c[i].distance);
          BOOST_TEST(std::abs(std::sqrt(c[i].normal.squared_length()) - 1) < 1e-9);
        }
    }
  }
  BOOST_TEST(nearest > 0u);
}

// Made-up values on a mesh of the unit sphere: the radial normal, and
// k1 = k2 = 1 + (vertex index) / 1000, distinct at every vertex.
std::vector<CAS3::Vertex_curvature<K> > made_up_values(const Surface_mesh& mesh)
{
  std::vector<CAS3::Vertex_curvature<K> > values(mesh.number_of_vertices());
  for(Surface_mesh::Vertex_index v : mesh.vertices())
  {
    const Vector radial = mesh.point(v) - CGAL::ORIGIN;
    const Vector n = radial / std::sqrt(radial.squared_length());
    const Vector d1 = CGAL::cross_product(n, Vector(0.3, 0.4, 0.5));
    const double k = 1 + double(std::size_t(v)) / 1000;
    CAS3::Vertex_curvature<K>& c = values[std::size_t(v)];
    c.normal = n;
    c.principal = CAS3::Principal_curvatures_and_directions<K>{k, k, d1 / std::sqrt(d1.squared_length()),
                                                               CGAL::cross_product(n, d1) / std::sqrt(d1.squared_length())};
    c.radius = 0.1;
  }
  return values;
}

// A sample of the unit sphere (`n` points), its shape and the shape's surface.
struct Sphere_surface
{
  std::vector<Point> pts;
  Cas cas;
  Surface_mesh mesh;
  Surface_mesh::Property_map<Surface_mesh::Vertex_index, std::size_t> input_index =
    mesh.add_property_map<Surface_mesh::Vertex_index, std::size_t>("v:input_index").first;

  explicit Sphere_surface(std::size_t n = 2000)
    : pts(cas3_test::ellipsoid_sample<Point>(n, 1, 1, 1)), cas(pts.begin(), pts.end())
  {
    CAS3::extract_surface(cas, CAS3::suggest_scale(cas), mesh, CAS3::parameters::vertex_input_index_map(input_index));
  }
};

// The same with 3000 points and the surface's cap above z = 0.8 cut off:
// the points of the cap are off the surface.
struct Sphere_without_cap : Sphere_surface
{
  Sphere_without_cap() : Sphere_surface(3000) { cas3_test::remove_cap_above(mesh, 0.8); }
};

// Where the nearest surface point is a vertex without a value (its own fit
// undefined), the point takes the mean of that vertex's neighbors with
// values, whichever of the vertex's facets the search named: made-up values
// on a sphere's surface, every tenth vertex's cleared.
BOOST_AUTO_TEST_CASE(a_vertex_without_a_value_takes_its_neighbors_mean)
{
  typedef Surface_mesh::Vertex_index Vertex;
  const Sphere_surface sphere;
  const std::vector<Point>& pts = sphere.pts;
  const Cas& cas = sphere.cas;
  const Surface_mesh& mesh = sphere.mesh;
  const auto& input_index = sphere.input_index;
  std::vector<CAS3::Vertex_curvature<K> > values = made_up_values(mesh);
  std::vector<Vertex> cleared;
  for(Vertex v : mesh.vertices())
  {
    bool apart = std::size_t(v) % 10 == 0;
    for(Vertex u : CGAL::vertices_around_target(v, mesh))
      apart = apart && values[std::size_t(u)].is_defined();
    if(apart)
    {
      cleared.push_back(v);
      values[std::size_t(v)] = CAS3::Vertex_curvature<K>();
    }
  }
  std::vector<std::vector<CAS3::Vertex_curvature<K> > > layers(1, values);
  std::vector<CAS3::Point_curvature<K> > out(pts.size());
  CAS3::transfer_to_points(cas, mesh, layers, [&](std::size_t) { return CGAL::make_property_map(out); },
                           CAS3::parameters::vertex_input_index_map(input_index));
  BOOST_TEST(cleared.size() > 100u);
  for(Vertex v : cleared)
  {
    double k = 0, count = 0;
    Vector n = CGAL::NULL_VECTOR;
    for(Vertex u : CGAL::vertices_around_target(v, mesh))
    {
      k += values[std::size_t(u)].principal.max_curvature;
      n = n + values[std::size_t(u)].normal;
      ++count;
    }
    n = n / std::sqrt(n.squared_length());
    const CAS3::Point_curvature<K>& c = out[input_index[v]];
    BOOST_TEST_INFO("vertex " << std::size_t(v) << ", " << count << " neighbors");
    BOOST_TEST(c.source == CAS3::NEAREST_SURFACE_POINT);
    BOOST_TEST(c.distance == 0.);
    BOOST_TEST(std::abs(c.mean_curvature - k / count) < 1e-12);
    BOOST_TEST(std::sqrt((c.normal - n).squared_length()) < 1e-12);
  }
}


// A point whose vertex stands for several surface vertices (a pinched
// vertex) takes their mean weighted by their facets' area, whichever of them
// the surface lists first: a sphere's surface and a copy of it scaled by 2
// (four times the area) as one mesh, each vertex of the copy standing for the
// same input point, with values of another normal and curvature.
BOOST_AUTO_TEST_CASE(a_pinched_vertex_takes_its_surface_vertices_mean_in_any_order)
{
  typedef Surface_mesh::Vertex_index Vertex;
  const Sphere_surface whole;
  const Surface_mesh& sphere = whole.mesh;
  const std::vector<CAS3::Vertex_curvature<K> > values = made_up_values(sphere);
  // the copy's values: the normal and directions turned by 60 degrees about z, k1 = k2 = 3
  const double c60 = 0.5, s60 = std::sqrt(3.) / 2;
  auto turned = [&](const Vector& x) { return Vector(c60 * x.x() - s60 * x.y(), s60 * x.x() + c60 * x.y(), x.z()); };
  auto copy_value = [&](CAS3::Vertex_curvature<K> c) {
    c.normal = turned(c.normal);
    c.principal = CAS3::Principal_curvatures_and_directions<K>{3, 3, turned(c.principal.max_direction),
                                                               turned(c.principal.min_direction)};
    return c;
  };
  auto transfer = [&](bool copy_first) {
    Surface_mesh mesh;
    auto input_index = mesh.add_property_map<Vertex, std::size_t>("v:input_index").first;
    std::vector<std::vector<CAS3::Vertex_curvature<K> > > layers(1);
    for(int part = 0; part < 2; ++part)
    {
      const bool copy = (part == 0) == copy_first;
      std::vector<Vertex> to(sphere.number_of_vertices());
      for(Vertex v : sphere.vertices())
      {
        to[std::size_t(v)] = mesh.add_vertex(CGAL::ORIGIN + (copy ? 2. : 1.) * (sphere.point(v) - CGAL::ORIGIN));
        input_index[to[std::size_t(v)]] = whole.input_index[v];
        layers[0].push_back(copy ? copy_value(values[std::size_t(v)]) : values[std::size_t(v)]);
      }
      for(Surface_mesh::Face_index f : sphere.faces())
      {
        std::vector<Vertex> corners;
        for(Vertex v : CGAL::vertices_around_face(sphere.halfedge(f), sphere))
          corners.push_back(to[std::size_t(v)]);
        mesh.add_face(corners);
      }
    }
    std::vector<CAS3::Point_curvature<K> > out(whole.pts.size());
    CAS3::transfer_to_points(whole.cas, mesh, layers, [&](std::size_t) { return CGAL::make_property_map(out); },
                             CAS3::parameters::vertex_input_index_map(input_index));
    return out;
  };
  const std::vector<CAS3::Point_curvature<K> > sphere_first = transfer(false), copy_first = transfer(true);
  std::size_t checked = 0;
  for(Vertex v : sphere.vertices())
  {
    const CAS3::Vertex_curvature<K>& a = values[std::size_t(v)];
    const CAS3::Vertex_curvature<K> b = copy_value(a);
    const Vector n = a.normal + 4 * b.normal;
    const double H = (a.mean_curvature() + 4 * b.mean_curvature()) / 5;
    for(const std::vector<CAS3::Point_curvature<K> >* out : {&sphere_first, &copy_first})
    {
      const CAS3::Point_curvature<K>& c = (*out)[whole.input_index[v]];
      BOOST_TEST_INFO("vertex " << std::size_t(v) << ", H " << c.mean_curvature << " against " << H);
      BOOST_TEST(c.source == CAS3::SURFACE_VERTEX);
      BOOST_TEST(std::abs(c.mean_curvature - H) < 1e-9);
      BOOST_TEST(std::sqrt((c.normal - n / std::sqrt(n.squared_length())).squared_length()) < 1e-9);
    }
    ++checked;
  }
  BOOST_TEST(checked > 1000u);
}

// A point off the surface takes the values interpolated at its nearest
// surface point, not those of one corner of the facet there: made-up values,
// distinct at every vertex, on a sphere whose cap is cut off; the points of
// the cap take values that no vertex has, but where their nearest surface
// point is a corner (many are: the rim of the cut is convex).
BOOST_AUTO_TEST_CASE(points_off_the_surface_interpolate_over_their_facet)
{
  const Sphere_without_cap sphere;
  const std::vector<Point>& pts = sphere.pts;
  const Surface_mesh& mesh = sphere.mesh;
  const std::vector<CAS3::Vertex_curvature<K> > values = made_up_values(mesh);
  std::vector<double> vertex_values;
  for(const CAS3::Vertex_curvature<K>& c : values)
    vertex_values.push_back(c.mean_curvature());
  std::sort(vertex_values.begin(), vertex_values.end());
  std::vector<std::vector<CAS3::Vertex_curvature<K> > > layers(1, values);
  std::vector<CAS3::Point_curvature<K> > out(pts.size());
  CAS3::transfer_to_points(sphere.cas, mesh, layers, [&](std::size_t) { return CGAL::make_property_map(out); },
                           CAS3::parameters::vertex_input_index_map(sphere.input_index));
  std::size_t nearest = 0, a_corner_value = 0;
  for(const CAS3::Point_curvature<K>& c : out)
    if(c.source == CAS3::NEAREST_SURFACE_POINT)
    {
      ++nearest;
      a_corner_value += std::binary_search(vertex_values.begin(), vertex_values.end(), c.mean_curvature) ? 1 : 0;
    }
  BOOST_TEST_MESSAGE(nearest << " points off the surface, " << a_corner_value << " with a corner's value");
  BOOST_TEST(nearest > 50u);
  BOOST_TEST(nearest - a_corner_value >= 30u);
}

// Layers made when the transfer asks for them, after it has called
// `release_shape`, give the points the values that the same layers given at
// once give them: made-up values on a sphere whose cap is cut off, every
// tenth vertex's cleared, so that points off the surface and vertices
// without a value both take values at their nearest surface point.
BOOST_AUTO_TEST_CASE(layers_made_when_asked_give_the_values_of_layers_given)
{
  const Sphere_without_cap sphere;
  const std::vector<Point>& pts = sphere.pts;
  const Surface_mesh& mesh = sphere.mesh;
  std::vector<CAS3::Vertex_curvature<K> > values = made_up_values(mesh);
  for(std::size_t v = 0; v < values.size(); v += 10)
    values[v] = CAS3::Vertex_curvature<K>();

  std::vector<std::vector<CAS3::Vertex_curvature<K> > > layers(2, values);
  std::vector<std::vector<CAS3::Point_curvature<K> > > given(2, std::vector<CAS3::Point_curvature<K> >(pts.size()));
  CAS3::transfer_to_points(sphere.cas, mesh, layers,
                           [&](std::size_t k) { return CGAL::make_property_map(given[k]); },
                           CAS3::parameters::vertex_input_index_map(sphere.input_index));
  BOOST_TEST((layers[0].empty() && layers[1].empty()));

  std::vector<std::vector<CAS3::Point_curvature<K> > > made(2, std::vector<CAS3::Point_curvature<K> >(pts.size()));
  int released = 0, asked = 0;
  CAS3::transfer_to_points(
    sphere.cas, mesh,
    [&]() {
      BOOST_TEST(released == 1);
      ++asked;
      return std::vector<std::vector<CAS3::Vertex_curvature<K> > >(2, values);
    },
    [&](std::size_t k) { return CGAL::make_property_map(made[k]); },
    CAS3::parameters::vertex_input_index_map(sphere.input_index,
                                             CAS3::parameters::release_shape([&]() { ++released; })));
  BOOST_TEST(released == 1);
  BOOST_TEST(asked == 1);
  std::size_t nearest = 0, differing = 0;
  for(std::size_t k = 0; k < 2; ++k)
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      nearest += given[k][i].source == CAS3::NEAREST_SURFACE_POINT ? 1 : 0;
      differing += same_bits(given[k][i], made[k][i]) ? 0 : 1;
    }
  BOOST_TEST(nearest > 100u);
  BOOST_TEST(differing == 0u);
}

// The nearest surface points found with a search tree over the faces near
// the points (internal::surface_feet() with a reach, widened where the
// nearest face is farther) are those of the tree over the whole surface:
// points near and far from a sphere with a cap cut off, the reach small
// enough that most need a wider one, and one far outside the surface's box.
BOOST_AUTO_TEST_CASE(feet_searched_near_the_points_are_the_whole_surface_feet)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  Surface_mesh sphere;
  cas3_test::irregular_sphere<Surface_mesh, Point>(3000, 1.0, sphere);
  cas3_test::remove_cap_above(sphere, 0.8);
  I::Shape_vertex_table<Point> table;
  CGAL::Random random(3);
  for(int k = 0; k < 300; ++k)
  {
    const double r = 1 + random.get_double(-0.5, 0.5) * (k % 3 == 0 ? 4 : 0.1);
    const double z = random.get_double(-1, 1), phi = random.get_double(0, 2 * CGAL_PI);
    const double s = std::sqrt(1 - z * z);
    table.points.push_back(Point(r * s * std::cos(phi), r * s * std::sin(phi), r * z));
  }
  table.points.push_back(Point(1e12, 0, 0));
  const std::vector<bool> needs(table.points.size(), true);
  const auto whole = I::surface_feet<CGAL::Sequential_tag, K>(
    table, sphere, sphere.points(), needs, std::vector<double>(needs.size(), std::numeric_limits<double>::infinity()));
  const auto near = I::surface_feet<CGAL::Sequential_tag, K>(table, sphere, sphere.points(), needs,
                                                             std::vector<double>(needs.size(), 0.01));
  BOOST_REQUIRE(whole.size() == table.points.size());
  BOOST_REQUIRE(near.size() == whole.size());
  for(std::size_t k = 0; k < whole.size(); ++k)
  {
    BOOST_TEST_INFO("point " << k);
    BOOST_TEST(near[k].shape_vertex == k);
    BOOST_TEST(std::abs(near[k].distance - whole[k].distance) <= 1e-12 * (1 + whole[k].distance));
    BOOST_TEST(CGAL::squared_distance(near[k].point, whole[k].point) <= 1e-20 * (1 + whole[k].distance));
  }
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_transfer_to_points
