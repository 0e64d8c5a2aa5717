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

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <type_traits>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

namespace internal {

// transfer_to_points(), the layers made by `make_layers()` once the shape is
// read and the points off the surface are found.
template <class ConcurrencyTag, class ConformalAlphaShape, class PolygonMesh, class MakeLayers,
          class PointCurvatureMaps, class NamedParameters>
void transfer_in_steps(const ConformalAlphaShape& cas, const PolygonMesh& pmesh, MakeLayers make_layers,
                       PointCurvatureMaps point_curvatures, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  static_assert(!CGAL::parameters::is_default_parameter<NamedParameters,
                                                        internal_np_cas3::vertex_input_index_map_t>::value,
                "transfer_to_points needs the named parameter vertex_input_index_map");
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NamedParameters>::const_type Vertex_point_map;
  // the surface is searched in the kernel of its points
  typedef typename Kernel_traits<typename boost::property_traits<Vertex_point_map>::value_type>::Kernel GT;
  const Vertex_point_map vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, pmesh));
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(pmesh, np);
  const std::vector<typename GT::Vector_3> no_normals;
  // the shape is read first, all of it, so that `release_shape` may free it
  const auto table = shape_vertex_table<ConcurrencyTag>(
    cas, pmesh, get_parameter(np, internal_np_cas3::vertex_input_index_map), vertex_index);
  std::vector<bool> off_surface = vertices_off_surface(table);
  const std::vector<double> far = far_distances(cas, table, off_surface);
  choose_parameter(get_parameter(np, internal_np_cas3::release_shape), []() {})();

  // the feet of the vertices off the surface are found before the layers
  // are made, so that the search tree is not held with their values
  auto feet = surface_feet<ConcurrencyTag, GT>(table, pmesh, vpm, off_surface, far);
  drop_far_feet(feet, far);
  std::vector<bool>().swap(off_surface);
  auto&& layers = make_layers();
  add_feet_on_surface<ConcurrencyTag, GT>(table, pmesh, vpm, needs_foot(table, layers), feet);
  write_at_points<ConcurrencyTag>(
    table, pmesh, vpm, vertex_index, layers, feet, point_curvatures,
    choose_parameter(CGAL::parameters::get_parameter_reference(np, internal_np_cas3::reference_normals), no_normals));
}

} // namespace internal

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
empty). Where several surface vertices with defined values stand for one vertex
of the shape (a pinched vertex, where sheets meet), the point takes their
mean weighted by a third of each one's facets' area, as above where their
normals nearly cancel, so that no order of the surface's vertices decides. With
`reference_normals`, a point whose reference normal points to the other
side of the surface gets the values seen from that side: normal and mean
and principal curvatures negated, principal directions swapped.

The nearest surface points are searched once for all layers, those of the
shape's vertices that are not vertices of `pmesh` before `layers` is read
(see the overload below); each layer's vertex values are released
(`layers[k]` emptied) once it is transferred, so that they and the points'
values are not all held at once.

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
  \cgalParamNBegin{release_shape}
    \cgalParamDescription{called once the function no longer reads `cas`, before it searches the surface, so that the caller may free the shape then}
    \cgalParamType{a function object callable as `release_shape()`}
    \cgalParamDefault{none}
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
  internal::transfer_in_steps<ConcurrencyTag>(cas, pmesh, [&layers]() -> auto& { return layers; }, point_curvatures,
                                              np);
}

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

The same transfer, with layers made when it asks for them: `make_layers()`
is called once, after `cas` is read (and `release_shape` called) and the
nearest surface points of the shape's vertices that are not vertices of
`pmesh` are found, and its layers are transferred as `layers` above. A
caller that estimates the vertex values there (`estimate_vertex_curvatures()`)
and frees the shape in `release_shape` holds the values with neither the
shape nor the search tree over the surface's faces, as
`Multiscale_curvatures` does; the points' values are those that the
layers given at once would get.

\tparam MakeLayers a function object callable as `make_layers()`, returning
        a `std::vector<std::vector<Vertex_curvature<GT> > >` or a reference
        to one (whose layers are then emptied as they are transferred)
*/
template <class ConcurrencyTag = CGAL::Sequential_tag, class ConformalAlphaShape, class PolygonMesh, class MakeLayers,
          class PointCurvatureMaps, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::enable_if_t<std::is_invocable<MakeLayers&>::value>
transfer_to_points(const ConformalAlphaShape& cas, const PolygonMesh& pmesh, MakeLayers make_layers,
                   PointCurvatureMaps point_curvatures, const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::transfer_in_steps<ConcurrencyTag>(cas, pmesh, make_layers, point_curvatures, np);
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_TRANSFER_TO_POINTS_H
