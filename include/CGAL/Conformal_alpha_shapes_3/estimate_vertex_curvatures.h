// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_VERTEX_CURVATURES_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_VERTEX_CURVATURES_H

// Over 400 lines: one public function (two overloads) with 150 lines of
// documentation, and the per-vertex neighbourhoods it offers (rings, a ball
// cut to the surface, the automatic choice among radii) with the fit that
// runs on them; the fits themselves are in internal/curvature_fits.h.

#include <CGAL/Conformal_alpha_shapes_3/internal/curvature_fits.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <queue>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/// \ingroup PkgConformalAlphaShapes3Curvature
/// Principal curvatures and directions at a vertex, as CGAL 6's
/// `Polygon_mesh_processing::Principal_curvatures_and_directions`:
/// `max_curvature >= min_curvature`, unit directions tangent to the surface,
/// right-handed with the normal: `min_direction` is the cross product of
/// the normal and `max_direction`.
template <typename GT>
struct Principal_curvatures_and_directions
{
  // NaN until set: an estimate that is not made reads as undefined
  typename GT::FT max_curvature = std::numeric_limits<double>::quiet_NaN();
  typename GT::FT min_curvature = std::numeric_limits<double>::quiet_NaN();
  typename GT::Vector_3 max_direction = typename GT::Vector_3(std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
  typename GT::Vector_3 min_direction = max_direction;
};

/// \ingroup PkgConformalAlphaShapes3Curvature
/// How `estimate_vertex_curvatures()` estimates curvature at a vertex from
/// its k-ring. See the manual for the measured accuracy of each.
enum Curvature_estimator
{
  /// The paper's method: Chen-Wu vertex normals, a normal curvature per
  /// neighbour from normal differences, and the Euler fit with `a` fixed to
  /// the largest normal curvature and `b`, `c` by least squares.
  PAPER_EULER_FIT,
  /// The same normal curvatures, with all three Euler coefficients fitted by
  /// least squares.
  EULER_LEAST_SQUARES_FIT,
  /// A quadric height function fitted by least squares to the positions of
  /// the k-ring in the frame of the Chen-Wu normal, with linear terms; the
  /// output normal is the fitted surface's. The default.
  QUADRIC_FIT
};

namespace internal {

// The vertex type of a mesh; no type for a parameter pack, so that the
// single-vertex overload drops out of `estimate_vertex_curvatures(mesh, np)`.
template <typename PolygonMesh, bool = Is_named_function_parameters<PolygonMesh>::value>
struct Vertex_of { typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor type; };
template <typename PolygonMesh>
struct Vertex_of<PolygonMesh, true> {};

inline Vec3 nan_vector()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return Vec3(nan, nan, nan);
}

template <typename Point>
Vec3 to_vec3(const Point& p)
{
  return Vec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// Chen-Wu vertex normal (the manual, section "Curvature"): unit face normals weighted by the inverse
// distance from the vertex to the face centroid. Faces of zero area are
// skipped; NaN when no face is left.
template <typename PolygonMesh, typename VPM>
Vec3 chen_wu_normal(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                    const PolygonMesh& pmesh, const VPM& vpm)
{
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

// Collects the vertices at most `rings` edges away from v, v excluded.
// `mark(u)` returns true the first time it is called for u.
template <typename PolygonMesh, typename Mark>
void collect_rings(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                   const PolygonMesh& pmesh, int rings, Mark mark,
                   std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& out)
{
  out.clear();
  mark(v);
  std::size_t begin = 0;
  std::size_t end = 0;
  out.push_back(v);  // the frontier starts at v; v is removed at the end
  for(int r = 0; r < rings; ++r)
  {
    begin = (r == 0) ? 0 : end;
    end = out.size();
    for(std::size_t i = begin; i < end; ++i)
    {
      if(halfedge(out[i], pmesh) == boost::graph_traits<PolygonMesh>::null_halfedge())
        continue;
      for(auto u : CGAL::vertices_around_target(out[i], pmesh))
        if(mark(u))
          out.push_back(u);
    }
    if(out.size() == end)
      break;
  }
  out.erase(out.begin());
}

// The vertices connected to v inside the ball of radius `radius` around it
// (v excluded), nearest first, with their distances: a search that always
// expands the nearest vertex not yet expanded, so that every prefix of the
// result within a smaller radius r is exactly the part connected to v inside
// the ball of radius r. `mark(u)` returns true the first time it is called for u.
template <typename PolygonMesh, typename VPM, typename Mark>
void collect_ball(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                  const PolygonMesh& pmesh, const VPM& vpm, double radius, Mark mark,
                  std::vector<std::pair<double, typename boost::graph_traits<PolygonMesh>::vertex_descriptor> >& out)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef std::pair<double, vertex_descriptor> Entry;
  auto farther = [](const Entry& a, const Entry& b) { return a.first > b.first; };
  std::priority_queue<Entry, std::vector<Entry>, decltype(farther)> queue(farther);
  const Vec3 p = to_vec3(get(vpm, v));
  out.clear();
  mark(v);
  queue.push(Entry(0, v));
  while(!queue.empty())
  {
    const Entry e = queue.top();
    queue.pop();
    if(e.second != v)
      out.push_back(e);
    if(halfedge(e.second, pmesh) == boost::graph_traits<PolygonMesh>::null_halfedge())
      continue;
    for(vertex_descriptor u : CGAL::vertices_around_target(e.second, pmesh))
    {
      const double d = (to_vec3(get(vpm, u)) - p).norm();
      if(d <= radius && mark(u))
        queue.push(Entry(d, u));
    }
  }
}

// Which neighbours a fit uses (see `estimate_vertex_curvatures()`): a ring
// size, a radius, or candidate radii to choose from per vertex.
struct Neighborhood_rule
{
  int rings = 1;
  double radius = 0;               // used when > 0
  std::vector<double> candidates;  // increasing; used when not empty
};

// The automatic neighbourhood (see `estimate_at_vertex()`): the half-width
// of the intervals of the mean curvature, in standard errors computed as if
// the heights' errors were independent. Wide, because they are not: the
// pipeline smooths noisy points (`denoise()`, jets of 24 to 64 neighbours)
// before the surface is built, which leaves errors correlated over about
// that many points (about 7 times the independent standard error) and hides
// them from the residuals. Measured on the ellipsoid and torus at 20k points
// with noise 0.1 spacing (evaluate_surfaces): with 2 the median radius is 4
// spacings and the median H error 15% and 8% (best fixed radius: 4.2%,
// 4.1%); 8 to 14 gives 5.2% to 5.6%; 25 and above grow too far. The cost:
// clean bumps about 6 spacings wide read as noise and are smoothed away.
constexpr double mean_curvature_interval_width = 10;
// ... and how many of the smallest candidate radii measure the noise.
constexpr std::size_t noise_measuring_radii = 4;

// Buffers reused from vertex to vertex.
template <typename PolygonMesh>
struct Ring_buffers
{
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> ring;
  std::vector<std::pair<double, typename boost::graph_traits<PolygonMesh>::vertex_descriptor> > ball;
  std::vector<Neighbor> neighbours;
};

// The estimate at one vertex, and the radius of the neighbourhood it used;
// `normal_of(u)` gives a vertex's Chen-Wu normal.
// A neighbourhood too small or too degenerate for the fit is widened (two
// more rings, or the radius by 1.5 twice) before the vertex is given up
// (NaN curvature). With candidate radii, the vertex's noise is measured from
// the residuals of the fits at the smallest radii, and the largest radius is
// kept whose confidence interval of the mean curvature (that noise through
// each fit) still meets those of all smaller ones (the intersection of
// confidence intervals rule): beyond it the fit's bias outgrows its noise.
template <typename PolygonMesh, typename VPM, typename Normal_of, typename Mark_factory>
bool estimate_at_vertex(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                        const PolygonMesh& pmesh, const VPM& vpm, const Neighborhood_rule& rule,
                        Curvature_estimator estimator, Normal_of normal_of,
                        Mark_factory new_mark, Ring_buffers<PolygonMesh>& buffers,
                        Local_curvature& out, double& radius)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out = Local_curvature{normal_of(v), nan, nan, nan_vector(), nan_vector()};
  radius = nan;
  if(!std::isfinite(out.normal.x()))
    return false;

  const Vec3 p = to_vec3(get(vpm, v));
  std::vector<Neighbor>& nbrs = buffers.neighbours;
  auto add = [&](vertex_descriptor u) {
    const Vec3 offset = to_vec3(get(vpm, u)) - p;
    if(!(offset.squaredNorm() > 0))
      return;  // a coincident vertex carries no direction
    double kn = 0;
    if(estimator != QUADRIC_FIT)
    {
      const Vec3 n_u = normal_of(u);
      if(!std::isfinite(n_u.x()))
        return;
      kn = normal_curvature(offset, out.normal, n_u);
    }
    nbrs.push_back(Neighbor{offset, kn});
  };
  auto fit = [&](Local_curvature& result, Quadric_fit_error* error) {
    bool ok = false;
    switch(estimator)
    {
      case PAPER_EULER_FIT:         ok = paper_euler_fit(out.normal, nbrs, result); break;
      case EULER_LEAST_SQUARES_FIT: ok = euler_least_squares_fit(out.normal, nbrs, result); break;
      case QUADRIC_FIT:             ok = quadric_fit(out.normal, nbrs, result, error); break;
    }
    return ok && std::isfinite(result.k1) && std::isfinite(result.k2);
  };
  Local_curvature result;

  if(!rule.candidates.empty())
  {
    collect_ball(v, pmesh, vpm, rule.candidates.back(), new_mark(), buffers.ball);
    nbrs.clear();
    // the fit at every candidate radius, smallest first
    std::vector<Local_curvature> fits;
    std::vector<Quadric_fit_error> errors;
    std::vector<double> radii;
    std::size_t used = 0;
    for(double r : rule.candidates)
    {
      for(; used < buffers.ball.size() && buffers.ball[used].first <= r; ++used)
        add(buffers.ball[used].second);
      Quadric_fit_error error;
      if(!fit(result, &error))
        continue;
      fits.push_back(result);
      errors.push_back(error);
      radii.push_back(r);
    }
    if(fits.empty())
      return false;
    // the noise of the heights: the residual variances of the fits at the
    // smallest radii, s^2(r) = sigma^2 + beta r^6 (the noise, and the cubic
    // terms that a quadric misses), fitted by least squares weighted by their
    // inverse variances (degrees of freedom / s^4), sigma^2 kept between 0
    // and the widest of these variances. Clean samples read about 0: their
    // residuals grow as r^3.
    const std::size_t measuring = (std::min)(fits.size(), noise_measuring_radii);
    double s00 = 0, s01 = 0, s11 = 0, t0 = 0, t1 = 0;
    for(std::size_t i = 0; i < measuring; ++i)
    {
      const Quadric_fit_error& e = errors[i];
      if(!(e.degrees_of_freedom >= 1) || !std::isfinite(e.noise))
        continue;
      const double s2 = e.noise * e.noise;
      const double x = std::pow(radii[i] / radii[0], 6);
      const double w = e.degrees_of_freedom / (s2 * s2 + (std::numeric_limits<double>::min)());
      s00 += w;
      s01 += w * x;
      s11 += w * x * x;
      t0 += w * s2;
      t1 += w * s2 * x;
    }
    const double det = s00 * s11 - s01 * s01;
    const double widest = errors[measuring - 1].noise * errors[measuring - 1].noise;
    double noise2 = det > 0 ? (t0 * s11 - t1 * s01) / det : widest;
    noise2 = std::isfinite(widest) ? (std::min)((std::max)(noise2, 0.), widest) : (std::max)(noise2, 0.);
    const double noise = std::sqrt(noise2);
    // the intersection of confidence intervals, from the smallest radius up
    double low = -std::numeric_limits<double>::infinity(), high = -low;
    for(std::size_t i = 0; i < fits.size(); ++i)
    {
      const double H = (fits[i].k1 + fits[i].k2) / 2;
      const double se = noise * errors[i].per_noise;
      low = (std::max)(low, H - mean_curvature_interval_width * se);
      high = (std::min)(high, H + mean_curvature_interval_width * se);
      if(i > 0 && !(low <= high))
        break;
      out = fits[i];
      radius = radii[i];
    }
    return true;
  }

  for(int widening = 0; widening <= 2; ++widening)
  {
    nbrs.clear();
    double reach = 0;
    if(rule.radius > 0)
    {
      reach = rule.radius * std::pow(1.5, widening);
      collect_ball(v, pmesh, vpm, reach, new_mark(), buffers.ball);
      for(const auto& entry : buffers.ball)
        add(entry.second);
    }
    else
    {
      collect_rings(v, pmesh, rule.rings + widening, new_mark(), buffers.ring);
      for(vertex_descriptor u : buffers.ring)
      {
        add(u);
        reach = (std::max)(reach, (to_vec3(get(vpm, u)) - p).norm());
      }
    }
    if(fit(result, nullptr))
    {
      out = result;
      radius = reach;
      return true;
    }
  }
  return false;
}

template <typename PolygonMesh, typename NamedParameters>
struct Curvature_maps
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NamedParameters>::const_type VPM;
  typedef typename Kernel_traits<typename boost::property_traits<VPM>::value_type>::Kernel GT;
  typedef typename GT::FT FT;
  typedef typename GT::Vector_3 Vector_3;
  typedef Principal_curvatures_and_directions<GT> Principal;

