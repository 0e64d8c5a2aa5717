// Tests of Conformal_alpha_shape_3: the filtration against CGAL's
// Alpha_shape_3 and against the definition computed by brute force, poles
// and local feature sizes (the noise-robust estimator against the paper's), the
// filtration's order, spectrum and quantiles, rejected input, the fuzz
// findings on the shape, and the same bits on one thread. (More bad input:
// test_bad_input.cpp.)
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shape_3.h>
#include <CGAL/Conformal_alpha_shapes_3/estimate_noise.h>
#include <CGAL/Conformal_alpha_shapes_3/extract_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/input_hygiene.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/order_free.h>
#include <CGAL/Conformal_alpha_shapes_3/suggest_scale.h>

#include <CGAL/Alpha_shape_3.h>
#include <CGAL/Alpha_shape_cell_base_3.h>
#include <CGAL/Alpha_shape_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Hilbert_sort_3.h>
#include <CGAL/Multiscale_sort.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include "cas3_test_shapes.h"
#include "cas3_test_types.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <list>
#include <map>
#include <random>
#include <string>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_conformal_alpha_shape_3 {

using namespace cas3_test_types;

typedef CGAL::Triangulation_data_structure_3<CGAL::Alpha_shape_vertex_base_3<K>,
                                             CGAL::Alpha_shape_cell_base_3<K> > Oracle_tds;
typedef CGAL::Alpha_shape_3<CGAL::Delaunay_triangulation_3<K, Oracle_tds> > Oracle;

// A simplex is identified by its sorted vertex points, so that simplices of
// two triangulations of the same points can be matched.
template <class Vertex_handle, std::size_t N>
std::vector<Point> key(const std::array<Vertex_handle, N>& vs)
{
  std::vector<Point> k;
  for(const auto& v : vs) k.push_back(v->point());
  std::sort(k.begin(), k.end());
  return k;
}

template <class Shape>
std::array<typename Shape::Vertex_handle, 3> facet_vertices(const typename Shape::Facet& f)
{
  return {f.first->vertex((f.second + 1) & 3), f.first->vertex((f.second + 2) & 3),
          f.first->vertex((f.second + 3) & 3)};
}

// Classification names of every finite simplex, keyed by its points.
template <class Shape, class Alpha>
std::map<std::vector<Point>, int> classification(const Shape& s, const Alpha& alpha)
{
  std::map<std::vector<Point>, int> m;
  for(auto v : s.finite_vertex_handles())
    m[key(std::array<typename Shape::Vertex_handle, 1>{v})] = int(s.classify(v, alpha));
  for(const auto& e : s.finite_edges())
    m[key(std::array<typename Shape::Vertex_handle, 2>{e.first->vertex(e.second),
                                                       e.first->vertex(e.third)})] =
      int(s.classify(e, alpha)) + 10;
  for(const auto& f : s.finite_facets())
    m[key(facet_vertices<Shape>(f))] = int(s.classify(f, alpha)) + 20;
  for(auto c : s.finite_cell_handles())
    m[key(std::array<typename Shape::Vertex_handle, 4>{c->vertex(0), c->vertex(1), c->vertex(2),
                                                       c->vertex(3)})] = int(s.classify(c, alpha)) + 30;
  return m;
}

void check_against_oracle(const std::vector<Point>& pts, const std::string& name)
{
  const std::vector<double> ones(pts.size(), 1.0);
  const Cas cas(pts.begin(), pts.end(), CAS3::parameters::local_feature_sizes(ones.begin()));
  const Oracle oracle(pts.begin(), pts.end(), 0, Oracle::GENERAL);
  BOOST_REQUIRE_EQUAL(cas.number_of_finite_cells(), oracle.number_of_finite_cells());

  // the enum values are declared in the same order in both classes
  BOOST_REQUIRE_EQUAL(int(Cas::EXTERIOR), int(Oracle::EXTERIOR));
  BOOST_REQUIRE_EQUAL(int(Cas::SINGULAR), int(Oracle::SINGULAR));
  BOOST_REQUIRE_EQUAL(int(Cas::REGULAR), int(Oracle::REGULAR));
  BOOST_REQUIRE_EQUAL(int(Cas::INTERIOR), int(Oracle::INTERIOR));

  // scales between consecutive spectrum values, across the whole spectrum
  const std::size_t n = oracle.number_of_alphas();
  for(double q : {0.001, 0.01, 0.05, 0.1, 0.2, 0.35, 0.5, 0.75, 0.95})
  {
    const std::size_t k = std::max<std::size_t>(1, std::size_t(q * double(n)));
    const double alpha2 = 0.5 * (oracle.get_nth_alpha(int(k)) + oracle.get_nth_alpha(int(k + 1)));
    const auto expected = classification(oracle, alpha2);
    const auto got = classification(cas, std::sqrt(alpha2));
    BOOST_REQUIRE_EQUAL(got.size(), expected.size());
    std::size_t mismatches = 0;
    for(const auto& kv : expected)
    {
      auto it = got.find(kv.first);
      if(it == got.end() || it->second != kv.second) ++mismatches;
    }
    BOOST_TEST_INFO(name << " at quantile " << q);
    BOOST_TEST(mismatches == 0u);
    BOOST_TEST(cas.number_of_solid_components(std::sqrt(alpha2)) ==
               oracle.number_of_solid_components(alpha2));
  }
}

