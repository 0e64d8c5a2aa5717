// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CURVATURE_ESTIMATION_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CURVATURE_ESTIMATION_H

// The curvature at every vertex of a mesh for one or several neighborhood
// rules (the manual, "Curvature on a Triangle Mesh" and "Neighborhoods"):
// the vertex normals, the searches (internal/surface_neighborhoods.h), the
// fits on them (internal/curvature_fits.h) and the automatic choice among
// candidate radii. `estimate_vertex_curvatures()` runs one rule;
// `Multiscale_curvatures` runs all the layers of a surface at once.

#include <CGAL/Conformal_alpha_shapes_3/curvature_estimator.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/automatic_radius.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/curvature_fits.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/fit_centers.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/surface_neighborhoods.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

inline Vec3 nan_vector()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return Vec3(nan, nan, nan);
}

// Chen-Wu vertex normal (the manual, section "Curvature"): unit face normals weighted by the inverse
// distance from the vertex to the face centroid. Faces of zero area are
// skipped; NaN when no face is left.
template <typename PolygonMesh, typename VPM>
Vec3 chen_wu_normal(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                    const PolygonMesh& pmesh, const VPM& vpm)
{
  if(halfedge(v, pmesh) == boost::graph_traits<PolygonMesh>::null_halfedge())
    return nan_vector();
  Vec3 sum = Vec3::Zero();
  const Vec3 p = to_vec3(get(vpm, v));
  for(auto h : CGAL::halfedges_around_target(halfedge(v, pmesh), pmesh))
  {
    if(is_border(h, pmesh))
      continue;
    const Vec3 a = to_vec3(get(vpm, source(h, pmesh)));
    const Vec3 b = to_vec3(get(vpm, target(h, pmesh)));
    const Vec3 c = to_vec3(get(vpm, target(next(h, pmesh), pmesh)));
    const Vec3 cross = (b - a).cross(c - a);
    const double twice_area = cross.norm();
    const double to_centroid = ((a + b + c) / 3 - p).norm();
    if(!(twice_area > 0) || !(to_centroid > 0))
      continue;
    sum += cross / (twice_area * to_centroid);
  }
  const double len = sum.norm();
  return len > 0 ? Vec3(sum / len) : nan_vector();
}

// Which neighbors a fit uses (see `estimate_vertex_curvatures()`): a ring
// size, a radius, or candidate radii to choose from per vertex.
struct Neighborhood_rule
{
  int rings = 1;
  double radius = 0;               // used when > 0
  std::vector<double> candidates;  // increasing; used when not empty
};

// The standard uncertainties of an estimate: of H, of K, and of the
// normal's direction (radians), and the noise's part of H's; NaN where unknown.
struct Estimate_uncertainty
{
  double H = std::numeric_limits<double>::quiet_NaN();
  double H_noise = std::numeric_limits<double>::quiet_NaN();
  double K = std::numeric_limits<double>::quiet_NaN();
  double normal = std::numeric_limits<double>::quiet_NaN();
};

// What one rule gives at one vertex: the curvature and the radius of the
// neighborhood used, and their uncertainty, NaN where undefined.
struct Vertex_estimate
{
  Local_curvature curvature{nan_vector(), std::numeric_limits<double>::quiet_NaN(),
                            std::numeric_limits<double>::quiet_NaN(), nan_vector(), nan_vector()};
  double radius = std::numeric_limits<double>::quiet_NaN();
  Estimate_uncertainty uncertainty;

  bool defined() const { return std::isfinite(curvature.k1) && std::isfinite(curvature.k2); }
};

// A fit at one radius around a vertex, with its uncertainty when computed.
struct Radius_fit
{
  Local_curvature curvature{nan_vector(), std::numeric_limits<double>::quiet_NaN(),
                            std::numeric_limits<double>::quiet_NaN(), nan_vector(), nan_vector()};
  Quadric_fit_error error;
  bool defined = false;
};

// The estimates of several neighborhood rules at every vertex, sharing
// one search per vertex: the radii of all rules (fixed ones and
// candidates) are nested balls found by one search, the ring sizes nested
// rings found by another, and each fit runs on a prefix of what the search
// found. A neighborhood too small or too degenerate for the fit is widened
// (two more rings, or the radius by 1.5 twice) before the vertex is given
// up (NaN). Radii of at least `large_radius_in_edges` median edge lengths
// are fitted at centers a seventh of the smallest such radius apart and
// interpolated to the other vertices (internal/fit_centers.h); a
// center's fits are made when a vertex first needs them.
// A seventh: the interpolation is exact for curvature that varies linearly,
// and its error on curvature that varies at the fit's own scale falls with
// the square of the centers' spacing (the manual, "Neighborhoods"); 10.5
// edge lengths, so that centers are at least 1.5 edges apart. Where the
// sample spacing is known the bound is `large_radius_in_spacings` of them
// instead, a length of the whole cloud: a tile, whose surface has a median
// edge of its own, then counts the same radii as large as one run does.
// 12 spacings, like 10.5 edges of a uniform sample (1.1 spacings), is
// between the automatic rule's largest candidate and 16 spacings.
constexpr double large_radius_in_edges = 10.5;
constexpr double large_radius_in_spacings = 12;
constexpr double large_radius_per_center_spacing = 7;

// The growth of the fits' bias with the radius at one vertex, from its fits
// at several radii, in x = (r / reference)^2 with one reference radius for
// every vertex: read as a line, H(r) = H0 + c x, and as a parabola,
// H(r) = H0 + c x + d x^2, which follows a bias that bends at large radii
// (bumps as wide as the radius) where the line, weighted towards the large
// radii on noisy points, reads the flatter part. The products of the
// fitted coefficients overstate the true ones' by their covariance (the
// fits' noise); a Bias_moments keeps them less that covariance, whose mean
// over vertices is the mean of the true products. At one vertex they are
// mostly noise where the fits are noisy, and the fits' own errors move them
// (an outlying fit at the radius tilts the line): the uncertainty takes
// their mean over the vertices around (pool_bias_rates()).
struct Bias_moments
{
  static constexpr double undefined = std::numeric_limits<double>::quiet_NaN();
  double line = undefined;  // c^2 less its variance; NaN: not fitted
  // c^2, c d, d^2, each less its covariance, and the variance of d; NaN: not fitted
  std::array<double, 4> parabola = {undefined, undefined, undefined, undefined};