  typedef CGAL::Constant_property_map<vertex_descriptor, Vector_3> Default_normal_map;
  typedef CGAL::Constant_property_map<vertex_descriptor, FT> Default_scalar_map;
  typedef CGAL::Constant_property_map<vertex_descriptor, Principal> Default_principal_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
    CGAL::internal_np::vertex_normal_map_t, NamedParameters, Default_normal_map>::type Normal_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
    internal_np_cas3::vertex_mean_curvature_map_t, NamedParameters, Default_scalar_map>::type H_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
    internal_np_cas3::vertex_Gaussian_curvature_map_t, NamedParameters, Default_scalar_map>::type K_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
    internal_np_cas3::vertex_principal_curvatures_and_directions_map_t, NamedParameters,
    Default_principal_map>::type Principal_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
    internal_np_cas3::vertex_neighborhood_radius_map_t, NamedParameters, Default_scalar_map>::type Radius_map;

  Curvature_maps(const NamedParameters& np)
    : normal(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_normal_map),
                                          Default_normal_map())),
      mean(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np_cas3::vertex_mean_curvature_map),
                                        Default_scalar_map())),
      gaussian(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np_cas3::vertex_Gaussian_curvature_map), Default_scalar_map())),
      principal(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np_cas3::vertex_principal_curvatures_and_directions_map),
        Default_principal_map())),
      radius(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np_cas3::vertex_neighborhood_radius_map), Default_scalar_map()))
  {}

  static Vector_3 to_vector(const Vec3& v) { return Vector_3(FT(v.x()), FT(v.y()), FT(v.z())); }

  void write(vertex_descriptor v, const Local_curvature& c, double used_radius) const
  {
    put(radius, v, FT(used_radius));
    put(normal, v, to_vector(c.normal));
    put(mean, v, FT((c.k1 + c.k2) / 2));
    put(gaussian, v, FT(c.k1 * c.k2));
    put(principal, v, Principal{FT(c.k1), FT(c.k2), to_vector(c.d1), to_vector(c.d2)});
  }

  Normal_map normal;
  H_map mean;
  K_map gaussian;
  Principal_map principal;
  Radius_map radius;
};