double angle_degrees(const Vector& a, const Vector& b)
{
  const double c = (a * b) / std::sqrt(a.squared_length() * b.squared_length());
  return std::acos(std::max(-1.0, std::min(1.0, c))) * 180.0 / M_PI;
}

BOOST_AUTO_TEST_SUITE(conformal_alpha_shape_3)

BOOST_AUTO_TEST_CASE(oracle_random_volume)
{
  check_against_oracle(cas3_test::cube_volume_sample<Point>(1500), "random volume");
}

BOOST_AUTO_TEST_CASE(oracle_noisy_ellipsoid)
{
  check_against_oracle(cas3_test::ellipsoid_sample<Point>(2000, 1.0, 0.7, 0.4, 0.01), "noisy ellipsoid");
}

BOOST_AUTO_TEST_CASE(oracle_noisy_torus)
{
  check_against_oracle(cas3_test::torus_sample<Point>(2000, 1.0, 0.3, 0.01), "noisy torus");
}

// The conformal value of every finite simplex of `pts` with the local
// scales `scales`, from the definition (the manual, "Values"), by brute
// force and without the class: the Delaunay cells are the 4-subsets whose
// circumsphere holds no other point; the ordinary value alpha(s) of a cell
// is its circumradius, that of a facet or an edge the radius of its
// smallest circumscribing ball when no other point is inside that ball,
// else the smallest value of its cofaces; a(s) = alpha(s) / (the smallest
// local feature size of its vertices), 0 for a vertex. Keyed by the sorted input
// indices of the vertices (the points must be distinct, in general
// position).
std::map<std::vector<std::size_t>, double> conformal_values_by_definition(const std::vector<Point>& pts,
                                                                          const std::vector<double>& scales)
{
  const std::size_t n = pts.size();
  typedef std::vector<std::size_t> Simplex_key;
  std::map<Simplex_key, double> alpha;                       // ordinary values
  std::map<Simplex_key, std::vector<double> > coface_values;  // of the facets and edges
  auto empty_ball = [&](const Simplex_key& s, auto inside) {
    for(std::size_t m = 0; m < n; ++m)
      if(std::find(s.begin(), s.end(), m) == s.end() && inside(pts[m]))
        return false;
    return true;
  };
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      for(std::size_t k = j + 1; k < n; ++k)
        for(std::size_t l = k + 1; l < n; ++l)
        {
          const Point &p = pts[i], &q = pts[j], &r = pts[k], &s = pts[l];
          if(CGAL::coplanar(p, q, r, s))
            continue;
          const Simplex_key cell = {i, j, k, l};
          if(!empty_ball(cell, [&](const Point& t) {
               return CGAL::side_of_bounded_sphere(p, q, r, s, t) == CGAL::ON_BOUNDED_SIDE; }))
            continue;
          alpha[cell] = std::sqrt(CGAL::squared_radius(p, q, r, s));
          for(std::size_t drop = 0; drop < 4; ++drop)
          {
            Simplex_key facet;
            for(std::size_t x = 0; x < 4; ++x)
              if(x != drop)
                facet.push_back(cell[x]);
            coface_values[facet].push_back(alpha[cell]);
          }
        }
  std::vector<Simplex_key> facets;
  for(const auto& f : coface_values)
    facets.push_back(f.first);
  for(const Simplex_key& f : facets)
  {
    const Point &p = pts[f[0]], &q = pts[f[1]], &r = pts[f[2]];
    const std::vector<double>& cofaces = coface_values[f];
    alpha[f] = empty_ball(f, [&](const Point& t) { return CGAL::side_of_bounded_sphere(p, q, r, t) == CGAL::ON_BOUNDED_SIDE; })
      ? std::sqrt(CGAL::squared_radius(p, q, r))
      : *std::min_element(cofaces.begin(), cofaces.end());
    for(const Simplex_key& e : {Simplex_key{f[0], f[1]}, Simplex_key{f[0], f[2]}, Simplex_key{f[1], f[2]}})
      coface_values[e].push_back(alpha[f]);
  }
  for(const auto& e : coface_values)
  {
    if(e.first.size() != 2)
      continue;
    const Point &p = pts[e.first[0]], &q = pts[e.first[1]];
    alpha[e.first] = empty_ball(e.first, [&](const Point& t) { return CGAL::side_of_bounded_sphere(p, q, t) == CGAL::ON_BOUNDED_SIDE; })
      ? std::sqrt(CGAL::squared_distance(p, q)) / 2
      : *std::min_element(e.second.begin(), e.second.end());
  }
  std::map<Simplex_key, double> conformal;
  for(std::size_t i = 0; i < n; ++i)
    conformal[Simplex_key{i}] = 0;
  for(const auto& s : alpha)
  {
    double smallest = scales[s.first[0]];
    for(std::size_t v : s.first)
      smallest = (std::min)(smallest, scales[v]);
    conformal[s.first] = s.second / smallest;
  }
  return conformal;
}

