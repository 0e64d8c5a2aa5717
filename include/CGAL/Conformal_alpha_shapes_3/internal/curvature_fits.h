// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CURVATURE_FITS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CURVATURE_FITS_H

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// Small fixed-size vector algebra on Eigen, independent of the kernel.
typedef Eigen::Vector3d Vec3;

// The curvature of a surface at one point, in 3D, with k1 >= k2.
struct Local_curvature
{
  Vec3 normal;
  double k1, k2;
  Vec3 d1, d2;
};

// An orthonormal tangent frame (e1, e2, n), right-handed: e2 = n x e1.
struct Tangent_frame
{
  Vec3 e1, e2, n;
};

inline Tangent_frame frame_from_normal_and_direction(const Vec3& n, const Vec3& direction)
{
  Tangent_frame f;
  f.n = n;
  f.e1 = (direction - direction.dot(n) * n).normalized();
  f.e2 = n.cross(f.e1);
  return f;
}

inline Tangent_frame frame_from_normal(const Vec3& n)
{
  const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  return frame_from_normal_and_direction(n, helper);
}

// The eigenvalues larger >= smaller of the symmetric matrix [[a, b], [b, c]]
// and a unit eigenvector of the larger, in closed form: every fit and every
// interpolation solves one, and Eigen's iterative solver is costly for a
// problem this small. Of the two eigenvectors that the rows give, the
// longer is taken, which avoids their cancellation; where the eigenvalues
// are equal any direction is one, and (1, 0) is given.
struct Symmetric_2x2_eigen
{
  double larger, smaller;
  Eigen::Vector2d larger_vector;

  Symmetric_2x2_eigen(double a, double b, double c)
  {
    const double mean = (a + c) / 2, root = std::sqrt((a - c) * (a - c) / 4 + b * b);
    larger = mean + root;
    smaller = mean - root;
    const Eigen::Vector2d from_first_row(b, larger - a), from_second_row(larger - c, b);
    larger_vector = from_first_row.squaredNorm() >= from_second_row.squaredNorm() ? from_first_row : from_second_row;
    const double length = larger_vector.norm();
    larger_vector = length > 0 ? Eigen::Vector2d(larger_vector / length) : Eigen::Vector2d(1, 0);
  }
};

// Principal curvatures and directions of the second fundamental form
// [[a, b/2], [b/2, c]] given in the frame (e1, e2). The eigenvectors' signs
// are arbitrary; the directions are made right-handed with the normal
// (d2 = n x d1), so that seeing the surface from the other side is a
// matter of swapping them.
inline Local_curvature from_tangent_form(const Tangent_frame& f, double a, double b, double c)
{
  const Symmetric_2x2_eigen eig(a, b / 2, c);
  const Vec3 d1 = eig.larger_vector(0) * f.e1 + eig.larger_vector(1) * f.e2;
  return Local_curvature{f.n, eig.larger, eig.smaller, d1, f.n.cross(d1)};
}

// One neighbor seen from the center vertex p: q - p, and the normal
// curvature estimate along it.
struct Neighbor
{
  Vec3 offset;
  double normal_curvature;
};

// The normal curvature along q - p from the normal difference (the manual,
// section "Curvature on a Triangle Mesh"; the paper's eq. 3.15):
// <q - p, N_q - N_p> / |q - p|^2.
inline double normal_curvature(const Vec3& offset, const Vec3& n_p, const Vec3& n_q)
{
  return offset.dot(n_q - n_p) / offset.squaredNorm();
}

// Unit tangent direction of an offset (the paper's eq. 3.6); false when the
// offset is along the normal.
inline bool tangent_direction(const Vec3& offset, const Vec3& n, Vec3& t)
{
  t = offset - offset.dot(n) * n;
  const double len = t.norm();
  if(!(len > 1e-12 * offset.norm()))
    return false;
  t /= len;
  return true;
}

