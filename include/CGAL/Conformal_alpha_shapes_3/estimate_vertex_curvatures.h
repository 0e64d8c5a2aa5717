// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_VERTEX_CURVATURES_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_VERTEX_CURVATURES_H

// The public function and its outputs; the estimation itself is in
// internal/curvature_estimation.h, the reading of its parameters in
// internal/curvature_parameters.h.

#include <CGAL/Conformal_alpha_shapes_3/curvature_estimator.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/curvature_estimation.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/curvature_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/scales_and_neighborhoods.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
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
/// The standard uncertainties of an estimate (the manual, section
/// "Uncertainty"): one standard deviation of the error of `H`, of `K`, and
/// of the normal's direction in degrees, from the fit's residuals, its
/// neighbors' count and spread, the sample's noise and the bias that the
/// radius implies (its rate averaged over the vertices within 5 sample
/// spacings, or 4.5 median edges); at a fixed radius the noise's part is
/// widened for the residuals' few degrees of freedom, so that twice it
/// covers the error as twice a known standard deviation would; NaN where
/// unknown (the Euler estimators, undefined values).
template <typename GT>
struct Curvature_uncertainty
{
  typename GT::FT mean_curvature = std::numeric_limits<double>::quiet_NaN();      ///< of `H`
  typename GT::FT gaussian_curvature = std::numeric_limits<double>::quiet_NaN();  ///< of `K`
  typename GT::FT normal_degrees = std::numeric_limits<double>::quiet_NaN();      ///< of the normal, in degrees
  /// the part of `mean_curvature` that the noise of the points gives (the
  /// sample's and the fit's residuals'); the rest is the bias of the radius
  /// and, for an automatic radius, its choice
  typename GT::FT mean_curvature_noise = std::numeric_limits<double>::quiet_NaN();
};

/// \ingroup PkgConformalAlphaShapes3Curvature
/// The curvature at a vertex, as `estimate_vertex_curvatures()` estimates it
/// for several neighborhoods at once; every number is NaN where it is undefined.
template <typename GT>
struct Vertex_curvature
{
  /// the unit normal
  typename GT::Vector_3 normal = typename GT::Vector_3(std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
  /// `max_curvature` is `k1`, `max_direction` `d1`; `min_curvature` is `k2`
  Principal_curvatures_and_directions<GT> principal;
  /// the radius of the neighborhood of the fit (for rings: the farthest neighbor used)
  typename GT::FT radius = std::numeric_limits<double>::quiet_NaN();
  /// the standard uncertainties of `H`, `K` and the normal
  Curvature_uncertainty<GT> uncertainty;

  /// the mean curvature `H`
  typename GT::FT mean_curvature() const { return (principal.max_curvature + principal.min_curvature) / 2; }
  /// the Gaussian curvature `K`
  typename GT::FT gaussian_curvature() const { return principal.max_curvature * principal.min_curvature; }
  /// whether the curvature is defined
  bool is_defined() const { return std::isfinite(principal.max_curvature) && std::isfinite(principal.min_curvature); }
};

namespace internal {

// The output maps of the named parameters, constant maps where not given.
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
  typedef CGAL::Constant_property_map<vertex_descriptor, Curvature_uncertainty<GT> > Default_uncertainty_map;
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
  typedef typename CGAL::internal_np::Lookup_named_param_def<
    internal_np_cas3::vertex_curvature_uncertainty_map_t, NamedParameters, Default_uncertainty_map>::type
    Uncertainty_map;

  Curvature_maps(const NamedParameters& np)
    : normal(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_normal_map),
                                          Default_normal_map(CGAL::NULL_VECTOR))),
      mean(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np_cas3::vertex_mean_curvature_map),
                                        Default_scalar_map())),
      gaussian(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np_cas3::vertex_Gaussian_curvature_map), Default_scalar_map())),
      principal(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np_cas3::vertex_principal_curvatures_and_directions_map),
        Default_principal_map())),
      radius(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np_cas3::vertex_neighborhood_radius_map), Default_scalar_map())),
      uncertainty(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np_cas3::vertex_curvature_uncertainty_map),
        Default_uncertainty_map()))
  {}

  void write(vertex_descriptor v, const Vertex_curvature<GT>& c) const
  {
    put(radius, v, c.radius);
    put(normal, v, c.normal);
    put(mean, v, c.mean_curvature());
    put(gaussian, v, c.gaussian_curvature());
    put(principal, v, c.principal);
    put(uncertainty, v, c.uncertainty);
  }

  Normal_map normal;
  H_map mean;
  K_map gaussian;
  Principal_map principal;
  Radius_map radius;
  Uncertainty_map uncertainty;
};

