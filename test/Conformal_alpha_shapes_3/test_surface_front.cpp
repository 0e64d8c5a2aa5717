// Tests of Surface_front, the advancing front that extract_surface() and
// suggest_scale() grow by default: how its triangle soup pairs neighbors
// and puts itself in a canonical order, and results that do not depend on
// the heap layout (through Multiscale_curvatures).
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/internal/cgal_front.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/conformal_front.h>
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_front.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cas3_analytic_surfaces.h"
#include "cas3_point_values.h"
#include "cas3_test_data.h"
#include "cas3_test_types.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_surface_front {

using namespace cas3_test_types;
using cas3_test::same_bits;
using cas3_test::sheet_points;

// Shuffles the heap's free memory: blocks of the small sizes the front
// allocates, allocated, then two thirds of them freed in a random order
// (the rest is returned, to be freed after the run that follows).
std::vector<void*> scramble_the_heap(unsigned seed)
{
  std::mt19937 random(seed);
  std::vector<void*> blocks, kept;
  for(std::size_t size = 16; size <= 256; size += 8)
    for(int i = 0; i < 4000; ++i)
      blocks.push_back(std::malloc(size));
  std::shuffle(blocks.begin(), blocks.end(), random);
  for(std::size_t i = 0; i < blocks.size(); ++i)
    if(i % 3 == 0)
      kept.push_back(blocks[i]);
    else
      std::free(blocks[i]);
  return kept;
}

BOOST_AUTO_TEST_SUITE(surface_front)

// The soup's neighbors are paired as CGAL's advancing-front surface pairs
// its faces: on an edge, the first triangle with the second, the third with
// the fourth, and a fifth is left with a border there; around a vertex of
// high degree too.
// The automatic scale is a trimmed mean of the tail: at coverage 0.99 the
// values of ranks 0.99 n to 0.999 n, so that the largest values (or any
// single one) do not decide it.
BOOST_AUTO_TEST_CASE(scale_of_closing_values_is_a_trimmed_mean_of_the_tail)
{
  std::vector<double> values;
  for(int v = 1000; v >= 1; --v)
    values.push_back(v);
  values.push_back(std::numeric_limits<double>::quiet_NaN());
  BOOST_TEST(CAS3::scale_of_closing_values(values, 0.99) == 995.0);  // ranks 990 to 998
  BOOST_TEST(CAS3::scale_of_closing_values(values, 1.0) == 1000);
  BOOST_TEST(CAS3::scale_of_closing_values(values, 0.9) == 945.5);   // ranks 900 to 989
  std::vector<double> moved = values;
  moved[0] = 1e9;  // the largest, trimmed
  BOOST_TEST(CAS3::scale_of_closing_values(moved, 0.99) == 995.0);
  moved[500] = 995.5;  // one value from the middle into the tail
  BOOST_TEST(CAS3::scale_of_closing_values(moved, 0.99) == 995.5);
  BOOST_TEST(CAS3::scale_of_closing_values({std::numeric_limits<double>::quiet_NaN()}, 0.99)
             == std::numeric_limits<double>::infinity());
  BOOST_TEST(CAS3::scale_of_closing_values({3.0}, 0.99) == 3.0);
  BOOST_CHECK_THROW(CAS3::scale_of_closing_values(values, 0.0), std::invalid_argument);
  BOOST_CHECK_THROW(CAS3::scale_of_closing_values(values, 1.5), std::invalid_argument);
}

// The number of points of `points` with x below `cut` whose closing value
// differs (beyond 1e-9) between the whole cloud and its piece of x below
// `cut + halo`, both given the whole cloud's noise estimate; and that of
// those points.
std::pair<std::size_t, std::size_t> closing_values_of_a_piece(const std::vector<Point>& points, double cut,
                                                              double halo)
{
  const CAS3::Noise_estimate noise = CAS3::estimate_noise(points);
  const Analysis whole(points.begin(), points.end(), CAS3::parameters::noise_estimate(noise));
  std::vector<Point> piece;
  for(const Point& p : points)
    if(p.x() < cut + halo)
      piece.push_back(p);
  const Analysis part(piece.begin(), piece.end(), CAS3::parameters::noise_estimate(noise));
  const std::vector<double> expected = whole.closing_values(), values = part.closing_values();
  std::size_t core = 0, differing = 0, k = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    if(!(points[i].x() < cut + halo))
      continue;
    const double value = values[k++];
    if(points[i].x() < cut)
    {
      ++core;
      const bool same = (std::isnan(value) && std::isnan(expected[i]))
                        || std::abs(value - expected[i]) <= 1e-9 * std::abs(expected[i]);
      differing += same ? 0 : 1;
    }
  }
  return {core, differing};
}