// The part of the values that is this package's own: on small random sets
// with random local feature sizes (a factor 30 between the smallest and the
// largest), every finite simplex's conformal value, through the filtration,
// is the one of the definition computed by brute force, and the filtration
// holds exactly the Delaunay simplices.
BOOST_AUTO_TEST_CASE(oracle_for_random_local_feature_sizes)
{
  std::mt19937 random(17);
  std::uniform_real_distribution<double> exponent(-1.5, 2);
  for(int trial = 0; trial < 8; ++trial)
  {
    // a volume, and a noisy sphere (many facets and edges that take a
    // coface's value)
    const std::vector<Point> pts = trial % 2 == 0
      ? cas3_test::cube_volume_sample<Point>(36, unsigned(100 + trial))
      : cas3_test::ellipsoid_sample<Point>(36, 1, 0.8, 0.6, 0.05, unsigned(100 + trial), 1e-3);
    std::vector<double> scales;
    for(std::size_t i = 0; i < pts.size(); ++i)
      scales.push_back(std::exp(exponent(random)));
    const auto expected = conformal_values_by_definition(pts, scales);
    const Cas cas(pts.begin(), pts.end(), CAS3::parameters::local_feature_sizes(scales));
    std::vector<std::pair<Cas::Simplex, double> > filtration;
    cas.filtration_with_alpha_values(std::back_inserter(filtration));
    std::size_t wrong = 0, unknown = 0;
    for(const auto& entry : filtration)
    {
      std::vector<std::size_t> simplex_key;
      const Cas::Simplex& s = entry.first;
      const int dimension = s.dimension();
      for(int k = 0; k <= dimension; ++k)
      {
        const Cas::Vertex_handle v = dimension == 0 ? Cas::Vertex_handle(s)
          : dimension == 1 ? (k == 0 ? Cas::Edge(s).first->vertex(Cas::Edge(s).second)
                                     : Cas::Edge(s).first->vertex(Cas::Edge(s).third))
          : dimension == 2 ? Cas::Facet(s).first->vertex((Cas::Facet(s).second + 1 + k) & 3)
                           : Cas::Cell_handle(s)->vertex(k);
        simplex_key.push_back(*cas.input_indices(v).begin());
      }
      std::sort(simplex_key.begin(), simplex_key.end());
      const auto it = expected.find(simplex_key);
      if(it == expected.end())
      {
        ++unknown;
        continue;
      }
      if(!(std::abs(entry.second - it->second) <= 1e-9 * it->second) && wrong++ == 0)
        BOOST_TEST_MESSAGE("trial " << trial << ": a simplex of dimension " << dimension << " has the value "
                           << entry.second << ", by the definition " << it->second);
    }
    BOOST_TEST_CONTEXT("trial " << trial)
    {
      BOOST_TEST(filtration.size() == expected.size());
      BOOST_TEST(unknown == 0u);
      BOOST_TEST(wrong == 0u);
    }
  }
}

BOOST_AUTO_TEST_CASE(poles_on_a_sphere)
{
  const double r = 2.5;
  const auto pts = cas3_test::ellipsoid_sample<Point>(4000, r, r, r, 0.0, 7, 1e-6 * r);
  const Cas cas(pts.begin(), pts.end());
  std::size_t checked = 0;
  for(auto v : cas.finite_vertex_handles())
  {
    const Vector normal = v->point() - CGAL::ORIGIN;
    BOOST_TEST(cas.local_feature_size(v) == r, boost::test_tools::tolerance(0.05));
    // the pole of a sphere sample is near the center, so p - pole is the normal
    BOOST_TEST(angle_degrees(v->point() - cas.pole(v), normal) < 3.0);
    BOOST_TEST(std::abs(std::sqrt(CGAL::squared_distance(v->point(), cas.pole(v))) - cas.local_feature_size(v))
               < 1e-9 * r);
    ++checked;
  }
  BOOST_TEST(checked == pts.size());
}

BOOST_AUTO_TEST_CASE(poles_follow_the_normal_on_an_ellipsoid)
{
  const double a = 1.0, b = 0.8, c = 0.5;
  const auto pts = cas3_test::ellipsoid_sample<Point>(6000, a, b, c);
  const Cas cas(pts.begin(), pts.end());
  std::vector<double> angles;
  for(auto v : cas.finite_vertex_handles())
  {
    const Point& p = v->point();
    const Vector normal(p.x() / (a * a), p.y() / (b * b), p.z() / (c * c));
    angles.push_back(angle_degrees(p - cas.pole(v), normal));
    // the inner pole lies on the medial axis, no farther than the largest
    // radius of curvature a^2/c and no closer than the smallest c^2/a
    BOOST_TEST(cas.local_feature_size(v) <= a * a / c * 1.05);
    BOOST_TEST(cas.local_feature_size(v) >= c * c / a * 0.9);
  }
  std::sort(angles.begin(), angles.end());
  BOOST_TEST(angles[angles.size() / 2] < 2.0);
  BOOST_TEST(angles.back() < 10.0);
}