  // The bias's square at x, never below 0: the line's, or the parabola's
  // where that is larger, its bend stands out of its noise (d^2 above its
  // variance) and the radius is at least half the largest (x >= 1/4),
  // where the bend was measured. A noisy bend would only widen the smooth
  // surfaces' uncertainty; below half the largest radius a bend at the
  // largest ones (a ball that spans much of a small cloud) steepens the
  // parabola's slope beyond the bias; and where the curvature varies at the
  // scale of the sampling neither model holds, and the parabola can bend
  // away from a bias that the line reads.
  double squared_bias(double x) const
  {
    const double x2 = x * x;
    double bias2 = line * x2;
    if(parabola[2] > parabola[3] && x >= 0.25)
      bias2 = (std::max)(bias2, x2 * (parabola[0] + x * (2 * parabola[1] + x * parabola[2])));
    return (std::max)(0., bias2);
  }
};

struct Bias_rates
{
  Bias_moments H, K;
};

// The bias that an uncertainty adds at its radius, in quadrature.
struct Bias_widening
{
  Bias_moments H, K;  // pooled: never NaN
  double reference = 1;

  template <typename FT>
  void widen(FT& sigma_H, FT& sigma_K, double radius) const
  {
    const double x = (radius / reference) * (radius / reference);
    const double h = CGAL::to_double(sigma_H), k = CGAL::to_double(sigma_K);
    sigma_H = FT(std::sqrt(h * h + H.squared_bias(x)));
    sigma_K = FT(std::sqrt(k * k + K.squared_bias(x)));
  }
};

// The mean of some vertices' Bias_rates, each moment over the vertices
// that have it.
class Bias_pool
{
public:
  void add(const Bias_rates& rates)
  {
    add(rates.H, m_H);
    add(rates.K, m_K);
  }

  Bias_widening mean(double reference) const
  {
    Bias_widening w;
    w.H = mean(m_H);
    w.K = mean(m_K);
    w.reference = reference;
    return w;
  }

private:
  struct Sums
  {
    double line = 0;
    std::array<double, 4> parabola = {0, 0, 0, 0};
    std::size_t lines = 0, parabolas = 0;
  };

  static void add(const Bias_moments& m, Sums& sums)
  {
    if(std::isfinite(m.line))
    {
      sums.line += m.line;
      ++sums.lines;
    }
    if(std::isfinite(m.parabola[0]))
    {
      for(int i = 0; i < 4; ++i)
        sums.parabola[i] += m.parabola[i];
      ++sums.parabolas;
    }
  }

  static Bias_moments mean(const Sums& sums)
  {
    Bias_moments m;
    m.line = sums.lines > 0 ? sums.line / double(sums.lines) : 0;
    for(int i = 0; i < 4; ++i)
      m.parabola[i] = sums.parabolas > 0 ? sums.parabola[i] / double(sums.parabolas) : 0;
    return m;
  }

  Sums m_H, m_K;
};

// The bias rates pooled at vertex v: the mean of the rates of v and the
// vertices connected to it within `reach` (one radius) on the surface. A
// few spacings keep where the bias is large, bumps a few times wider
// included.
inline Bias_widening pool_bias_rates(const Vertex_graph& graph, const std::vector<Bias_rates>& rates, std::size_t v,
                                     const std::vector<double>& reach, double reference,
                                     Nested_neighborhood_search& search)
{
  search.balls(graph, v, reach);
  Bias_pool pool;
  pool.add(rates[v]);
  for(std::size_t k = 0; k < search.end(0); ++k)
    pool.add(rates[search.vertices()[k]]);
  return pool.mean(reference);
}

// The reach of pool_bias_rates(): 5 spacings, as many as 4.5 median edges
// of a uniform sample where the spacing is unknown.
constexpr double bias_pooling_radius_in_spacings = 5;
constexpr double bias_pooling_radius_in_edges = 4.5;

// A fit's curvature, radius and the standard uncertainty of its curvature
// due to the noise, for bias_rates().
struct Radius_sample
{
  double radius, H, K, se_H, se_K;
};

// Weighted least squares in the basis (1, x, x^2) or its first two terms,
// its normal equations summed one observation at a time.
template <int n>
class Weighted_polynomial_fit
{
public:
  typedef Eigen::Matrix<double, n, 1> Vector;
  typedef Eigen::Matrix<double, n, n> Matrix;

  void add(const Vector& basis, double y, double w)
  {
    m_a += w * basis * basis.transpose();
    m_b += (w * y) * basis;
  }

  // The coefficients and their covariance (the inverse of the normal
  // equations); false where these are singular.
  bool solve(Vector& coefficient, Matrix& covariance) const
  {
    if(!(m_a.determinant() > 1e-12 * m_a.diagonal().prod()))
      return false;
    covariance = m_a.inverse();
    coefficient = covariance * m_b;
    return true;
  }

private:
  Matrix m_a = Matrix::Zero();
  Vector m_b = Vector::Zero();
};

