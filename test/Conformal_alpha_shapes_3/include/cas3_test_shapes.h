// Point samples of analytic surfaces and volumes for the tests and benchmarks.
#ifndef CAS3_TEST_SHAPES_H
#define CAS3_TEST_SHAPES_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace cas3_test {

// Quasi-uniform unit directions (Fibonacci spiral).
template <class Vector>
std::vector<Vector> fibonacci_directions(std::size_t n)
{
  std::vector<Vector> d;
  d.reserve(n);
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for(std::size_t i = 0; i < n; ++i)
  {
    const double z = 1.0 - (2.0 * double(i) + 1.0) / double(n);
    const double r = std::sqrt(1.0 - z * z);
    d.push_back(Vector(r * std::cos(golden * double(i)), r * std::sin(golden * double(i)), z));
  }
  return d;
}

// Points on the ellipsoid (x/a)^2 + (y/b)^2 + (z/c)^2 = 1, roughly uniform in
// parameter, each displaced along the radial direction by a relative
// Gaussian noise of standard deviation `noise` and jittered tangentially by
// `jitter` (absolute) so that no four points are exactly cospherical.
template <class Point>
std::vector<Point> ellipsoid_sample(std::size_t n, double a, double b, double c,
                                    double noise = 0, unsigned seed = 1, double jitter = 1e-7)
{
  std::mt19937 gen(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Point> pts;
  pts.reserve(n);
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for(std::size_t i = 0; i < n; ++i)
  {
    const double z = 1.0 - (2.0 * double(i) + 1.0) / double(n);
    const double r = std::sqrt(1.0 - z * z);
    const double t = golden * double(i);
    const double s = 1.0 + noise * gauss(gen);
    pts.push_back(Point(a * r * std::cos(t) * s + jitter * gauss(gen),
                        b * r * std::sin(t) * s + jitter * gauss(gen),
                        c * z * s + jitter * gauss(gen)));
  }
  return pts;
}

// Points on the torus with radii R > r around the z axis, uniform in area
// times a density that grows by the factor `gradient` from x = -(R + r) to
// x = R + r (exponentially), with relative normal noise `noise` (times r)
// along the tube normal.
template <class Point>
std::vector<Point> torus_sample(std::size_t n, double R, double r, double noise = 0, unsigned seed = 2,
                                double gradient = 1)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Point> pts;
  pts.reserve(n);
  while(pts.size() < n)
  {
    const double u = 2 * M_PI * unit(gen), v = 2 * M_PI * unit(gen);
    // rejection sampling of v makes the density uniform in area
    if(unit(gen) * (R + r) > R + r * std::cos(v))
      continue;
    const double x = (R + r * std::cos(v)) * std::cos(u) / (R + r);
    if(unit(gen) > std::exp(std::log(gradient) * (x - 1) / 2))
      continue;
    const double rr = r * (1.0 + noise * gauss(gen));
    pts.push_back(Point((R + rr * std::cos(v)) * std::cos(u), (R + rr * std::cos(v)) * std::sin(u),
                        rr * std::sin(v)));
  }
  return pts;
}

// Points on the ellipsoid (x/a)^2 + (y/b)^2 + (z/c)^2 = 1 whose density
// grows by the factor `gradient` from x = -a to x = a (exponentially), with
// relative radial noise `noise`.
template <class Point>
std::vector<Point> graded_ellipsoid_sample(std::size_t n, double a, double b, double c, double gradient,
                                           double noise = 0, unsigned seed = 6)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Point> pts;
  pts.reserve(n);
  while(pts.size() < n)
  {
    double x = gauss(gen), y = gauss(gen), z = gauss(gen);
    const double len = std::sqrt(x * x + y * y + z * z);
    x /= len; y /= len; z /= len;
    if(unit(gen) > std::exp(std::log(gradient) * (x - 1) / 2))
      continue;
    const double s = 1.0 + noise * gauss(gen);
    pts.push_back(Point(a * x * s, b * y * s, c * z * s));
  }
  return pts;
}

// Points on the torus with radii R > r around the z axis, with density
// proportional to 1 / lfs^2, lfs = min(r, distance to the axis) being the
// local feature size: dense around the hole, sparse outside, an
// epsilon-sample for a uniform epsilon. Relative noise `noise` (times R + r)
// along the tube normal.
template <class Point>
std::vector<Point> lfs_torus_sample(std::size_t n, double R, double r, double noise = 0, unsigned seed = 4)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Point> pts;
  pts.reserve(n);
  const double smallest_lfs = R - r;
  while(pts.size() < n)
  {
    const double u = 2 * M_PI * unit(gen), v = 2 * M_PI * unit(gen);
    const double rho = R + r * std::cos(v);
    const double lfs = std::min(r, rho);
    // area element rho / (R + r), density (smallest_lfs / lfs)^2
    if(unit(gen) > (rho / (R + r)) * (smallest_lfs / lfs) * (smallest_lfs / lfs))
      continue;
    const double rr = r + noise * (R + r) * gauss(gen);
    pts.push_back(Point((R + rr * std::cos(v)) * std::cos(u), (R + rr * std::cos(v)) * std::sin(u),
                        rr * std::sin(v)));
  }
  return pts;
}

// Uniform random points in the cube [-1, 1]^3.
template <class Point>
std::vector<Point> cube_volume_sample(std::size_t n, unsigned seed = 3)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::vector<Point> pts;
  pts.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    pts.push_back(Point(coord(gen), coord(gen), coord(gen)));
  return pts;
}

} // namespace cas3_test

#endif // CAS3_TEST_SHAPES_H