BOOST_AUTO_TEST_CASE(noise_robust_scales_do_not_collapse)
{
  // 0.1% radial noise on 200k points is far above the sagitta: the paper's
  // pole distances of inward-displaced points collapse (not at 60k points:
  // this test keeps its size under the sanitizers)
  const auto clean = cas3_test::ellipsoid_sample<Point>(200000, 1.0, 0.7, 0.4);
  const auto noisy = cas3_test::ellipsoid_sample<Point>(200000, 1.0, 0.7, 0.4, 1e-3);
  auto fifth_percentile = [](const Cas& cas) {
    std::vector<double> s;
    for(auto v : cas.finite_vertex_handles()) s.push_back(cas.local_feature_size(v));
    std::nth_element(s.begin(), s.begin() + std::ptrdiff_t(s.size() / 20), s.end());
    return s[s.size() / 20];
  };
  const double reference = fifth_percentile(Cas(clean.begin(), clean.end(),
    CAS3::parameters::local_feature_size_estimator(CAS3::PAPER_POLE_DISTANCE)));
  const Cas paper(noisy.begin(), noisy.end(), CAS3::parameters::local_feature_size_estimator(CAS3::PAPER_POLE_DISTANCE));
  const Cas robust(noisy.begin(), noisy.end());
  BOOST_TEST_MESSAGE("5th percentile of the local feature sizes: clean " << reference << ", noisy paper "
                     << fifth_percentile(paper) << ", noisy robust " << fifth_percentile(robust));
  BOOST_TEST(fifth_percentile(paper) < 0.1 * reference);  // the weakness
  // floored at 4 sample spacings: not the feature size, but no longer a
  // collapse to the noise's scale
  BOOST_TEST(fifth_percentile(robust) > 2 * fifth_percentile(paper));
  // the robust scale is the pole distance or more, and equal to it where
  // the sample is dense and clean
  const Cas clean_robust(clean.begin(), clean.end());
  std::size_t equal = 0;
  for(auto v : clean_robust.finite_vertex_handles())
  {
    const double pole_distance = std::sqrt(CGAL::squared_distance(v->point(), clean_robust.pole(v)));
    BOOST_TEST(clean_robust.local_feature_size(v) >= pole_distance * (1 - 1e-9));
    equal += clean_robust.local_feature_size(v) <= pole_distance * (1 + 1e-9) ? 1 : 0;
  }
  BOOST_TEST(double(equal) > 0.9 * double(clean.size()));
}

BOOST_AUTO_TEST_CASE(filtration_order_and_monotone_values)
{
  const auto pts = cas3_test::torus_sample<Point>(1500, 1.0, 0.35, 0.002);
  const Cas cas(pts.begin(), pts.end());

  // a face's value never exceeds a coface's
  for(auto c : cas.finite_cell_handles())
    for(int i = 0; i < 4; ++i)
    {
      BOOST_TEST(cas.conformal_alpha(c, i) <= cas.conformal_alpha(c));
      for(int j = 0; j < 4; ++j)
        for(int k = j + 1; k < 4; ++k)
          if(j != i && k != i)
            BOOST_TEST(cas.conformal_alpha(c, j, k) <= cas.conformal_alpha(c, i));
    }

  typedef std::pair<Cas::Simplex, double> Entry;
  std::vector<Entry> filtration;
  cas.filtration_with_alpha_values(std::back_inserter(filtration));
  const std::size_t expected = cas.number_of_vertices() + cas.number_of_finite_edges() +
                               cas.number_of_finite_facets() + cas.number_of_finite_cells();
  BOOST_TEST(filtration.size() == expected);
  std::map<Cas::Simplex, std::size_t> position;
  for(std::size_t i = 0; i < filtration.size(); ++i)
  {
    BOOST_TEST(position.emplace(filtration[i].first, i).second);  // listed once
    if(i > 0) BOOST_TEST(filtration[i - 1].second <= filtration[i].second);
  }
  for(auto c : cas.finite_cell_handles())
    for(int i = 0; i < 4; ++i)
    {
      const std::size_t facet = position.at(Cas::Simplex(Cas::Facet(c, i)));
      BOOST_TEST(facet < position.at(Cas::Simplex(c)));
      for(int j = 0; j < 4; ++j)
        for(int k = j + 1; k < 4; ++k)
          if(j != i && k != i)
            BOOST_TEST(position.at(Cas::Simplex(Cas::Edge(c, j, k))) < facet);
    }
}

