// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CURVATURE_PARAMETERS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CURVATURE_PARAMETERS_H

// What `estimate_vertex_curvatures()` reads from its arguments: the
// estimator, the neighborhood rules and the keys of the fit centers, and
// which of its overloads a call selects.

#include <CGAL/Conformal_alpha_shapes_3/curvature_estimator.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/curvature_estimation.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/fit_centers.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/scales_and_neighborhoods.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {


// The vertex type of a mesh; no type for a parameter pack or a concurrency
// tag, so that the single-vertex overload drops out of
// `estimate_vertex_curvatures(mesh, np)` and `estimate_vertex_curvatures<Tag>(mesh, np)`.
template <typename PolygonMesh, bool = Is_named_function_parameters<PolygonMesh>::value
                                       || std::is_base_of<CGAL::Sequential_tag, PolygonMesh>::value>
struct Vertex_of { typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor type; };
template <typename PolygonMesh>
struct Vertex_of<PolygonMesh, true> {};

template <typename PolygonMesh, typename NamedParameters>
Curvature_estimator get_estimator(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np_cas3::estimator), QUADRIC_FIT);
}

// `smoothing_radius` and `smoothing_passes` (at least one pass where a radius is given).
template <typename NamedParameters>
Noise_smoothing get_noise_smoothing(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Noise_smoothing smoothing;
  smoothing.reach = choose_parameter(get_parameter(np, internal_np_cas3::smoothing_radius), 0.);
  smoothing.passes = smoothing.reach > 0 ? (std::max)(1, choose_parameter(get_parameter(np, internal_np_cas3::smoothing_passes), 1)) : 0;
  return smoothing;
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

// The rule of `neighborhood`, whose spacings are `spacing` long.
inline Neighborhood_rule neighborhood_rule(const Neighborhood& neighborhood, double spacing)
{
  Neighborhood_rule rule;
  switch(neighborhood.kind())
  {
    case Neighborhood::RINGS: rule.rings = int(neighborhood.value()); break;
    case Neighborhood::RADIUS: rule.radius = neighborhood.value(); break;
    case Neighborhood::SPACINGS: rule.radius = neighborhood.value() * spacing; break;
    case Neighborhood::AUTOMATIC:
      for(double m : Neighborhood::automatic_radii())
        rule.candidates.push_back(m * spacing);
      break;
  }
  return rule;
}

// By vertex index, the keys of `fit_center_key_map`, or those of the
// shapes of the vertices' stars in `graph`.
template <typename PolygonMesh, typename VertexIndexMap, typename NamedParameters>
std::vector<std::uint64_t> fit_center_keys(const PolygonMesh& pmesh, const VertexIndexMap& vertex_index,
                                           const Vertex_graph& graph, const NamedParameters& np)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, internal_np_cas3::fit_center_key_map_t>::value)
    return star_shape_keys(graph);
  else
  {
    const auto given = CGAL::parameters::get_parameter(np, internal_np_cas3::fit_center_key_map);
    std::vector<std::uint64_t> keys(graph.size());
    for(auto v : vertices(pmesh))
      keys[get(vertex_index, v)] = std::uint64_t(get(given, v));
    return keys;
  }
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_CURVATURE_PARAMETERS_H