template <typename PolygonMesh, typename NamedParameters>
Curvature_estimator get_estimator(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np_cas3::estimator), QUADRIC_FIT);
}

template <typename NamedParameters>
Neighborhood_rule get_neighborhood_rule(const NamedParameters& np, Curvature_estimator estimator)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Neighborhood_rule rule;
  rule.rings = choose_parameter(get_parameter(np, internal_np_cas3::ring_size), 1);
  rule.radius = choose_parameter(get_parameter(np, internal_np_cas3::neighborhood_radius), 0.);
  rule.candidates = choose_parameter(get_parameter(np, internal_np_cas3::neighborhood_radii), std::vector<double>());
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
  return rule;
}

} // namespace internal

/*!
\ingroup PkgConformalAlphaShapes3Curvature

Estimates, at every vertex of the triangle mesh `pmesh`, the unit normal,
the mean curvature `H`, the Gaussian curvature `K`, and the principal
curvatures and directions, writing each into the property map passed for it
(an output is computed only when its map is passed).

Conventions: with outward-oriented faces, convex regions have positive
curvature (a sphere of radius `r`: `H = 1/r`, `K = 1/r^2`); the curvatures
are `max_curvature >= min_curvature`, `H` their mean and `K` their product.

Neighborhood, by the first of these named parameters given:
- `neighborhood_radii`: per vertex, one of the candidate radii, chosen from
  the data alone by the intersection of confidence intervals rule. The
  vertex's noise `sigma` is measured from the residual variances `s^2` of the
  fits at the four smallest radii, by fitting `s^2(r) = sigma^2 + beta r^6`
  (noise, plus the cubic terms a quadric misses; a clean sample reads about
  0). Each fit gives the mean curvature with the standard error that noise
  `sigma` on the heights implies (weighted least squares); the largest radius
  is kept whose interval (ten such standard errors either side: they assume
  independent errors, which smoothed noisy points do not have) still meets
  the intervals of all smaller radii. On clean samples this keeps the
  smallest radius, under noise it grows (see the manual's measurements).
  `QUADRIC_FIT` only.
- `neighborhood_radius`: the vertices within that distance of the vertex
  and connected to it through surface edges inside that ball (a ball cut to
  the vertex's side of the surface: a thin part or a nearby sheet does not
  leak into the fit). Widened by 1.5 up to twice when too small.
- `ring_size`: the `k`-ring of the vertex; up to two more rings are used when
  it is too small.

A neighbourhood is too small or too degenerate for the fit with fewer
neighbours than unknowns, all neighbours along one line, or a singular
system. Border
vertices are estimated from their one-sided neighbourhood. Faces of zero area
do not contribute to the normals. A vertex whose normal or curvature is still
undefined (an isolated vertex, only degenerate faces, too few vertices even
with the wider rings) gets NaN values and is counted in the return value.

\tparam PolygonMesh a model of `FaceGraph` whose faces are triangles.
\tparam NamedParameters a sequence of named parameters.

\param pmesh the mesh
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the positions of the vertices}
    \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `GT::Point_3` as value}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, pmesh)`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_index_map}
    \cgalParamDescription{a property map associating to each vertex of `pmesh` a unique index between `0` and `num_vertices(pmesh) - 1`}
    \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `std::size_t` as value}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_normal_map}
    \cgalParamDescription{output: unit normals (the Chen-Wu normal for the Euler estimators, the fitted surface's for `QUADRIC_FIT`)}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `GT::Vector_3` as value}
    \cgalParamDefault{not computed}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_mean_curvature_map}
    \cgalParamDescription{output: mean curvature `H`}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `GT::FT` as value}
    \cgalParamDefault{not computed}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_Gaussian_curvature_map}
    \cgalParamDescription{output: Gaussian curvature `K`}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `GT::FT` as value}
    \cgalParamDefault{not computed}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_principal_curvatures_and_directions_map}
    \cgalParamDescription{output: principal curvatures and directions}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `Principal_curvatures_and_directions<GT>` as value}
    \cgalParamDefault{not computed}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_neighborhood_radius_map}
    \cgalParamDescription{output: the radius of the neighbourhood used (for rings: the distance of the farthest neighbour used; NaN where the curvature is undefined)}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `GT::FT` as value}
    \cgalParamDefault{not computed}
  \cgalParamNEnd
  \cgalParamNBegin{neighborhood_radii}
    \cgalParamDescription{candidate radii, increasing, to choose from per vertex (see above)}
    \cgalParamType{`std::vector<double>`}
    \cgalParamDefault{empty: not used}
  \cgalParamNEnd
  \cgalParamNBegin{neighborhood_radius}
    \cgalParamDescription{the neighbourhood's radius, in the units of the points (see above)}
    \cgalParamType{`double`}
    \cgalParamDefault{0: not used}
  \cgalParamNEnd
  \cgalParamNBegin{ring_size}
    \cgalParamDescription{the size `k >= 1` of the ring of neighbours used at each vertex}
    \cgalParamType{`int`}
    \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{estimator}
    \cgalParamDescription{the estimator}
    \cgalParamType{`Curvature_estimator`}
    \cgalParamDefault{`QUADRIC_FIT`}
  \cgalParamNEnd
\cgalNamedParamsEnd

Here `GT` is the kernel of the points of the vertex point map.

\throws std::invalid_argument for a ring size below 1, a radius that is
negative or not finite, candidate radii that are not positive and increasing,
or candidate radii with another estimator than `QUADRIC_FIT`.

\returns the number of vertices whose curvature is undefined (NaN).
*/
template <typename PolygonMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = typename std::enable_if<
            internal::Is_named_function_parameters<NamedParameters>::value>::type>
