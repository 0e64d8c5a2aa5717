// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_TRANSFER_TO_POINTS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_TRANSFER_TO_POINTS_H

// The public function; the tables it reads of the shape, the search of the
// nearest surface points and the interpolation there are in internal/
// (shape_vertex_table.h, surface_feet.h, values_at_points.h).

#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/shape_vertex_table.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/surface_feet.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/values_at_points.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/point_curvature.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

Gives every input point of the conformal alpha shape `cas` the values that
the layers `layers` hold at the vertices of a surface `pmesh` of the shape
(from `extract_surface()`, with values from `estimate_vertex_curvatures()`),
writing layer `k`'s value of input point `i` at key `i` into the map that
`point_curvatures(k)` returns, called once for each layer, in order, just
before its values are written (so that the caller may allocate a layer's
storage only then). A point whose vertex is a vertex of the surface with a defined
value takes that value (`SURFACE_VERTEX`); any other point takes the values
at its nearest point on the surface, interpolated over the facet there by
barycentric weights over the corners with values (`NEAREST_SURFACE_POINT`,
with the distance; where that point is a corner without a value, the mean
of the corner's neighbors with values; where the normals averaged nearly
cancel, their weighted sum shorter than one half, the values of the one of
largest weight), unless it is farther than `far_from_surface()` local
spacings (`NO_VALUE`, all NaN; so is every point when the surface is
empty). Where several surface vertices stand for one vertex of the shape
(a pinched vertex), the first with a defined value gives it. With
`reference_normals`, a point whose reference normal points to the other
side of the surface gets the values seen from that side: normal and mean
and principal curvatures negated, principal directions swapped.

The nearest surface points are searched once for all layers; each layer's
vertex values are released (`layers[k]` emptied) once it is transferred, so
that they and the points' values are not all held at once.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_if_available_tag`
        (TBB's threads; the same results)
\tparam PointCurvatureMaps a function object taking a layer index and
        returning a model of `WritablePropertyMap` with `std::size_t` (an
        input index of `cas`) as key and `Point_curvature<GT>` as value,
        written for distinct keys from several threads with a parallel tag

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_input_index_map}
    \cgalParamDescription{the input index of `cas` of each vertex of `pmesh` (as `extract_surface()` writes it); required}
    \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `std::size_t` as value}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the positions of the vertices of `pmesh`, in the coordinates of `cas`}
    \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `GT::Point_3` as value}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, pmesh)`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_index_map}
    \cgalParamDescription{the index of each vertex in `layers[k]`}
    \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `std::size_t` as value}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
  \cgalParamNBegin{reference_normals}
    \cgalParamDescription{a normal per input point of `cas`, or an empty range}
    \cgalParamType{a random access range of `GT::Vector_3`}
    \cgalParamDefault{empty}
  \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class ConcurrencyTag = CGAL::Sequential_tag, class ConformalAlphaShape, class PolygonMesh, class GT,
          class PointCurvatureMaps, class NamedParameters = CGAL::parameters::Default_named_parameters>
void transfer_to_points(const ConformalAlphaShape& cas, const PolygonMesh& pmesh,
                        std::vector<std::vector<Vertex_curvature<GT> > >& layers,
                        PointCurvatureMaps point_curvatures,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  static_assert(!CGAL::parameters::is_default_parameter<NamedParameters,
                                                        internal_np_cas3::vertex_input_index_map_t>::value,
                "transfer_to_points needs the named parameter vertex_input_index_map");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, pmesh));
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(pmesh, np);
  const std::vector<typename GT::Vector_3> no_normals;
  const auto table = internal::shape_vertex_table<ConcurrencyTag>(
    cas, pmesh, get_parameter(np, internal_np_cas3::vertex_input_index_map), vertex_index);
  // the feet are found once for all layers, so that the search tree over
  // the surface's faces is freed before the values are written
  const std::vector<bool> needs_foot = internal::needs_foot(table, layers);
  const std::vector<double> far = internal::far_distances(cas, table, needs_foot);
  auto feet = internal::surface_feet<ConcurrencyTag, GT>(table, pmesh, vpm, needs_foot, far);
  internal::drop_far_feet(feet, far);
  internal::write_at_points<ConcurrencyTag>(
    table, pmesh, vpm, vertex_index, layers, feet, point_curvatures,
    choose_parameter(CGAL::parameters::get_parameter_reference(np, internal_np_cas3::reference_normals), no_normals));
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_TRANSFER_TO_POINTS_H