template <typename GT>
Vertex_curvature<GT> to_vertex_curvature(const Vertex_estimate& e)
{
  auto vector = [](const Vec3& v) { return typename GT::Vector_3(v.x(), v.y(), v.z()); };
  Vertex_curvature<GT> c;
  c.normal = vector(e.curvature.normal);
  c.principal = Principal_curvatures_and_directions<GT>{e.curvature.k1, e.curvature.k2, vector(e.curvature.d1),
                                                        vector(e.curvature.d2)};
  c.radius = e.radius;
  c.uncertainty.mean_curvature = e.uncertainty.H;
  c.uncertainty.gaussian_curvature = e.uncertainty.K;
  c.uncertainty.normal_degrees = e.uncertainty.normal * (180 / 3.14159265358979323846);
  c.uncertainty.mean_curvature_noise = e.uncertainty.H_noise;
  return c;
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

The `QUADRIC_FIT` estimator fits a quadric height function, corrected for
the fourth-order term of a surface of the fitted curvature (exact on
spheres and cylinders): that removes most of a plain quadric's bias, of
relative size `(k r)^2`, without adding variance, so that large, less noisy
radii stay accurate where the curvature varies slowly.

Neighborhood, by the first of these named parameters given:
- `neighborhood_radii`: per vertex, one of the candidate radii, chosen from
  the data alone by least expected squared error of the mean curvature. The
  vertex's noise `sigma` is measured from the residual variances `s^2` of the
  fits at the four smallest radii, by fitting `s^2(r) = sigma^2 + beta r^10`
  (a clean sample reads about 0), and raised 7 times (smoothed noisy points
  hide most of their noise from the residuals, not from the curvature; given
  the sample's noise before smoothing, `noise_level`, as
  `multiscale_curvatures()` does, that is used instead). Each fit gives the standard error of the mean curvature
  that `sigma` implies; its bias is modeled as `c r^2` (what the correction
  leaves: the curvature's variation), `c` fitted to the fits' mean
  curvatures; the radius of least `c^2 r^4` plus squared standard error is
  kept, among the radii below the first whose fit leaves residuals
  over 3 `sigma` (not a height polynomial at that size: a thin part, or
  detail). On clean samples this keeps the smallest radius, under noise it
  grows (see the manual's measurements). `QUADRIC_FIT` only.
- `neighborhood_radius`: the vertices within that distance of the vertex
  and connected to it through surface edges inside that ball (a ball cut to
  the vertex's side of the surface: a thin part or a nearby sheet does not
  leak into the fit). Widened by 1.5 up to twice when too small.
- Large radii (candidates too), of at least 10.5 median edge lengths, with
  `QUADRIC_FIT`: such a ball holds about 350 vertices or more, and its fit
  changes little from one vertex to the next, so it is fitted at centers
  more than a seventh of the smallest large radius apart (every vertex within
  that distance of one) and carried to each vertex by a weighted linear
  least-squares fit in the vertex's tangent plane over its center and the
  adjacent ones (exact where the curvature varies linearly; the shape
  operators are interpolated as tensors, the normals as vectors), at a
  fraction of the cost of a fit at every vertex (manual, "Neighborhoods").
  The centers are chosen greedily in a pseudo-random order given by a key
  per vertex (`fit_center_key_map`; by default a hash of the shape of its
  star, the lengths of its edges relative to the longest), so that the
  values depend neither on the vertices' numbering nor on a rigid motion or
  a scaling of the mesh, and a part of the mesh (a tile) gets the centers
  of the whole mesh away from its borders.
- `ring_size`: the `k`-ring of the vertex; up to two more rings are used when
  it is too small.

A neighborhood is too small or too degenerate for the fit with fewer
neighbors than unknowns, all neighbors along one line, or a singular
system. Border
vertices are estimated from their one-sided neighborhood. Faces of zero area
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
    \cgalParamDescription{output: the radius of the neighborhood used (for rings: the distance of the farthest neighbor used; NaN where the curvature is undefined)}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `GT::FT` as value}
    \cgalParamDefault{not computed}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_curvature_uncertainty_map}
    \cgalParamDescription{output: the standard uncertainties of `H`, `K` and the normal (the manual, section "Uncertainty"; NaN where unknown)}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `Curvature_uncertainty<GT>` as value}
    \cgalParamDefault{not computed}
  \cgalParamNEnd
  \cgalParamNBegin{neighborhood_radii}
    \cgalParamDescription{candidate radii, increasing, to choose from per vertex (see above)}
    \cgalParamType{`std::vector<double>`}
    \cgalParamDefault{empty: not used}
  \cgalParamNEnd
  \cgalParamNBegin{neighborhood_radius}
    \cgalParamDescription{the neighborhood's radius, in the units of the points (see above)}
    \cgalParamType{`double`}
    \cgalParamDefault{0: not used}
  \cgalParamNEnd
  \cgalParamNBegin{ring_size}
    \cgalParamDescription{the size `k >= 1` of the ring of neighbors used at each vertex}
    \cgalParamType{`int`}
    \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{estimator}
    \cgalParamDescription{the estimator}
    \cgalParamType{`Curvature_estimator`}
    \cgalParamDefault{`QUADRIC_FIT`}
  \cgalParamNEnd
  \cgalParamNBegin{noise_level}
    \cgalParamDescription{the standard deviation of the sample's noise along the normal, in the units of the points, before any smoothing (`Noise_estimate::noise` times `Noise_estimate::spacing`), for the choice among `neighborhood_radii`}
    \cgalParamType{`double`}
    \cgalParamDefault{0: measured at each vertex from the fits}
  \cgalParamNEnd
  \cgalParamNBegin{smoothing_radius}
    \cgalParamDescription{the radius, in the units of the points, over which the points were smoothed before the mesh was made (`Denoising_plan::smoothing_radius_in_spacings()` times the spacing after `denoise()`): in the uncertainties, a fit of radius `r` sees `noise_level` as a smooth field, `(r / smoothing_radius)^2` of itself below that radius, leveling off at 0.93 of it above (the manual, section \ref CAS3_Uncertainty)}
    \cgalParamType{`double`}
    \cgalParamDefault{0: the points were not smoothed}
  \cgalParamNEnd
  \cgalParamNBegin{smoothing_passes}
    \cgalParamDescription{the smoothing's passes (`Denoising_plan::passes`), with `smoothing_radius` (a value below 1 counts as 1): after two or more, fits smaller than 0.45 `smoothing_radius` see less of the noise still}
    \cgalParamType{`int`}
    \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{fit_center_key_map}
    \cgalParamDescription{the keys of the vertices in whose increasing order the large radii's centers are chosen (ties by position); the same keys for the same vertices of two meshes give the same centers where the meshes agree}
    \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `std::uint64_t` as value}
    \cgalParamDefault{a hash of the lengths of the vertex's edges relative to the longest: the same on a moved, turned or scaled copy of the mesh}
  \cgalParamNEnd
\cgalNamedParamsEnd

Here `GT` is the kernel of the points of the vertex point map.

\throws std::invalid_argument for a ring size below 1, a radius that is
negative or not finite, candidate radii that are not positive and increasing,
or candidate radii with another estimator than `QUADRIC_FIT`.
\throws std::length_error for a mesh of more than 2^32 - 1 vertices.

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
  typedef typename internal::Curvature_maps<PolygonMesh, NamedParameters>::GT GT;
  const internal::Curvature_maps<PolygonMesh, NamedParameters> maps(np);
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, pmesh));
  const Curvature_estimator estimator = internal::get_estimator<PolygonMesh>(np);
  const std::vector<internal::Neighborhood_rule> rules(1, internal::get_neighborhood_rule(np, estimator));
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(pmesh, np);
  const internal::Vertex_graph graph = internal::vertex_graph(pmesh, vpm, vertex_index);
  const std::vector<internal::Vec3> normals = internal::chen_wu_normals<ConcurrencyTag>(pmesh, vpm, vertex_index);
  const double noise =
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np_cas3::noise_level), 0.);
  const internal::Noise_smoothing smoothing = internal::get_noise_smoothing(np);
  std::vector<internal::Vertex_estimate> estimates(graph.size());
  internal::estimate_at_every_vertex<ConcurrencyTag>(
    graph, normals, rules, estimator, noise, 0, smoothing, internal::fit_center_keys(pmesh, vertex_index, graph, np),
    [&](std::size_t, std::size_t v, const internal::Vertex_estimate& e) { estimates[v] = e; },
    [&](std::size_t, std::size_t v, const internal::Bias_widening& bias) {
      internal::Vertex_estimate& e = estimates[v];
      bias.widen(e.uncertainty.H, e.uncertainty.K, e.radius);
    });
  std::size_t undefined = 0;
  for(vertex_descriptor v : vertices(pmesh))
  {
    const internal::Vertex_estimate& e = estimates[get(vertex_index, v)];
    undefined += e.defined() ? 0 : 1;
    maps.write(v, internal::to_vertex_curvature<GT>(e));
  }
  return undefined;
}