// The paper's Euler fit: e1 along the neighbor of largest normal curvature,
// a fixed to that curvature, b and c by least squares (the manual, section
// "Curvature on a Triangle Mesh", estimator `PAPER_EULER_FIT`).
inline bool paper_euler_fit(const Vec3& n, const std::vector<Neighbor>& nbrs, Local_curvature& out)
{
  std::size_t best = nbrs.size();
  for(std::size_t i = 0; i < nbrs.size(); ++i)
    if(best == nbrs.size() || nbrs[i].normal_curvature > nbrs[best].normal_curvature)
      best = i;
  if(best == nbrs.size())
    return false;
  Vec3 t_best;
  if(!tangent_direction(nbrs[best].offset, n, t_best))
    return false;
  const Tangent_frame f = frame_from_normal_and_direction(n, t_best);
  const double a = nbrs[best].normal_curvature;

  double a11 = 0, a12 = 0, a22 = 0, a13 = 0, a23 = 0;
  for(const Neighbor& q : nbrs)
  {
    Vec3 t;
    if(!tangent_direction(q.offset, n, t))
      continue;
    const double c = t.dot(f.e1), s = t.dot(f.e2);
    const double r = q.normal_curvature - a * c * c;
    a11 += c * c * s * s;
    a12 += c * s * s * s;
    a22 += s * s * s * s;
    a13 += r * c * s;
    a23 += r * s * s;
  }
  const double det = a11 * a22 - a12 * a12;
  if(!(det > 1e-12 * a11 * a22) || !(a11 * a22 > 0))
    return false;
  const double b = (a13 * a22 - a23 * a12) / det;
  const double cc = (a11 * a23 - a12 * a13) / det;
  out = from_tangent_form(f, a, b, cc);
  return true;
}

// Least-squares fit of all three Euler coefficients to the normal
// curvatures: k_i ~ a cos^2 + b cos sin + c sin^2.
inline bool euler_least_squares_fit(const Vec3& n, const std::vector<Neighbor>& nbrs,
                                    Local_curvature& out)
{
  const Tangent_frame f = frame_from_normal(n);
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  std::size_t used = 0;
  for(const Neighbor& q : nbrs)
  {
    Vec3 t;
    if(!tangent_direction(q.offset, n, t))
      continue;
    const double c = t.dot(f.e1), s = t.dot(f.e2);
    const Eigen::Vector3d phi(c * c, c * s, s * s);
    m += phi * phi.transpose();
    rhs += q.normal_curvature * phi;
    ++used;
  }
  if(used < 3)
    return false;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
  if(!(eig.eigenvalues()(0) > 1e-10 * eig.eigenvalues()(2)))
    return false;
  const Eigen::Vector3d abc = m.ldlt().solve(rhs);
  out = from_tangent_form(f, abc(0), abc(1), abc(2));
  return true;
}

// The uncertainty of a quadric fit, from its residuals: the standard
// errors of its mean and Gaussian curvatures and of its normal's direction
// per unit of noise of the heights.
struct Quadric_fit_error
{
  double noise = 0;               // standard deviation of the heights about the fit (model units)
  double degrees_of_freedom = 0;  // effective: weighted rows less what the fit absorbs
  double per_noise = 0;           // standard error of H per unit of noise
  double per_noise_K = 0;         // standard error of K per unit of noise, to first order in the fitted coefficients
  double per_squared_noise_K = 0; // of K's second-order term per squared unit of noise
  double per_noise_normal = 0;    // of the normal's direction (radians, both tangent axes) per unit of noise
};

// The moments sum x^i y^j, i + j < 7, stored by pairs of consecutive
// powers of x, (x^2q y^j, x^(2q+1) y^j), so that a neighbor's products are
// added two at a time in one packet operation. The pairs are built in
// registers from the point: a compiler left to vectorize the products of
// a row of scalars stored them and read them back as pairs, which stalls
// on every neighbor.
struct Shell_moments
{
  static constexpr int size = 7;
  Eigen::Array2d pairs[size][4];  // [j][q]; entries with 2q + j > 6 unused

  Shell_moments()
  {
    for(auto& row : pairs)
      for(Eigen::Array2d& pair : row)
        pair.setZero();
  }

  double operator()(int i, int j) const { return pairs[j][i / 2](i % 2); }