BOOST_AUTO_TEST_CASE(spectrum_and_quantiles)
{
  const auto pts = cas3_test::ellipsoid_sample<Point>(3000, 1.0, 0.6, 0.4, 0.001);
  Cas cas(pts.begin(), pts.end());
  BOOST_TEST(cas.number_of_alphas() > 0u);
  BOOST_TEST(cas.get_nth_alpha(1) == 0.0);
  BOOST_TEST(std::is_sorted(cas.alpha_begin(), cas.alpha_end()));
  BOOST_TEST(bool(std::adjacent_find(cas.alpha_begin(), cas.alpha_end()) == cas.alpha_end()));

  double previous = -1;
  for(double q : {0.0, 0.1, 0.25, 0.35, 0.5, 0.9, 1.0})
  {
    const double a = cas.alpha_at_quantile(q);
    BOOST_TEST(a >= previous);
    BOOST_TEST(std::binary_search(cas.alpha_begin(), cas.alpha_end(), a));
    previous = a;
  }

  // the surface appears as singular and regular facets, and grows with a
  cas.set_alpha(cas.alpha_at_quantile(0.25));
  std::vector<Cas::Facet> singular, regular;
  cas.get_conformal_alpha_shape_facets(std::back_inserter(singular), Cas::SINGULAR);
  cas.get_conformal_alpha_shape_facets(std::back_inserter(regular), Cas::REGULAR);
  BOOST_TEST(singular.size() + regular.size() > pts.size());
  std::vector<Cas::Cell_handle> interior_small, interior_large;
  cas.get_conformal_alpha_shape_cells(std::back_inserter(interior_small), Cas::INTERIOR,
                                      cas.alpha_at_quantile(0.1));
  cas.get_conformal_alpha_shape_cells(std::back_inserter(interior_large), Cas::INTERIOR,
                                      cas.alpha_at_quantile(0.5));
  BOOST_TEST(interior_small.size() <= interior_large.size());
  std::vector<Cas::Vertex_handle> vertices;
  cas.get_conformal_alpha_shape_vertices(std::back_inserter(vertices), Cas::EXTERIOR);
  BOOST_TEST(vertices.empty());  // every vertex is in every complex
}

BOOST_AUTO_TEST_CASE(duplicates_collapse_and_remember_their_indices)
{
  std::vector<Point> pts = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1),
                            Point(1, 0, 0), Point(1, 1, 1), Point(0, 0, 0), Point(1, 0, 0)};
  const Cas cas(pts.begin(), pts.end());
  BOOST_TEST(cas.number_of_vertices() == 5u);
  BOOST_TEST(cas.number_of_input_points() == pts.size());
  const auto v = cas.input_vertex(1);
  const auto idx = cas.input_indices(v);
  BOOST_TEST(std::vector<std::size_t>(idx.begin(), idx.end()) == std::vector<std::size_t>({1, 4, 7}),
             boost::test_tools::per_element());
  for(std::size_t i = 0; i < pts.size(); ++i)
    BOOST_TEST(cas.input_vertex(i)->point() == pts[i]);
  for(auto w : cas.finite_vertex_handles())
    BOOST_TEST(cas.local_feature_size(w) > 0);
}

BOOST_AUTO_TEST_CASE(input_that_does_not_span_3d_is_rejected)
{
  auto rejects = [](const std::vector<Point>& pts) {
    try { Cas cas(pts.begin(), pts.end()); }
    catch(const std::invalid_argument& e) { return std::string(e.what()).find("span dimension") != std::string::npos; }
    return false;
  };
  BOOST_TEST(rejects({}));
  BOOST_TEST(rejects({Point(0, 0, 0)}));
  BOOST_TEST(rejects({Point(0, 0, 0), Point(1, 0, 0)}));
  BOOST_TEST(rejects({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)}));
  BOOST_TEST(rejects({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0), Point(2, 3, 0)}));
  BOOST_TEST(rejects({Point(0, 0, 0), Point(1, 1, 1), Point(2, 2, 2), Point(3, 3, 3)}));
  BOOST_TEST(rejects({Point(0, 0, 0), Point(0, 0, 0), Point(0, 0, 0), Point(0, 0, 0), Point(0, 0, 0)}));
  // the smallest valid input: one tetrahedron
  const std::vector<Point> tet = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  Cas cas(tet.begin(), tet.end());
  BOOST_TEST(cas.number_of_finite_cells() == 1u);
  BOOST_TEST(cas.classify(Cas::Cell_handle(*cas.finite_cell_handles().begin())->neighbor(0), 1e300) == Cas::EXTERIOR);
  // a failed rebuild leaves an empty shape behind
  const std::vector<Point> flat = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0)};
  BOOST_CHECK_THROW(cas.make_conformal_alpha_shape(flat.begin(), flat.end()), std::invalid_argument);
  BOOST_TEST(cas.number_of_vertices() == 0u);
  BOOST_TEST(cas.number_of_input_points() == 0u);
}

