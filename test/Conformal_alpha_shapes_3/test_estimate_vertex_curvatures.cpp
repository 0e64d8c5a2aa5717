// Tests of estimate_vertex_curvatures() on analytic surfaces with known
// curvature, at three scales, on Surface_mesh and Polyhedron_3, serial and
// parallel, with the named parameters of named_parameters.h. (What each
// Curvature_estimator promises: test_curvature_estimator.cpp; non-manifold,
// border and isolated vertices: test_bad_input.cpp.)
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/tags.h>

#include "cas3_test_meshes.h"
#include "cas3_test_types.h"

#include <boost/mpl/list.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <mutex>
#include <random>
#include <set>
#include <thread>
#include <utility>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_estimate_vertex_curvatures {

using namespace cas3_test_types;

typedef CAS3::Principal_curvatures_and_directions<K> Principal;

// Per-vertex results of one run, in vertex order.
template <class Mesh>
struct Estimate
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> vertices;
  std::vector<Point> points;
  std::vector<Vector> normals;
  std::vector<double> H, K;
  std::vector<Principal> principal;
  std::size_t undefined = 0;

  Estimate(const Mesh& mesh, int rings, CAS3::Curvature_estimator estimator)
  {
    auto n_map = get(CGAL::dynamic_vertex_property_t<Vector>(), mesh);
    auto h_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    auto k_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    auto p_map = get(CGAL::dynamic_vertex_property_t<Principal>(), mesh);
    undefined = CAS3::estimate_vertex_curvatures(
      mesh, CAS3::parameters::vertex_mean_curvature_map(h_map,
            CAS3::parameters::vertex_Gaussian_curvature_map(k_map,
            CAS3::parameters::vertex_principal_curvatures_and_directions_map(p_map,
            CAS3::parameters::ring_size(rings,
            CAS3::parameters::estimator(estimator)))))
              .vertex_normal_map(n_map));
    for(auto v : CGAL::vertices(mesh))
    {
      vertices.push_back(v);
      points.push_back(get(CGAL::vertex_point, mesh, v));
      normals.push_back(get(n_map, v));
      H.push_back(get(h_map, v));
      K.push_back(get(k_map, v));
      principal.push_back(get(p_map, v));
    }
  }
};

double quantile(std::vector<double> v, double q)
{
  BOOST_REQUIRE(!v.empty());
  std::sort(v.begin(), v.end());
  return v[std::size_t(q * double(v.size() - 1))];
}

double angle_degrees(const Vector& a, const Vector& b)
{
  const double c = (a * b) / std::sqrt(a.squared_length() * b.squared_length());
  return std::acos(std::max(-1.0, std::min(1.0, c))) * 180.0 / M_PI;
}

const CAS3::Curvature_estimator all_estimators[] = {CAS3::PAPER_EULER_FIT, CAS3::EULER_LEAST_SQUARES_FIT,
                                                    CAS3::QUADRIC_FIT};
const char* estimator_name[] = {"paper", "euler-ls", "quadric"};

// The bound of a relative error of H (or of k1, k2) on clean meshes: the
// manual's figures ("Measured Accuracy"), with a stated margin. The quadric
// fit 0.77% (0.3-0.7% at 1 ring, the upper end, 10% above); Euler least
// squares 2.2% (1.98% at its best ring on the ellipsoid, 10% above); the
// paper's fit, biased by about 11% on H, 13%. K, a product of two
// curvatures, errs about twice as much: twice the bound.
double h_bound(CAS3::Curvature_estimator e)
{
  return e == CAS3::QUADRIC_FIT ? 0.0077 : e == CAS3::PAPER_EULER_FIT ? 0.13 : 0.022;
}

// Median relative errors of H and K against a sphere of radius r, every
// normal outward, k1 >= k2, directions tangent and orthogonal.
template <class Mesh>
std::pair<double, double> sphere_errors(const Mesh& mesh, double r, int rings, CAS3::Curvature_estimator e)
{
  const Estimate<Mesh> est(mesh, rings, e);
  BOOST_TEST(est.undefined == 0u);
  std::vector<double> eh, ek;
  for(std::size_t i = 0; i < est.points.size(); ++i)
  {
    const Vector radial = est.points[i] - CGAL::ORIGIN;
    BOOST_TEST(angle_degrees(est.normals[i], radial) < 10.0);
    BOOST_TEST(est.principal[i].max_curvature >= est.principal[i].min_curvature);
    BOOST_TEST(std::abs(est.principal[i].max_direction * est.principal[i].min_direction) < 1e-6);
    BOOST_TEST(std::abs(est.principal[i].max_direction * est.normals[i]) < 1e-6);
    eh.push_back(std::abs(est.H[i] * r - 1.0));
    ek.push_back(std::abs(est.K[i] * r * r - 1.0));
  }
  return {quantile(eh, 0.5), quantile(ek, 0.5)};
}

BOOST_AUTO_TEST_SUITE(estimate_vertex_curvatures)

// Bounds: h_bound() on H, twice that on K (the quadric fit: 1.2% on K, the
// upper end of its 0.7-1.1%, 10% above), at 1 and 2 rings (Euler least
// squares, whose best ring is 3 to 4, at 2). A wrong sign, a factor 2 or a
// wrong frame fails them by far. (Measured at
// scale 1 on the irregular sphere, 1 ring / 2 rings: quadric H 0.017% /
// 0.021%, K 0.034% / 0.043%; Euler least squares 5.5% / 1.98%, K 9.7% /
// 3.8%; the paper's 11.8% / 12.5%, K 16.3% / 18.6%.)
BOOST_AUTO_TEST_CASE_TEMPLATE(sphere_meshes, Mesh, Mesh_types)
{
  for(double scale : {1e-3, 1.0, 1e3})
  {
    Mesh ico, irregular;
    cas3_test::icosphere<Mesh, Point>(4, scale, ico);
    cas3_test::irregular_sphere<Mesh, Point>(3000, scale, irregular);
    for(int rings : {1, 2})
      for(CAS3::Curvature_estimator e : all_estimators)
      {
        const auto ico_err = sphere_errors(ico, scale, rings, e);
        const auto irr_err = sphere_errors(irregular, scale, rings, e);
        BOOST_TEST_MESSAGE("sphere scale " << scale << " rings " << rings << " " << estimator_name[e]
                           << ": icosphere H " << ico_err.first << " K " << ico_err.second
                           << " | irregular H " << irr_err.first << " K " << irr_err.second);
        BOOST_TEST_CONTEXT("scale " << scale << " rings " << rings << " estimator " << estimator_name[e])
        {
          const double k_bound = e == CAS3::QUADRIC_FIT ? 0.012 : 2 * h_bound(e);
          BOOST_TEST(ico_err.first < h_bound(e));
          BOOST_TEST(ico_err.second < k_bound);
          // Euler least squares needs more than one ring of an irregular mesh
          if(rings == 2 || e != CAS3::EULER_LEAST_SQUARES_FIT)
          {
            BOOST_TEST(irr_err.first < h_bound(e));
            BOOST_TEST(irr_err.second < k_bound);
          }
        }
      }
  }
}