std::size_t estimate_vertex_curvatures(const PolygonMesh& pmesh,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef internal::Curvature_maps<PolygonMesh, NamedParameters> Maps;
  const Maps maps(np);
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, pmesh));
  const Curvature_estimator estimator = internal::get_estimator<PolygonMesh>(np);
  const internal::Neighborhood_rule rule = internal::get_neighborhood_rule(np, estimator);

  const auto vertex_index = CGAL::get_initialized_vertex_index_map(pmesh, np);
  std::vector<internal::Vec3> normals(num_vertices(pmesh));
  for(vertex_descriptor v : vertices(pmesh))
    normals[get(vertex_index, v)] =
      halfedge(v, pmesh) == boost::graph_traits<PolygonMesh>::null_halfedge()
        ? internal::nan_vector() : internal::chen_wu_normal(v, pmesh, vpm);

  // a vertex is marked in the current ring search when its stamp is current
  std::vector<std::size_t> stamps(num_vertices(pmesh), 0);
  std::size_t stamp = 0;
  auto new_mark = [&]() {
    ++stamp;
    return [&, s = stamp](vertex_descriptor u) {
      std::size_t& mark = stamps[get(vertex_index, u)];
      const bool fresh = mark != s;
      mark = s;
      return fresh;
    };
  };

  std::size_t undefined = 0;
  internal::Local_curvature c;
  double radius = 0;
  internal::Ring_buffers<PolygonMesh> buffers;
  for(vertex_descriptor v : vertices(pmesh))
  {
    if(!internal::estimate_at_vertex(v, pmesh, vpm, rule, estimator,
                                     [&](vertex_descriptor u) { return normals[get(vertex_index, u)]; }, new_mark,
                                     buffers, c, radius))
      ++undefined;
    maps.write(v, c, radius);
  }
  return undefined;
}