BOOST_AUTO_TEST_CASE(non_finite_coordinates_and_scales_are_rejected_by_index)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Point> pts = cas3_test::cube_volume_sample<Point>(20);
  auto message = [](const std::vector<Point>& p) {
    try { Cas cas(p.begin(), p.end()); }
    catch(const std::invalid_argument& e) { return std::string(e.what()); }
    return std::string();
  };
  pts[13] = Point(0.5, nan, 0.1);
  BOOST_TEST(message(pts).find("input point 13 ") != std::string::npos);
  pts[13] = Point(0.5, 0.2, 0.1);
  pts[4] = Point(-inf, 0, 0);
  BOOST_TEST(message(pts).find("input point 4 ") != std::string::npos);
  pts[4] = Point(0.1, 0.2, 0.3);
  BOOST_TEST(message(pts).empty());

  std::vector<double> scales(pts.size(), 1.0);
  auto scale_message = [&](const std::vector<double>& s) {
    try { Cas cas(pts.begin(), pts.end(), CAS3::parameters::local_feature_sizes(s.begin())); }
    catch(const std::invalid_argument& e) { return std::string(e.what()); }
    return std::string();
  };
  scales[7] = 0.0;
  BOOST_TEST(scale_message(scales).find("input point 7 ") != std::string::npos);
  scales[7] = nan;
  BOOST_TEST(scale_message(scales).find("input point 7 ") != std::string::npos);
  scales[7] = inf;
  BOOST_TEST(scale_message(scales).find("input point 7 ") != std::string::npos);
  scales[7] = 1.0;
  BOOST_TEST(scale_message(scales).empty());
}

BOOST_AUTO_TEST_CASE(local_feature_sizes_from_an_iterator_or_a_range)
{
  const std::vector<Point> pts = cas3_test::cube_volume_sample<Point>(20);
  std::list<double> scales;  // any input range
  for(std::size_t i = 0; i < pts.size(); ++i)
    scales.push_back(1.0 + 0.01 * double(i % 7));
  const Cas from_iterator(pts.begin(), pts.end(), CAS3::parameters::local_feature_sizes(scales.begin()));
  const Cas from_range(pts.begin(), pts.end(), CAS3::parameters::local_feature_sizes(scales));
  auto scale = scales.begin();
  for(std::size_t i = 0; i < pts.size(); ++i, ++scale)
  {
    BOOST_TEST(from_iterator.local_feature_size(from_iterator.input_vertex(i)) == *scale);
    BOOST_TEST(from_range.local_feature_size(from_range.input_vertex(i)) == *scale);
  }
  // the caller's scales take precedence over the estimator
  const Cas both(pts.begin(), pts.end(),
                 CAS3::parameters::local_feature_sizes(scales, CAS3::parameters::local_feature_size_estimator(
                                                          CAS3::PAPER_POLE_DISTANCE)));
  BOOST_TEST(both.local_feature_size(both.input_vertex(3)) == from_range.local_feature_size(from_range.input_vertex(3)));

  scales.pop_back();
  Cas cas;
  BOOST_CHECK_THROW(cas.make_conformal_alpha_shape(pts.begin(), pts.end(), CAS3::parameters::local_feature_sizes(scales)),
                    std::invalid_argument);
  BOOST_TEST(cas.number_of_input_points() == 0u);
}

BOOST_AUTO_TEST_CASE(scales_and_quantiles_outside_their_range_throw)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Point> pts = cas3_test::cube_volume_sample<Point>(20);
  Cas cas(pts.begin(), pts.end());
  for(double q : {-0.01, 1.01, nan})
    BOOST_CHECK_THROW(cas.alpha_at_quantile(q), std::invalid_argument);
  BOOST_CHECK_NO_THROW(cas.alpha_at_quantile(0.0));
  BOOST_CHECK_NO_THROW(cas.alpha_at_quantile(1.0));
  for(double a : {-1.0, nan})
  {
    BOOST_CHECK_THROW(cas.set_alpha(a), std::invalid_argument);
    BOOST_CHECK_THROW(Cas{a}, std::invalid_argument);
  }
  BOOST_TEST(cas.get_alpha() == 0.0);
  for(double f : {-0.5, 1.5, nan})
    BOOST_CHECK_THROW(CAS3::suggest_scale(cas, CAS3::parameters::coverage(f, CAS3::parameters::surface_extraction(CAS3::SOLID_BOUNDARY))),
                      std::invalid_argument);
  const Cas empty;
  BOOST_CHECK_THROW(empty.alpha_at_quantile(0.5), std::invalid_argument);
}