// The bias rates at one vertex from its fits at increasing radii. Under
// noise the fits at nested radii share their neighbors, so that a larger
// fit's noise is part of each smaller one's: their errors are those of
// independent increments, and the least squares weigh each change from one
// radius to the next larger by its own variance (the smaller fit's less the
// larger's, at least a twentieth of the smaller's where the uncertainties
// do not fall with the radius), the largest fit by its whole variance.
// That needs `every_radius`, the fits at all the radii of the call: where
// an automatic choice settled early (a clean sample) the few fits err by
// what the quadric misses, not by noise they share, and the line alone is
// fitted, each fit weighed by its inverse variance (a parabola through
// them bends with their errors).
inline Bias_rates bias_rates(const std::vector<Radius_sample>& samples, double reference, bool every_radius)
{
  constexpr double least_variance_share = 0.05;
  Bias_rates rates;
  for(int which = 0; which < 2; ++which)
  {
    Weighted_polynomial_fit<2> line;
    Weighted_polynomial_fit<3> parabola;
    int count = 0;
    double larger_x = 0, larger_value = 0, larger_variance = 0;
    for(auto q = samples.rbegin(); q != samples.rend(); ++q)
    {
      const double se = which == 0 ? q->se_H : q->se_K, value = which == 0 ? q->H : q->K;
      if(!(se > 0) || !std::isfinite(se) || !std::isfinite(value))
        continue;
      const double x = (q->radius / reference) * (q->radius / reference), variance = se * se;
      double w = 1 / variance, y = value;
      Eigen::Vector3d basis(1, x, x * x);
      if(count > 0)
      {
        w = 1 / (std::max)(variance - larger_variance, least_variance_share * variance);
        y = value - larger_value;
        basis = Eigen::Vector3d(0, x - larger_x, x * x - larger_x * larger_x);
      }
      if(every_radius)
      {
        line.add(basis.head<2>(), y, w);
        parabola.add(basis, y, w);
      }
      else
        line.add(Eigen::Vector2d(1, x), value, 1 / variance);
      larger_x = x;
      larger_value = value;
      larger_variance = variance;
      ++count;
    }
    Bias_moments& m = which == 0 ? rates.H : rates.K;
    Eigen::Vector2d ab;
    Eigen::Matrix2d v2;
    if(count >= 2 && line.solve(ab, v2))
      m.line = ab(1) * ab(1) - v2(1, 1);
    Eigen::Vector3d abc;
    Eigen::Matrix3d v3;
    if(every_radius && count >= 3 && parabola.solve(abc, v3))
      m.parabola = {abc(1) * abc(1) - v3(1, 1), abc(1) * abc(2) - v3(1, 2), abc(2) * abc(2) - v3(2, 2), v3(2, 2)};
  }
  return rates;
}

// Student's t quantile 0.975 with `nu` degrees of freedom over the normal
// law's: the factor by which a standard uncertainty whose variance was
// estimated with `nu` degrees of freedom widens so that twice it covers as
// often as it would with the variance known (an expanded uncertainty's
// coverage factor). Interpolated in a table (within 2%) from 0.5 to 1024
// degrees, the expansion's first term above; infinite at 0.5 or less.
// A table rather than Boost.Math's quantile, whose series assert under
// CGAL's -frounding-math.
inline double t_coverage_factor(double nu)
{
  // t_0.975(2^(k / 4 - 1)) / z_0.975 for k = 0, ..., 44
  static constexpr double table[45] = {
    83.9595, 36.0169, 18.0072, 10.2387, 6.48288, 4.48852, 3.34464, 2.64555, 2.19527, 1.8923, 1.6809, 1.52881,
    1.41658, 1.33197, 1.26704, 1.21645, 1.17655, 1.14475, 1.11918, 1.09848, 1.0816, 1.06779, 1.05642, 1.04704,
    1.03927, 1.03282, 1.02746, 1.023, 1.01927, 1.01615, 1.01355, 1.01137, 1.00954, 1.00801, 1.00673, 1.00565,
    1.00475, 1.00399, 1.00335, 1.00282, 1.00237, 1.00199, 1.00167, 1.00141, 1.00118};
  constexpr double z = 1.959963984540054;
  if(!(nu > 0.5))
    return std::numeric_limits<double>::infinity();
  const double x = (std::log2(nu) + 1) * 4;
  if(x >= 44)
    return 1 + (z * z + 1) / (4 * nu);
  const int k = int(x);
  return table[k] * std::pow(table[k + 1] / table[k], x - k);  // linear in the logarithms
}

// Whether fit_uncertainty() widens the noise's part for the residual
// variance's few degrees of freedom.
enum class Residual_degrees { COUNTED, IGNORED };

// How the points were smoothed before the surface was made: `passes` jet
// projections averaging the noise over `reach` (0: not smoothed).
struct Noise_smoothing
{
  double reach = 0;
  int passes = 0;
};

// The share of the sample's noise (as a standard deviation) that a fit of
// radius `radius` sees on smoothed points. Below the reach the noise is a
// smooth field whose curvature error grows as 1 / r^2 rather than
// independent noise's 1 / r^3, a share of (r / reach)^2; above it the share
// levels off at 0.93 (one jet pass keeps a little less than the whole
// noise at any scale). A second pass smooths the field further: below 0.45
// of the reach its share falls in proportion to the radius as well. Both
// measured on noisy spheres against the errors (the manual, "Uncertainty").
inline double smoothed_noise_share(double radius, const Noise_smoothing& smoothing)
{
  if(!(smoothing.reach > 0) || smoothing.passes <= 0)
    return 1;
  constexpr double plateau = 0.93, second_pass_knee = 0.45;
  const double x = radius / smoothing.reach, x2 = x * x;
  const double level = x2 / plateau;
  double share = x2 / std::sqrt(std::sqrt(1 + level * level * level * level));
  if(smoothing.passes > 1)
    share *= (std::min)(1., x / second_pass_knee);
  return share;
}

// The uncertainty of a fit at radius `radius` due to the noise, to which
// Bias_widening adds the bias's in quadrature. The noise is the
// sample's, `sample_noise`, as smoothed_noise_share() says a fit sees it,
// and the residuals' beyond it: on points that were not smoothed the
// residuals hold the sample's noise, and only their excess over it (what
// the quadric misses) adds; on smoothed points they hold what smoothing
// left, independent of the smooth field, and add whole.
// With `Residual_degrees::COUNTED` the noise's part is widened by
// t_coverage_factor() of its effective degrees of freedom (Welch and
// Satterthwaite's: the sample's noise is known, the residuals' part
// estimated from the fit's few): a 2-spacing fit has about three, and its
// errors over a residual standard deviation have the long tails of
// Student's t.
inline Estimate_uncertainty fit_uncertainty(const Quadric_fit_error& e, double radius, double sample_noise,
                                            const Noise_smoothing& smoothing, Residual_degrees residual_degrees)
{
  Estimate_uncertainty u;
  if(!(e.per_noise > 0))
    return u;
  const double seen = smoothed_noise_share(radius, smoothing) * sample_noise;
  const double residual = smoothing.passes > 0 ? e.noise * e.noise
                                               : (std::max)(0., e.noise * e.noise - sample_noise * sample_noise);
  double noise = std::sqrt(seen * seen + residual);
  if(residual_degrees == Residual_degrees::COUNTED && residual > 0 && std::isfinite(residual))
  {
    const double share = noise * noise / residual;  // the whole variance over the residuals' part
    noise *= t_coverage_factor(e.degrees_of_freedom * share * share);
  }
  const double se_H = noise * e.per_noise;
  // the first-order variance of K read with the fitted coefficients
  // overstates it by twice its second-order part, which it counts once
  const double second = noise * noise * e.per_squared_noise_K, first = noise * e.per_noise_K;
  const double se_K = std::sqrt((std::max)(first * first - second * second, second * second));
  u.H = se_H;
  u.H_noise = se_H;
  u.K = se_K;
  u.normal = noise * e.per_noise_normal;
  return u;
}