  void add(double x, double y)
  {
    static const Eigen::Array2d one_and_zero(1, 0), zero_and_one(0, 1);
    const double x2 = x * x;
    Eigen::Array2d px[4];
    px[0] = one_and_zero + zero_and_one * x;  // (1, x)
    for(int q = 1; q < 4; ++q)
      px[q] = px[q - 1] * x2;
    double yj = 1;
    for(int j = 0; j < size; ++j, yj *= y)
      for(int q = 0; 2 * q + j < size; ++q)
        pairs[j][q] += px[q] * yj;
  }

  // adds w times the moments of `other` of degree < `degree`
  void add(double w, const Shell_moments& other, int degree = size)
  {
    for(int j = 0; j < degree; ++j)
      for(int q = 0; 2 * q + j < degree; ++q)
        pairs[j][q] += w * other.pairs[j][q];
  }
};

// Neighbors of a vertex as the quadric fit sees them, summed by shells:
// the neighbors in one shell (about the same distance from the vertex, see
// `quadric_shell_index()`) share their sums, and a fit weighs the whole
// shell by its kernel at the shell's mean squared distance. The cost of a
// fit is then that of its shells, not of its neighbors: the fits at
// several radii around a vertex share one pass over the neighbors.
// Coordinates (x, y, z) are in the vertex's tangent frame divided by a
// length L; squared distances are in model units.
// A shell keeps the moments sum x^i y^j (i + j <= 6) and sum z x^i y^j
// (i + j <= 2) rather than the products of the rows: every entry of the
// quadric's X' X is a moment of degree 4 or less, and its correction for
// the fourth order (`quadric_fit()`) needs those of degree 5 and 6.
struct Quadric_shell
{
  Shell_moments moments;       // sum x^i y^j, i + j <= 6
  double heights[3][3] = {};   // [i][j]: sum z x^i y^j, i + j <= 2
  double squared_heights = 0;  // sum of z^2
  double count = 0;
  double squared_distances = 0;

  void add(double x, double y, double z, double squared_distance)
  {
    moments.add(x, y);
    const double zx = z * x, zy = z * y;
    heights[0][0] += z;
    heights[0][1] += zy;
    heights[0][2] += zy * y;
    heights[1][0] += zx;
    heights[1][1] += zx * y;
    heights[2][0] += zx * x;
    squared_heights += z * z;
    count += 1;
    squared_distances += squared_distance;
  }
};

// The monomials x^i y^j of the quadric, in the order of its coefficients
// (x^2, x y, y^2, x, y, 1).
constexpr int quadric_monomials[6][2] = {{2, 0}, {1, 1}, {0, 2}, {1, 0}, {0, 1}, {0, 0}};

// Shells are a quarter of an octave of squared distance wide (distances
// within 9% of each other), relative to the length L: shell 0 holds
// everything closer than L / 256, where the kernel is flat anyway.
constexpr int quadric_shells_per_octave = 4;
constexpr int number_of_quadric_shells = 16 * quadric_shells_per_octave;
// The ratio's binary exponent and mantissa are read from its representation
// as std::frexp() would give them (a library call, once per neighbor, was a
// tenth of the fits' preparation); a subnormal ratio lands in shell 0 either
// way. The quarter is a sum of comparisons rather than a choice by branches,
// which a neighbor's distance would take at random.
inline int quadric_shell_index(double squared_distance, double squared_length)
{
  const double ratio = squared_distance / squared_length;
  std::uint64_t bits;
  std::memcpy(&bits, &ratio, sizeof bits);
  const int exponent = int((bits >> 52) & 0x7ff) - 1022;
  bits = (bits & 0x000fffffffffffffull) | (std::uint64_t(1022) << 52);
  double mantissa;  // in [0.5, 1)
  std::memcpy(&mantissa, &bits, sizeof bits);
  const int quarter = int(mantissa >= 0.5946) + int(mantissa >= 0.7071) + int(mantissa >= 0.8409);
  return (std::max)(0, (std::min)(number_of_quadric_shells - 1,
                                  (exponent - 1) * quadric_shells_per_octave + quarter + number_of_quadric_shells));
}