// A vertex's closing value is a value of its star: a piece of the cloud
// whose halo holds the stars and poles of its core gives the core the whole
// cloud's values (to rounding: the pieces' working frames differ), so that
// tiles read one run's automatic scale from their own values. On the torus
// a halo over the tube's radius holds every pole; building.ply, an open
// scan of flat walls, has far poles and long facets off its borders, so a
// few of its core values may differ (the front's greedy growth, which set
// these values before, changes several times more).
BOOST_AUTO_TEST_CASE(closing_values_are_those_of_the_star)
{
  Sample torus = cas3_analytic::torus_truth_sample<Point, Vector>(sheet_points, 1.0, 0.35);
  cas3_analytic::add_normal_noise(torus, 0.1, 11);
  const std::pair<std::size_t, std::size_t> on_torus = closing_values_of_a_piece(torus.points, 0.0, 0.5);
  BOOST_TEST(on_torus.first > sheet_points / 3);
  BOOST_TEST(on_torus.second == 0u);
#ifndef CAS3_SANITIZED
  const std::vector<Point> building = cas3_test::read_points<Point>(cas3_test::test_data_file("building.ply"));
  std::vector<double> x;
  for(const Point& p : building)
    x.push_back(p.x());
  std::nth_element(x.begin(), x.begin() + std::ptrdiff_t(x.size() / 2), x.end());
  const double spacing = CAS3::estimate_noise(building).spacing;
  const std::pair<std::size_t, std::size_t> on_building =
    closing_values_of_a_piece(building, x[x.size() / 2], 40 * spacing);
  BOOST_TEST_MESSAGE("building.ply: " << on_building.second << " of " << on_building.first
                                      << " core closing values differ");
  BOOST_TEST(on_building.first > building.size() / 3);
  BOOST_TEST(on_building.second <= on_building.first / 500);
#else
  BOOST_TEST_MESSAGE("sanitizer build: building.ply is tested in the Release build");
#endif
}

BOOST_AUTO_TEST_CASE(soup_neighbors_pair_the_triangles_on_an_edge)
{
  CAS3::internal::Advancing_front_soup soup;
  soup.shape_vertex = {0, 1, 2, 3, 4, 5, 6, 7};
  soup.triangles = {{{0, 1, 2}}, {{1, 0, 3}}, {{0, 1, 4}}, {{1, 0, 5}}, {{0, 1, 6}}, {{2, 1, 7}}};
  soup.values.assign(soup.triangles.size(), 1.);
  CAS3::internal::pair_neighbors(soup);
  const std::size_t o = CAS3::internal::Advancing_front_soup::no_neighbor;
  const std::vector<std::array<std::size_t, 3> > expected = {
    {{5, o, 1}}, {{o, o, 0}}, {{o, o, 3}}, {{o, o, 2}}, {{o, o, o}}, {{o, o, 0}}};
  BOOST_TEST((soup.neighbors == expected));

  // a closed fan of 1,000 triangles around vertex 0: each spoke joins two
  // triangles, the rim is a border
  const std::size_t n = 1000;
  CAS3::internal::Advancing_front_soup fan;
  fan.shape_vertex.resize(n + 1);
  for(std::size_t i = 0; i < n; ++i)
    fan.triangles.push_back({{0, i + 1, (i + 1) % n + 1}});
  fan.values.assign(n, 1.);
  CAS3::internal::pair_neighbors(fan);
  std::size_t wrong = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::array<std::size_t, 3> around = {{o, (i + 1) % n, (i + n - 1) % n}};
    wrong += fan.neighbors[i] == around ? 0 : 1;
  }
  BOOST_TEST(wrong == 0u);
}

