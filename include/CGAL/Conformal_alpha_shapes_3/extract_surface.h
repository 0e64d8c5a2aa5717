// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_EXTRACT_SURFACE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_EXTRACT_SURFACE_H

#include <CGAL/Conformal_alpha_shapes_3/internal/solid_boundary_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_front.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_report.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Surface

Writes into `pmesh` the surface of the conformal alpha shape `cas` at scale
`a`, whose faces are facets of the triangulation, by one of two methods
(named parameter `surface_extraction`).

`ADVANCING_FRONT` (the default): one oriented 2-manifold sheet per part of
the sampled surface, closed where the sample is closed and with a border
where it stops (a single view, a facade), cut at `a` from the front of
`Surface_front`, grown anew at each call (keep a `Surface_front` to
extract several scales). Orientation (the manual, "Orientation"): with
`reference_normals`, every sheet faces the side that the majority of the
reference normals at its vertices point to; without, a closed sheet points
out of the volume it encloses and an open sheet away from the center of the
surface's vertices, or up (+z) where its cone from that center nearly
cancels and it mostly faces along z (a terrain). Parts that the front grew separately but that meet
along border edges are one sheet, oriented alike, so that the pieces of one
scan agree. Without reference normals, open sheets that continue each other
across a gap the front did not bridge (border vertices within 8 local
spacings of each other, the gap within 45 degrees of their tangent planes,
their normals within 45 degrees of parallel: a strip the scan missed, a step
whose riser it did not sample) face alike too, and point away from the
center together; sheets offset along their normals (the two faces of a thin
wall) are not joined, nor are closed sheets. An open sheet that nearly
closes round its own center (a blob with a small hole) is not joined
either, and points out of that center, as a closed sheet does.

`SOLID_BOUNDARY`: the boundary of the solid that the facets `REGULAR` or
`SINGULAR` at `a` enclose (the cells that a walk from the infinite cells
through facets not in the complex never reaches), outward, closed by
construction: candidate facets that do not bound the solid are dropped, its
non-manifold vertices mended by moving a few cells of their star into or
out of it, cells that hold a point just inside the surface removed, and each
umbrella of a vertex where it still pinches given a vertex of its own (the
manual, "The Solid Boundary"). A hole in the data wider than `a` lets the
walk into the volume, and that part of the surface is missing.

Faces and vertices are added to `pmesh`, which is usually empty; nothing is
added when `a` is below every facet value (or NaN) or `cas` is empty, and
the report says so.

\tparam ConformalAlphaShape a `Conformal_alpha_shape_3`
\tparam PolygonMesh a model of `MutableFaceGraph`
\tparam NamedParameters a sequence of named parameters

\param cas the conformal alpha shape
\param a the scale
\param pmesh the output mesh
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{surface_extraction}
    \cgalParamDescription{the method}
    \cgalParamType{`Surface_extraction`}
    \cgalParamDefault{`ADVANCING_FRONT`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the positions of the vertices of `pmesh`}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and a point type constructible from three `double` as value}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, pmesh)`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_input_index_map}
    \cgalParamDescription{output: for each vertex added to `pmesh`, the index of its input point (the smallest one when duplicates collapsed into the vertex; the same for the copies of a pinched vertex)}
    \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `std::size_t` as value}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{face_orientation_group_map}
    \cgalParamDescription{output: for each face added to `pmesh`, its orientation group, numbered from 0: the faces of one group were oriented together by one vote (a sheet, or the open sheets joined across gaps), so that a caller who cuts the surface into pieces, as a tiled run does, knows which pieces one vote turns together; `ADVANCING_FRONT` only}
    \cgalParamType{a model of `WritablePropertyMap` with `face_descriptor` as key and `std::size_t` as value}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{reference_normals}
    \cgalParamDescription{a normal per input point (a scanner's), or an empty range; `ADVANCING_FRONT` only}
    \cgalParamType{a random access range of `Vector_3`, indexed by input point}
    \cgalParamDefault{empty}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Surface_report`: faces, parts, and input points not on the surface.
*/
template <class ConformalAlphaShape, class PolygonMesh,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Surface_report extract_surface(const ConformalAlphaShape& cas, double a, PolygonMesh& pmesh,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  const Surface_extraction method = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np_cas3::surface_extraction), ADVANCING_FRONT);
  if(method == SOLID_BOUNDARY)
    return internal::extract_solid_boundary(cas, a, pmesh, np);
  return Surface_front<ConformalAlphaShape>(cas).extract_surface(a, pmesh, np);
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_EXTRACT_SURFACE_H
