// Tests of multiscale_curvatures() and Multiscale_curvatures: the accuracy
// the manual documents (section "Neighborhoods", measured by
// evaluate_surfaces on the same samples) and claims against CGAL's jet
// fitting at its best neighborhood, computed here on the same points; a
// radius in model units at two densities, the automatic radius under noise,
// and results independent of the order of the points. Scale and
// Neighborhood (scales_and_neighborhoods.h) are tested here.
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>
#include <CGAL/Conformal_alpha_shapes_3/scales_and_neighborhoods.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cas3_analytic_surfaces.h"
#include "cas3_jet_fitting.h"
#include "cas3_point_values.h"
#include "cas3_test_meshes.h"
#include "cas3_test_data.h"
#include "cas3_test_shapes.h"
#include "cas3_test_types.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_multiscale_curvatures {

using namespace cas3_test_types;
using cas3_test::same_bits;
using cas3_test::sheet_points;
using cas3_test::curvature_points;
using cas3_test::jet_samples;

// The manual's accuracy measure (METHOD.md section 7): the median, over the
// points of `index` whose own vertex is on the surface (jet fitting: all
// of them), of |H - H_true|, over the median |H_true| of the whole sample.
double median_H_error(const std::vector<double>& H, const std::vector<std::size_t>& index, const Sample& truth)
{
  std::vector<double> errors;
  for(std::size_t j = 0; j < index.size(); ++j)
    if(std::isfinite(H[j]))
      errors.push_back(std::abs(H[j] - truth.mean_curvature[index[j]]));
  BOOST_REQUIRE(!errors.empty());
  return cas3_test::quantile(errors, 0.5) / cas3_test::median_abs(truth.mean_curvature);
}

// The same for a layer of the pipeline, over every input point (NaN off
// the surface: only points on their own vertex count, as in
// evaluate_surfaces).
double median_H_error(const std::vector<CAS3::Point_curvature<K> >& layer, const Sample& truth)
{
  std::vector<double> H;
  std::vector<std::size_t> index;
  for(std::size_t i = 0; i < layer.size(); ++i)
  {
    H.push_back(layer[i].on_surface() ? double(layer[i].mean_curvature) : std::numeric_limits<double>::quiet_NaN());
    index.push_back(i);
  }
  return median_H_error(H, index, truth);
}

// Jet fitting's median H error at its best k among `ks` (its normal's sign
// from the truth: its best case), at about `samples` points spread over the
// sample, against `truth`.
std::pair<int, double> best_jet_fitting(const Sample& s, const Sample& truth, const std::vector<int>& ks,
                                        std::size_t samples)
{
  const std::vector<std::size_t> index = cas3_test::spread_indices(s.points.size(), samples);
  const cas3_test::Jet_estimates<K> jet = cas3_test::jet_fitting<K>(s.points, truth.normals, index, ks);
  std::pair<int, double> best(0, std::numeric_limits<double>::infinity());
  for(std::size_t j = 0; j < ks.size(); ++j)
  {
    const double e = median_H_error(jet.H[j], index, truth);
    if(e < best.second)
      best = {ks[j], e};
  }
  return best;
}