// The soup's canonical order depends on its triangles only, not on the
// order, the vertex numbers or the orientation of each part that the front
// gave (which follow memory addresses): a strip of two triangles and a
// lone triangle, given both ways, come out the same.
BOOST_AUTO_TEST_CASE(canonical_soup_order_ignores_how_the_front_gave_it)
{
  typedef std::array<std::size_t, 3> Triangle;
  // triangles over shape vertices, with their values
  const std::vector<Triangle> strip_and_lone = {{{0, 1, 2}}, {{2, 1, 3}}, {{4, 5, 6}}};
  const std::vector<double> values = {1., 2., 3.};
  auto canonical = [&](bool renumbered, bool reversed, bool strip_turned, bool lone_turned) {
    CAS3::internal::Advancing_front_soup soup;
    for(std::size_t v = 0; v < 7; ++v)
      soup.shape_vertex.push_back(renumbered ? 6 - v : v);
    for(std::size_t i = 0; i < 3; ++i)
    {
      const std::size_t t = reversed ? 2 - i : i;
      Triangle triangle = strip_and_lone[t];
      for(std::size_t& v : triangle)
        v = renumbered ? 6 - v : v;
      if((strip_turned && t < 2) || (lone_turned && t == 2))
        std::swap(triangle[1], triangle[2]);
      soup.triangles.push_back(triangle);
      soup.values.push_back(values[t]);
    }
    CAS3::internal::pair_neighbors(soup);
    CAS3::internal::put_in_canonical_order(soup);
    return soup;
  };
  const CAS3::internal::Advancing_front_soup reference = canonical(false, false, false, false);
  for(int variant = 1; variant < 16; ++variant)
  {
    const CAS3::internal::Advancing_front_soup other =
      canonical(variant & 1, variant & 2, variant & 4, variant & 8);
    BOOST_TEST_CONTEXT("variant " << variant)
    {
      BOOST_TEST((other.shape_vertex == reference.shape_vertex));
      BOOST_TEST((other.triangles == reference.triangles));
      BOOST_TEST((other.neighbors == reference.neighbors));
      BOOST_TEST((other.values == reference.values));
    }
  }
  // the strip is one part: its triangles are neighbors
  BOOST_TEST(reference.neighbors[0][0] == 1u);
}

