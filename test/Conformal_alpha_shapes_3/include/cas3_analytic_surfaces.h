// Point samples of analytic surfaces with their exact differential geometry:
// every point comes with its true outward unit normal, mean curvature H and
// Gaussian curvature K (convex with outward normals: H > 0; sphere of radius
// r: H = 1/r, K = 1/r^2), the surface area and the sample spacing
// sqrt(area / n) (the manual, "Measured: Advancing Front against the Solid
// Boundary"). For the evaluation program and for
// tests.
//
// The truth comes from an implicit function F (F < 0 inside, F > 0 outside),
// differentiated exactly twice by forward-mode automatic differentiation
// (`Jet2`): n = grad F / |grad F|, H = div(n) / 2 and
// K = grad F^T adj(Hess F) grad F / |grad F|^4 (Goldman 2005).
// Points are uniform in area (rejection sampling against the exact area
// element); areas are exact or computed by quadrature.
#ifndef CAS3_ANALYTIC_SURFACES_H
#define CAS3_ANALYTIC_SURFACES_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

namespace cas3_analytic {

// A value with its exact gradient and Hessian in (x, y, z).
struct Jet2
{
  double v = 0;
  double g[3] = {0, 0, 0};
  double h[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};

  Jet2() = default;
  Jet2(double value) : v(value) {}
  static Jet2 variable(double value, int axis)
  {
    Jet2 j(value);
    j.g[axis] = 1;
    return j;
  }
};

// f(a) given f(a.v), f'(a.v), f''(a.v)
inline Jet2 chain(const Jet2& a, double f, double df, double ddf)
{
  Jet2 r(f);
  for(int i = 0; i < 3; ++i)
  {
    r.g[i] = df * a.g[i];
    for(int j = 0; j < 3; ++j)
      r.h[i][j] = df * a.h[i][j] + ddf * a.g[i] * a.g[j];
  }
  return r;
}

inline Jet2 operator+(const Jet2& a, const Jet2& b)
{
  Jet2 r(a.v + b.v);
  for(int i = 0; i < 3; ++i)
  {
    r.g[i] = a.g[i] + b.g[i];
    for(int j = 0; j < 3; ++j) r.h[i][j] = a.h[i][j] + b.h[i][j];
  }
  return r;
}
inline Jet2 operator-(const Jet2& a) { return chain(a, -a.v, -1, 0); }
inline Jet2 operator-(const Jet2& a, const Jet2& b) { return a + (-b); }
inline Jet2 operator*(const Jet2& a, const Jet2& b)
{
  Jet2 r(a.v * b.v);
  for(int i = 0; i < 3; ++i)
  {
    r.g[i] = a.g[i] * b.v + a.v * b.g[i];
    for(int j = 0; j < 3; ++j)
      r.h[i][j] = a.h[i][j] * b.v + a.v * b.h[i][j] + a.g[i] * b.g[j] + b.g[i] * a.g[j];
  }
  return r;
}
inline Jet2 inverse(const Jet2& a) { return chain(a, 1 / a.v, -1 / (a.v * a.v), 2 / (a.v * a.v * a.v)); }
inline Jet2 operator/(const Jet2& a, const Jet2& b) { return a * inverse(b); }
inline Jet2 sqrt(const Jet2& a)
{
  const double s = std::sqrt(a.v);
  return chain(a, s, 0.5 / s, -0.25 / (s * a.v));
}
inline Jet2 sin(const Jet2& a) { return chain(a, std::sin(a.v), std::cos(a.v), -std::sin(a.v)); }
inline Jet2 cos(const Jet2& a) { return chain(a, std::cos(a.v), -std::sin(a.v), -std::cos(a.v)); }
inline Jet2 exp(const Jet2& a)
{
  const double e = std::exp(a.v);
  return chain(a, e, e, e);
}

// The truth at a point of the zero set of F.
struct Differential
{
  double n[3];  // outward unit normal
  double H, K;
};

template <class Implicit>
Differential differential(const Implicit& F, double x, double y, double z)
{
  const Jet2 f = F(Jet2::variable(x, 0), Jet2::variable(y, 1), Jet2::variable(z, 2));
  const double* g = f.g;
  const auto& M = f.h;
  const double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  const double len = std::sqrt(g2);
  double gMg = 0, trace = M[0][0] + M[1][1] + M[2][2];
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) gMg += g[i] * M[i][j] * g[j];
  // adjugate of the symmetric Hessian
  double A[3][3];
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
    {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      A[j][i] = M[i1][j1] * M[i2][j2] - M[i1][j2] * M[i2][j1];
    }
  double gAg = 0;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) gAg += g[i] * A[i][j] * g[j];
  Differential d;
  for(int i = 0; i < 3; ++i) d.n[i] = g[i] / len;
  d.H = (g2 * trace - gMg) / (2 * g2 * len);
  d.K = gAg / (g2 * g2);
  return d;
}