typedef Eigen::Matrix<double, 6, 6> Matrix6;
typedef Eigen::Matrix<double, 6, 1> Vector6;

// The inverse of the quadric fit's normal matrix, a symmetric positive
// definite 6x6 matrix, from its Cholesky factor; false when a pivot is not
// above 1e-14 times the largest (singular to working precision). The fit
// solves three right-hand sides and needs the trace of M^-1 M2: one
// explicit inverse in plain loops is cheaper than Eigen's LDLT on a matrix
// right-hand side, which goes through its general blocked solver.
inline bool symmetric_positive_inverse(const Matrix6& m, Matrix6& inverse)
{
  double l[6][6] = {}, pivot[6];
  for(int j = 0; j < 6; ++j)
  {
    double d = m(j, j);
    for(int k = 0; k < j; ++k)
      d -= l[j][k] * l[j][k];
    if(!(d > 0))
      return false;
    pivot[j] = d;
    l[j][j] = std::sqrt(d);
    for(int i = j + 1; i < 6; ++i)
    {
      double sum = m(i, j);
      for(int k = 0; k < j; ++k)
        sum -= l[i][k] * l[j][k];
      l[i][j] = sum / l[j][j];
    }
  }
  const double largest = *std::max_element(pivot, pivot + 6), smallest = *std::min_element(pivot, pivot + 6);
  if(!(smallest > 1e-14 * largest))
    return false;
  double li[6][6] = {};  // the inverse of l, lower triangular
  for(int j = 0; j < 6; ++j)
  {
    li[j][j] = 1 / l[j][j];
    for(int i = j + 1; i < 6; ++i)
    {
      double sum = 0;
      for(int k = j; k < i; ++k)
        sum -= l[i][k] * li[k][j];
      li[i][j] = sum / l[i][i];
    }
  }
  for(int i = 0; i < 6; ++i)
    for(int j = 0; j <= i; ++j)
    {
      double sum = 0;
      for(int k = i; k < 6; ++k)
        sum += li[k][i] * li[k][j];
      inverse(i, j) = inverse(j, i) = sum;
    }
  return true;
}

