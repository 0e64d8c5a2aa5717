// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_VERTEX_CURVATURES_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_VERTEX_CURVATURES_H

// Over 400 lines: one public function (two overloads) with 150 lines of
// documentation, and the per-vertex neighbourhoods it offers (rings, a ball
// cut to the surface, the automatic choice among radii) with the fit that
// runs on them; the fits themselves are in internal/curvature_fits.h.

#include <CGAL/Conformal_alpha_shapes_3/internal/curvature_fits.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/surface_neighborhoods.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <stdexcept>
#include <string>
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

// The vertex type of a mesh; no type for a parameter pack or a concurrency
// tag, so that the single-vertex overload drops out of
// `estimate_vertex_curvatures(mesh, np)` and `estimate_vertex_curvatures<Tag>(mesh, np)`.
template <typename PolygonMesh, bool = Is_named_function_parameters<PolygonMesh>::value
                                       || std::is_base_of<CGAL::Sequential_tag, PolygonMesh>::value>
struct Vertex_of { typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor type; };
template <typename PolygonMesh>
struct Vertex_of<PolygonMesh, true> {};

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

// Which neighbours a fit uses (see `estimate_vertex_curvatures()`): a ring
// size, a radius, or candidate radii to choose from per vertex.
struct Neighborhood_rule
{
  int rings = 1;
  double radius = 0;               // used when > 0
  std::vector<double> candidates;  // increasing; used when not empty
};

// The automatic neighbourhood (see `choose_by_confidence_intervals()`): the half-width
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

// What one rule gives at one vertex: the curvature and the radius of the
// neighbourhood used, NaN where undefined.
struct Vertex_estimate
{
  Local_curvature curvature{nan_vector(), std::numeric_limits<double>::quiet_NaN(),
                            std::numeric_limits<double>::quiet_NaN(), nan_vector(), nan_vector()};
  double radius = std::numeric_limits<double>::quiet_NaN();

  bool defined() const { return std::isfinite(curvature.k1) && std::isfinite(curvature.k2); }
};

// A fit at one of the candidate radii of the automatic rule.
struct Candidate_fit
{
  Local_curvature curvature;
  Quadric_fit_error error;
  double radius;
};

// The automatic neighbourhood: the vertex's noise is measured from the
// residual variances of the fits at the smallest candidate radii,
// s^2(r) = sigma^2 + beta r^6 (the noise, and the cubic terms that a
// quadric misses), fitted by least squares weighted by their inverse
// variances (degrees of freedom / s^4), sigma^2 kept between 0 and the
// widest of these variances (clean samples read about 0: their residuals
// grow as r^3); then the largest radius is kept whose confidence interval
// of the mean curvature (that noise through each fit) still meets those of
// all smaller ones (the intersection of confidence intervals rule): beyond
// it the fit's bias outgrows its noise. `fits` holds the defined fits, by
// increasing radius; at least one.
inline Vertex_estimate choose_by_confidence_intervals(const std::vector<Candidate_fit>& fits)
{
  const std::size_t measuring = (std::min)(fits.size(), noise_measuring_radii);
  double s00 = 0, s01 = 0, s11 = 0, t0 = 0, t1 = 0;
  for(std::size_t i = 0; i < measuring; ++i)
  {
    const Quadric_fit_error& e = fits[i].error;
    if(!(e.degrees_of_freedom >= 1) || !std::isfinite(e.noise))
      continue;
    const double s2 = e.noise * e.noise;
    const double x = std::pow(fits[i].radius / fits[0].radius, 6);
    const double w = e.degrees_of_freedom / (s2 * s2 + (std::numeric_limits<double>::min)());
    s00 += w;
    s01 += w * x;
    s11 += w * x * x;
    t0 += w * s2;
    t1 += w * s2 * x;
  }
  const double det = s00 * s11 - s01 * s01;
  const double widest = fits[measuring - 1].error.noise * fits[measuring - 1].error.noise;
  double noise2 = det > 0 ? (t0 * s11 - t1 * s01) / det : widest;
  noise2 = std::isfinite(widest) ? (std::min)((std::max)(noise2, 0.), widest) : (std::max)(noise2, 0.);
  const double noise = std::sqrt(noise2);
  Vertex_estimate chosen;
  double low = -std::numeric_limits<double>::infinity(), high = -low;
  for(std::size_t i = 0; i < fits.size(); ++i)
  {
    const double H = (fits[i].curvature.k1 + fits[i].curvature.k2) / 2;
    const double se = noise * fits[i].error.per_noise;
    low = (std::max)(low, H - mean_curvature_interval_width * se);
    high = (std::min)(high, H + mean_curvature_interval_width * se);
    if(i > 0 && !(low <= high))
      break;
    chosen.curvature = fits[i].curvature;
    chosen.radius = fits[i].radius;
  }
  return chosen;
}