// The manual's "Measured Accuracy" table (benchmark_curvature), clean
// rows: each estimator at its best ring on an irregular ellipsoid
// 1 : 0.8 : 0.5 of 5,000 vertices and a jittered torus 1 : 0.35 of 9,600;
// the documented median errors of H and K, 10% above.
BOOST_AUTO_TEST_CASE(documented_accuracy_on_clean_irregular_meshes)
{
  typedef cas3_test::Mesh_with_truth<Surface_mesh, Vector> Truth;
  const Truth surfaces[] = {cas3_test::irregular_ellipsoid_with_truth<Surface_mesh, Point, Vector>(5000, 1.0, 0.8, 0.5),
                            cas3_test::jittered_torus_with_truth<Surface_mesh, Point, Vector>(160, 60, 1.0, 0.35)};
  struct Row { std::size_t surface; CAS3::Curvature_estimator estimator; int rings; double H, K; };
  const Row rows[] = {{0, CAS3::PAPER_EULER_FIT, 2, 0.1130, 0.1126}, {0, CAS3::EULER_LEAST_SQUARES_FIT, 3, 0.0198, 0.0342},
                      {0, CAS3::QUADRIC_FIT, 1, 0.0070, 0.0113},     {1, CAS3::PAPER_EULER_FIT, 3, 0.0620, 0.0973},
                      {1, CAS3::EULER_LEAST_SQUARES_FIT, 4, 0.0098, 0.0253}, {1, CAS3::QUADRIC_FIT, 1, 0.0027, 0.0066}};
  for(const Row& row : rows)
  {
    const Truth& s = surfaces[row.surface];
    const Estimate<Surface_mesh> est(s.mesh, row.rings, row.estimator);
    const cas3_test::Curvature_errors e = cas3_test::curvature_errors(s, est.H, est.K);
    BOOST_TEST_MESSAGE(s.name << ", " << estimator_name[row.estimator] << ", " << row.rings << " rings: H "
                       << 100 * e.h50 << "%, K " << 100 * e.k50 << "%");
    BOOST_TEST_CONTEXT(s.name << ", " << estimator_name[row.estimator] << ", " << row.rings << " rings")
    {
      BOOST_TEST(e.h50 <= 1.1 * row.H);
      BOOST_TEST(e.k50 <= 1.1 * row.K);
    }
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(cylinder_mesh, Mesh, Mesh_types)
{
  const double r = 0.5, height = 3.0;
  for(double scale : {1e-3, 1.0, 1e3})
  {
    Mesh mesh;
    cas3_test::parametric_grid<Mesh, Point>(64, 60, true, false, 0.25, [&](double u, double v) {
      return Point(scale * r * std::cos(2 * M_PI * u), scale * r * std::sin(2 * M_PI * u),
                   scale * height * (v - 0.5));
    }, mesh);
    for(CAS3::Curvature_estimator e : all_estimators)
    {
      const Estimate<Mesh> est(mesh, 2, e);
      std::vector<double> eh, ek, axis_max, axis_min;
      for(std::size_t i = 0; i < est.points.size(); ++i)
      {
        if(std::abs(est.points[i].z()) > scale * height / 4) continue;  // away from the borders
        eh.push_back(std::abs(est.H[i] * 2 * r * scale - 1.0));
        ek.push_back(std::abs(est.K[i]) * r * r * scale * scale);
        axis_max.push_back(std::abs(est.principal[i].max_direction.z()));
        axis_min.push_back(std::abs(est.principal[i].min_direction.z()));
      }
      BOOST_TEST_CONTEXT("scale " << scale << " estimator " << estimator_name[e])
      {
        // the quadric fit's fourth-order correction is exact on a cylinder
        // (the manual): 0.1% (measured 0.015% on H, 0.001% on K; without
        // the correction a 2-ring here reads H several percent high); the
        // others at their documented accuracy (h_bound())
        const double bound = e == CAS3::QUADRIC_FIT ? 0.001 : h_bound(e);
        BOOST_TEST(quantile(eh, 0.5) < bound);
        BOOST_TEST(quantile(ek, 0.5) < 2 * bound);
        BOOST_TEST(quantile(axis_max, 0.9) < 0.2);   // max curvature goes around the axis
        BOOST_TEST(quantile(axis_min, 0.1) > 0.97);  // min curvature along it
      }
    }
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(torus_mesh, Mesh, Mesh_types)
{
  const double R = 1.0, r = 0.35;
  for(double scale : {1e-3, 1.0, 1e3})
  {
    Mesh mesh;
    cas3_test::parametric_grid<Mesh, Point>(150, 60, true, true, 0.25, [&](double u, double v) {
      const double a = 2 * M_PI * u, b = 2 * M_PI * v;
      return Point(scale * (R + r * std::cos(b)) * std::cos(a), scale * (R + r * std::cos(b)) * std::sin(a),
                   scale * r * std::sin(b));
    }, mesh);
    for(CAS3::Curvature_estimator e : all_estimators)
    {
      const Estimate<Mesh> est(mesh, 2, e);
      BOOST_TEST(est.undefined == 0u);
      std::vector<double> e1, e2, eh;
      for(std::size_t i = 0; i < est.points.size(); ++i)
      {
        const Point& p = est.points[i];
        const double rho = std::sqrt(p.x() * p.x() + p.y() * p.y()) / scale;
        const double v = std::atan2(p.z() / scale, rho - R);
        const double k1 = 1 / r, k2 = std::cos(v) / (R + r * std::cos(v));
        e1.push_back(std::abs(est.principal[i].max_curvature * scale - k1) * r);
        e2.push_back(std::abs(est.principal[i].min_curvature * scale - k2) * r);
        eh.push_back(std::abs(est.H[i] * scale - (k1 + k2) / 2) * r);
      }
      // relative to 1/r, at the documented accuracy (measured at 2 rings:
      // the quadric 0.16%, 0.19%, 0.15% on k1, k2, H; Euler least squares
      // 1.1%, 0.66%, 0.61%; the paper's 7.5%, 2.2%, 2.7%)
      BOOST_TEST_CONTEXT("scale " << scale << " estimator " << estimator_name[e])
      {
        BOOST_TEST(quantile(e1, 0.5) < h_bound(e));
        BOOST_TEST(quantile(e2, 0.5) < h_bound(e));
        BOOST_TEST(quantile(eh, 0.5) < h_bound(e));
      }
    }
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(saddle_mesh, Mesh, Mesh_types)
{
  // z = x^2 - y^2 with upward normals: k1 = 2 along y, k2 = -2 along x at 0
  for(double scale : {1e-3, 1.0, 1e3})
  {
    Mesh mesh;
    cas3_test::parametric_grid<Mesh, Point>(41, 41, false, false, 0.2, [&](double u, double v) {
      const double x = u - 0.5, y = v - 0.5;
      return Point(scale * x, scale * y, scale * (x * x - y * y));
    }, mesh);
    for(CAS3::Curvature_estimator e : all_estimators)
    {
      const Estimate<Mesh> est(mesh, 2, e);
      std::size_t center = 0;
      for(std::size_t i = 0; i < est.points.size(); ++i)
        if((est.points[i] - CGAL::ORIGIN).squared_length() <
           (est.points[center] - CGAL::ORIGIN).squared_length())
          center = i;
      // at the documented accuracy: H relative to |k1| = 2, K twice that
      // (measured: the quadric K -3.978, H 2e-5; Euler least squares
      // -3.945, -0.0025; the paper's -4.377, 0.046)
      BOOST_TEST_CONTEXT("scale " << scale << " estimator " << estimator_name[e])
      {
        BOOST_TEST(est.K[center] * scale * scale < 0);
        BOOST_TEST(std::abs(est.K[center] * scale * scale + 4) < 4 * 2 * h_bound(e));
        BOOST_TEST(std::abs(est.H[center] * scale) < 2 * h_bound(e));
        BOOST_TEST(std::abs(est.principal[center].max_direction.y()) > 0.9);
        BOOST_TEST(est.normals[center].z() > 0.99);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(single_vertex_matches_the_whole_mesh, Mesh, Mesh_types)
{
  Mesh mesh;
  cas3_test::irregular_sphere<Mesh, Point>(500, 2.0, mesh);
  for(CAS3::Curvature_estimator e : all_estimators)
  {
    const Estimate<Mesh> all(mesh, 2, e);
    auto h_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    for(std::size_t i = 0; i < all.vertices.size(); i += 37)
    {
      BOOST_TEST(CAS3::estimate_vertex_curvatures(all.vertices[i], mesh,
                   CAS3::parameters::vertex_mean_curvature_map(h_map,
                   CAS3::parameters::ring_size(2, CAS3::parameters::estimator(e)))));
      BOOST_TEST(get(h_map, all.vertices[i]) == all.H[i], boost::test_tools::tolerance(1e-12));
    }
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(degenerate_meshes, Mesh, Mesh_types)
{
  // empty mesh: nothing to do
  {
    Mesh empty;
    BOOST_TEST(CAS3::estimate_vertex_curvatures(empty) == 0u);
  }
  // a lone triangle: normals defined, curvature not (too few neighbors)
  {
    Mesh tri;
    CGAL::make_triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), tri);
    const Estimate<Mesh> est(tri, 1, CAS3::QUADRIC_FIT);
    BOOST_TEST(est.undefined == 3u);
    for(std::size_t i = 0; i < 3; ++i)
    {
      BOOST_TEST(std::isnan(est.H[i]));
      BOOST_TEST(std::isnan(est.principal[i].max_curvature));
    }
  }
  // a zero-area face (three collinear vertices) inside a sphere: the normals
  // ignore it, and only its vertices may be undefined
  {
    Mesh mesh;
    cas3_test::icosphere<Mesh, Point>(3, 1.0, mesh);
    auto v0 = *CGAL::vertices(mesh).begin();
    auto h = CGAL::halfedge(v0, mesh);
    // collapse one face by moving a vertex onto the middle of its opposite edge
    auto a = CGAL::source(h, mesh), b = CGAL::target(CGAL::next(h, mesh), mesh);
    const Point pa = get(CGAL::vertex_point, mesh, a), pb = get(CGAL::vertex_point, mesh, b);
    put(CGAL::vertex_point, mesh, v0, CGAL::midpoint(pa, pb));
    for(CAS3::Curvature_estimator e : all_estimators)
    {
      const Estimate<Mesh> est(mesh, 1, e);
      BOOST_TEST(est.undefined <= 3u);
      std::size_t finite = 0;
      for(std::size_t i = 0; i < est.H.size(); ++i)
      {
        if(std::isnan(est.H[i])) continue;
        ++finite;
        BOOST_TEST(std::isfinite(est.K[i]));
        BOOST_TEST(std::isfinite(est.normals[i].x()));
      }
      BOOST_TEST(finite + est.undefined == est.H.size());
    }
  }
  // an isolated vertex: NaN normal and curvature, counted
  {
    Mesh mesh;
    cas3_test::icosphere<Mesh, Point>(2, 1.0, mesh);
    auto lone = CGAL::add_vertex(mesh);
    put(CGAL::vertex_point, mesh, lone, Point(5, 5, 5));
    const Estimate<Mesh> est(mesh, 1, CAS3::QUADRIC_FIT);
    BOOST_TEST(est.undefined == 1u);
    BOOST_TEST(std::isnan(est.normals.back().x()));
    BOOST_TEST(std::isnan(est.H.back()));
  }
}

BOOST_AUTO_TEST_CASE(combined_named_parameters)
{
  Surface_mesh mesh;
  cas3_test::icosphere<Surface_mesh, Point>(3, 2.0, mesh);
  auto h_map = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:H", 0).first;
  // a pack of CGAL's parameters joined with one of this package's
  const auto np = CAS3::parameters::combine(CAS3::parameters::vertex_mean_curvature_map(h_map),
                                            CGAL::parameters::vertex_point_map(mesh.points()));
  BOOST_TEST(CAS3::estimate_vertex_curvatures(mesh, np) == 0u);
  for(auto v : mesh.vertices())
    BOOST_TEST(h_map[v] == 0.5, boost::test_tools::tolerance(0.02));
}

// Every output of one run at every vertex of `mesh`, the uncertainties
// included, as bits: two runs agree when these are equal.
template <class ConcurrencyTag, class NamedParameters>
std::vector<double> all_outputs(const Surface_mesh& mesh, const NamedParameters& neighborhood)
{
  auto n_map = get(CGAL::dynamic_vertex_property_t<Vector>(), mesh);
  auto h_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  auto k_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  auto r_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  auto p_map = get(CGAL::dynamic_vertex_property_t<Principal>(), mesh);
  auto u_map = get(CGAL::dynamic_vertex_property_t<CAS3::Curvature_uncertainty<K> >(), mesh);
  CAS3::estimate_vertex_curvatures<ConcurrencyTag>(mesh,
    CAS3::parameters::vertex_mean_curvature_map(h_map,
    CAS3::parameters::vertex_Gaussian_curvature_map(k_map,
    CAS3::parameters::vertex_principal_curvatures_and_directions_map(p_map,
    CAS3::parameters::vertex_neighborhood_radius_map(r_map,
    CAS3::parameters::vertex_curvature_uncertainty_map(u_map, neighborhood))))).vertex_normal_map(n_map));
  std::vector<double> out;
  for(auto v : mesh.vertices())
  {
    const Principal p = get(p_map, v);
    const CAS3::Curvature_uncertainty<K> u = get(u_map, v);
    for(const Vector& w : {get(n_map, v), p.max_direction, p.min_direction})
      out.insert(out.end(), {w.x(), w.y(), w.z()});
    out.insert(out.end(), {get(h_map, v), get(k_map, v), get(r_map, v), p.max_curvature, p.min_curvature,
                           u.mean_curvature, u.gaussian_curvature, u.normal_degrees});
  }
  return out;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// A torus of 36,000 vertices on a jittered grid.
Surface_mesh jittered_torus(double R, double r)
{
  Surface_mesh mesh;
  cas3_test::parametric_grid<Surface_mesh, Point>(300, 120, true, true, 0.25, [&](double u, double v) {
    const double a = 2 * M_PI * u, b = 2 * M_PI * v;
    return Point((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b));
  }, mesh);
  return mesh;
}

// A rough sphere: the irregular sphere with its vertices moved along the
// radius by up to 1% (so that the automatic radius has noise to weigh).
Surface_mesh rough_sphere(std::size_t n)
{
  Surface_mesh mesh;
  cas3_test::irregular_sphere<Surface_mesh, Point>(n, 1.0, mesh);
  for(auto v : mesh.vertices())
  {
    const double bump = 1 + 0.01 * std::sin(1e3 * double(v.idx()));
    mesh.point(v) = CGAL::ORIGIN + bump * (mesh.point(v) - CGAL::ORIGIN);
  }
  return mesh;
}

// smoothing_radius changes the uncertainties and nothing else: a fit sees
// (r / smoothing_radius)^2 of the noise below that radius, 0.93 of it well
// above. The noise given, 0.1, is more than three times the residuals (the
// bumps, 0.007) even where a quarter of it counts: the coverage factor of
// the residuals' few degrees of freedom stays near 1 and does not offset
// the lower noise.
BOOST_AUTO_TEST_CASE(smoothing_radius_lowers_the_noise_of_smaller_fits_most)
{
  const Surface_mesh mesh = rough_sphere(6000);
  const double radius = 0.08, noise = 0.1;
  auto run = [&](double smoothing) {
    auto h_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    auto u_map = get(CGAL::dynamic_vertex_property_t<CAS3::Curvature_uncertainty<K> >(), mesh);
    CAS3::estimate_vertex_curvatures(mesh, CAS3::parameters::vertex_mean_curvature_map(h_map,
      CAS3::parameters::vertex_curvature_uncertainty_map(u_map, CAS3::parameters::neighborhood_radius(radius,
      CAS3::parameters::noise_level(noise, CAS3::parameters::smoothing_radius(smoothing))))));
    std::vector<std::pair<double, double> > out;  // (H, sigma_H)
    for(auto v : mesh.vertices())
      out.emplace_back(get(h_map, v), get(u_map, v).mean_curvature);
    return out;
  };
  const auto alone = run(0), wider = run(2 * radius), narrower = run(radius / 4);
  std::size_t lower = 0, defined = 0;
  for(std::size_t i = 0; i < alone.size(); ++i)
  {
    BOOST_TEST(std::memcmp(&alone[i].first, &wider[i].first, sizeof(double)) == 0);
    BOOST_TEST(std::memcmp(&alone[i].first, &narrower[i].first, sizeof(double)) == 0);
    if(std::isfinite(alone[i].second))
    {
      ++defined;
      lower += wider[i].second < narrower[i].second && narrower[i].second < alone[i].second ? 1 : 0;
    }
  }
  BOOST_TEST(defined > alone.size() / 2);
  BOOST_TEST(lower == defined);
}

// The share of the noise a fit sees on smoothed points (the manual,
// "Uncertainty"): (r / reach)^2 well below the reach, 0.93 well above; a
// second pass halves it at a quarter of the reach and leaves it above
// 0.45 of the reach; none without smoothing.
BOOST_AUTO_TEST_CASE(smoothed_points_show_a_share_of_the_noise)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  const I::Noise_smoothing none, one{10, 1}, two{10, 2};
  BOOST_TEST(I::smoothed_noise_share(1, none) == 1);
  BOOST_TEST(I::smoothed_noise_share(1, one) == 0.01, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(I::smoothed_noise_share(1000, one) == 0.93, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(I::smoothed_noise_share(2.25, two) / I::smoothed_noise_share(2.25, one) == 0.5,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(I::smoothed_noise_share(5, two) == I::smoothed_noise_share(5, one));
  for(double r = 0.5; r < 100; r *= 1.5)
    BOOST_TEST(I::smoothed_noise_share(r, one) < I::smoothed_noise_share(1.5 * r, one));
}

#ifdef CGAL_LINKED_WITH_TBB
// Tests of the parallel path: built only with TBB (without it, the
// "parallel" run would be the serial run compared with itself); CI's Release
// build requires TBB (CAS3_REQUIRE_TBB).

// The parallel run (TBB's threads) gives the same bits as the serial run,
// for every kind of neighborhood.
BOOST_AUTO_TEST_CASE(parallel_run_matches_the_serial_run_bit_for_bit)
{
  const Surface_mesh mesh = rough_sphere(6000);
  const std::vector<double> radii = {0.04, 0.06, 0.08, 0.12, 0.16};
  auto check = [&](const auto& np) {
    const std::vector<double> serial = all_outputs<CGAL::Sequential_tag>(mesh, np);
    BOOST_TEST(same_bits(serial, all_outputs<CGAL::Parallel_tag>(mesh, np)));
    BOOST_TEST(std::count_if(serial.begin(), serial.end(), [](double x) { return std::isfinite(x); }) > 0);
  };
  check(CAS3::parameters::ring_size(2));
  check(CAS3::parameters::neighborhood_radius(0.08));
  check(CAS3::parameters::neighborhood_radii(radii));
}

// The centers' fits are made when the vertices first need them, on
// whichever thread: the fixed rules' large radius first where the automatic
// rule settles at small radii (the clean half of a torus), all large radii
// where it does not (the noisy half), both at centers between. The
// parallel runs give the serial run's bits, layer by layer.
BOOST_AUTO_TEST_CASE(center_fits_made_on_demand_match_the_serial_run)
{
  Surface_mesh mesh = jittered_torus(1.0, 0.35);
  std::vector<double> lengths;
  for(auto e : mesh.edges())
    lengths.push_back(std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1)))));
  const double spacing = quantile(lengths, 0.5) / 1.1;
  for(auto v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    if(p.x() > 0)  // radial noise of a third of a spacing on half of the torus
      mesh.point(v) = p + (p - CGAL::ORIGIN) * (spacing / 3 * std::sin(1e3 * double(v.idx())) / std::sqrt((p - CGAL::ORIGIN).squared_length()));
  }
  const std::vector<CAS3::Neighborhood> neighborhoods = {CAS3::Neighborhood::automatic(), CAS3::Neighborhood::spacings(16)};
  const auto np = CAS3::parameters::sample_spacing(spacing);
  auto bits = [&](const auto& layers) {
    std::vector<double> out;
    for(const auto& layer : layers)
      for(const auto& c : layer)
        for(double x : {c.principal.max_curvature, c.principal.min_curvature, c.radius, c.normal.x(),
                        c.principal.max_direction.y()})
          out.push_back(x);
    return out;
  };
  const auto serial = CAS3::estimate_vertex_curvatures<CGAL::Sequential_tag>(mesh, neighborhoods, np);
  std::size_t small = 0, large = 0;
  for(const auto& c : serial[0])
  {
    small += c.radius < 8.5 * spacing ? 1 : 0;
    large += c.radius > 12 * spacing ? 1 : 0;
  }
  BOOST_TEST_MESSAGE("automatic radius below 8.5 spacings at " << small << " vertices, above 12 at " << large);
  BOOST_TEST(small > 5000u);
  BOOST_TEST(large > 5000u);
  for(int run = 0; run < 3; ++run)
    BOOST_TEST(same_bits(bits(serial), bits(CAS3::estimate_vertex_curvatures<CGAL::Parallel_tag>(mesh, neighborhoods, np))));
}

// A vertex point map that records the threads reading it once it has been
// read `serial_reads` times (the positions are first copied serially, one
// read per vertex); from then on, the first read of each thread waits (up
// to 20 s) until a second thread reads too, so that a parallel loop over
// the vertices shows two threads even on a busy machine, and a serial one
// shows one, after the wait.
struct Thread_recording_point_map
{
  typedef Surface_mesh::Vertex_index key_type;
  typedef Point value_type;
  typedef const Point& reference;
  typedef boost::readable_property_map_tag category;

  const Surface_mesh* mesh;
  std::size_t serial_reads;
  std::shared_ptr<std::atomic<std::size_t> > reads = std::make_shared<std::atomic<std::size_t> >(0);
  std::shared_ptr<std::mutex> mutex = std::make_shared<std::mutex>();
  std::shared_ptr<std::set<std::thread::id> > threads = std::make_shared<std::set<std::thread::id> >();

  std::size_t number_of_threads() const
  {
    std::lock_guard<std::mutex> lock(*mutex);
    return threads->size();
  }
  friend reference get(const Thread_recording_point_map& map, key_type v)
  {
    if(++*map.reads > map.serial_reads)
    {
      bool first;
      {
        std::lock_guard<std::mutex> lock(*map.mutex);
        first = map.threads->insert(std::this_thread::get_id()).second;
      }
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while(first && map.number_of_threads() < 2 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::yield();
    }
    return map.mesh->point(v);
  }
};

// estimate_vertex_curvatures<CGAL::Parallel_tag> runs on several threads
// (the vertex point map is read in the parallel loops), with the serial
// run's results.
BOOST_AUTO_TEST_CASE(parallel_tag_runs_on_several_threads)
{
  const Surface_mesh mesh = rough_sphere(3000);
  const Thread_recording_point_map points{&mesh, mesh.number_of_vertices()};
  auto h_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  CAS3::estimate_vertex_curvatures<CGAL::Parallel_tag>(mesh,
    CAS3::parameters::vertex_mean_curvature_map(h_map, CAS3::parameters::ring_size(2)).vertex_point_map(points));
  BOOST_TEST_MESSAGE("threads that read the points: " << points.number_of_threads());
  BOOST_TEST(points.number_of_threads() >= 2u);
  const std::vector<double> serial = all_outputs<CGAL::Sequential_tag>(mesh, CAS3::parameters::ring_size(2));
  const std::size_t per_vertex = serial.size() / mesh.number_of_vertices();  // H is the 10th
  std::size_t differing = 0, i = 0;
  for(auto v : mesh.vertices())
  {
    differing += std::memcmp(&serial[per_vertex * i + 9], &get(h_map, v), sizeof(double)) == 0 ? 0 : 1;
    ++i;
  }
  BOOST_TEST(differing == 0u);
}
#endif // CGAL_LINKED_WITH_TBB

// The estimate at one vertex is the one the whole mesh gets, with a radius
// and with candidate radii (the one-vertex search sees only the part of the
// mesh it can reach).
BOOST_AUTO_TEST_CASE(single_vertex_matches_the_whole_mesh_with_radii)
{
  const Surface_mesh mesh = rough_sphere(3000);
  const std::vector<double> radii = {0.06, 0.09, 0.13, 0.2};
  auto check = [&](const auto& np) {
    auto h_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    auto r_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    CAS3::estimate_vertex_curvatures(mesh, CAS3::parameters::vertex_mean_curvature_map(h_map,
                                             CAS3::parameters::vertex_neighborhood_radius_map(r_map, np)));
    auto h_one = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    auto r_one = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    for(auto v : mesh.vertices())
    {
      if(v.idx() % 97 != 0)
        continue;
      BOOST_TEST(CAS3::estimate_vertex_curvatures(v, mesh, CAS3::parameters::vertex_mean_curvature_map(h_one,
                                                         CAS3::parameters::vertex_neighborhood_radius_map(r_one, np))));
      BOOST_TEST(get(h_one, v) == get(h_map, v));
      BOOST_TEST(get(r_one, v) == get(r_map, v));
    }
  };
  check(CAS3::parameters::neighborhood_radius(0.1));
  check(CAS3::parameters::neighborhood_radii(radii));
}

// Large radii (at least 10.5 median edge lengths) are fitted at centers and
// interpolated to the vertices: on a torus, whose curvature varies along
// the tube, the whole mesh's values stay close to each vertex's own fit
// (the one-vertex estimate fits at the vertex itself) and to the truth, and
// the parallel run gives the same bits.
BOOST_AUTO_TEST_CASE(large_radii_from_centers_follow_the_own_fits)
{
  const double R = 1.0, r = 0.35;
  const Surface_mesh mesh = jittered_torus(R, r);
  const double radius = 0.3;  // about 12 median edge lengths
  const auto np = CAS3::parameters::neighborhood_radius(radius);
  auto h_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  CAS3::estimate_vertex_curvatures(mesh, CAS3::parameters::vertex_mean_curvature_map(h_map, np));
  std::vector<double> to_own, to_truth, own_to_truth;
  auto h_one = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  for(auto v : mesh.vertices())
  {
    if(v.idx() % 37 != 0)
      continue;
    BOOST_TEST(CAS3::estimate_vertex_curvatures(v, mesh, CAS3::parameters::vertex_mean_curvature_map(h_one, np)));
    const Point& p = mesh.point(v);
    const double tube = std::atan2(p.z(), std::sqrt(p.x() * p.x() + p.y() * p.y()) - R);
    const double H = (1 / r + std::cos(tube) / (R + r * std::cos(tube))) / 2;
    to_own.push_back(std::abs(get(h_map, v) - get(h_one, v)) / H);
    to_truth.push_back(std::abs(get(h_map, v) - H) / H);
    own_to_truth.push_back(std::abs(get(h_one, v) - H) / H);
  }
  BOOST_TEST_MESSAGE("relative H difference to the own fit: median " << quantile(to_own, 0.5) << ", p90 "
                     << quantile(to_own, 0.9) << "; error: " << quantile(to_truth, 0.5) << " (own fit "
                     << quantile(own_to_truth, 0.5) << ")");
  BOOST_TEST(quantile(to_own, 0.5) < 0.01);
  BOOST_TEST(quantile(to_own, 0.9) < 0.03);
  BOOST_TEST(quantile(to_truth, 0.5) < 1.2 * quantile(own_to_truth, 0.5) + 0.002);
#ifdef CGAL_LINKED_WITH_TBB  // without TBB there is no parallel path to compare
  BOOST_TEST(same_bits(all_outputs<CGAL::Sequential_tag>(mesh, np), all_outputs<CGAL::Parallel_tag>(mesh, np)));
#endif
}

// The large radii's centers are chosen in the order of keys, not of the
// vertices' numbering: the torus numbered backwards gives the same values,
// and a copy moved by an offset (whose positions differ in their last bits)
// gets the original's centers when given the original's keys, which its
// own positions' hashes (the default keys) do not give.
BOOST_AUTO_TEST_CASE(large_radii_centers_follow_keys_not_numbering)
{
  const Surface_mesh mesh = jittered_torus(1.0, 0.35);
  const std::size_t n = num_vertices(mesh);
  auto mean_curvatures = [&](const Surface_mesh& m, const auto& np) {
    auto h = get(CGAL::dynamic_vertex_property_t<double>(), m);
    BOOST_TEST(CAS3::estimate_vertex_curvatures(m, CAS3::parameters::vertex_mean_curvature_map(h,
                 CAS3::parameters::neighborhood_radius(0.3, np))) == 0u);  // about 12 median edge lengths
    std::vector<double> values;
    for(auto v : m.vertices())
      values.push_back(get(h, v));
    return values;
  };
  auto largest_difference = [](const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0;
    for(std::size_t i = 0; i < a.size(); ++i)
      d = (std::max)(d, std::abs(a[i] - b[i]));
    return d;
  };
  const std::vector<double> reference = mean_curvatures(mesh, CGAL::parameters::default_values());
  const auto backwards = boost::make_function_property_map<Surface_mesh::Vertex_index>(
    [n](Surface_mesh::Vertex_index v) { return n - 1 - std::size_t(v.idx()); });
  BOOST_TEST(largest_difference(reference, mean_curvatures(mesh, CGAL::parameters::vertex_index_map(backwards))) < 1e-9);

  Surface_mesh moved = mesh;
  for(auto v : moved.vertices())
    moved.point(v) = moved.point(v) + K::Vector_3(0.123456789, -0.3, 0.7);
  const auto original_key = boost::make_function_property_map<Surface_mesh::Vertex_index>(
    [](Surface_mesh::Vertex_index v) { return std::uint64_t(v.idx()) * 0x9E3779B97F4A7C15ull; });
  const std::vector<double> with_keys = mean_curvatures(mesh, CAS3::parameters::fit_center_key_map(original_key));
  const double keyed = largest_difference(with_keys, mean_curvatures(moved, CAS3::parameters::fit_center_key_map(original_key)));
  const double unkeyed = largest_difference(with_keys, mean_curvatures(moved, CGAL::parameters::default_values()));
  BOOST_TEST_MESSAGE("moved torus, largest H difference: with the original's keys " << keyed << ", without " << unkeyed);
  BOOST_TEST(keyed < 1e-6);
  BOOST_TEST(unkeyed > 1e-4);
}

// With the sample spacing given, the large radii are those of at least 12
// spacings, whatever the mesh's median edge length: on a torus whose edges
// are 0.9 spacings, 11 spacings (12.2 edge lengths) is fitted at every
// vertex, close to the one-vertex estimate, and 13 spacings at centers.
BOOST_AUTO_TEST_CASE(large_radii_in_spacings_when_the_spacing_is_known)
{
  const Surface_mesh mesh = jittered_torus(1.0, 0.35);
  std::vector<double> lengths;
  for(auto e : mesh.edges())
    lengths.push_back(std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1)))));
  const double spacing = quantile(lengths, 0.5) / 0.9;
  const auto whole = CAS3::estimate_vertex_curvatures(
    mesh, {CAS3::Neighborhood::spacings(11), CAS3::Neighborhood::spacings(13)}, CAS3::parameters::sample_spacing(spacing));
  std::vector<double> fine, large;  // relative differences to the one-vertex estimate
  auto h_one = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  for(auto v : mesh.vertices())
  {
    if(v.idx() % 101 != 0)
      continue;
    for(int k = 0; k < 2; ++k)
    {
      BOOST_TEST(CAS3::estimate_vertex_curvatures(v, mesh, CAS3::parameters::vertex_mean_curvature_map(h_one,
                                                  CAS3::parameters::neighborhood_radius((k ? 13 : 11) * spacing))));
      (k ? large : fine).push_back(std::abs(get(h_one, v) / whole[k][v.idx()].mean_curvature() - 1));
    }
  }
  BOOST_TEST_MESSAGE("relative H difference to the one-vertex estimate, median: 11 spacings "
                     << quantile(fine, 0.5) << ", 13 spacings " << quantile(large, 0.5));
  BOOST_TEST(quantile(fine, 0.5) < 1e-3);  // the fits' shells follow the set of radii
  BOOST_TEST(quantile(large, 0.5) > 2e-3);
}

// The quadric fit is corrected for the fourth order of a surface of its own
// curvature: on a sphere that term is exact, so a radius of half the
// sphere's radius (where a plain quadric reads H too high by several
// percent) stays within a fraction of a percent, on an irregular mesh.
BOOST_AUTO_TEST_CASE(large_radius_on_a_sphere_is_unbiased)
{
  Surface_mesh mesh;
  cas3_test::irregular_sphere<Surface_mesh, Point>(3000, 1.0, mesh);
  auto h_map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  BOOST_TEST(CAS3::estimate_vertex_curvatures(mesh, CAS3::parameters::vertex_mean_curvature_map(h_map,
                                                    CAS3::parameters::neighborhood_radius(0.5))) == 0u);
  std::vector<double> errors;
  for(auto v : mesh.vertices())
    errors.push_back(std::abs(get(h_map, v) - 1.0));
  BOOST_TEST_MESSAGE("sphere, radius 0.5: median |H - 1| " << quantile(errors, 0.5));
  BOOST_TEST(quantile(errors, 0.5) < 0.005);
}

// The quadric fit's closed forms against Eigen's solvers: the symmetric 2x2
// eigenproblem (distinct, equal and nearly equal eigenvalues) and the 6x6
// inverse from the Cholesky factor, which refuses a singular matrix.
BOOST_AUTO_TEST_CASE(quadric_fit_closed_forms_match_eigen)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<std::array<double, 3> > forms = {{2, 0, 2}, {1, 0, -3}, {0, 1, 0}, {1, 1e-9, 1}, {-5, 0, 1}};
  for(int k = 0; k < 1000; ++k)
    forms.push_back({uniform(random), uniform(random), uniform(random)});
  for(const auto& form : forms)
  {
    const I::Symmetric_2x2_eigen closed(form[0], form[1], form[2]);
    Eigen::Matrix2d m;
    m << form[0], form[1], form[1], form[2];
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(m);
    BOOST_TEST(std::abs(closed.larger - eigen.eigenvalues()(1)) < 1e-14);
    BOOST_TEST(std::abs(closed.smaller - eigen.eigenvalues()(0)) < 1e-14);
    BOOST_TEST(std::abs(closed.larger_vector.norm() - 1) < 1e-14);
    BOOST_TEST((m * closed.larger_vector - closed.larger * closed.larger_vector).norm() < 1e-12);
  }

  for(int k = 0; k < 100; ++k)
  {
    const I::Matrix6 a = I::Matrix6::NullaryExpr([&]() { return uniform(random); });
    const I::Matrix6 m = a * a.transpose() + 0.1 * I::Matrix6::Identity();
    I::Matrix6 inverse;
    BOOST_TEST(I::symmetric_positive_inverse(m, inverse));
    BOOST_TEST((inverse - I::Matrix6(m.inverse())).norm() < 1e-9 * inverse.norm());
    BOOST_TEST((inverse - inverse.transpose()).norm() == 0.);
  }
  I::Matrix6 rank_five = I::Matrix6::Identity(), inverse;
  rank_five(5, 5) = 0;
  BOOST_TEST(!I::symmetric_positive_inverse(rank_five, inverse));
  const I::Vector6 row = I::Vector6::Ones();
  BOOST_TEST(!I::symmetric_positive_inverse(I::Matrix6(row * row.transpose()), inverse));
}

// The shells of the quadric fit are quarter octaves of the squared distance
// relative to the squared length, read from the bits of the ratio: the
// index is floor(4 log2(ratio)) + 64, within [0, 63], wherever the ratio is
// not within rounding of a quarter octave's boundary.
BOOST_AUTO_TEST_CASE(quadric_shell_index_is_the_quarter_octave)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> exponent(-20, 4);
  int checked = 0;
  for(int k = 0; k < 100000; ++k)
  {
    const double quarters = 4 * exponent(random);
    if(std::abs(quarters - std::round(quarters)) < 1e-3)
      continue;
    const double squared_length = 0.37;
    const double ratio = std::exp2(quarters / 4);
    const int expected = (std::min)(I::number_of_quadric_shells - 1,
                                    (std::max)(0, int(std::floor(quarters)) + I::number_of_quadric_shells));
    BOOST_TEST(I::quadric_shell_index(ratio * squared_length, squared_length) == expected);
    ++checked;
  }
  BOOST_TEST(checked > 90000);
  BOOST_TEST(I::quadric_shell_index(0., 1.) == 0);
  BOOST_TEST(I::quadric_shell_index(std::numeric_limits<double>::denorm_min(), 1.) == 0);
  BOOST_TEST(I::quadric_shell_index(1e300, 1.) == I::number_of_quadric_shells - 1);
}

// The automatic rule is settled by the fits at its smaller radii when they
// hold those that measure the noise and one past what the choice weighs
// (the search then stops short of the larger radii): on random candidate
// fits, the choice among every settled prefix is the choice among all,
// and prefixes that are not settled do choose otherwise, so that a wrong
// answer from choice_is_settled() would show.
BOOST_AUTO_TEST_CASE(automatic_choice_settled_by_a_prefix_is_the_whole_choice)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  const std::vector<double> radii = CAS3::Neighborhood::automatic_radii();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  int settled = 0, unsettled_and_different = 0;
  for(int k = 0; k < 20000; ++k)
  {
    // heights of noise sigma, a bias growing as r^2 and, past a random
    // radius, residuals that grow fast (a thin part, detail of its own)
    const double sigma = std::pow(10., -6 * unit(random)), bias = 4 * unit(random) - 2, H0 = unit(random);
    const std::size_t wrap = 1 + std::size_t(unit(random) * double(radii.size()));
    std::vector<I::Candidate_fit> fits;
    for(std::size_t i = 0; i < radii.size(); ++i)
    {
      if(unit(random) < 0.05)
        continue;  // an undefined fit
      I::Candidate_fit fit;
      fit.curvature.normal = fit.curvature.d1 = fit.curvature.d2 = I::Vec3::UnitZ();
      const double r = radii[i] / radii.back(), H = H0 + bias * r * r + sigma * (unit(random) - 0.5) / radii[i];
      fit.curvature.k1 = fit.curvature.k2 = H;
      fit.error.noise = sigma * (1 + 0.2 * unit(random)) * (i >= wrap ? 100 * double(i - wrap + 1) : 1);
      fit.error.degrees_of_freedom = radii[i] * radii[i];
      fit.error.per_noise = 1 / radii[i];
      fit.radius = radii[i];
      fits.push_back(fit);
    }
    if(fits.empty())
      continue;
    const double sample_noise = unit(random) < 0.5 ? 0. : sigma;
    const I::Candidate_fit& whole = I::choose_by_least_squared_error(fits, sample_noise);
    for(std::size_t n = 1; n <= fits.size(); ++n)
    {
      const std::vector<I::Candidate_fit> prefix(fits.begin(), fits.begin() + std::ptrdiff_t(n));
      const I::Candidate_fit& chosen = I::choose_by_least_squared_error(prefix, sample_noise);
      if(I::choice_is_settled(prefix, sample_noise))
      {
        ++settled;
        BOOST_TEST(chosen.radius == whole.radius);
        BOOST_TEST(chosen.curvature.k1 == whole.curvature.k1);
      }
      else if(chosen.radius != whole.radius)
        ++unsettled_and_different;
    }
  }
  BOOST_TEST_MESSAGE("settled prefixes " << settled << ", unsettled ones that choose otherwise " << unsettled_and_different);
  BOOST_TEST(settled > 10000);
  BOOST_TEST(unsettled_and_different > 1000);
}

// The automatic radius's choice adds half the mean square of the bias that
// each adjacent candidate's change implies at the chosen radius, under a
// bias growing as r^2 (the manual, "Uncertainty"): radii 2, 4 and 8 with H
// 1, 1.1 and 1.5 imply 0.1 x 16 / 12 and 0.4 x 16 / 48 at radius 4.
BOOST_AUTO_TEST_CASE(automatic_choice_uncertainty_is_the_bias_its_neighbors_imply)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  std::vector<I::Candidate_fit> fits;
  for(const auto& [radius, H] : {std::pair<double, double>{2, 1.0}, {4, 1.1}, {8, 1.5}})
  {
    I::Candidate_fit fit;
    fit.curvature.normal = fit.curvature.d1 = fit.curvature.d2 = I::Vec3::UnitZ();
    fit.curvature.k1 = fit.curvature.k2 = H;
    fit.radius = radius;
    fits.push_back(fit);
  }
  I::Estimate_uncertainty fit;
  fit.H = 0.01;
  fit.K = 0.02;
  const I::Estimate_uncertainty u = I::choice_uncertainty(fits, fits[1], fit);
  const double below = 0.1 * 16 / 12, above = 0.4 * 16 / 48;
  BOOST_TEST(u.H == std::sqrt(0.01 * 0.01 + (below * below + above * above) / 4), boost::test_tools::tolerance(1e-12));
  // K = H^2 here: the changes 0.21 and 1.04
  const double below_K = 0.21 * 16 / 12, above_K = 1.04 * 16 / 48;
  BOOST_TEST(u.K == std::sqrt(0.02 * 0.02 + (below_K * below_K + above_K * above_K) / 4), boost::test_tools::tolerance(1e-12));
  // at the first candidate only the one above counts
  const I::Estimate_uncertainty first = I::choice_uncertainty(fits, fits[0], fit);
  BOOST_TEST(first.H == std::sqrt(0.01 * 0.01 + std::pow(0.1 * 4 / 12, 2) / 2), boost::test_tools::tolerance(1e-12));
}

// A fixed radius's noise part widens by Student's t coverage factor of its
// residuals' effective degrees of freedom (the manual, "Uncertainty"):
// t_0.975 over z_0.975 is 12.706 / 1.960 with one degree, 3.182 / 1.960
// with three; a known sample noise at least as large as the residuals,
// which then hold only it, leaves it as it is.
BOOST_AUTO_TEST_CASE(fixed_radius_uncertainty_widens_for_few_residual_degrees)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  const double z = 1.959964;
  BOOST_TEST(I::t_coverage_factor(1) == 12.7062 / z, boost::test_tools::tolerance(0.02));
  BOOST_TEST(I::t_coverage_factor(3) == 3.18245 / z, boost::test_tools::tolerance(0.02));
  BOOST_TEST(I::t_coverage_factor(30) == 2.04227 / z, boost::test_tools::tolerance(0.02));
  BOOST_TEST(I::t_coverage_factor(1e5) == 1, boost::test_tools::tolerance(1e-4));
  BOOST_TEST(std::isinf(I::t_coverage_factor(0.5)));
  I::Quadric_fit_error e;
  e.noise = 0.01;
  e.degrees_of_freedom = 3;
  e.per_noise = e.per_noise_K = e.per_noise_normal = 10;
  const I::Noise_smoothing unsmoothed;
  const auto counted = I::fit_uncertainty(e, 1, 0, unsmoothed, I::Residual_degrees::COUNTED);
  const auto ignored = I::fit_uncertainty(e, 1, 0, unsmoothed, I::Residual_degrees::IGNORED);
  BOOST_TEST(ignored.H == 0.1, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(counted.H / ignored.H == I::t_coverage_factor(3), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(counted.K / ignored.K == I::t_coverage_factor(3), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(counted.H_noise == counted.H, boost::test_tools::tolerance(1e-12));
  const auto known = I::fit_uncertainty(e, 1, 0.1, unsmoothed, I::Residual_degrees::COUNTED);
  BOOST_TEST(known.H == 0.1 * 10, boost::test_tools::tolerance(1e-12));
}

// The bias rates fitted over the radii in x = (r / reference)^2, the
// coefficients' products less their covariance. With fits at every radius
// (noise they share) each change from one radius to the next larger is
// weighed by its own variance, the smaller fit's less the larger's, and a
// parabola is fitted as well; with a few fits (a clean sample's settled
// choice) the line alone, each fit weighed by its inverse variance.
BOOST_AUTO_TEST_CASE(bias_rates_weigh_the_changes_between_nested_fits)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  // a line through two fits, H = 1 + 0.5 x: c = 0.5 exactly, its variance
  // the change's, (0.2^2 - 0.1^2) / 0.75^2, or the two fits' as if
  // independent, (0.2^2 + 0.1^2) / 0.75^2
  const std::vector<I::Radius_sample> two = {I::Radius_sample{1, 1.125, 2, 0.2, 0.2},
                                             I::Radius_sample{2, 1.5, 2, 0.1, 0.1}};
  const I::Bias_rates nested = I::bias_rates(two, 2, true);
  BOOST_TEST(nested.H.line == 0.25 - 0.03 / 0.5625, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(nested.K.line == -0.03 / 0.5625, boost::test_tools::tolerance(1e-12));  // K constant: no rate
  BOOST_TEST(std::isnan(nested.H.parabola[0]));  // two fits: no parabola
  BOOST_TEST(I::bias_rates(two, 2, false).H.line == 0.25 - 0.05 / 0.5625, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::isnan(I::bias_rates(std::vector<I::Radius_sample>(1, two[0]), 2, true).H.line));

  // a parabola through three fits, H = 1 + 0.5 x + 0.25 x^2 at x = 1/4,
  // 9/16, 1: its coefficients exactly, their covariance that of the changes
  // (variances 0.09 - 0.04 and 0.04 - 0.01) and the largest fit's (0.01);
  // with the fits taken as independent the variance of d would be 3.87
  std::vector<I::Radius_sample> three;
  const double se[3] = {0.3, 0.2, 0.1};
  for(int i = 0; i < 3; ++i)
  {
    const double r = 0.5 + 0.25 * i, x = r * r;
    three.push_back(I::Radius_sample{r, 1 + 0.5 * x + 0.25 * x * x, 0, se[i], se[i]});
  }
  const I::Bias_rates bent = I::bias_rates(three, 1, true);
  BOOST_TEST(bent.H.parabola[3] == 1.1888616780045143, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(bent.H.parabola[2] == 0.0625 - 1.1888616780045143, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(bent.H.parabola[1] == 0.125 + 1.6486167800453226, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(bent.H.parabola[0] == 0.25 - 2.406167800453475, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(std::isnan(I::bias_rates(three, 1, false).H.parabola[0]));  // a few fits: no parabola

  // uncertainties that do not fall with the radius: each change keeps a
  // twentieth of its fit's variance, not none
  for(I::Radius_sample& q : three)
    q.se_H = 0.1;
  BOOST_TEST(I::bias_rates(three, 1, true).H.parabola[3] == 0.013746213151927459, boost::test_tools::tolerance(1e-9));
}

// The bias that an uncertainty adds is the mean of the moments of the
// vertex and of those connected to it within the pooling radius, read at
// the estimate's radius as the line's, or the parabola's where that is
// larger, its bend stands out of its noise and the radius is at least half
// the largest, never below 0, in quadrature with the noise's.
BOOST_AUTO_TEST_CASE(bias_rates_are_pooled_over_the_vertices_around)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  I::Vertex_graph path;  // 0 - 1 - 2 - 3 on a line, one apart
  for(int i = 0; i < 4; ++i)
    path.points.push_back(I::Vec3(i, 0, 0));
  path.first = {0, 1, 3, 5, 6};
  path.adjacent = {1, 0, 2, 1, 3, 2};
  std::vector<I::Bias_rates> rates(4);
  rates[0].H.line = 4;
  rates[1].H.line = -1;
  rates[2].H.line = 3;  // vertex 3 has none
  rates[1].K.line = -2;
  rates[2].H.parabola = {0.5, 2, 3, 1};  // alone among the vertices around 1; d^2 3 above its variance 1
  I::Nested_neighborhood_search search(4);
  const I::Bias_widening at_1 = I::pool_bias_rates(path, rates, 1, std::vector<double>(1, 1.5), 2, search);
  BOOST_TEST(at_1.H.line == 2.);  // (4 - 1 + 3) / 3
  BOOST_TEST(at_1.H.parabola[2] == 3.);
  BOOST_TEST(at_1.K.squared_bias(1) == 0.);  // negative mean: no bias
  const I::Bias_widening at_3 = I::pool_bias_rates(path, rates, 3, std::vector<double>(1, 0.5), 2, search);
  BOOST_TEST(at_3.H.squared_bias(1) == 0.);  // none within reach
  double sigma_H = 3, sigma_K = 1;
  at_1.widen(sigma_H, sigma_K, 2.);  // x = 1: the parabola's 0.5 + 4 + 3, above the line's 2
  BOOST_TEST(sigma_H == std::sqrt(9. + 7.5), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(sigma_K == 1.);
  sigma_H = 3;
  at_1.widen(sigma_H, sigma_K, 1.);  // x = 1/4: the line's 2 / 16, above the parabola's (0.5 + 1 + 3 / 16) / 16
  BOOST_TEST(sigma_H == std::sqrt(9. + 2. / 16), boost::test_tools::tolerance(1e-12));
  I::Bias_moments noisy_bend = at_1.H;
  noisy_bend.parabola[3] = 4;  // d^2 3 within its variance: the line
  BOOST_TEST(noisy_bend.squared_bias(1) == 2.);
  I::Bias_moments small = I::Bias_moments();  // a parabola alone, read from half the largest radius on
  small.line = 0;
  small.parabola = {1, 0, 0.5, 0};
  BOOST_TEST(small.squared_bias(0.2) == 0.);
  BOOST_TEST(small.squared_bias(0.25) == 0.0625 * (1 + 0.25 * 0.25 * 0.5), boost::test_tools::tolerance(1e-12));
}

// The residuals of a fit to points that were not smoothed hold the
// sample's noise: they add only their excess over it (what the quadric
// misses), where on smoothed points they add whole (what smoothing left).
BOOST_AUTO_TEST_CASE(residuals_add_beyond_the_noise_they_hold)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  I::Quadric_fit_error e;
  e.noise = 0.1;
  e.degrees_of_freedom = 1e6;
  e.per_noise = e.per_noise_K = e.per_noise_normal = 10;
  const I::Noise_smoothing unsmoothed, smoothed{1e-9, 1};  // a reach far below the fit: 0.93 of the noise
  auto H = [&](double sample, const I::Noise_smoothing& s) {
    return I::fit_uncertainty(e, 1, sample, s, I::Residual_degrees::IGNORED).H;
  };
  BOOST_TEST(H(0.1, unsmoothed) == 1, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(H(0.2, unsmoothed) == 2, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(H(0.06, unsmoothed) == 1, boost::test_tools::tolerance(1e-12));  // sqrt(0.06^2 + 0.1^2 - 0.06^2)
  BOOST_TEST(H(0.1, smoothed) == std::sqrt(0.093 * 0.093 + 0.01) * 10, boost::test_tools::tolerance(1e-9));
}

// K's first-order variance read with the fitted coefficients overstates the
// variance by twice its second-order part: the uncertainty takes that part
// off once, and keeps at least the second-order part (a flat patch, whose
// K errors are products of the two curvatures' errors).
BOOST_AUTO_TEST_CASE(gaussian_curvature_uncertainty_counts_its_second_order_once)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  I::Quadric_fit_error e;
  e.noise = 0.1;
  e.degrees_of_freedom = 1e6;
  e.per_noise = e.per_noise_normal = 10;
  e.per_noise_K = 50;
  e.per_squared_noise_K = 300;  // second-order part 3 against a first-order 5
  auto K = [&]() {
    return I::fit_uncertainty(e, 1, 0, I::Noise_smoothing(), I::Residual_degrees::IGNORED).K;
  };
  BOOST_TEST(K() == 4, boost::test_tools::tolerance(1e-12));
  e.per_noise_K = 30;  // no more than the second-order part
  BOOST_TEST(K() == 3, boost::test_tools::tolerance(1e-12));
}

// The nested balls found level by level (the automatic rule searches the
// larger radii only where its choice needs them) are those found at once.
BOOST_AUTO_TEST_CASE(balls_found_level_by_level_are_found_at_once)
{
  namespace I = CGAL::Conformal_alpha_shapes_3::internal;
  const Surface_mesh mesh = jittered_torus(1.0, 0.35);
  const I::Vertex_graph graph = I::vertex_graph(mesh, get(CGAL::vertex_point, mesh), get(CGAL::vertex_index, mesh));
  const std::vector<double> radii = {0.05, 0.08, 0.13, 0.2, 0.3};
  I::Nested_neighborhood_search at_once(graph.size()), by_level(graph.size());
  for(std::size_t v = 0; v < graph.size(); v += 97)
  {
    at_once.balls(graph, v, radii);
    by_level.balls(graph, v, radii, 1);
    BOOST_TEST(by_level.levels_found() == 1u);
    by_level.more_balls(graph, 3);
    by_level.more_balls(graph, 3);
    by_level.more_balls(graph, radii.size());
    BOOST_TEST(by_level.levels_found() == radii.size());
    BOOST_TEST(by_level.vertices() == at_once.vertices());
    BOOST_TEST(by_level.squared_distances() == at_once.squared_distances());
    for(std::size_t level = 0; level < radii.size(); ++level)
      BOOST_TEST(by_level.end(level) == at_once.end(level));
  }
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_estimate_vertex_curvatures