// A sample with its truth (by input index).
template <class Point, class Vector>
struct Truth_sample
{
  std::vector<Point> points;
  std::vector<Vector> normals;              // true outward unit normals
  std::vector<double> mean_curvature;       // true H
  std::vector<double> gaussian_curvature;   // true K
  double area = 0;
  double spacing = 0;                       // sqrt(area / n)
  bool closed = true;

  void push(double x, double y, double z, const Differential& d)
  {
    points.push_back(Point(x, y, z));
    normals.push_back(Vector(d.n[0], d.n[1], d.n[2]));
    mean_curvature.push_back(d.H);
    gaussian_curvature.push_back(d.K);
  }
  void finish(double surface_area)
  {
    area = surface_area;
    spacing = std::sqrt(area / double(points.size()));
  }
};

// Moves every point along its true normal by a Gaussian of standard
// deviation r * spacing; the truth stays that of the unmoved point.
template <class Point, class Vector>
void add_normal_noise(Truth_sample<Point, Vector>& s, double r, unsigned seed)
{
  if(r <= 0)
    return;
  std::mt19937 gen(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for(std::size_t i = 0; i < s.points.size(); ++i)
    s.points[i] = s.points[i] + (r * s.spacing * gauss(gen)) * s.normals[i];
}

// ---------------------------------------------------------------------------
// Star-shaped surfaces |x| = rho(x / |x|): F(x) = |x| - rho(x / |x|).

template <class Rho>
struct Star_implicit
{
  Rho rho;
  template <class T>
  T operator()(const T& x, const T& y, const T& z) const
  {
    using std::sqrt;
    const T r = sqrt(x * x + y * y + z * z);
    return r - rho(x / r, y / r, z / r);
  }
};

struct Ellipsoid_radius
{
  double a, b, c;
  template <class T>
  T operator()(const T& ux, const T& uy, const T& uz) const
  {
    using std::sqrt;
    return 1.0 / sqrt(ux * ux * (1 / (a * a)) + uy * uy * (1 / (b * b)) + uz * uz * (1 / (c * c)));
  }
};

// 1 + amplitude * sin(k ux) sin(k uy) sin(k uz)
//   - dent_depth * exp(-|u - dent_direction|^2 / dent_width^2)
struct Bumpy_radius
{
  double amplitude = 0.02, frequency = 10;
  double dent_depth = 0, dent_width = 0.4;
  double dx = 1, dy = 0, dz = 0;  // dent direction (unit)
  template <class T>
  T operator()(const T& ux, const T& uy, const T& uz) const
  {
    using std::exp;
    using std::sin;
    T r = 1.0 + amplitude * (sin(frequency * ux) * sin(frequency * uy) * sin(frequency * uz));
    if(dent_depth != 0)
    {
      const T ex = ux - dx, ey = uy - dy, ez = uz - dz;
      r = r - dent_depth * exp((ex * ex + ey * ey + ez * ez) * (-1 / (dent_width * dent_width)));
    }
    return r;
  }
};

// Uniform in area on the part of the star-shaped surface with z > z_min.
// With `other` (the same directions on another star-shaped surface), also
// the truth of `other` at the point of it in the same direction: used to
// judge a bumpy surface against its smooth version.
template <class Point, class Vector, class Rho>
Truth_sample<Point, Vector> star_sample(std::size_t n, const Rho& rho, double z_min, unsigned seed,
                                        const Rho* other = nullptr,
                                        Truth_sample<Point, Vector>* other_truth = nullptr)
{
  const Star_implicit<Rho> F{rho};
  // area element on the unit sphere of directions: rho^2 / (n . u)
  auto weight = [&](double ux, double uy, double uz, double& x, double& y, double& z, Differential& d) {
    const double r = rho(ux, uy, uz);
    x = r * ux; y = r * uy; z = r * uz;
    d = differential(F, x, y, z);
    return r * r / (d.n[0] * ux + d.n[1] * uy + d.n[2] * uz);
  };
  // area and the largest weight by quadrature over Fibonacci directions
  const std::size_t m = 400000;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  double sum = 0, w_max = 0;
  for(std::size_t i = 0; i < m; ++i)
  {
    const double uz = 1.0 - (2.0 * double(i) + 1.0) / double(m);
    const double s = std::sqrt(1.0 - uz * uz);
    double x, y, z;
    Differential d;
    const double w = weight(s * std::cos(golden * double(i)), s * std::sin(golden * double(i)), uz, x, y, z, d);
    w_max = std::max(w_max, w);
    if(z > z_min) sum += w;
  }
  w_max *= 1.1;

  Truth_sample<Point, Vector> out;
  out.closed = !(z_min > -std::numeric_limits<double>::max());
  out.points.reserve(n);
  std::mt19937 gen(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Star_implicit<Rho> G{other ? *other : rho};
  while(out.points.size() < n)
  {
    double ux = gauss(gen), uy = gauss(gen), uz = gauss(gen);
    const double len = std::sqrt(ux * ux + uy * uy + uz * uz);
    ux /= len; uy /= len; uz /= len;
    double x, y, z;
    Differential d;
    const double w = weight(ux, uy, uz, x, y, z, d);
    if(z <= z_min || unit(gen) * w_max > w)
      continue;
    out.push(x, y, z, d);
    if(other && other_truth)
    {
      const double r = (*other)(ux, uy, uz);
      other_truth->push(r * ux, r * uy, r * uz, differential(G, r * ux, r * uy, r * uz));
    }
  }
  out.finish(4 * M_PI * sum / double(m));
  if(other_truth)
  {
    other_truth->closed = out.closed;
    other_truth->finish(out.area);
  }
  return out;
}

// Ellipsoid with semi-axes a, b, c; the cap z > z_min when z_min > -c.
template <class Point, class Vector>
Truth_sample<Point, Vector> ellipsoid_truth_sample(std::size_t n, double a, double b, double c,
                                                   double z_min = -std::numeric_limits<double>::infinity(),
                                                   unsigned seed = 11)
{
  return star_sample<Point, Vector>(n, Ellipsoid_radius{a, b, c}, z_min, seed);
}

// Unit sphere with bumps (and a dent); the cap z > z_min when given. With
// `smooth_truth`, also the truth of the same surface without the bumps, in
// the same directions.
template <class Point, class Vector>
Truth_sample<Point, Vector> bumpy_sphere_truth_sample(std::size_t n, const Bumpy_radius& shape,
                                                      double z_min = -std::numeric_limits<double>::infinity(),
                                                      unsigned seed = 12,
                                                      Truth_sample<Point, Vector>* smooth_truth = nullptr)
{
  Bumpy_radius smooth = shape;
  smooth.amplitude = 0;
  return star_sample<Point, Vector>(n, shape, z_min, seed, smooth_truth ? &smooth : nullptr, smooth_truth);
}

// ---------------------------------------------------------------------------
// Torus around the z axis, radii R > r: F = (sqrt(x^2 + y^2) - R)^2 + z^2 - r^2.
// Tube angle v (0 on the outer equator, pi/2 on top), around angle u. The
// patch u in [0, u_max), v in [v_min, v_max); the whole torus by default.
struct Torus_implicit
{
  double R, r;
  template <class T>
  T operator()(const T& x, const T& y, const T& z) const
  {
    using std::sqrt;
    const T d = sqrt(x * x + y * y) - R;
    return d * d + z * z - r * r;
  }
};

template <class Point, class Vector>
Truth_sample<Point, Vector> torus_truth_sample(std::size_t n, double R, double r, double u_max = 2 * M_PI,
                                               double v_min = -M_PI, double v_max = M_PI, unsigned seed = 13)
{
  const Torus_implicit F{R, r};
  Truth_sample<Point, Vector> out;
  out.closed = u_max >= 2 * M_PI && v_max - v_min >= 2 * M_PI;
  out.points.reserve(n);
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  while(out.points.size() < n)
  {
    const double u = u_max * unit(gen), v = v_min + (v_max - v_min) * unit(gen);
    if(unit(gen) * (R + r) > R + r * std::cos(v))
      continue;
    const double x = (R + r * std::cos(v)) * std::cos(u), y = (R + r * std::cos(v)) * std::sin(u),
                 z = r * std::sin(v);
    out.push(x, y, z, differential(F, x, y, z));
  }
  // area: integral of r (R + r cos v) du dv
  out.finish(u_max * r * (R * (v_max - v_min) + r * (std::sin(v_max) - std::sin(v_min))));
  return out;
}

// The square [-h, h]^2 in the plane z = 0, normal +z.
template <class Point, class Vector>
Truth_sample<Point, Vector> square_truth_sample(std::size_t n, double h = 1, unsigned seed = 14)
{
  Truth_sample<Point, Vector> out;
  out.closed = false;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> coord(-h, h);
  Differential d{{0, 0, 1}, 0, 0};
  for(std::size_t i = 0; i < n; ++i)
  {
    const double x = coord(gen), y = coord(gen);
    out.push(x, y, 0, d);
  }
  out.finish(4 * h * h);
  return out;
}

} // namespace cas3_analytic

#endif // CAS3_ANALYTIC_SURFACES_H