// The estimates of several neighbourhood rules at every vertex, sharing
// one search per vertex: the radii of all rules (fixed ones and
// candidates) are nested balls found by one search, the ring sizes nested
// rings found by another, and each fit runs on a prefix of what the search
// found. A neighbourhood too small or too degenerate for the fit is widened
// (two more rings, or the radius by 1.5 twice) before the vertex is given
// up (NaN).
class Curvature_estimation
{
public:
  // Per thread: the searches and the fit's buffers.
  struct Workspace
  {
    explicit Workspace(std::size_t number_of_vertices) : search(number_of_vertices) {}
    Nested_neighborhood_search search;
    std::vector<Quadric_point> points;
    std::vector<Neighbor> neighbors;
    std::vector<Local_curvature> fits;
    std::vector<char> fitted;
    std::vector<Quadric_fit_error> errors;
    std::vector<Candidate_fit> candidates;
  };

  // `normals`: the Chen-Wu normal of each vertex of `graph`.
  Curvature_estimation(const Vertex_graph& graph, const std::vector<Vec3>& normals,
                       const std::vector<Neighborhood_rule>& rules, Curvature_estimator estimator)
    : m_graph(graph), m_normals(normals), m_rules(rules), m_estimator(estimator)
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
    m_with_error.assign(m_radii.size(), 0);
    for(const Neighborhood_rule& rule : rules)
      for(double r : rule.candidates)
        m_with_error[radius_level(r)] = 1;
  }

  Workspace make_workspace() const { return Workspace(m_graph.size()); }

  // The estimates at vertex v, one per rule, into out[0, rules.size()).
  void estimate(std::size_t v, Workspace& ws, Vertex_estimate* out) const
  {
    for(std::size_t r = 0; r < m_rules.size(); ++r)
      out[r] = Vertex_estimate();
    const Vec3& n = m_normals[v];
    if(!std::isfinite(n.x()))
      return;
    for(std::size_t r = 0; r < m_rules.size(); ++r)
      out[r].curvature.normal = n;
    if(!m_radii.empty())
      estimate_in_balls(v, ws, out);
    if(m_rings > 0)
      estimate_in_rings(v, ws, out);
  }