// Fuzz finding solid_labeling_id_of_out_of_range (fuzz/README.md): the 11
// points that fuzz_pipeline's input hygiene made of its bytes (far outliers,
// up to 2^152, kept beside points of size 1). Two causes: the sample
// spacing, kept as a float squared length, overflowed to an infinite local
// scale, so that facet values were NaN or infinite and suggest_scale()
// returned +infinity; at that scale the outside walk did not cross the
// infinite facets, left infinite cells in the solid, and the splitting read
// before the start of the boundary facets.
BOOST_AUTO_TEST_CASE(regression_fuzz_solid_labeling_id_of_out_of_range)
{
  const std::vector<Point> pts = {
      {0x1.dededededededp-1, -0x1.dedededc15767p-1, -0x1.dedededededa9p-1},
      {0x0p+0, -0x1.dededededededp-1, -0x1.dedededededa9p-1},
      {0x0p+0, -0x1.dededededededp-1, -0x1.dedededededa9p-1},
      {0x0p+0, 0x0p+0, 0x1.11b850cc7363fp-47},
      {-0x1.8ddac35fa3fffp+60, 0x1.3479046966954p-283, -0x1.0d14a64ffc7bfp+148},
      {0x1.dededededededp-1, 0x1.356edededededp-283, 0x0p+0},
      {-0x1.a4e7242a70e3fp+84, 0x1.356edededededp-283, 0x1.11b850cc7363fp-47},
      {0x1.dededededededp-1, 0x1.356edededededp-283, -0x1.34abf7fe2bc96p+34},
      {-0x1.b543ff1a9c47ep+152, -0x1.d8276cedb19bfp-128, 0x1.11b850cc7363fp-47},
      {0x1.dededededededp-1, 0x1.356edededededp-283, 0x1.11b850cc7363fp-47},
      {0x1.dededededededp-1, -0x1.828e81e62283fp+26, 0x1.11b850cc7363fp-47}};
  const Cas cas(pts.begin(), pts.end());
  for(Cas::Vertex_handle v : cas.finite_vertex_handles())
    BOOST_TEST(std::isfinite(cas.local_feature_size(v)));
  std::vector<double> values;
  cas.boundary_facet_alphas(std::back_inserter(values));
  for(double a : values)
    BOOST_TEST(!std::isnan(a));

  typedef CGAL::Surface_mesh<Point> Mesh;
  const double infinity = std::numeric_limits<double>::infinity();
  for(double alpha : {CAS3::suggest_scale(cas, CAS3::parameters::surface_extraction(CAS3::SOLID_BOUNDARY)), cas.alpha_at_quantile(0.5), infinity})
  {
    Mesh mesh;
    const CAS3::Surface_report report = CAS3::extract_surface(cas, alpha, mesh, CAS3::parameters::surface_extraction(CAS3::SOLID_BOUNDARY));
    BOOST_TEST(report.number_of_faces == num_faces(mesh));
    BOOST_TEST(CGAL::is_closed(mesh));
    BOOST_TEST(mesh.is_valid(false));
  }
  // at +infinity every finite cell is in the complex, and no infinite cell
  // is in the solid
  const CAS3::internal::Solid_labeling<Cas> solid(cas, infinity);
  std::vector<Cas::Cell_handle> infinite_cells;
  cas.incident_cells(cas.infinite_vertex(), std::back_inserter(infinite_cells));
  for(Cas::Cell_handle c : infinite_cells)
    BOOST_TEST(!solid.is_solid(c));
  BOOST_TEST(!solid.boundary().empty());
}

BOOST_AUTO_TEST_CASE(exactly_cospherical_points_give_a_valid_filtration)
{
  // every integer point on the sphere x^2 + y^2 + z^2 = 50: all cells share
  // one circumsphere, a fully degenerate Delaunay triangulation
  std::vector<Point> pts;
  for(int x = -7; x <= 7; ++x)
    for(int y = -7; y <= 7; ++y)
      for(int z = -7; z <= 7; ++z)
        if(x * x + y * y + z * z == 50) pts.push_back(Point(x, y, z));
  BOOST_REQUIRE(pts.size() > 20u);
  // the pole distances (a sample this coarse triggers the robust floor)
  const Cas cas(pts.begin(), pts.end(), CGAL::Conformal_alpha_shapes_3::parameters::local_feature_size_estimator(
                                          CGAL::Conformal_alpha_shapes_3::PAPER_POLE_DISTANCE));
  BOOST_TEST(cas.is_valid());
  for(auto v : cas.finite_vertex_handles())
    BOOST_TEST(cas.local_feature_size(v) == std::sqrt(50.0), boost::test_tools::tolerance(1e-9));
  for(auto c : cas.finite_cell_handles())
  {
    BOOST_TEST(cas.conformal_alpha(c) == 1.0, boost::test_tools::tolerance(1e-9));
    for(int i = 0; i < 4; ++i)
      BOOST_TEST(cas.conformal_alpha(c, i) <= cas.conformal_alpha(c));
  }
  std::vector<std::pair<Cas::Simplex, double> > filtration;
  cas.filtration_with_alpha_values(std::back_inserter(filtration));
  for(std::size_t i = 1; i < filtration.size(); ++i)
    BOOST_TEST(filtration[i - 1].second <= filtration[i].second);
  BOOST_TEST(cas.number_of_solid_components(1.0) == 1u);
  BOOST_TEST(cas.number_of_solid_components(0.999) == 0u);
}

BOOST_AUTO_TEST_CASE(bundled_bunny_builds)
{
  std::ifstream in(CAS3_BUNNY_XYZ);
  BOOST_REQUIRE(in);
  std::size_t n = 0;
  in >> n;
  std::vector<Point> pts;
  double x, y, z;
  while(in >> x >> y >> z) pts.push_back(Point(x, y, z));
  BOOST_REQUIRE_EQUAL(pts.size(), n);
  const Cas cas(pts.begin(), pts.end());
  BOOST_TEST(cas.number_of_input_points() == n);
  BOOST_TEST(cas.alpha_at_quantile(0.1) < cas.alpha_at_quantile(0.5));
}