// The uncertainty of an automatic rule's choice `chosen` among `candidates`:
// the fit's, and in quadrature half the mean square of the bias that each
// adjacent candidate's change implies at the chosen radius, the change
// scaled by r^2 / |r_j^2 - r^2| as a bias growing with r^2 would be (a
// radius chosen for its least estimated error is where the estimate of that
// error is most often too small, and the step to the next candidate shows
// the bias that the fit over all radii smooths away where the curvature
// varies at the radius's scale).
inline Estimate_uncertainty choice_uncertainty(const std::vector<Candidate_fit>& candidates,
                                               const Candidate_fit& chosen, Estimate_uncertainty u)
{
  const std::size_t i = std::size_t(&chosen - candidates.data());
  const double r2 = chosen.radius * chosen.radius;
  double dH = 0, dK = 0;
  int count = 0;
  for(std::size_t j : {i - 1, i + 1})
  {
    if(j >= candidates.size())  // i - 1 wraps around at the first
      continue;
    const Local_curvature& a = chosen.curvature;
    const Local_curvature& b = candidates[j].curvature;
    const double scale = r2 / std::abs(candidates[j].radius * candidates[j].radius - r2);
    const double h = scale * (a.k1 + a.k2 - b.k1 - b.k2) / 2, k = scale * (a.k1 * a.k2 - b.k1 * b.k2);
    if(!std::isfinite(h) || !std::isfinite(k))
      continue;
    dH += h * h;
    dK += k * k;
    ++count;
  }
  if(count > 0)
  {
    u.H = std::sqrt(u.H * u.H + dH / (2 * count));
    u.K = std::sqrt(u.K * u.K + dK / (2 * count));
  }
  return u;
}

class Curvature_estimation
{
public:
  // Where the prepared neighbors of the levels up to one end: how many
  // neighbors, and how many of the quadric fit's shells hold them.
  struct Level_end
  {
    std::size_t neighbors = 0, shells = 0;
  };

  // Per thread: the searches and the fit's buffers.
  struct Workspace
  {
    explicit Workspace(std::size_t number_of_vertices) : search(number_of_vertices) {}
    Nested_neighborhood_search search;
    std::vector<Quadric_shell> shells;                    // by level, then shell
    std::array<int, number_of_quadric_shells> shell_of;  // in the current level
    std::vector<Neighbor> neighbors;
    // where prepare() stopped: the vertices prepared, their last level
    // and where it ends
    struct Prepared
    {
      std::size_t vertices = 0, level = 0;
      Level_end end;
    };
    Prepared prepared;
    std::vector<Radius_fit> fits;  // by radius
    std::vector<Candidate_fit> candidates;
    std::vector<Radius_sample> samples;
    // the centers around the vertex: where, whether fitted at the
    // current radius and at the previous one, their fits, their weights
    std::vector<Vec3> around;
    std::vector<char> defined, defined_before;
    std::vector<const Center_fit*> around_fits;
    Center_weights weights;
  };

  // `normals`: the Chen-Wu normal of each vertex of `graph`; `center_keys`:
  // by vertex, the keys that order the choice of the centers (Fit_centers).
  // Without keys every radius is fitted at every vertex (the estimate at
  // one vertex, whose graph is only what its search reaches).
  // `sample_spacing`: 0 where unknown; `smoothing`: see fit_uncertainty().
  Curvature_estimation(const Vertex_graph& graph, const std::vector<Vec3>& normals,
                       const std::vector<Neighborhood_rule>& rules, Curvature_estimator estimator,
                       double sample_noise, double sample_spacing, const Noise_smoothing& smoothing,
                       const std::vector<std::uint64_t>* center_keys)
    : m_graph(graph), m_normals(normals), m_rules(rules), m_estimator(estimator), m_sample_noise(sample_noise),
      m_smoothing(smoothing)
  {
    for(const Neighborhood_rule& rule : rules)
    {
      if(!rule.candidates.empty())
        m_radii.insert(m_radii.end(), rule.candidates.begin(), rule.candidates.end());
      else if(rule.radius > 0)
        m_radii.push_back(rule.radius);
      else
        m_rings = (std::max)(m_rings, std::size_t(rule.rings) + 2);
    }
    std::sort(m_radii.begin(), m_radii.end());
    m_radii.erase(std::unique(m_radii.begin(), m_radii.end()), m_radii.end());
    // every fit's error: the automatic rules weigh it, and every estimate
    // reports its uncertainty
    m_with_error.assign(m_radii.size(), 1);

    if(!m_radii.empty())
      m_bias_pooling_radius = sample_spacing > 0 ? bias_pooling_radius_in_spacings * sample_spacing
                                                 : bias_pooling_radius_in_edges * median_edge_length(graph);

    m_fine_levels = m_radii.size();
    const bool at_centers = center_keys && estimator == QUADRIC_FIT && !m_radii.empty();
    const double large = !at_centers ? 0.
                         : sample_spacing > 0 ? large_radius_in_spacings * sample_spacing
                                              : large_radius_in_edges * median_edge_length(graph);
    if(large > 0)
    {
      m_fine_levels = radius_level(large);
      if(m_fine_levels < m_radii.size())
      {
        const double spacing = m_radii[m_fine_levels] / large_radius_per_center_spacing;
        m_centers = std::make_shared<const Fit_centers>(graph, spacing, *center_keys);
        // the centers around a vertex: its own, within `spacing`, and
        // those adjacent to it, up to about three times that; the weights
        // fade at 1.5 times `spacing` (less smoothing)
        m_center_reach = 1.5 * spacing;
      }
    }
    m_fine_radii.assign(m_radii.begin(), m_radii.begin() + std::ptrdiff_t(m_fine_levels));

    // the fine radii searched at every vertex: those of the fixed rules,
    // and the candidates that measure the noise; the others only where an
    // automatic choice needs them
    m_first_levels = m_fine_levels;
    bool automatic = false;
    std::size_t needed = 0;
    for(const Neighborhood_rule& rule : rules)
      if(!rule.candidates.empty())
      {
        automatic = true;
        const std::size_t measuring = (std::min)(rule.candidates.size(), noise_measuring_radii);
        needed = (std::max)(needed, radius_level(rule.candidates[measuring - 1]) + 1);
      }
      else if(rule.radius > 0 && radius_level(rule.radius) < m_fine_levels)
        needed = (std::max)(needed, radius_level(rule.radius) + 1);
      else if(rule.radius > 0)  // a large radius, from the centers
        m_fixed_large_levels = (std::max)(m_fixed_large_levels, radius_level(rule.radius) - m_fine_levels + 1);
    if(automatic)
      m_first_levels = (std::min)(needed, m_fine_levels);

    m_large_radii.assign(m_radii.begin() + std::ptrdiff_t(m_fine_levels), m_radii.end());
    if(m_centers)
    {
      m_center_fits.assign(m_centers->size() * m_large_radii.size(), Center_fit());
      m_center_state.reset(new std::atomic<std::uint32_t>[m_centers->size()]);
      for(std::size_t c = 0; c < m_centers->size(); ++c)
        m_center_state[c].store(0, std::memory_order_relaxed);
    }
  }