private:
  std::size_t radius_level(double r) const
  {
    return std::size_t(std::lower_bound(m_radii.begin(), m_radii.end(), r) - m_radii.begin());
  }

  // What the fit needs of each vertex the search found, in coordinates
  // divided by `length`; coincident vertices carry no direction and are
  // left out (`kept` counts, per level, those of that level and below).
  void prepare(std::size_t v, const Tangent_frame& f, double length, std::size_t levels, Workspace& ws,
               std::vector<std::size_t>& kept) const
  {
    const Vec3& p = m_graph.points[v];
    const std::vector<std::size_t>& found = ws.search.vertices();
    const std::vector<double>& distance = ws.search.distances();
    ws.points.clear();
    ws.neighbors.clear();
    kept.assign(levels, 0);
    std::size_t level = 0;
    for(std::size_t k = 0; k < found.size(); ++k)
    {
      while(ws.search.end(level) <= k)
        kept[level++] = count(ws);
      if(!(distance[k] > 0))
        continue;
      const Vec3 offset = m_graph.points[found[k]] - p;
      if(m_estimator == QUADRIC_FIT)
      {
        const Vec3 o = offset / length;
        ws.points.push_back(Quadric_point{o.dot(f.e1), o.dot(f.e2), o.dot(f.n), distance[k] * distance[k]});
        continue;
      }
      const Vec3& n_u = m_normals[found[k]];
      if(std::isfinite(n_u.x()))
        ws.neighbors.push_back(Neighbor{offset, normal_curvature(offset, f.n, n_u)});
    }
    for(; level < levels; ++level)
      kept[level] = count(ws);
  }

  std::size_t count(const Workspace& ws) const
  {
    return m_estimator == QUADRIC_FIT ? ws.points.size() : ws.neighbors.size();
  }

  // The fit over the first `count` prepared neighbours, fading at `fade`.
  bool fit(const Tangent_frame& f, std::size_t count, double fade, double length, Workspace& ws,
           Local_curvature& out, Quadric_fit_error* error) const
  {
    bool ok = false;
    if(m_estimator == QUADRIC_FIT)
      ok = quadric_fit(f, ws.points.data(), count, fade, length, out, error);
    else
    {
      const std::vector<Neighbor> prefix(ws.neighbors.begin(), ws.neighbors.begin() + std::ptrdiff_t(count));
      ok = m_estimator == PAPER_EULER_FIT ? paper_euler_fit(f.n, prefix, out)
                                          : euler_least_squares_fit(f.n, prefix, out);
    }
    return ok && std::isfinite(out.k1) && std::isfinite(out.k2);
  }

  void estimate_in_balls(std::size_t v, Workspace& ws, Vertex_estimate* out) const
  {
    const Tangent_frame f = frame_from_normal(m_normals[v]);
    const double length = m_radii.back();
    std::vector<std::size_t> kept;
    ws.search.balls(m_graph, v, m_radii);
    prepare(v, f, length, m_radii.size(), ws, kept);
    ws.fits.resize(m_radii.size());
    ws.errors.resize(m_radii.size());
    ws.fitted.assign(m_radii.size(), 0);
    for(std::size_t j = 0; j < m_radii.size(); ++j)
      ws.fitted[j] = fit(f, kept[j], m_radii[j], length, ws, ws.fits[j], m_with_error[j] ? &ws.errors[j] : nullptr);

    std::vector<std::size_t> to_widen;
    for(std::size_t r = 0; r < m_rules.size(); ++r)
    {
      const Neighborhood_rule& rule = m_rules[r];
      if(!rule.candidates.empty())
      {
        ws.candidates.clear();
        for(double radius : rule.candidates)
        {
          const std::size_t j = radius_level(radius);
          if(ws.fitted[j])
            ws.candidates.push_back(Candidate_fit{ws.fits[j], ws.errors[j], radius});
        }
        if(!ws.candidates.empty())
          out[r] = choose_by_confidence_intervals(ws.candidates);
      }
      else if(rule.radius > 0)
      {
        const std::size_t j = radius_level(rule.radius);
        if(ws.fitted[j])
          out[r] = Vertex_estimate{ws.fits[j], rule.radius};
        else
          to_widen.push_back(r);
      }
    }
    // the wider balls of the few vertices that need them, last: their
    // searches replace the shared one
    for(std::size_t r : to_widen)
      for(int widening = 1; widening <= 2 && !out[r].defined(); ++widening)
      {
        const double radius = m_rules[r].radius * std::pow(1.5, widening);
        ws.search.balls(m_graph, v, std::vector<double>(1, radius));
        prepare(v, f, radius, 1, ws, kept);
        Local_curvature c;
        if(fit(f, kept[0], radius, radius, ws, c, nullptr))
          out[r] = Vertex_estimate{c, radius};
      }
  }

  // Rings up to the largest ring size plus two (the widening), fitted on
  // each prefix; a ring's fit fades at 1.5 times the distance of its
  // farthest neighbour, which is the radius reported.
  void estimate_in_rings(std::size_t v, Workspace& ws, Vertex_estimate* out) const
  {
    const Tangent_frame f = frame_from_normal(m_normals[v]);
    ws.search.rings(m_graph, v, m_rings);
    const std::vector<double>& distance = ws.search.distances();
    double length = 0;
    for(double d : distance)
      length = (std::max)(length, d);
    if(!(length > 0))
      return;
    std::vector<std::size_t> kept;
    prepare(v, f, length, m_rings, ws, kept);
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
          reach = (std::max)(reach, distance[k]);
        Local_curvature c;
        if(fit(f, kept[ring], reach, length, ws, c, nullptr))
          out[r] = Vertex_estimate{c, reach};
      }
    }
  }

  const Vertex_graph& m_graph;
  const std::vector<Vec3>& m_normals;
  std::vector<Neighborhood_rule> m_rules;
  Curvature_estimator m_estimator;
  std::vector<double> m_radii;     // every rule's radii, increasing
  std::vector<char> m_with_error;  // by radius: a candidate of an automatic rule
  std::size_t m_rings = 0;         // rings searched: the largest ring size plus two
};