double median(std::vector<double> v)
{
  BOOST_REQUIRE(!v.empty());
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

BOOST_AUTO_TEST_SUITE(multiscale_curvatures)

// The default job (multiscale_curvatures() with its default scale and
// neighborhoods) on 20,000 points of an ellipsoid 1 : 0.7 : 0.4 and of a
// torus 1 : 0.35 with Gaussian noise of 0.1 spacings along the normal,
// evaluate_surfaces' samples and noise seeds: the automatic neighborhood's
// median H error is the manual's (ellipsoid 2.59%, torus 1.46%; bound 10%
// above), and at most 0.8 times jet fitting's at its best k of 60, 120, 240,
// 480 (the manual: 4.35% at k = 240, 3.87% at k = 120).
BOOST_AUTO_TEST_CASE(automatic_radius_under_noise_against_jet_fitting)
{
  struct Case
  {
    const char* name;
    Sample sample;
    unsigned noise_seed;
    double documented;  // the automatic neighborhood's median H error, Release sizes
  };
  Case cases[] = {
    {"ellipsoid", cas3_analytic::ellipsoid_truth_sample<Point, Vector>(curvature_points, 1, 0.7, 0.4),
     unsigned(curvature_points + 100), 0.0259},
    {"torus", cas3_analytic::torus_truth_sample<Point, Vector>(curvature_points, 1, 0.35),
     unsigned(1000 + curvature_points + 100), 0.0146}};
  for(Case& c : cases)
  {
    cas3_analytic::add_normal_noise(c.sample, 0.1, c.noise_seed);
    const auto layers = CAS3::multiscale_curvatures(c.sample.points);
    BOOST_REQUIRE(layers.size() == CAS3::default_neighborhoods().size());
    BOOST_REQUIRE(layers.front().neighborhood.kind() == CAS3::Neighborhood::AUTOMATIC);
    const double automatic = median_H_error(layers.front().points, c.sample);
    const std::pair<int, double> jet = best_jet_fitting(c.sample, c.sample, {60, 120, 240, 480}, jet_samples);
    BOOST_TEST_MESSAGE(c.name << ", " << curvature_points << " points, noise 0.1 spacings: automatic neighborhood "
                       << 100 * automatic << "%, jet fitting " << 100 * jet.second << "% at k = " << jet.first
                       << " (ratio " << automatic / jet.second << ")");
    BOOST_TEST_CONTEXT(c.name)
    {
#ifndef CAS3_SANITIZED
      BOOST_TEST(automatic <= 1.1 * c.documented);
#endif
      BOOST_TEST(automatic <= 0.8 * jet.second);
    }
  }
}

// The bump test (the manual's bump figures), clean 20,000-point spheres:
// the finest layer (1 ring) reads fine bumps (amplitude 0.005, frequency 40)
// with a median H error of 35.4% against 47.3% for jet fitting at its best
// k of 12 and 24; the coarsest (16 spacings) summarizes the same bumps on a
// sphere with a dent as the smooth dented sphere, 0.55% against 2.31% at
// its best k of 400 and 1000. Each at most 0.8 times jet fitting, and
// within 10% of the manual's figure.
BOOST_AUTO_TEST_CASE(finest_and_coarsest_layers_of_the_bump_test_against_jet_fitting)
{
  cas3_analytic::Bumpy_radius fine{0.005, 40, 0, 0.4, 1, 0, 0};
  cas3_analytic::Bumpy_radius dent = fine;
  dent.dent_depth = 0.25;
  struct Case
  {
    const char* name;
    Sample sample, truth;
    CAS3::Neighborhood layer;
    std::vector<int> ks;
    double documented;
  };
  Sample smooth;
  Case cases[] = {
    {"fine bumps at 1 ring", cas3_analytic::bumpy_sphere_truth_sample<Point, Vector>(20000, fine, -INFINITY, 15),
     Sample(), CAS3::Neighborhood::rings(1), {12, 24}, 0.354},
    {"dented sphere at 16 spacings", cas3_analytic::bumpy_sphere_truth_sample<Point, Vector>(20000, dent, -INFINITY, 16,
                                                                                             &smooth),
     Sample(), CAS3::Neighborhood::spacings(16), {400, 1000}, 0.0055}};
  cases[0].truth = cases[0].sample;
  cases[1].truth = smooth;
  for(const Case& c : cases)
  {
    const auto layers = CAS3::multiscale_curvatures(
      c.sample.points, CAS3::parameters::neighborhoods(std::vector<CAS3::Neighborhood>{c.layer}));
    const double ours = median_H_error(layers.front().points, c.truth);
    const std::pair<int, double> jet = best_jet_fitting(c.sample, c.truth, c.ks, jet_samples);
    BOOST_TEST_MESSAGE(c.name << ": " << 100 * ours << "%, jet fitting " << 100 * jet.second << "% at k = "
                       << jet.first << " (ratio " << ours / jet.second << ")");
    BOOST_TEST_CONTEXT(c.name)
    {
      BOOST_TEST(ours <= 1.1 * c.documented);
      BOOST_TEST(ours <= 0.8 * jet.second);
    }
  }
}

// A radius in model units means the same on two samplings of one surface:
// on a bumpy sphere sampled at 4000 and 16000 points, mean curvature with a
// 0.25 radius agrees between the two; with 2-rings (half the radius on the
// denser sampling) it does not.
BOOST_AUTO_TEST_CASE(a_radius_means_the_same_at_two_densities)
{
  auto bumpy = [](std::size_t n) {
    std::vector<Point> p = cas3_test::ellipsoid_sample<Point>(n, 1, 1, 1);
    for(Point& x : p)
    {
      const double r = 1 + 0.03 * std::sin(8 * x.x()) * std::sin(8 * x.y()) * std::sin(8 * x.z());
      x = CGAL::ORIGIN + r * (x - CGAL::ORIGIN);
    }
    return p;
  };
  const std::vector<Point> sparse = bumpy(4000), dense = bumpy(16000);
  auto mean_curvatures = [](const std::vector<Point>& p, const CAS3::Neighborhood& n) {
    const Analysis analysis(p.begin(), p.end());
    Analysis::Surface surface;
    analysis.surface(analysis.scale_value(CAS3::Scale::automatic()), surface);
    std::vector<double> H;
    const auto layers = analysis.estimate_curvatures(surface, {n});
    for(const auto& c : layers.front())
      H.push_back(c.mean_curvature);
    return H;
  };
  // the dense sample's point nearest to each sparse point (Fibonacci points:
  // compare along the same z, by brute force over a window)
  auto difference = [&](const CAS3::Neighborhood& n) {
    const std::vector<double> Hs = mean_curvatures(sparse, n), Hd = mean_curvatures(dense, n);
    std::vector<double> d;
    for(std::size_t i = 0; i < sparse.size(); i += 10)
    {
      std::size_t best = 0;
      double best_d = 1e300;
      for(std::size_t j = 0; j < dense.size(); ++j)
      {
        const double dd = CGAL::squared_distance(sparse[i], dense[j]);
        if(dd < best_d)
        {
          best_d = dd;
          best = j;
        }
      }
      d.push_back(std::abs(Hs[i] - Hd[best]));
    }
    return median(d);
  };
  const double by_radius = difference(CAS3::Neighborhood::radius(0.25));
  const double by_rings = difference(CAS3::Neighborhood::rings(2));
  // 0.35 is a large radius (fitted at centers, interpolated) in the dense
  // sample only: the two ways of fitting still agree
  const double by_large_radius = difference(CAS3::Neighborhood::radius(0.35));
  BOOST_TEST_MESSAGE("median |H(4000) - H(16000)|: radius 0.25 " << by_radius << ", 0.35 " << by_large_radius
                     << ", 2-rings " << by_rings);
  BOOST_TEST(by_radius < 0.05);  // H is about 1, the bumps reach 1.9 at 2-rings
  BOOST_TEST(by_radius < 0.5 * by_rings);
  BOOST_TEST(by_large_radius < 0.05);
}

// The automatic neighborhood grows with the noise, from the data alone.
// Without denoising, so that the noise the rule reads is the one the fits
// see (measured: 3.1, 8.8 and 8.9 spacings; with the default denoising,
// which passes the noise it measured before smoothing, 2.83, 19, 22.6 and
// 22.6 spacings at noise 0, 0.1, 0.3 and 0.5 on 20,000 points, see the
// manual).
BOOST_AUTO_TEST_CASE(the_automatic_radius_grows_with_noise)
{
  const double spacing = std::sqrt(4 * M_PI / 5000);
  std::vector<double> radius;
  for(double noise : {0.0, 0.1, 0.3})
  {
    const std::vector<Point> pts = cas3_test::ellipsoid_sample<Point>(5000, 1, 1, 1, noise * spacing, 3);
    const Analysis analysis(pts.begin(), pts.end(), CAS3::parameters::denoising(CAS3::NEVER_DENOISE));
    Analysis::Surface surface;
    analysis.surface(analysis.scale_value(CAS3::Scale::automatic()), surface);
    std::vector<double> r;
    const auto layers = analysis.estimate_curvatures(surface, {CAS3::Neighborhood::automatic()});
    for(const auto& c : layers.front())
      if(std::isfinite(c.radius))
        r.push_back(c.radius / spacing);
    BOOST_TEST(r.size() > 4950u);
    radius.push_back(median(r));
  }
  BOOST_TEST_MESSAGE("median automatic radius (spacings) at noise 0, 0.1, 0.3: " << radius[0] << " " << radius[1]
                     << " " << radius[2]);
  BOOST_TEST(radius[0] <= radius[1]);
  BOOST_TEST(radius[1] <= radius[2]);
  BOOST_TEST(radius[0] < radius[2]);
}

// The results do not depend on the order of the points: a shuffled copy of
// a noisy torus (smoothed, so the noise estimate and the smoothing are in
// the path) gives the same scale and the same bits at every point, for a
// fine radius, a large one (fitted at centers), the automatic one and rings.
BOOST_AUTO_TEST_CASE(any_order_of_the_points_gives_the_same_results)
{
  Sample s = cas3_analytic::torus_truth_sample<Point, Vector>(sheet_points / 2, 1.0, 0.35);
  cas3_analytic::add_normal_noise(s, 0.1, 5);
  std::vector<std::size_t> permutation(s.points.size());
  std::iota(permutation.begin(), permutation.end(), std::size_t(0));
  std::shuffle(permutation.begin(), permutation.end(), std::mt19937(11));
  std::vector<Point> shuffled;
  for(std::size_t i : permutation)
    shuffled.push_back(s.points[i]);

  const std::vector<CAS3::Neighborhood> neighborhoods{CAS3::Neighborhood::spacings(2), CAS3::Neighborhood::spacings(16),
                                                      CAS3::Neighborhood::automatic(), CAS3::Neighborhood::rings(2)};
  const Analysis analysis(s.points.begin(), s.points.end()), analysis_shuffled(shuffled.begin(), shuffled.end());
  BOOST_TEST(analysis.denoising().passes > 0);
  const double a = analysis.scale_value(CAS3::Scale::automatic());
  BOOST_TEST(a == analysis_shuffled.scale_value(CAS3::Scale::automatic()));
  Analysis::Surface surface, surface_shuffled;
  analysis.surface(a, surface);
  analysis_shuffled.surface(a, surface_shuffled);
  BOOST_TEST(surface.number_of_faces() == surface_shuffled.number_of_faces());
  const auto layers = analysis.estimate_curvatures(surface, neighborhoods);
  const auto layers_shuffled = analysis_shuffled.estimate_curvatures(surface_shuffled, neighborhoods);
  for(std::size_t l = 0; l < neighborhoods.size(); ++l)
  {
    std::size_t differing = 0;
    for(std::size_t k = 0; k < permutation.size(); ++k)
      differing += same_bits(layers[l][permutation[k]], layers_shuffled[l][k]) ? 0 : 1;
    BOOST_TEST_CONTEXT("neighborhood " << l) { BOOST_TEST(differing == 0u); }
  }
}

// The layers of `analysis` at its automatic scale and the default neighborhoods.
std::vector<std::vector<CAS3::Point_curvature<K> > > default_layers(const Analysis& analysis)
{
  Analysis::Surface surface;
  analysis.surface(analysis.scale_value(CAS3::Scale::automatic()), surface);
  return analysis.estimate_curvatures(surface, CAS3::default_neighborhoods());
}

// Whether two doubles have the same bits (NaN equals NaN).
bool same_double(double x, double y) { return std::memcmp(&x, &y, sizeof(double)) == 0; }

// The overload giving each layer as it is made gives the returned layers,
// in their order, and leaves the same surface properties (the last layer's).
BOOST_AUTO_TEST_CASE(layers_given_as_they_are_made)
{
  Sample s = cas3_analytic::ellipsoid_truth_sample<Point, Vector>(3000, 1, 0.7, 0.4);
  cas3_analytic::add_normal_noise(s, 0.1, 3);
  s.points.push_back(Point(40, 0, 0));  // an outlier: NO_VALUE in every layer
  const Analysis analysis(s.points.begin(), s.points.end());
  BOOST_TEST(analysis.outliers().size() == 1u);
  const std::vector<CAS3::Neighborhood> neighborhoods{CAS3::Neighborhood::automatic(), CAS3::Neighborhood::spacings(4),
                                                      CAS3::Neighborhood::rings(2)};
  const double a = analysis.scale_value(CAS3::Scale::automatic());
  Analysis::Surface returned_surface, given_surface;
  analysis.surface(a, returned_surface);
  analysis.surface(a, given_surface);
  const auto returned = analysis.estimate_curvatures(returned_surface, neighborhoods);
  std::size_t next = 0;
  analysis.estimate_curvatures(given_surface, neighborhoods, CAS3::QUADRIC_FIT,
                               [&](std::size_t k, std::vector<CAS3::Point_curvature<K> >&& layer) {
                                 BOOST_TEST(k == next++);
                                 BOOST_REQUIRE(layer.size() == s.points.size());
                                 std::size_t differing = 0;
                                 for(std::size_t i = 0; i < layer.size(); ++i)
                                   differing += same_bits(layer[i], returned[k][i]) ? 0 : 1;
                                 BOOST_TEST(differing == 0u);
                                 BOOST_TEST(layer.back().source == CAS3::NO_VALUE);
                               });
  BOOST_TEST(next == neighborhoods.size());
  const auto returned_h = returned_surface.property_map<Analysis::Surface_vertex, double>("v:mean_curvature").first;
  const auto given_h = given_surface.property_map<Analysis::Surface_vertex, double>("v:mean_curvature").first;
  std::size_t differing = 0;
  for(Analysis::Surface_vertex v : given_surface.vertices())
    differing += same_double(returned_h[v], given_h[v]) ? 0 : 1;
  BOOST_TEST(differing == 0u);
}

// Consumed (estimate_curvatures() on an rvalue), an analysis frees its
// shape before the fits and gives the same bits in every layer as one that
// keeps it, on a noisy ellipsoid whose surface lost a cap (points off the
// surface, near it and far from it) with a neighborhood too small for some
// fits (their points take the values of a nearest surface point, found
// after the fits); then what needs the shape throws, and the rest answers.
BOOST_AUTO_TEST_CASE(a_consumed_analysis_gives_the_same_values)
{
  Sample s = cas3_analytic::ellipsoid_truth_sample<Point, Vector>(3000, 1, 0.7, 0.4);
  cas3_analytic::add_normal_noise(s, 0.3, 7);
  const std::vector<CAS3::Neighborhood> neighborhoods{
    CAS3::Neighborhood::automatic(), CAS3::Neighborhood::spacings(0.5), CAS3::Neighborhood::spacings(4)};
  const Analysis kept(s.points.begin(), s.points.end());
  Analysis consumed(s.points.begin(), s.points.end());
  const double a = kept.scale_value(CAS3::Scale::automatic());
  BOOST_TEST(a == consumed.scale_value(CAS3::Scale::automatic()));
  Analysis::Surface kept_surface, consumed_surface;
  kept.surface(a, kept_surface);
  consumed.surface(a, consumed_surface);
  cas3_test::remove_cap_above(kept_surface, 0.3);
  cas3_test::remove_cap_above(consumed_surface, 0.3);
  const auto expected = kept.estimate_curvatures(kept_surface, neighborhoods);
  const auto layers = std::move(consumed).estimate_curvatures(consumed_surface, neighborhoods);
  for(std::size_t l = 0; l < neighborhoods.size(); ++l)
  {
    std::size_t differing = 0, off = 0, far = 0, on_but_undefined = 0;
    for(std::size_t i = 0; i < s.points.size(); ++i)
    {
      differing += same_bits(layers[l][i], expected[l][i]) ? 0 : 1;
      if(layers[l][i].source == CAS3::NEAREST_SURFACE_POINT)
        (layers[l][i].distance < 1e-9 ? on_but_undefined : off) += 1;
      far += layers[l][i].source == CAS3::NO_VALUE ? 1 : 0;
    }
    BOOST_TEST_CONTEXT("neighborhood " << l)
    {
      BOOST_TEST(differing == 0u);
      BOOST_TEST(off > 0u);
      BOOST_TEST(far > 0u);
      if(l == 1)
        BOOST_TEST(on_but_undefined > 0u);
    }
  }

  BOOST_TEST(consumed.shape().number_of_vertices() == 0u);
  BOOST_CHECK_THROW(consumed.surface(a, consumed_surface), std::logic_error);
  BOOST_CHECK_THROW(consumed.closing_values(), std::logic_error);
  BOOST_CHECK_THROW(consumed.scale_value(CAS3::Scale::quantile(0.25)), std::logic_error);
  BOOST_CHECK_THROW(consumed.estimate_curvatures(consumed_surface, neighborhoods), std::logic_error);
  BOOST_TEST(consumed.scale_value(CAS3::Scale::automatic()) == a);
  BOOST_TEST(consumed.noise().spacing == kept.noise().spacing);
  BOOST_TEST(consumed.number_of_input_points() == s.points.size());
}

// The noise_estimate of a larger run (as tiles take the whole cloud's
// decisions): given a run's own noise(), a run on the same points,
// far from the unit size so that the working frame rescales them, gives the
// same bits in every layer; a spacing twice as large doubles the radius of
// the "4s" layer; the denoising decision follows the given noise; an
// invalid estimate is refused.
BOOST_AUTO_TEST_CASE(noise_estimate_of_a_larger_run)
{
  Sample s = cas3_analytic::ellipsoid_truth_sample<Point, Vector>(5000, 1, 0.7, 0.4);
  cas3_analytic::add_normal_noise(s, 0.1, 5100);
  for(Point& p : s.points)
    p = Point(1000 * p.x() + 3, 1000 * p.y() - 7, 1000 * p.z() + 11);
  const CAS3::Multiscale_curvatures<K> own(s.points.begin(), s.points.end());
  const CAS3::Noise_estimate noise = own.noise();
  BOOST_REQUIRE(own.denoising().passes > 0);
  const CAS3::Multiscale_curvatures<K> given(s.points.begin(), s.points.end(), CAS3::parameters::noise_estimate(noise));
  BOOST_TEST(same_double(given.noise().spacing, noise.spacing));
  BOOST_TEST(same_double(given.noise().noise, noise.noise));
  BOOST_TEST(given.denoising().passes == own.denoising().passes);
  BOOST_TEST(given.denoising().neighbors == own.denoising().neighbors);
  // The automatic scale to rounding: in this test binary it differs in its
  // last bit (a standalone program of the same code gives the same bits);
  // the surfaces and every layer below are the same to the bit, and tiles
  // pass their scale explicitly.
  BOOST_TEST(given.scale_value(CAS3::Scale::automatic()) == own.scale_value(CAS3::Scale::automatic()),
             boost::test_tools::tolerance(1e-14));
  const auto own_layers = default_layers(own), given_layers = default_layers(given);
  BOOST_REQUIRE(given_layers.size() == own_layers.size());
  for(std::size_t k = 0; k < own_layers.size(); ++k)
  {
    std::size_t differing = 0;
    for(std::size_t i = 0; i < own_layers[k].size(); ++i)
      differing += !same_bits(own_layers[k][i], given_layers[k][i]);
    BOOST_TEST(differing == 0u, "layer " << k << ": " << differing << " points differ");
  }

  CAS3::Noise_estimate doubled = noise;
  doubled.spacing *= 2;
  const CAS3::Multiscale_curvatures<K> coarser(s.points.begin(), s.points.end(),
                                               CAS3::parameters::noise_estimate(doubled));
  const CAS3::Neighborhood four = CAS3::Neighborhood::spacings(4);
  BOOST_TEST(coarser.radius(four) == 2 * own.radius(four));
  CAS3::Multiscale_curvatures<K>::Surface surface;
  coarser.surface(coarser.scale_value(CAS3::Scale::automatic()), surface);
  const auto four_layer = coarser.estimate_curvatures(surface, {four}).front();
  std::size_t on_surface = 0, wrong_radius = 0;
  for(const CAS3::Point_curvature<K>& p : four_layer)
    if(p.on_surface())
    {
      ++on_surface;
      wrong_radius += p.radius != 2 * own.radius(four);
    }
  BOOST_TEST(on_surface > 0u);
  BOOST_TEST(wrong_radius == 0u);

  CAS3::Noise_estimate clean = noise;
  clean.noise = clean.noise_24 = 0;
  BOOST_TEST(CAS3::Multiscale_curvatures<K>(s.points.begin(), s.points.end(), CAS3::parameters::noise_estimate(clean))
               .denoising()
               .passes
             == 0);

  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::vector<Point> few(s.points.begin(), s.points.begin() + 200);
  for(const CAS3::Noise_estimate& bad : {CAS3::Noise_estimate{0, 0.1, 0.1}, CAS3::Noise_estimate{-1, 0.1, 0.1},
                                         CAS3::Noise_estimate{inf, 0.1, 0.1}, CAS3::Noise_estimate{nan, 0.1, 0.1},
                                         CAS3::Noise_estimate{1, -0.1, -0.1}, CAS3::Noise_estimate{1, nan, nan},
                                         CAS3::Noise_estimate{1e300, 0.1, 0.1}})
  {
    // the last spacing overflows in the working frame of points this small
    std::vector<Point> tiny;
    for(const Point& p : few)
      tiny.push_back(Point(1e-70 * p.x(), 1e-70 * p.y(), 1e-70 * p.z()));
    std::string message;
    try
    {
      CAS3::Multiscale_curvatures<K>(tiny.begin(), tiny.end(), CAS3::parameters::noise_estimate(bad));
    }
    catch(const std::invalid_argument& e)
    {
      message = e.what();
    }
    BOOST_TEST_CONTEXT("spacing " << bad.spacing << ", noise " << bad.noise)
    {
      BOOST_TEST(message.find("noise_estimate") != std::string::npos, message);
    }
  }
}

// The closing values (Surface_front::local_closing_values() by input point)
// are what the automatic scale is read from: a tiled run pools them over its
// tiles. Coincident points count once, on the first of them.
BOOST_AUTO_TEST_CASE(closing_values_give_the_automatic_scale)
{
  Sample s = cas3_analytic::ellipsoid_truth_sample<Point, Vector>(3000, 1, 0.7, 0.4);
  std::vector<Point> points = s.points;
  points.push_back(points[5]);
  points.push_back(points[7]);
  const CAS3::Multiscale_curvatures<K> m(points.begin(), points.end());
  const std::vector<double> closing = m.closing_values();
  BOOST_REQUIRE(closing.size() == points.size());
  BOOST_TEST(std::isnan(closing[3000]));
  BOOST_TEST(std::isnan(closing[3001]));
  BOOST_TEST(!std::isnan(closing[5]));
  std::vector<double> values;
  for(double c : closing)
    if(!std::isnan(c))
      values.push_back(c);
  BOOST_TEST(values.size() > 2900u);
  // the mean of the sorted values of ranks 0.99 n to 0.999 n
  std::sort(values.begin(), values.end());
  const std::size_t first = std::size_t(0.99 * double(values.size())), last = std::size_t(0.999 * double(values.size()));
  double sum = 0;
  for(std::size_t k = first; k < last; ++k)
    sum += values[k];
  BOOST_TEST(sum / double(last - first) == m.scale_value(CAS3::Scale::automatic()), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(CAS3::scale_of_closing_values(closing, 0.99) == m.scale_value(CAS3::Scale::automatic()));
  const CAS3::Surface_front<CAS3::Multiscale_curvatures<K>::Shape> front(m.shape());
  const std::vector<double> by_vertex = front.local_closing_values(), raw = front.closing_values();
  BOOST_TEST(by_vertex.size() == m.shape().number_of_vertices());
  BOOST_REQUIRE(raw.size() == by_vertex.size());
  for(std::size_t v = 0; v < raw.size(); ++v)
    BOOST_TEST(std::isnan(raw[v]) == std::isnan(by_vertex[v]));
  BOOST_TEST(by_vertex.size() == m.shape().number_of_vertices());
}


// ---------------------------------------------------------------------------
// The same surface gives the same answer (the manual, "Input Rules"): a
// change of how the points are written down that leaves the sampled surface
// as it is moves no value beyond rounding.

#ifdef CAS3_SANITIZED
constexpr std::size_t invariance_points = 2500;
#else
constexpr std::size_t invariance_points = 8000;
#endif

// A noisy torus: no symmetry of the sample that a rotation could map onto itself.
Sample noisy_torus()
{
  Sample s = cas3_analytic::torus_truth_sample<Point, Vector>(invariance_points, 1, 0.35);
  cas3_analytic::add_normal_noise(s, 0.1, 21);
  return s;
}

// How far `changed` (of a copy of the points moved by a similarity of
// scale `scale`, whose linear part maps the normals by `turn`) strays from
// `base` at the first `n` points: the largest relative change of `a`, the
// smallest share of points whose normals stay on the same side, the
// largest median relative change of H, and the largest 99th percentile of
// the relative change of H's uncertainty, over the layers.
struct Change
{
  double a = 0, same_side = 1, H = 0, H_sigma = 0;
};
template <class Turn>
Change change_between(const std::vector<CAS3::Curvature_layer<K> >& base,
                      const std::vector<CAS3::Curvature_layer<K> >& changed, std::size_t n, double scale, Turn turn)
{
  Change c;
  BOOST_REQUIRE(base.size() == changed.size());
  for(std::size_t l = 0; l < base.size(); ++l)
  {
    c.a = (std::max)(c.a, std::abs(changed[l].a / base[l].a - 1));
    std::size_t same = 0, compared = 0;
    std::vector<double> relative, relative_sigma;
    for(std::size_t i = 0; i < n; ++i)
    {
      const CAS3::Point_curvature<K>& x = base[l].points[i];
      const CAS3::Point_curvature<K>& y = changed[l].points[i];
      if(!std::isfinite(x.mean_curvature) || !std::isfinite(y.mean_curvature))
        continue;
      ++compared;
      same += x.normal * turn(y.normal) > 0 ? 1 : 0;
      relative.push_back(std::abs(y.mean_curvature * scale - x.mean_curvature) / std::abs(x.mean_curvature));
      const double sigma = x.uncertainty.mean_curvature;
      relative_sigma.push_back(std::abs(y.uncertainty.mean_curvature * std::abs(scale) - sigma) / sigma);
    }
    BOOST_REQUIRE(compared > n * 9 / 10);
    c.same_side = (std::min)(c.same_side, double(same) / double(compared));
    c.H = (std::max)(c.H, cas3_test::quantile(relative, 0.5));
    c.H_sigma = (std::max)(c.H_sigma, cas3_test::quantile(relative_sigma, 0.99));
  }
  return c;
}

BOOST_AUTO_TEST_CASE(copies_of_points_change_nothing)
{
  const Sample s = noisy_torus();
  std::vector<Point> points = s.points;
  for(std::size_t i = 0; i < s.points.size(); i += 20)  // 5% written twice, at the end
    points.push_back(s.points[i]);
  const auto base = CAS3::multiscale_curvatures(s.points);
  const CAS3::Multiscale_curvatures<K> m(points.begin(), points.end());
  BOOST_TEST(m.number_of_merged_points() == points.size() - s.points.size());
  const CAS3::Multiscale_curvatures<K> without_copies(s.points.begin(), s.points.end());
  BOOST_TEST(m.noise().spacing == without_copies.noise().spacing);
  BOOST_TEST(m.noise().noise == without_copies.noise().noise);
  BOOST_TEST(CAS3::estimate_noise(points).noise == CAS3::estimate_noise(s.points).noise);
  const auto copied = CAS3::multiscale_curvatures(points);
  for(std::size_t l = 0; l < base.size(); ++l)
  {
    BOOST_TEST(copied[l].a == base[l].a);
    BOOST_TEST(copied[l].surface.number_of_input_points == points.size());
    BOOST_TEST(copied[l].surface.number_of_points_off_surface
               >= base[l].surface.number_of_points_off_surface);
    std::size_t differ = 0;
    for(std::size_t i = 0; i < s.points.size(); ++i)
      differ += same_bits(copied[l].points[i], base[l].points[i]) ? 0 : 1;
    for(std::size_t i = s.points.size(), j = 0; i < points.size(); ++i, j += 20)
      differ += same_bits(copied[l].points[i], base[l].points[j]) ? 0 : 1;
    BOOST_TEST(differ == 0u);
  }
}

BOOST_AUTO_TEST_CASE(rigid_motions_and_scalings_change_nothing_beyond_rounding)
{
  const Sample s = noisy_torus();
  const auto base = CAS3::multiscale_curvatures(s.points);
  const CAS3::Noise_estimate noise = CAS3::estimate_noise(s.points);
  struct Case
  {
    std::string name;
    double scale;
    std::function<Point(const Point&)> move;
    std::function<Vector(const Vector&)> turn_back;
  };
  const auto same = [](const Vector& v) { return v; };
  const std::vector<Case> cases = {
    {"translated by 1e-7 of the diagonal", 1, [](const Point& p) { return p + Vector(3e-7, 2e-7, 1e-7); }, same},
    {"turned by 90 degrees about z", 1, [](const Point& p) { return Point(-p.y(), p.x(), p.z()); },
     [](const Vector& v) { return Vector(v.y(), -v.x(), v.z()); }},
    {"times 4", 4, [](const Point& p) { return Point(4 * p.x(), 4 * p.y(), 4 * p.z()); }, same},
    {"times 3", 3, [](const Point& p) { return Point(3 * p.x(), 3 * p.y(), 3 * p.z()); }, same}};
  for(const Case& c : cases)
  {
    BOOST_TEST_CONTEXT(c.name)
    {
      std::vector<Point> moved;
      for(const Point& p : s.points)
        moved.push_back(c.move(p));
      const CAS3::Noise_estimate moved_noise = CAS3::estimate_noise(moved);
      BOOST_TEST(std::abs(moved_noise.spacing / (c.scale * noise.spacing) - 1) < 0.005);
      BOOST_TEST(std::abs(moved_noise.noise / noise.noise - 1) < 0.005);
      const Change change = change_between(base, CAS3::multiscale_curvatures(moved), s.points.size(), c.scale,
                                           c.turn_back);
      BOOST_TEST(change.a < 0.002);
      BOOST_TEST(change.same_side >= 0.999);
      BOOST_TEST(change.H <= 0.001);
      BOOST_TEST_MESSAGE(c.name << ": 99th percentile of H_sigma's relative change " << change.H_sigma);
      BOOST_TEST(change.H_sigma <= 0.01);
    }
  }
}

// The automatic scale of real scans under motions that change the
// coordinates' last bits, and so the front's choices at near ties: oni.pwn
// (1,435 points, where one such choice moved the 0.99 quantile of the
// closing values by 5.6%) and the kitten.
BOOST_AUTO_TEST_CASE(the_automatic_scale_of_scans_stays_under_rigid_motions)
{
  for(const std::string name : {"oni.pwn", "kitten.xyz"})
  {
    std::vector<Point> points;
    std::vector<Vector> normals;
    cas3_test::read_oriented_points(name, points, normals);
    const CGAL::Bbox_3 box = CGAL::bbox_3(points.begin(), points.end());
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin())
                                      + CGAL::square(box.zmax() - box.zmin()));
    auto automatic = [](const std::vector<Point>& p) {
      return CAS3::Multiscale_curvatures<K>(p.begin(), p.end()).scale_value(CAS3::Scale::automatic());
    };
    const double a = automatic(points);
    const std::vector<std::pair<std::string, std::function<Point(const Point&)> > > motions = {
      {"translated by 1e-7 of the diagonal", [&](const Point& p) { return p + Vector(1e-7, 1e-7, 1e-7) * diagonal; }},
      {"translated by 1e-4 of the diagonal", [&](const Point& p) { return p + Vector(1e-4, 0, 0) * diagonal; }},
      {"times 3", [](const Point& p) { return Point(3 * p.x(), 3 * p.y(), 3 * p.z()); }},
      {"turned by 90 degrees about z", [](const Point& p) { return Point(-p.y(), p.x(), p.z()); }}};
    for(const auto& motion : motions)
    {
      BOOST_TEST_CONTEXT(name << ", " << motion.first)
      {
        std::vector<Point> moved;
        for(const Point& p : points)
          moved.push_back(motion.second(p));
        BOOST_TEST(std::abs(automatic(moved) / a - 1) < 0.002);
      }
    }
  }
}