// The same on random soups: closed tetrahedra, open and closed fans, and
// strips whose last soup vertex may stand for the shape vertex of their
// first (as where the front met itself), each given in a random numbering,
// triangle order, rotation and orientation of each part. The canonical soup
// also keeps every neighbor across its edge, running the other way.
BOOST_AUTO_TEST_CASE(canonical_soup_order_on_random_soups)
{
  typedef std::array<std::size_t, 3> Triangle;
  typedef CAS3::internal::Advancing_front_soup Soup;
  std::mt19937 random(5);
  auto below = [&](std::size_t n) { return std::size_t(random() % n); };
  for(int trial = 0; trial < 300; ++trial)
  {
    std::vector<std::vector<Triangle> > parts;  // over soup vertices
    std::vector<std::size_t> shape_vertex;      // by soup vertex
    auto vertex = [&]() {
      shape_vertex.push_back(shape_vertex.size());
      return shape_vertex.size() - 1;
    };
    for(std::size_t p = 0, n = 1 + below(4); p < n; ++p)
    {
      std::vector<Triangle> part;
      const std::size_t kind = below(3);
      if(kind == 0)
      {
        const std::size_t a = vertex(), b = vertex(), c = vertex(), d = vertex();
        part = {{{a, b, c}}, {{a, d, b}}, {{b, d, c}}, {{a, c, d}}};
      }
      else if(kind == 1)
      {
        const std::size_t center = vertex(), k = 3 + below(4);
        std::vector<std::size_t> rim(k);
        for(std::size_t& v : rim)
          v = vertex();
        for(std::size_t i = 0, triangles = below(2) ? k : k - 1; i < triangles; ++i)
          part.push_back({{center, rim[i], rim[(i + 1) % k]}});
      }
      else
      {
        const std::size_t length = 2 + below(3);
        std::vector<std::size_t> a(length + 1), b(length + 1);
        for(std::size_t i = 0; i <= length; ++i)
        {
          a[i] = vertex();
          b[i] = vertex();
        }
        for(std::size_t i = 0; i < length; ++i)
        {
          part.push_back({{a[i], b[i], a[i + 1]}});
          part.push_back({{b[i], b[i + 1], a[i + 1]}});
        }
        if(below(2))
          shape_vertex[b[length]] = shape_vertex[a[0]];
      }
      parts.push_back(part);
    }

    auto canonical = [&](bool as_built) {
      std::vector<std::size_t> number(shape_vertex.size());
      std::iota(number.begin(), number.end(), std::size_t(0));
      if(!as_built)
        std::shuffle(number.begin(), number.end(), random);
      Soup soup;
      soup.shape_vertex.resize(shape_vertex.size());
      for(std::size_t v = 0; v < shape_vertex.size(); ++v)
        soup.shape_vertex[number[v]] = shape_vertex[v];
      std::vector<std::pair<Triangle, double> > given;
      for(const std::vector<Triangle>& part : parts)
      {
        const bool turned = !as_built && below(2) == 1;
        for(Triangle t : part)
        {
          for(std::size_t& v : t)
            v = number[v];
          if(turned)
            std::swap(t[1], t[2]);
          if(!as_built)
            std::rotate(t.begin(), t.begin() + std::ptrdiff_t(below(3)), t.end());
          given.emplace_back(t, double(given.size()));
        }
      }
      if(!as_built)
        std::shuffle(given.begin(), given.end(), random);
      for(const std::pair<Triangle, double>& t : given)
      {
        soup.triangles.push_back(t.first);
        soup.values.push_back(t.second);
      }
      CAS3::internal::pair_neighbors(soup);
      CAS3::internal::put_in_canonical_order(soup);
      return soup;
    };

    const Soup reference = canonical(true);
    std::size_t wrong = 0;
    for(std::size_t t = 0; t < reference.triangles.size(); ++t)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t n = reference.neighbors[t][k];
        if(n == Soup::no_neighbor)
          continue;
        const std::size_t a = reference.triangles[t][(k + 1) % 3], b = reference.triangles[t][(k + 2) % 3];
        bool back = false;
        for(int j = 0; j < 3; ++j)
          back = back || (reference.triangles[n][(j + 1) % 3] == b && reference.triangles[n][(j + 2) % 3] == a
                          && reference.neighbors[n][j] == t);
        wrong += back ? 0 : 1;
      }
    BOOST_TEST_CONTEXT("trial " << trial)
    {
      BOOST_TEST(wrong == 0u);
      for(int variant = 0; variant < 4; ++variant)
      {
        const Soup other = canonical(false);
        BOOST_TEST((other.shape_vertex == reference.shape_vertex));
        BOOST_TEST((other.triangles == reference.triangles));
        BOOST_TEST((other.neighbors == reference.neighbors));
        BOOST_TEST((other.values == reference.values));
      }
    }
  }
}