// Estimates of every rule at every vertex of `graph`: [rule][vertex index].
template <typename ConcurrencyTag>
std::vector<std::vector<Vertex_estimate> > estimate_at_every_vertex(const Vertex_graph& graph,
                                                                   const std::vector<Vec3>& normals,
                                                                   const std::vector<Neighborhood_rule>& rules,
                                                                   Curvature_estimator estimator)
{
  const Curvature_estimation estimation(graph, normals, rules, estimator);
  std::vector<std::vector<Vertex_estimate> > by_rule(rules.size(), std::vector<Vertex_estimate>(graph.size()));
  typedef Curvature_estimation::Workspace Workspace;
  struct Per_thread
  {
    Workspace workspace;
    std::vector<Vertex_estimate> estimates;
  };
  for_each_index<ConcurrencyTag>(graph.size(),
    [&]() { return Per_thread{estimation.make_workspace(), std::vector<Vertex_estimate>(rules.size())}; },
    [&](std::size_t v, Per_thread& thread) {
      estimation.estimate(v, thread.workspace, thread.estimates.data());
      for(std::size_t r = 0; r < rules.size(); ++r)
        by_rule[r][v] = thread.estimates[r];
    });
  return by_rule;
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

template <typename NamedParameters>
Neighborhood_rule get_neighborhood_rule(const NamedParameters& np, Curvature_estimator estimator)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Neighborhood_rule rule;
  rule.rings = choose_parameter(get_parameter(np, internal_np_cas3::ring_size), 1);
  rule.radius = choose_parameter(get_parameter(np, internal_np_cas3::neighborhood_radius), 0.);
  rule.candidates = choose_parameter(get_parameter(np, internal_np_cas3::neighborhood_radii), std::vector<double>());
  check_neighborhood_rule(rule, estimator);
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

\tparam ConcurrencyTag `CGAL::Sequential_tag` (default), `CGAL::Parallel_tag`
        or `CGAL::Parallel_if_available_tag`: the vertices are estimated on
        TBB's threads with the parallel tags (which need
        `CGAL_LINKED_WITH_TBB`); the results are the same whichever the tag.
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
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename PolygonMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename = typename std::enable_if<
            internal::Is_named_function_parameters<NamedParameters>::value>::type>
std::size_t estimate_vertex_curvatures(const PolygonMesh& pmesh,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  const internal::Curvature_maps<PolygonMesh, NamedParameters> maps(np);
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, pmesh));
  const Curvature_estimator estimator = internal::get_estimator<PolygonMesh>(np);
  const std::vector<internal::Neighborhood_rule> rules(1, internal::get_neighborhood_rule(np, estimator));
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(pmesh, np);
  const internal::Vertex_graph graph = internal::vertex_graph(pmesh, vpm, vertex_index);
  const std::vector<internal::Vec3> normals = internal::chen_wu_normals<ConcurrencyTag>(pmesh, vpm, vertex_index);
  const std::vector<internal::Vertex_estimate> estimates =
    internal::estimate_at_every_vertex<ConcurrencyTag>(graph, normals, rules, estimator).front();
  std::size_t undefined = 0;
  for(vertex_descriptor v : vertices(pmesh))
  {
    const internal::Vertex_estimate& e = estimates[get(vertex_index, v)];
    undefined += e.defined() ? 0 : 1;
    maps.write(v, e.curvature, e.radius);
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
  const internal::Curvature_maps<PolygonMesh, NamedParameters> maps(np);
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, pmesh));
  const Curvature_estimator estimator = internal::get_estimator<PolygonMesh>(np);
  const std::vector<internal::Neighborhood_rule> rules(1, internal::get_neighborhood_rule(np, estimator));
  // the part of the mesh the searches can reach: two rings beyond the ring
  // size, or the widest radius (a fixed radius widens to 2.25 times itself)
  const internal::Neighborhood_rule& rule = rules.front();
  const double reach = rule.candidates.empty() ? 2.25 * rule.radius : rule.candidates.back();
  std::vector<vertex_descriptor> by_index;
  const internal::Vertex_graph graph =
    internal::local_vertex_graph(v, pmesh, vpm, reach > 0 ? 0 : std::size_t(rule.rings) + 2, reach, by_index);
  std::vector<internal::Vec3> normals(graph.size());
  for(std::size_t i = 0; i < graph.size(); ++i)
    normals[i] = internal::chen_wu_normal(by_index[i], pmesh, vpm);
  const internal::Curvature_estimation estimation(graph, normals, rules, estimator);
  internal::Curvature_estimation::Workspace workspace = estimation.make_workspace();
  internal::Vertex_estimate estimate;
  estimation.estimate(0, workspace, &estimate);
  maps.write(v, estimate.curvature, estimate.radius);
  return estimate.defined();
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_VERTEX_CURVATURES_H