// Weighted least-squares fit of the height function
//   z = A x^2 + B x y + C y^2 + D x + E y + F
// to the vertex (at the origin) and the neighbors summed in
// `shells[0, shell_count)` (`neighbors` of them), in the frame `f` of the
// vertex normal. The linear terms absorb the normal's error and the
// constant term the vertex's own displacement (noise); the curvature is that
// of the graph at the origin, positive where the surface bends away from
// the normal. The fit is corrected for the fourth order of a surface of its
// own curvature (below), which removes most of the bias that a plain
// quadric has where the curvature varies slowly. A neighbor at distance d
// has the weight (1 - d^2 / (1.5 fade)^2)^4, which fades to 0 at 1.5 times
// `fade` (the neighborhood's radius), taken at its shell's mean squared
// distance; the shells are in coordinates divided by `length`, and the fit
// runs in coordinates divided by `fade`, which condition it whatever the
// size of the neighborhood.
// When `error` is given, it receives the uncertainty of the mean curvature
// A + C for heights with independent noise of one standard deviation
// (weighted least squares: the sandwich variance, and the residual variance
// over the effective degrees of freedom; infinite with none left): what the
// automatic neighborhood weighs against the bias of larger neighborhoods.
// False with fewer than 5 neighbors or a singular system.
inline bool quadric_fit(const Tangent_frame& f, const Quadric_shell* shells, std::size_t shell_count,
                        std::size_t neighbors, double fade, double length, Local_curvature& out,
                        Quadric_fit_error* error = nullptr)
{
  if(neighbors < 5 || !(fade > 0))
    return false;
  constexpr int size = Shell_moments::size;
  // the weighted moments (and squared-weighted ones, of degree 4 or less,
  // for the error); the vertex's own row is (0, ..., 0, 1) with height 0
  // and weight 1
  Shell_moments m, m2;
  double h[3][3] = {};
  double zz = 0, weights = 1;
  const double reach2 = 2.25 * fade * fade;
  for(std::size_t t = 0; t < shell_count; ++t)
  {
    const Quadric_shell& shell = shells[t];
    const double u = 1 - shell.squared_distances / (shell.count * reach2);
    if(!(u > 0))
      continue;
    const double w = (u * u) * (u * u);
    m.add(w, shell.moments);
    for(int i = 0; i <= 2; ++i)
      for(int j = 0; j <= 2 - i; ++j)
        h[i][j] += w * shell.heights[i][j];
    zz += w * shell.squared_heights;
    if(error != nullptr)
    {
      m2.add(w * w, shell.moments, 5);
      weights += w * shell.count;
    }
  }
  m.add(0, 0);  // the vertex's own row
  m2.add(0, 0);

  // from coordinates divided by `length` to coordinates divided by `fade`:
  // a monomial of degree k scales by s^k, s = length / fade, the height by s
  const double s = length / fade;
  double power[size];
  power[0] = 1;
  for(int k = 1; k < size; ++k)
    power[k] = power[k - 1] * s;
  Matrix6 normal_matrix, squared_weights;
  Vector6 rhs;
  for(int a = 0; a < 6; ++a)
  {
    const int ia = quadric_monomials[a][0], ja = quadric_monomials[a][1];
    rhs(a) = power[ia + ja + 1] * h[ia][ja];
    for(int b = 0; b < 6; ++b)
    {
      const int i = ia + quadric_monomials[b][0], j = ja + quadric_monomials[b][1];
      normal_matrix(a, b) = power[i + j] * m(i, j);
      squared_weights(a, b) = power[i + j] * m2(i, j);
    }
  }
  Matrix6 inverse;
  if(!symmetric_positive_inverse(normal_matrix, inverse))
    return false;
  const Vector6 least_squares = inverse * rhs;
  // The heights less the fourth-order term of a surface whose shape
  // operator is the fitted S everywhere, (x' S x)(x' S^2 x) / 8: exact on
  // spheres (k^3 r^4 / 8) and cylinders, where a quadric alone reads the
  // curvature too high by a relative (k R)^2 term. One step: the term is
  // second order in what it corrects.
  const double b = least_squares(1);
  const double p[3] = {2 * least_squares(0), 2 * b, 2 * least_squares(2)};  // x' S x = p0 x^2 + p1 x y + p2 y^2
  const double q[3] = {p[0] * p[0] + b * b, 2 * b * (p[0] + p[2]), b * b + p[2] * p[2]};  // x' S^2 x
  const double term[5] = {p[0] * q[0] / 8, (p[0] * q[1] + p[1] * q[0]) / 8,
                          (p[0] * q[2] + p[1] * q[1] + p[2] * q[0]) / 8, (p[1] * q[2] + p[2] * q[1]) / 8,
                          p[2] * q[2] / 8};  // x^4, x^3 y, x^2 y^2, x y^3, y^4
  Vector6 quartic;
  for(int a = 0; a < 6; ++a)
  {
    const int ia = quadric_monomials[a][0], ja = quadric_monomials[a][1];
    double sum = 0;
    for(int k = 0; k < 5; ++k)
      sum += term[k] * m(ia + 4 - k, ja + k);
    quartic(a) = power[ia + ja + 4] * sum;
  }
  const Vector6 coef = inverse * (rhs - quartic);
  const double A = coef(0) / fade, B = coef(1) / fade, C = coef(2) / fade, D = coef(3), E = coef(4);
  if(error != nullptr)
  {
    // rows weighted by W: E[sum W r^2] = s^2 (sum W - tr(M^-1 M2)) and
    // var(m' coef) = s^2 m' M^-1 M2 M^-1 m, M = X' W X, M2 = X' W^2 X;
    // sum W r^2 = z' W z - 2 coef' X' W z + coef' M coef
    const Vector6 mean_solution = inverse.col(0) + inverse.col(2);  // M^-1 (1, 0, 1, 0, 0, 0)
    const double spread = mean_solution.dot(squared_weights * mean_solution);
    // the covariance of the coefficients per unit noise, M^-1 M2 M^-1
    const Matrix6 covariance = inverse * squared_weights * inverse;
    // K = (4 A C - B^2) / fade^2 to first order in the coefficients
    const Eigen::Vector3d gradient(4 * coef(2), -2 * coef(1), 4 * coef(0));
    const double spread_K = gradient.dot(covariance.topLeftCorner<3, 3>() * gradient);
    // K's second-order term q' Q q (q the coefficients' errors) has variance 2 tr((Q C)^2)
    Eigen::Matrix3d form;
    form << 0, 0, 2, 0, -1, 0, 2, 0, 0;
    const Eigen::Matrix3d QC = form * covariance.topLeftCorner<3, 3>();
    const double spread_K2 = 2 * (QC * QC).trace();
    // of the least-squares solution (the correction is not fitted)
    const double residuals = (std::max)(0., s * s * zz - 2 * least_squares.dot(rhs)
                                              + least_squares.dot(normal_matrix * least_squares));
    const double dof = weights - inverse.cwiseProduct(squared_weights).sum();  // tr(M^-1 M2), both symmetric
    const double variance = dof > 0.5 ? residuals / dof : std::numeric_limits<double>::infinity();
    error->noise = std::sqrt(variance) * fade;
    error->degrees_of_freedom = dof;
    error->per_noise = std::sqrt(spread) / (fade * fade);
    error->per_noise_K = std::sqrt((std::max)(0., spread_K)) / (fade * fade * fade);
    error->per_squared_noise_K = std::sqrt((std::max)(0., spread_K2)) / (fade * fade * fade * fade);
    error->per_noise_normal = std::sqrt((std::max)(0., covariance(3, 3) + covariance(4, 4))) / fade;
  }

  // first and second fundamental forms of (x, y, z(x, y)) at the origin,
  // the second one for the normal (-D, -E, 1) / w
  const double w = std::sqrt(1 + D * D + E * E);
  Eigen::Matrix2d first, second;
  first << 1 + D * D, D * E, D * E, 1 + E * E;
  second << 2 * A, B, B, 2 * C;
  second /= w;
  // curvature positive where the surface bends away from the normal: the
  // eigenvalues of -second relative to first, those of R^-1 (-second) R^-T
  // for first = R R' (Cholesky, in closed form), whose eigenvectors u give
  // the principal directions R^-T u in (xu, xv)
  const double r11 = std::sqrt(first(0, 0)), r21 = first(1, 0) / r11;
  const double r22 = std::sqrt(first(1, 1) - r21 * r21);
  const double i11 = 1 / r11, i21 = -r21 / (r11 * r22), i22 = 1 / r22;  // R^-1, lower triangular
  const Eigen::Matrix2d shape_form = -second;
  const double c11 = i11 * i11 * shape_form(0, 0);
  const double c21 = i21 * i11 * shape_form(0, 0) + i22 * i11 * shape_form(1, 0);
  const double c22 = i21 * i21 * shape_form(0, 0) + 2 * i21 * i22 * shape_form(1, 0) + i22 * i22 * shape_form(1, 1);
  const Symmetric_2x2_eigen eig(c11, c21, c22);
  if(!std::isfinite(eig.larger) || !std::isfinite(eig.smaller))
    return false;
  const Vec3 xu = f.e1 + D * f.n, xv = f.e2 + E * f.n;
  const Eigen::Vector2d v_max(i11 * eig.larger_vector(0) + i21 * eig.larger_vector(1), i22 * eig.larger_vector(1));
  const Vec3 normal = ((f.n - D * f.e1 - E * f.e2) / w).normalized();
  const Vec3 d1 = (v_max(0) * xu + v_max(1) * xv).normalized();
  // the principal directions are orthogonal: d2 is d1 turned about the
  // normal, right-handed as in from_tangent_form()
  out = Local_curvature{normal, eig.larger, eig.smaller, d1, normal.cross(d1)};
  return true;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CURVATURE_FITS_H