/*!
\ingroup PkgConformalAlphaShapes3Curvature
The same estimate for several neighborhoods at once, returned by
neighborhood (in their order), then by vertex index: cheaper than one call
per neighborhood, since each vertex's neighborhoods are found by one search,
the largest, and each fit runs on a part of it. Neighborhoods in sample
spacings (`Neighborhood::spacings()`, and the candidates of
`Neighborhood::automatic()`) are multiples of `sample_spacing`.

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map, vertex_index_map, estimator, noise_level, smoothing_radius, smoothing_passes}
    \cgalParamDescription{as above}
  \cgalParamNEnd
  \cgalParamNBegin{sample_spacing}
    \cgalParamDescription{the length of a sample spacing, in the units of the points (`Noise_estimate::spacing`); radii of at least 12 spacings are then the large ones, fitted at centers (instead of 10.5 median edge lengths: a length of the whole cloud, the same for any part of its surface)}
    \cgalParamType{`double`}
    \cgalParamDefault{0: no neighborhood may be in spacings}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument as above, and for a neighborhood in spacings
without a positive `sample_spacing`.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename PolygonMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<std::vector<Vertex_curvature<typename internal::Curvature_maps<PolygonMesh, NamedParameters>::GT> > >
estimate_vertex_curvatures(const PolygonMesh& pmesh, const std::vector<Neighborhood>& neighborhoods,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename internal::Curvature_maps<PolygonMesh, NamedParameters>::GT GT;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, pmesh));
  const Curvature_estimator estimator = internal::get_estimator<PolygonMesh>(np);
  const double spacing = choose_parameter(get_parameter(np, internal_np_cas3::sample_spacing), 0.);
  std::vector<internal::Neighborhood_rule> rules;
  for(const Neighborhood& neighborhood : neighborhoods)
  {
    const bool in_spacings = neighborhood.kind() == Neighborhood::SPACINGS || neighborhood.kind() == Neighborhood::AUTOMATIC;
    if(in_spacings && !(spacing > 0))
      throw std::invalid_argument("estimate_vertex_curvatures: a neighborhood in sample spacings needs a positive "
                                  "sample_spacing");
    rules.push_back(internal::neighborhood_rule(neighborhood, spacing));
    internal::check_neighborhood_rule(rules.back(), estimator);
  }
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(pmesh, np);
  const internal::Vertex_graph graph = internal::vertex_graph(pmesh, vpm, vertex_index);
  std::vector<std::vector<Vertex_curvature<GT> > > curvatures(rules.size(),
                                                              std::vector<Vertex_curvature<GT> >(graph.size()));
  internal::estimate_at_every_vertex<ConcurrencyTag>(
    graph, internal::chen_wu_normals<ConcurrencyTag>(pmesh, vpm, vertex_index), rules, estimator,
    choose_parameter(get_parameter(np, internal_np_cas3::noise_level), 0.), spacing,
    internal::get_noise_smoothing(np),
    internal::fit_center_keys(pmesh, vertex_index, graph, np),
    [&](std::size_t r, std::size_t v, const internal::Vertex_estimate& e) {
      curvatures[r][v] = internal::to_vertex_curvature<GT>(e);
    },
    [&](std::size_t r, std::size_t v, const internal::Bias_widening& bias) {
      Curvature_uncertainty<GT>& u = curvatures[r][v].uncertainty;
      bias.widen(u.mean_curvature, u.gaussian_curvature, CGAL::to_double(curvatures[r][v].radius));
    });
  return curvatures;
}

/*!
\ingroup PkgConformalAlphaShapes3Curvature
The same estimate at the single vertex `v`, written into the maps passed in
`np` at `v` only. Its cost is that of the vertex's neighborhood. Large
radii are fitted at `v` itself, not interpolated from centers: for them
the value differs slightly from the whole mesh's. The uncertainty's bias
part is `v`'s own bias rate, not its mean over the vertices around (which
would need their fits).
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
  const internal::Curvature_estimation estimation(graph, normals, rules, estimator, 0, 0, internal::Noise_smoothing(), nullptr);
  internal::Curvature_estimation::Workspace workspace = estimation.make_workspace();
  internal::Vertex_estimate estimate;
  internal::Bias_rates rates;
  estimation.estimate(0, workspace, &estimate, &rates);
  internal::Bias_pool own;  // the vertex's own: its neighbors' need their searches
  own.add(rates);
  if(rule.radius > 0 || !rule.candidates.empty())
    own.mean(estimation.bias_reference_radius()).widen(estimate.uncertainty.H, estimate.uncertainty.K, estimate.radius);
  typedef typename internal::Curvature_maps<PolygonMesh, NamedParameters>::GT GT;
  maps.write(v, internal::to_vertex_curvature<GT>(estimate));
  return estimate.defined();
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_ESTIMATE_VERTEX_CURVATURES_H