// The results do not depend on the heap layout: the front orders its
// candidates of equal priority by vertex and cell indices, not by address
// (CGAL's front did not, and exact ties of fold angles on a lattice once
// changed 15 of the cube's 1,538 points). On a noisy torus and on the
// surface of a 17 x 17 x 17 cube lattice the same bits come out after the
// heap's free memory was shuffled, three ways.
BOOST_AUTO_TEST_CASE(the_heap_layout_does_not_change_the_results)
{
  Sample torus = cas3_analytic::torus_truth_sample<Point, Vector>(sheet_points / 2, 1.0, 0.35);
  cas3_analytic::add_normal_noise(torus, 0.1, 5);
  std::vector<Point> cube;
  for(int x = 0; x < 17; ++x)
    for(int y = 0; y < 17; ++y)
      for(int z = 0; z < 17; ++z)
        if(x == 0 || x == 16 || y == 0 || y == 16 || z == 0 || z == 16)
          cube.push_back(Point(x, y, z));
  const std::vector<CAS3::Neighborhood> neighborhoods{CAS3::Neighborhood::rings(2), CAS3::Neighborhood::automatic()};
  for(const std::vector<Point>& points : {torus.points, cube})
  {
    auto run = [&]() {
      const Analysis analysis(points.begin(), points.end());
      Analysis::Surface surface;
      analysis.surface(analysis.scale_value(CAS3::Scale::automatic()), surface);
      return analysis.estimate_curvatures(surface, neighborhoods);
    };
    const auto reference = run();
    for(unsigned seed : {1u, 2u, 3u})
    {
      const std::vector<void*> kept = scramble_the_heap(seed);
      const auto layers = run();
      for(void* block : kept)
        std::free(block);
      for(std::size_t l = 0; l < neighborhoods.size(); ++l)
      {
        std::size_t differing = 0;
        for(std::size_t i = 0; i < points.size(); ++i)
          differing += same_bits(reference[l][i], layers[l][i]) ? 0 : 1;
        BOOST_TEST_CONTEXT(points.size() << " points, heap shuffled with seed " << seed << ", neighborhood " << l)
        {
          BOOST_TEST(differing == 0u);
        }
      }
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

// The advancing front grown on the shape's own triangulation
// (internal/conformal_front.h, the library's) against CGAL's, run on a copy
// of it (cgal_front_soup()): the same soup, to the last bit of every value
// (a facet's value does not depend on the cell it is read from).
BOOST_AUTO_TEST_SUITE(conformal_front)

bool same_double_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

struct Front_cloud
{
  std::string name;
  std::vector<Point> points;
};

std::vector<Front_cloud> front_clouds()
{
  std::vector<Front_cloud> clouds;
  auto sampled = [&](const std::string& name, Sample s, double noise, unsigned seed) {
    cas3_analytic::add_normal_noise(s, noise, seed);
    clouds.push_back(Front_cloud{name, s.points});
  };
  sampled("noisy sphere", cas3_analytic::ellipsoid_truth_sample<Point, Vector>(3000, 1, 1, 1), 0.1, 1);
  sampled("very noisy sphere", cas3_analytic::ellipsoid_truth_sample<Point, Vector>(3000, 1, 1, 1), 0.6, 2);
  sampled("noisy ellipsoid", cas3_analytic::ellipsoid_truth_sample<Point, Vector>(4000, 1, 0.7, 0.4), 0.1, 3);
  sampled("open noisy cap", cas3_analytic::ellipsoid_truth_sample<Point, Vector>(3000, 1, 1, 1, 0.2), 0.1, 4);
  sampled("noisy torus", cas3_analytic::torus_truth_sample<Point, Vector>(4000, 1.0, 0.35), 0.1, 5);
  clouds.push_back(Front_cloud{"bunny", cas3_test::read_points<Point>(CAS3_BUNNY_XYZ)});
  return clouds;
}

BOOST_AUTO_TEST_CASE(the_same_soup_as_cgal_advancing_front)
{
  for(const Front_cloud& cloud : front_clouds())
  {
    const Cas cas(cloud.points.begin(), cloud.points.end());
    const CAS3::internal::Advancing_front_soup cgal = CAS3::internal::cgal_front_soup(cas);
    std::size_t anomalies = 0;
    const CAS3::internal::Advancing_front_soup ours = CAS3::internal::conformal_front_soup(cas, &anomalies);
    BOOST_TEST_CONTEXT(cloud.name)
    {
      BOOST_TEST(anomalies == 0u);
      BOOST_TEST(ours.triangles.size() == cgal.triangles.size());
      BOOST_TEST((ours.shape_vertex == cgal.shape_vertex));
      BOOST_TEST((ours.triangles == cgal.triangles));
      BOOST_TEST((ours.neighbors == cgal.neighbors));
      BOOST_REQUIRE(ours.values.size() == cgal.values.size());
      std::size_t differing = 0;
      for(std::size_t t = 0; t < ours.values.size(); ++t)
        differing += same_double_bits(ours.values[t], cgal.values[t]) ? 0 : 1;
      BOOST_TEST(differing == 0u);
      BOOST_TEST_MESSAGE(cloud.name << ": " << ours.triangles.size() << " triangles");
    }
  }
}

// Its soup, in the front's order too, does not depend on the heap layout.
BOOST_AUTO_TEST_CASE(the_heap_layout_does_not_change_the_soup)
{
  Sample s = cas3_analytic::ellipsoid_truth_sample<Point, Vector>(3000, 1, 0.8, 0.6, 0.1);
  cas3_analytic::add_normal_noise(s, 0.3, 6);
  const Cas cas(s.points.begin(), s.points.end());
  const CAS3::internal::Advancing_front_soup reference = CAS3::internal::conformal_front_triangles(cas);
  for(unsigned seed : {1u, 2u})
  {
    const std::vector<void*> kept = scramble_the_heap(seed);
    const CAS3::internal::Advancing_front_soup soup = CAS3::internal::conformal_front_triangles(cas);
    for(void* block : kept)
      std::free(block);
    BOOST_TEST_CONTEXT("heap shuffled with seed " << seed)
    {
      BOOST_TEST((soup.shape_vertex == reference.shape_vertex));
      BOOST_TEST((soup.triangles == reference.triangles));
      BOOST_TEST((soup.neighbors == reference.neighbors));
      std::size_t differing = 0;
      for(std::size_t t = 0; t < soup.values.size() && t < reference.values.size(); ++t)
        differing += same_double_bits(soup.values[t], reference.values[t]) ? 0 : 1;
      BOOST_TEST(differing == 0u);
    }
  }
}

#ifdef CGAL_LINKED_WITH_TBB
// The front's passes over cells, facets and triangles (the seeds, the
// surface's order and values, the neighbors, the canonical order) and its
// sorts run on TBB's threads, and so does the cut at a scale: on one thread,
// the same soups to the last bit.
BOOST_AUTO_TEST_CASE(one_thread_gives_the_same_soups)
{
  std::vector<Front_cloud> clouds = front_clouds();
  Sample large = cas3_analytic::ellipsoid_truth_sample<Point, Vector>(40000, 1, 0.7, 0.4);
  cas3_analytic::add_normal_noise(large, 0.3, 7);
  clouds.push_back(Front_cloud{"large noisy ellipsoid", large.points});
  for(const Front_cloud& cloud : clouds)
  {
    const Cas cas(cloud.points.begin(), cloud.points.end());
    const CAS3::internal::Advancing_front_soup soup = CAS3::internal::conformal_front_soup(cas);
    const CAS3::Surface_front<Cas> front(cas);
    const double a = front.suggest_scale();
    const CAS3::internal::Advancing_front_soup pruned = CAS3::internal::pruned_soup(soup, a);
    CAS3::internal::Advancing_front_soup one_soup, one_pruned;
    double one_a = 0;
    tbb::task_arena(1).execute([&]() {
      one_soup = CAS3::internal::conformal_front_soup(cas);
      one_pruned = CAS3::internal::pruned_soup(one_soup, a);
      one_a = front.suggest_scale();
    });
    BOOST_TEST_CONTEXT(cloud.name)
    {
      BOOST_TEST(one_a == a);
      for(const auto& pair : {std::make_pair(&soup, &one_soup), std::make_pair(&pruned, &one_pruned)})
      {
        const CAS3::internal::Advancing_front_soup &threads = *pair.first, &one = *pair.second;
        BOOST_TEST(threads.triangles.size() > 100u);
        BOOST_TEST((one.shape_vertex == threads.shape_vertex));
        BOOST_TEST((one.triangles == threads.triangles));
        BOOST_TEST((one.neighbors == threads.neighbors));
        BOOST_TEST((one.values.size() == threads.values.size()
                    && std::memcmp(one.values.data(), threads.values.data(), one.values.size() * sizeof(double)) == 0));
      }
    }
  }
}
#endif // CGAL_LINKED_WITH_TBB

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_surface_front