  Workspace make_workspace() const { return Workspace(m_graph.size()); }

  // Whether the rules fit balls, whose estimates' uncertainty adds a bias
  // (Bias_widening) to what estimate() gives.
  bool fits_balls() const { return !m_radii.empty(); }

  // The length within which pool_bias_rates() averages.
  double bias_pooling_radius() const { return m_bias_pooling_radius; }

  // The unit of the bias rates' radii: the largest radius fitted.
  double bias_reference_radius() const { return m_radii.empty() ? 1 : m_radii.back(); }

  // The estimates at vertex v, one per rule, into out[0, rules.size()),
  // their uncertainty the noise's only; the bias rates of the fits at v
  // into `rates` if given.
  void estimate(std::size_t v, Workspace& ws, Vertex_estimate* out, Bias_rates* rates = nullptr) const
  {
    for(std::size_t r = 0; r < m_rules.size(); ++r)
      out[r] = Vertex_estimate();
    const Vec3& n = m_normals[v];
    if(!std::isfinite(n.x()))
      return;
    for(std::size_t r = 0; r < m_rules.size(); ++r)
      out[r].curvature.normal = n;
    if(!m_radii.empty())
      estimate_in_balls(v, ws, out, rates);
    if(m_rings > 0)
      estimate_in_rings(v, ws, out);
  }

private:
  std::size_t radius_level(double r) const
  {
    return std::size_t(std::lower_bound(m_radii.begin(), m_radii.end(), r) - m_radii.begin());
  }

  // What the fit needs of each vertex the search found (in coordinates
  // divided by `length` for the quadric fit, in shells level by level);
  // coincident vertices carry no direction and are left out. `ends[j]` is
  // where level j ends.
  void prepare(std::size_t v, const Tangent_frame& f, double length, std::size_t levels, Workspace& ws,
               std::vector<Level_end>& ends) const
  {
    ws.shells.clear();
    ws.neighbors.clear();
    ws.shell_of.fill(-1);
    ends.assign(levels, Level_end());
    ws.prepared = Workspace::Prepared();
    prepare_more(v, f, length, ws, ends);
  }

  // prepare() of the levels that the search found since.
  void prepare_more(std::size_t v, const Tangent_frame& f, double length, Workspace& ws,
                    std::vector<Level_end>& ends) const
  {
    const Vec3& p = m_graph.points[v];
    const std::vector<Vertex_graph::Index>& found = ws.search.vertices();
    const std::vector<double>& squared_distance = ws.search.squared_distances();
    const double squared_length = length * length, inverse_length = 1 / length;
    Level_end end = ws.prepared.end;
    std::size_t level = ws.prepared.level;
    for(std::size_t k = ws.prepared.vertices; k < found.size(); ++k)
    {
      for(; ws.search.end(level) <= k; ++level)
      {
        ends[level] = end;
        ws.shell_of.fill(-1);  // a level's shells are its own
      }
      const double d2 = squared_distance[k];
      if(!(d2 > 0))
        continue;
      const Vec3 offset = m_graph.points[found[k]] - p;
      if(m_estimator == QUADRIC_FIT)
      {
        int& shell = ws.shell_of[std::size_t(quadric_shell_index(d2, squared_length))];
        if(shell < 0)
        {
          shell = int(ws.shells.size());
          ws.shells.emplace_back();
        }
        const Vec3 o = offset * inverse_length;
        ws.shells[std::size_t(shell)].add(o.dot(f.e1), o.dot(f.e2), o.dot(f.n), d2);
        end.shells = ws.shells.size();
        ++end.neighbors;
        continue;
      }
      const Vec3& n_u = m_normals[found[k]];
      if(std::isfinite(n_u.x()))
      {
        ws.neighbors.push_back(Neighbor{offset, normal_curvature(offset, f.n, n_u)});
        ++end.neighbors;
      }
    }
    for(; level < ws.search.levels_found(); ++level)
    {
      ends[level] = end;
      ws.shell_of.fill(-1);
    }
    ws.prepared = Workspace::Prepared{found.size(), level, end};
  }

  // The fit over the prepared neighbors up to `end`, fading at `fade`,
  // with its uncertainty when `with_error`.
  void fit(const Tangent_frame& f, const Level_end& end, double fade, double length, Workspace& ws,
           bool with_error, Radius_fit& out) const
  {
    bool ok = false;
    if(m_estimator == QUADRIC_FIT)
      ok = quadric_fit(f, ws.shells.data(), end.shells, end.neighbors, fade, length, out.curvature,
                       with_error ? &out.error : nullptr);
    else
    {
      const std::vector<Neighbor> prefix(ws.neighbors.begin(), ws.neighbors.begin() + std::ptrdiff_t(end.neighbors));
      ok = m_estimator == PAPER_EULER_FIT ? paper_euler_fit(f.n, prefix, out.curvature)
                                          : euler_least_squares_fit(f.n, prefix, out.curvature);
    }
    out.defined = ok && std::isfinite(out.curvature.k1) && std::isfinite(out.curvature.k2);
  }