/*!
\ingroup PkgConformalAlphaShapes3Curvature
The same estimate at the single vertex `v`, written into the maps passed in
`np` at `v` only. Its cost is that of the vertex's neighbourhood.
\returns whether the curvature at `v` is defined.
*/
template <typename PolygonMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
bool estimate_vertex_curvatures(typename internal::Vertex_of<PolygonMesh>::type v,
                                const PolygonMesh& pmesh,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef internal::Curvature_maps<PolygonMesh, NamedParameters> Maps;
  const Maps maps(np);
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, pmesh));
  auto normal_of = [&](vertex_descriptor u) {
    return halfedge(u, pmesh) == boost::graph_traits<PolygonMesh>::null_halfedge()
             ? internal::nan_vector() : internal::chen_wu_normal(u, pmesh, vpm);
  };
  std::unordered_set<vertex_descriptor> marked;
  auto new_mark = [&]() {
    marked.clear();
    return [&marked](vertex_descriptor u) { return marked.insert(u).second; };
  };
  internal::Local_curvature c;
  double radius = 0;
  internal::Ring_buffers<PolygonMesh> buffers;
  const Curvature_estimator estimator = internal::get_estimator<PolygonMesh>(np);
  const bool ok = internal::estimate_at_vertex(v, pmesh, vpm, internal::get_neighborhood_rule(np, estimator),
                                               estimator, normal_of, new_mark, buffers, c, radius);
  maps.write(v, c, radius);
  return ok;
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_VERTEX_CURVATURES_H