#ifdef CGAL_LINKED_WITH_TBB
// Built only with TBB: without it both constructions would be the same
// serial path (CI's Release build requires TBB, CAS3_REQUIRE_TBB).

// Everything the construction stores, as bits: each cell's radius and
// encroached facets, each vertex's local feature size and pole (by cell index), in
// the triangulation's order.
std::vector<double> construction_bits(const Cas& cas)
{
  std::vector<double> bits;
  for(auto c : cas.all_cell_handles())
  {
    bits.push_back(c->alpha());
    bits.push_back(double(c->cell_index()));
    for(int i = 0; i < 4; ++i)
      bits.push_back(c->encroaches_facet(i) ? 1. : 0.);
  }
  for(auto v : cas.finite_vertex_handles())
  {
    bits.push_back(v->local_feature_size());
    bits.push_back(double(v->pole_cell()->cell_index()));
  }
  return bits;
}

std::vector<double> construction_bits_on_one_thread(const std::vector<Point>& pts)
{
  std::vector<double> bits;
  tbb::task_arena(1).execute([&]() { bits = construction_bits(Cas(pts.begin(), pts.end())); });
  return bits;
}

// The construction's passes over the cells run on TBB's threads (in chunks
// of cells, merged): on one thread they give the same bits. A lattice on the
// surface of a cube has many cells of equal radius, so the order in which
// poles of equal distance are met is tested too.
BOOST_AUTO_TEST_CASE(construction_on_one_thread_gives_the_same_bits)
{
  std::vector<Point> lattice;
  const int n = 24;
  for(int x = 0; x <= n; ++x)
    for(int y = 0; y <= n; ++y)
      for(int z = 0; z <= n; ++z)
        if(x == 0 || y == 0 || z == 0 || x == n || y == n || z == n)
          lattice.push_back(Point(x, y, z));
  for(const std::vector<Point>& pts : {lattice, cas3_test::ellipsoid_sample<Point>(20000, 1.0, 0.7, 0.4, 0.01, 3)})
  {
    const std::vector<double> one_thread = construction_bits_on_one_thread(pts);
    const std::vector<double> threads = construction_bits(Cas(pts.begin(), pts.end()));
    BOOST_TEST(one_thread.size() > 10000u);
    BOOST_TEST((one_thread.size() == threads.size()
                && std::memcmp(one_thread.data(), threads.data(), threads.size() * sizeof(double)) == 0));
  }
}

// What comes before the construction runs on TBB's threads too: the input
// checks and the noise estimate (their kd-trees built in parallel) give the
// same bits on one thread, and the insertion order, Hilbert-sorted in
// parallel, is the serial sort's.
BOOST_AUTO_TEST_CASE(input_checks_noise_and_insertion_order_on_one_thread)
{
  const std::vector<Point> pts = cas3_test::ellipsoid_sample<Point>(30000, 1.0, 0.7, 0.4, 0.01, 5);
  CGAL::Conformal_alpha_shapes_3::internal::Normalized_input<K> one_input, input;
  CGAL::Conformal_alpha_shapes_3::Noise_estimate one_noise, noise;
  tbb::task_arena(1).execute([&]() {
    one_input = CGAL::Conformal_alpha_shapes_3::internal::normalize_input<K>(pts);
    one_noise = CGAL::Conformal_alpha_shapes_3::estimate_noise(one_input.points);
  });
  input = CGAL::Conformal_alpha_shapes_3::internal::normalize_input<K>(pts);
  noise = CGAL::Conformal_alpha_shapes_3::estimate_noise(input.points);
  BOOST_TEST((one_input.points == input.points));
  BOOST_TEST((one_input.input_index == input.input_index));
  BOOST_TEST((one_input.is_outlier == input.is_outlier));
  const double one_values[3] = {one_noise.spacing, one_noise.noise, one_noise.noise_24};
  const double values[3] = {noise.spacing, noise.noise, noise.noise_24};
  BOOST_TEST(std::memcmp(one_values, values, sizeof values) == 0);

  typedef std::pair<Point, std::size_t> Point_and_index;
  const std::vector<Point_and_index> order = CGAL::Conformal_alpha_shapes_3::internal::order_free_insertion_order<K>(pts);
  std::vector<Point_and_index> serial;
  for(std::size_t i : CGAL::Conformal_alpha_shapes_3::internal::order_free_permutation(pts))
    serial.emplace_back(pts[i], i);
  typedef CGAL::Spatial_sort_traits_adapter_3<K, CGAL::First_of_pair_property_map<Point_and_index> > Sort_traits;
  typedef CGAL::Hilbert_sort_3<Sort_traits, CGAL::Hilbert_sort_median_policy, CGAL::Sequential_tag> Hilbert_sort;
  CGAL::Multiscale_sort<Hilbert_sort>(Hilbert_sort(Sort_traits(), 8), 64, 0.125)(serial.begin(), serial.end());
  BOOST_TEST((order == serial));
}
#endif // CGAL_LINKED_WITH_TBB

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_conformal_alpha_shape_3