  // Makes the fits at the first `levels` large radii at center c, unless
  // made: by one thread, while the others that need them wait. A center's
  // state is how many are made, with `busy` set while a thread makes more;
  // the fits below that count are read without a lock. The fits do not
  // depend on how many levels the search found, so which vertex asks
  // first, on which thread, changes nothing.
  void fit_at_center(std::size_t c, std::size_t levels, Workspace& ws) const
  {
    constexpr std::uint32_t busy = std::uint32_t(1) << 31;
    std::atomic<std::uint32_t>& state = m_center_state[c];
    std::uint32_t s = state.load(std::memory_order_acquire);
    for(;;)
    {
      if((s & ~busy) >= levels)
        return;
      if(!(s & busy) && state.compare_exchange_weak(s, s | busy, std::memory_order_acquire))
        break;
      std::this_thread::yield();
      s = state.load(std::memory_order_acquire);
    }
    const std::size_t made = s, large = m_large_radii.size(), v = m_centers->vertex[c];
    try
    {
      if(std::isfinite(m_normals[v].x()))
      {
        const Tangent_frame f = frame_from_normal(m_normals[v]);
        std::vector<Level_end> ends;
        ws.search.balls(m_graph, v, m_large_radii, levels);
        prepare(v, f, m_radii.back(), large, ws, ends);
        for(std::size_t j = made; j < levels; ++j)
        {
          Radius_fit q;
          fit(f, ends[j], m_large_radii[j], m_radii.back(), ws, m_with_error[m_fine_levels + j] != 0, q);
          if(q.defined)
            m_center_fits[c * large + j].set(q.curvature, q.error);
        }
      }
    }
    catch(...)
    {
      state.store(s, std::memory_order_release);  // not busy: a thread that waits takes over
      throw;
    }
    state.store(std::uint32_t(levels), std::memory_order_release);
  }

  // The fits at the first `levels` large radii interpolated from the
  // centers around v; the weights are computed again only where the
  // centers with a fit change.
  void interpolate_large_radii(std::size_t v, std::size_t levels, Workspace& ws) const
  {
    const std::size_t large = m_large_radii.size();
    const std::size_t own = m_centers->center_of[v];
    fit_at_center(own, levels, ws);
    ws.around.clear();
    ws.around.push_back(m_graph.points[m_centers->vertex[own]]);
    for(std::size_t e = m_centers->first[own]; e < m_centers->first[own + 1]; ++e)
    {
      fit_at_center(m_centers->adjacent[e], levels, ws);
      ws.around.push_back(m_graph.points[m_centers->vertex[m_centers->adjacent[e]]]);
    }
    bool weighted = false;
    for(std::size_t j = 0; j < levels; ++j)
    {
      ws.around_fits.clear();
      ws.defined.clear();
      ws.around_fits.push_back(&m_center_fits[own * large + j]);
      for(std::size_t e = m_centers->first[own]; e < m_centers->first[own + 1]; ++e)
        ws.around_fits.push_back(&m_center_fits[m_centers->adjacent[e] * large + j]);
      for(const Center_fit* fit : ws.around_fits)
        ws.defined.push_back(fit->defined ? 1 : 0);
      if(j == 0 || ws.defined != ws.defined_before)
        weighted = ws.weights.compute(m_graph.points[v], m_normals[v], ws.around, ws.defined, m_center_reach);
      std::swap(ws.defined, ws.defined_before);
      Radius_fit& out = ws.fits[m_fine_levels + j];
      out.defined = weighted && interpolate_center_fits(m_normals[v], ws.around_fits, ws.weights, out.curvature,
                                                        out.error);
    }
  }

  // The defined fits of an automatic rule's candidates below level
  // `levels`, in ws.candidates.
  void candidates_below(const Neighborhood_rule& rule, std::size_t levels, Workspace& ws) const
  {
    ws.candidates.clear();
    for(double radius : rule.candidates)
    {
      const std::size_t level = radius_level(radius);
      if(level >= levels)
        break;
      const Radius_fit& q = ws.fits[level];
      if(q.defined)
        ws.candidates.push_back(Candidate_fit{q.curvature, q.error, radius});
    }
  }

  // Whether every automatic rule's choice is settled by the fits below
  // level `levels` (choice_is_settled()).
  bool choices_are_settled(std::size_t levels, Workspace& ws) const
  {
    for(const Neighborhood_rule& rule : m_rules)
      if(!rule.candidates.empty())
      {
        candidates_below(rule, levels, ws);
        if(!choice_is_settled(ws.candidates, m_sample_noise))
          return false;
      }
    return true;
  }