// Input normals are hints: where they point about as often to one side as
// to the other (random signs, an unoriented estimate) the sheets are
// oriented as without them, with a count in the report; consistent ones,
// flipped or not, are followed.
BOOST_AUTO_TEST_CASE(normals_of_random_signs_orient_as_no_normals)
{
  for(const bool open : {false, true})
  {
    BOOST_TEST_CONTEXT((open ? "open cap" : "closed ellipsoid"))
    {
      Sample s = cas3_analytic::ellipsoid_truth_sample<Point, Vector>(invariance_points, 1, 0.7, 0.4,
                                                                      open ? 0.1 : -1e300);
      cas3_analytic::add_normal_noise(s, 0.1, 22);
      std::mt19937 random(5);
      std::vector<Vector> random_signs, flipped;
      for(const Vector& n : s.normals)
      {
        random_signs.push_back(random() % 2 ? n : -n);
        flipped.push_back(-n);
      }
      const auto none = CAS3::multiscale_curvatures(s.points);
      const auto with_random = CAS3::multiscale_curvatures(s.points, CAS3::parameters::reference_normals(random_signs));
      const auto with_flipped = CAS3::multiscale_curvatures(s.points, CAS3::parameters::reference_normals(flipped));
      const auto same = [](const Vector& v) { return v; };
      const auto opposite = [](const Vector& v) { return -v; };
      BOOST_TEST(with_random.front().surface.number_of_sheets_with_inconsistent_normals > 0u);
      BOOST_TEST(with_random.front().surface.reference_normal_agreement < 0.6);
      BOOST_TEST(change_between(none, with_random, s.points.size(), 1, same).same_side >= 0.995);
      BOOST_TEST(with_flipped.front().surface.number_of_sheets_with_inconsistent_normals == 0u);
      BOOST_TEST(with_flipped.front().surface.reference_normal_agreement > 0.99);
      // the flipped normals' values against the true normals' side
      const Change change = change_between(none, with_flipped, s.points.size(), -1, opposite);
      BOOST_TEST(change.same_side >= 0.999);
      BOOST_TEST(change.H <= 0.001);
      // beyond rounding only where a front decision differs (the sanitizers' smaller samples)
      BOOST_TEST(change.H_sigma <= 0.02);
    }
  }
}

