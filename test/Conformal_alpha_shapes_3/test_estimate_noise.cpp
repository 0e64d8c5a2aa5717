// Tests of estimate_noise(): the noise of a sample relative to its spacing,
// on noisy samples and on clean ones with fine detail.
#include <boost/test/unit_test.hpp>

#include <CGAL/Conformal_alpha_shapes_3/estimate_noise.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cas3_analytic_surfaces.h"
#include "cas3_test_types.h"

#include <cmath>
#include <vector>

// Every name of this file is in its own namespace: the test runner compiles
// several test files as one translation unit.
namespace test_estimate_noise {

using namespace cas3_test_types;

BOOST_AUTO_TEST_SUITE(estimate_noise)

// The noise estimate reads Gaussian noise along the normal and leaves clean
// detail (fine bumps) alone.
BOOST_AUTO_TEST_CASE(noise_estimate)
{
  cas3_analytic::Bumpy_radius bumps;
  bumps.amplitude = 0.005;
  bumps.frequency = 40;
  const Sample clean = cas3_analytic::bumpy_sphere_truth_sample<Point, Vector>(20000, bumps);
  const CAS3::Noise_estimate detail = CAS3::estimate_noise(clean.points);
  BOOST_TEST_MESSAGE("clean bumpy sphere: noise " << detail.noise << ", spacing " << detail.spacing);
  BOOST_TEST(detail.noise < 0.02);
  BOOST_TEST(!detail.calls_for_denoising());
  for(double r : {0.05, 0.1, 0.3})
  {
    Sample s = cas3_analytic::torus_truth_sample<Point, Vector>(20000, 1.0, 0.35);
    cas3_analytic::add_normal_noise(s, r, 10);
    const CAS3::Noise_estimate e = CAS3::estimate_noise(s.points);
    BOOST_TEST_CONTEXT("noise " << r)
    {
      BOOST_TEST(std::abs(e.noise / r - 1) < 0.1);
      BOOST_TEST(std::abs(e.spacing / s.spacing - 1) < 0.1);
      BOOST_TEST(e.calls_for_denoising());
    }
  }
  BOOST_TEST(CAS3::estimate_noise(std::vector<Point>(10, Point(0, 0, 0))).noise == 0);
}

BOOST_AUTO_TEST_SUITE_END()

} // namespace test_estimate_noise