  void estimate_in_balls(std::size_t v, Workspace& ws, Vertex_estimate* out, Bias_rates* rates) const
  {
    const Tangent_frame f = frame_from_normal(m_normals[v]);
    std::vector<Level_end> ends;
    ws.fits.assign(m_radii.size(), Radius_fit());
    // the automatic rules choose among the radii below this level: all of
    // them, or those that settled their choices, the larger ones left
    // unsearched (a clean sample settles at a few spacings)
    std::size_t choice_levels = m_radii.size();
    if(m_fine_levels > 0)
    {
      // the shells' unit is the largest radius whether or not it is fitted
      // here, so that the small radii's fits do not depend on it
      const double length = m_radii.back();
      std::size_t levels = m_first_levels;
      ws.search.balls(m_graph, v, m_fine_radii, levels);
      prepare(v, f, length, m_fine_levels, ws, ends);
      for(std::size_t j = 0; j < levels; ++j)
        fit(f, ends[j], m_radii[j], length, ws, m_with_error[j] != 0, ws.fits[j]);
      while(levels < m_fine_levels && !choices_are_settled(levels, ws))
      {
        ws.search.more_balls(m_graph, levels + 1);
        prepare_more(v, f, length, ws, ends);
        fit(f, ends[levels], m_radii[levels], length, ws, m_with_error[levels] != 0, ws.fits[levels]);
        ++levels;
      }
      if(levels < m_fine_levels)
        choice_levels = levels;
    }
    if(m_centers)
      interpolate_large_radii(v, choice_levels < m_radii.size() ? m_fixed_large_levels : m_large_radii.size(), ws);

    // the growth of the bias, from the fits made at this vertex
    ws.samples.clear();
    for(std::size_t j = 0; j < m_radii.size(); ++j)
    {
      const Radius_fit& q = ws.fits[j];
      if(!q.defined || !(q.error.per_noise > 0))
        continue;
      const Estimate_uncertainty u =
        fit_uncertainty(q.error, m_radii[j], m_sample_noise, m_smoothing, Residual_degrees::COUNTED);
      ws.samples.push_back(Radius_sample{m_radii[j], (q.curvature.k1 + q.curvature.k2) / 2,
                                         q.curvature.k1 * q.curvature.k2, u.H, u.K});
    }
    if(rates)
      *rates = bias_rates(ws.samples, bias_reference_radius(), ws.samples.size() == m_radii.size());
    std::vector<std::size_t> to_widen;
    for(std::size_t r = 0; r < m_rules.size(); ++r)
    {
      const Neighborhood_rule& rule = m_rules[r];
      if(!rule.candidates.empty())
      {
        candidates_below(rule, choice_levels, ws);
        if(!ws.candidates.empty())
        {
          const Candidate_fit& chosen = choose_by_least_squared_error(ws.candidates, m_sample_noise);
          // the change to the adjacent candidates already shows how far the
          // chosen fit's residuals miss; widened as well, the automatic
          // values would be within two sigma at 99% of the points
          out[r] = Vertex_estimate{chosen.curvature, chosen.radius,
                                   choice_uncertainty(ws.candidates, chosen,
                                     fit_uncertainty(chosen.error, chosen.radius, m_sample_noise, m_smoothing,
                                                     Residual_degrees::IGNORED))};
        }
      }
      else if(rule.radius > 0)
      {
        const Radius_fit& q = ws.fits[radius_level(rule.radius)];
        if(q.defined)
          out[r] = Vertex_estimate{q.curvature, rule.radius,
                                   fit_uncertainty(q.error, rule.radius, m_sample_noise, m_smoothing,
                                                   Residual_degrees::COUNTED)};
        else
          to_widen.push_back(r);
      }
    }
    // the wider balls of the few vertices that need them, last: their
    // searches replace the shared one; a large radius is first fitted at
    // the vertex itself, as its centers had no value to give
    for(std::size_t r : to_widen)
      for(int widening = radius_level(m_rules[r].radius) < m_fine_levels ? 1 : 0;
          widening <= 2 && !out[r].defined(); ++widening)
      {
        const double radius = m_rules[r].radius * std::pow(1.5, widening);
        ws.search.balls(m_graph, v, std::vector<double>(1, radius));
        prepare(v, f, radius, 1, ws, ends);
        Radius_fit q;
        fit(f, ends[0], radius, radius, ws, true, q);
        if(q.defined)
          out[r] = Vertex_estimate{q.curvature, radius, fit_uncertainty(q.error, radius, m_sample_noise, m_smoothing,
                                                                        Residual_degrees::COUNTED)};
      }
  }

  // Rings up to the largest ring size plus two (the widening), fitted on
  // each prefix; a ring's fit fades at 1.5 times the distance of its
  // farthest neighbor, which is the radius reported.
  void estimate_in_rings(std::size_t v, Workspace& ws, Vertex_estimate* out) const
  {
    const Tangent_frame f = frame_from_normal(m_normals[v]);
    ws.search.rings(m_graph, v, m_rings);
    const std::vector<double>& squared_distance = ws.search.squared_distances();
    double length = 0;
    for(double d2 : squared_distance)
      length = (std::max)(length, d2);
    length = std::sqrt(length);
    if(!(length > 0))
      return;
    std::vector<Level_end> ends;
    prepare(v, f, length, m_rings, ws, ends);
    for(std::size_t r = 0; r < m_rules.size(); ++r)
    {
      const Neighborhood_rule& rule = m_rules[r];
      if(!rule.candidates.empty() || rule.radius > 0)
        continue;
      for(int widening = 0; widening <= 2 && !out[r].defined(); ++widening)
      {
        const std::size_t ring = std::size_t(rule.rings + widening) - 1;
        double reach = 0;
        for(std::size_t k = 0; k < ws.search.end(ring); ++k)
          reach = (std::max)(reach, squared_distance[k]);
        reach = std::sqrt(reach);
        Radius_fit q;
        fit(f, ends[ring], reach, length, ws, true, q);
        if(q.defined)
          out[r] = Vertex_estimate{q.curvature, reach, fit_uncertainty(q.error, reach, m_sample_noise, m_smoothing,
                                                                       Residual_degrees::COUNTED)};
      }
    }
  }

  const Vertex_graph& m_graph;
  const std::vector<Vec3>& m_normals;
  std::vector<Neighborhood_rule> m_rules;
  Curvature_estimator m_estimator;
  double m_sample_noise;           // of the points before any denoising, model units; 0 when unknown
  double m_bias_pooling_radius = 0;
  Noise_smoothing m_smoothing;     // see fit_uncertainty()
  std::vector<double> m_radii;     // every rule's radii, increasing
  std::vector<char> m_with_error;  // by radius: whether its fits compute their error
  std::size_t m_rings = 0;         // rings searched: the largest ring size plus two
  // radii [0, m_fine_levels) are fitted at every vertex, the others at
  // the centers
  std::size_t m_fine_levels = 0;
  std::vector<double> m_fine_radii;
  std::size_t m_first_levels = 0;  // of the fine radii, searched at every vertex
  std::shared_ptr<const Fit_centers> m_centers;
  double m_center_reach = 0;
  std::vector<double> m_large_radii;
  std::size_t m_fixed_large_levels = 0;  // the large radii that the fixed rules need, a prefix
  // by center, then large radius; made as vertices need them (fit_at_center())
  mutable std::vector<Center_fit> m_center_fits;
  std::unique_ptr<std::atomic<std::uint32_t>[]> m_center_state;
};