BOOST_AUTO_TEST_CASE(the_automatic_layer_is_the_same_whatever_radii_beside_it)
{
  const Sample s = noisy_torus();
  const std::vector<CAS3::Neighborhood> alone = {CAS3::Neighborhood::automatic()};
  const std::vector<CAS3::Neighborhood> beside = {
    CAS3::Neighborhood::automatic(), CAS3::Neighborhood::spacings(2), CAS3::Neighborhood::spacings(3),
    CAS3::Neighborhood::spacings(4), CAS3::Neighborhood::spacings(8), CAS3::Neighborhood::spacings(16),
    CAS3::Neighborhood::spacings(22), CAS3::Neighborhood::spacings(32)};
  const auto a = CAS3::multiscale_curvatures(s.points, CAS3::parameters::neighborhoods(alone));
  const auto b = CAS3::multiscale_curvatures(s.points, CAS3::parameters::neighborhoods(beside));
  const auto c = CAS3::multiscale_curvatures(s.points);  // the default radii
  std::size_t differ = 0;
  for(std::size_t i = 0; i < s.points.size(); ++i)
    differ += (same_bits(a.front().points[i], b.front().points[i]) ? 0 : 1)
              + (same_bits(a.front().points[i], c.front().points[i]) ? 0 : 1);
  BOOST_TEST(differ == 0u);
}