// estimate_at_every_vertex() of rules that share one pass: the estimates
// first, then their uncertainty widened by the bias rates pooled around
// each vertex, which needs every vertex's own.
template <typename ConcurrencyTag, typename Write, typename Widen>
void estimate_in_one_pass(const Vertex_graph& graph, const std::vector<Vec3>& normals,
                          const std::vector<Neighborhood_rule>& rules, Curvature_estimator estimator,
                          double sample_noise, double sample_spacing, const Noise_smoothing& smoothing,
                          const std::vector<std::uint64_t>& center_keys, Write write, Widen widen)
{
  Curvature_estimation estimation(graph, normals, rules, estimator, sample_noise, sample_spacing, smoothing,
                                  &center_keys);
  typedef Curvature_estimation::Workspace Workspace;
  struct Per_thread
  {
    Workspace workspace;
    std::vector<Vertex_estimate> estimates;
  };
  std::vector<Bias_rates> rates(estimation.fits_balls() ? graph.size() : 0);
  for_each_index<ConcurrencyTag>(graph.size(),
    [&]() { return Per_thread{estimation.make_workspace(), std::vector<Vertex_estimate>(rules.size())}; },
    [&](std::size_t v, Per_thread& thread) {
      estimation.estimate(v, thread.workspace, thread.estimates.data(), rates.empty() ? nullptr : &rates[v]);
      for(std::size_t r = 0; r < rules.size(); ++r)
        write(r, v, thread.estimates[r]);
    });
  if(rates.empty())
    return;
  const std::vector<double> reach(1, estimation.bias_pooling_radius());
  for_each_index<ConcurrencyTag>(graph.size(), [&]() { return Nested_neighborhood_search(graph.size()); },
    [&](std::size_t v, Nested_neighborhood_search& search) {
      const Bias_widening bias = pool_bias_rates(graph, rates, v, reach, estimation.bias_reference_radius(), search);
      for(std::size_t r = 0; r < rules.size(); ++r)
        if(rules[r].radius > 0 || !rules[r].candidates.empty())
          widen(r, v, bias);
    });
}

// Estimates of every rule at every vertex of `graph`, each handed to
// `write(rule, vertex index, estimate)` once, from TBB's threads as the tag
// says: the callers keep them in their own form, without a copy of every
// layer in this one. Once every vertex is written, `widen(rule, vertex
// index, bias)` asks for the uncertainty of the estimates in balls to be
// widened by `bias` (Bias_widening::widen()).
// The rules share one pass (one search per vertex) where that leaves the
// automatic rules' values as they are alone: the fits at the candidate
// radii sum the same shells in the same units with the fixed radii among
// the candidates, not with others, which then get a pass of their own.
template <typename ConcurrencyTag, typename Write, typename Widen>
void estimate_at_every_vertex(const Vertex_graph& graph, const std::vector<Vec3>& normals,
                              const std::vector<Neighborhood_rule>& rules, Curvature_estimator estimator,
                              double sample_noise, double sample_spacing, const Noise_smoothing& smoothing,
                              const std::vector<std::uint64_t>& center_keys, Write write, Widen widen)
{
  std::vector<double> candidates;
  for(const Neighborhood_rule& rule : rules)
    candidates.insert(candidates.end(), rule.candidates.begin(), rule.candidates.end());
  std::vector<std::size_t> shared, apart;  // rule indices
  for(std::size_t r = 0; r < rules.size(); ++r)
  {
    const bool alone = !candidates.empty() && rules[r].candidates.empty() && rules[r].radius > 0
                       && std::find(candidates.begin(), candidates.end(), rules[r].radius) == candidates.end();
    (alone ? apart : shared).push_back(r);
  }
  for(const std::vector<std::size_t>* pass : {&shared, &apart})
  {
    if(pass->empty())
      continue;
    std::vector<Neighborhood_rule> pass_rules;
    for(std::size_t r : *pass)
      pass_rules.push_back(rules[r]);
    estimate_in_one_pass<ConcurrencyTag>(graph, normals, pass_rules, estimator, sample_noise, sample_spacing,
                                         smoothing, center_keys,
                                         [&](std::size_t k, std::size_t v, const Vertex_estimate& e) {
                                           write((*pass)[k], v, e);
                                         },
                                         [&](std::size_t k, std::size_t v, const Bias_widening& bias) {
                                           widen((*pass)[k], v, bias);
                                         });
  }
}

// The Chen-Wu normal of every vertex, by vertex index.
template <typename ConcurrencyTag, typename PolygonMesh, typename VPM, typename VertexIndexMap>
std::vector<Vec3> chen_wu_normals(const PolygonMesh& pmesh, const VPM& vpm, const VertexIndexMap& vertex_index)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> by_index(num_vertices(pmesh));
  for(vertex_descriptor v : vertices(pmesh))
    by_index[get(vertex_index, v)] = v;
  std::vector<Vec3> normals(by_index.size());
  for_each_index<ConcurrencyTag>(by_index.size(), []() { return 0; },
    [&](std::size_t i, int) { normals[i] = chen_wu_normal(by_index[i], pmesh, vpm); });
  return normals;
}

// Throws std::invalid_argument on a rule that `estimate_vertex_curvatures()` rejects.
inline void check_neighborhood_rule(const Neighborhood_rule& rule, Curvature_estimator estimator)
{
  const std::string where = "estimate_vertex_curvatures: ";
  if(rule.rings < 1)
    throw std::invalid_argument(where + "ring size " + std::to_string(rule.rings) + " is below 1");
  if(!(rule.radius >= 0) || !std::isfinite(rule.radius))
    throw std::invalid_argument(where + "the neighborhood radius must be finite and positive");
  for(std::size_t i = 0; i < rule.candidates.size(); ++i)
    if(!(rule.candidates[i] > 0) || !std::isfinite(rule.candidates[i])
       || (i > 0 && !(rule.candidates[i] > rule.candidates[i - 1])))
      throw std::invalid_argument(where + "the candidate radii must be finite, positive and increasing");
  if(!rule.candidates.empty() && estimator != QUADRIC_FIT)
    throw std::invalid_argument(where + "choosing among candidate radii needs the QUADRIC_FIT estimator");
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CURVATURE_ESTIMATION_H