// The uncertainties are calibrated (the manual, "Uncertainty"): on a clean
// and a noisy ellipsoid, in every layer of the default job, most of the
// points' H and K errors lie within two standard uncertainties, not all of
// them, and the median uncertainty is of the size of the median error: a
// guard against uncertainties off by a factor, with bounds wider than the
// measured ones. On the clean one the 2-spacing fits have about three
// residual degrees of freedom: without their coverage factor, 85% of the
// values are within two sigma at 8,000 points, 93% with it.
BOOST_AUTO_TEST_CASE(uncertainties_are_calibrated)
{
  for(const double noise : {0.0, 0.1, 0.3})
  {
    Sample s = cas3_analytic::ellipsoid_truth_sample<Point, Vector>(invariance_points, 1, 0.8, 0.6);
    if(noise > 0)
      cas3_analytic::add_normal_noise(s, noise, 5);
    const auto layers = CAS3::multiscale_curvatures(s.points);
    for(std::size_t l = 0; l < layers.size(); ++l)
    {
      const CAS3::Curvature_layer<K>& layer = layers[l];
      std::vector<double> eH, sH;
      std::size_t H_in = 0, K_in = 0;
      for(std::size_t i = 0; i < s.points.size(); ++i)
      {
        const CAS3::Point_curvature<K>& c = layer.points[i];
        if(!c.on_surface() || !std::isfinite(c.mean_curvature))
          continue;
        const double e_H = std::abs(c.mean_curvature - s.mean_curvature[i]);
        eH.push_back(e_H);
        sH.push_back(c.uncertainty.mean_curvature);
        H_in += e_H <= 2 * c.uncertainty.mean_curvature ? 1 : 0;
        K_in += std::abs(c.gaussian_curvature - s.gaussian_curvature[i]) <= 2 * c.uncertainty.gaussian_curvature ? 1 : 0;
        BOOST_REQUIRE(c.uncertainty.normal_degrees >= 0);
        // the noise's part of the whole
        BOOST_REQUIRE(c.uncertainty.mean_curvature_noise > 0);
        BOOST_REQUIRE(c.uncertainty.mean_curvature_noise <= c.uncertainty.mean_curvature * (1 + 1e-12));
      }
      BOOST_REQUIRE(eH.size() > s.points.size() / 2);
      const double n = double(eH.size());
      const double ratio = cas3_test::quantile(sH, 0.5) / cas3_test::quantile(eH, 0.5);
      BOOST_TEST_MESSAGE("noise " << noise << ", layer " << l << ": H within 2 sigma "
                         << double(H_in) / n << ", K " << double(K_in) / n << ", median sigma / error " << ratio);
      const bool two_spacings = layer.neighborhood.kind() == CAS3::Neighborhood::SPACINGS
                                && layer.neighborhood.value() == 2;
      BOOST_TEST(double(H_in) / n >= (noise > 0 ? 0.75 : two_spacings ? 0.9 : 0.85));
      // not all of them, where the error is mostly noise (the 2- and 4-spacing
      // layers) or the clean cloud's below 16 spacings; where it is mostly the
      // bias of a large radius, the bias term reads it at nearly every point
      // (the manual: 99-100% at 16 spacings on clean clouds), and on a cloud
      // this small, where 16 spacings span much of the ellipsoid, it
      // overstates it under noise (the manual, small clouds); the ratio
      // bounds them
      const bool fine = layer.neighborhood.kind() == CAS3::Neighborhood::SPACINGS
                        && layer.neighborhood.value() <= 4;
      const bool sixteen_spacings = layer.neighborhood.kind() == CAS3::Neighborhood::SPACINGS
                                    && layer.neighborhood.value() == 16;
      if(fine || (noise == 0 && !sixteen_spacings))
        BOOST_TEST(double(H_in) / n <= 0.999);
      BOOST_TEST(double(K_in) / n >= 0.75);
      BOOST_TEST(ratio >= 0.5);
      // on 2,500 points under noise the automatic and 8-spacing layers'
      // sigma is 4-5 times their error (the manual, small clouds)
      BOOST_TEST(ratio <= 6);
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_multiscale_curvatures
