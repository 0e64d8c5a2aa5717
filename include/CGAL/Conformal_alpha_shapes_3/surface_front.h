// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_SURFACE_FRONT_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_SURFACE_FRONT_H

#include <CGAL/Conformal_alpha_shapes_3/internal/conformal_front.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/orient_surface_parts.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/surface_output_maps.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/vertex_closing_value.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/vertices_by_index.h>
#include <CGAL/Conformal_alpha_shapes_3/interruption.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_report.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Surface

The automatic scale of `Surface_front::suggest_scale()` from (local)
closing values: the mean of the values above their `coverage` quantile
less the largest tenth of those, a trimmed tail: with `n` values (NaN left
out) sorted, the values of ranks from `floor(coverage * n)` up to, not
including, `floor((coverage + 0.9 * (1 - coverage)) * n)` (at least one),
summed in increasing order. A mean over the tail rather than one quantile, so that no
single value decides it. Infinity when every value is NaN.

\throws std::invalid_argument when `coverage` is outside `(0, 1]`
*/
inline double scale_of_closing_values(std::vector<double> values, double coverage)
{
  if(!(coverage > 0 && coverage <= 1))
    throw std::invalid_argument("scale_of_closing_values: coverage must be in (0, 1]");
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return std::isnan(v); }), values.end());
  if(values.empty())
    return std::numeric_limits<double>::infinity();
  std::sort(values.begin(), values.end());
  const double n = double(values.size());
  const std::size_t first = (std::min)(values.size() - 1, std::size_t(coverage * n));
  const std::size_t last =
    (std::max)(first + 1, (std::min)(values.size(), std::size_t((coverage + 0.9 * (1 - coverage)) * n)));
  double sum = 0;
  for(std::size_t k = first; k < last; ++k)
    sum += values[k];
  return sum / double(last - first);
}

/*!
\ingroup PkgConformalAlphaShapes3Surface

The advancing front of a conformal alpha shape, grown once with no bound on
the scale, from which the surface at any scale `a` is cut: the default
method of `extract_surface()` and `suggest_scale()`, which grow it anew at
each call; keep one `Surface_front` to extract several scales of one shape.

The front grows facet by facet over the Delaunay facets, from the smallest
conformal value, by the rules of CGAL's
`Advancing_front_surface_reconstruction` but on the shape's own
triangulation (no copy of it). (Facets between two cells of the complex are candidates too: under
noise, the flat cells along the sampled surface enter the complex before the
surface closes, and the facets between them are the surface.) It only grows
where the surface stays a manifold, so a noisy layer gives one sheet, not a
shell with an inner wall, and an open scan one sheet with a border, not a
two-sided slab. Vertices the front cannot attach are left off every
surface; so are pockets too small to carry curvature once they are all the
front finds (the manual, "The Advancing Front").

The shape must outlive the front and must not change while it is used.

\tparam ConformalAlphaShape a `Conformal_alpha_shape_3`
*/
template <class ConformalAlphaShape>
class Surface_front
{
public:
  typedef ConformalAlphaShape Shape;

  /// Grows the front over `cas`; an empty front when `cas` has dimension below 3.
  explicit Surface_front(const Shape& cas) : m_shape(cas), m_soup(internal::conformal_front_soup(cas)) {}

  /// the number of faces of the front (of the surface at an infinite scale)
  std::size_t number_of_faces() const { return m_soup.triangles.size(); }

  /*!
  The automatic scale: the smallest `a` at which the surface covers the
  points. Each vertex of the front needs its closing value (the smallest
  scale at which the complex holds a fan of facets around it,
  `closing_values()`) for the surface to close around it; the scale
  returned is `scale_of_closing_values()` of the local closing values
  (`local_closing_values()`) with this `coverage`: about the `coverage`
  quantile of the closing values, read off their spatially smoothed upper
  tail, so that no few vertices decide it. At that scale, about that share
  of the vertices can close, and the rest (a border that would need larger
  facets, gaps in the sampling) is left as a border rather than
  bridged. On samples of closed or open surfaces, clean or noisy (after
  denoising), the surface at this scale holds over 99% of the points (the
  manual gives the measurements). It fails where the sample does not
  describe a surface at all (a volume of points, scattered noise): then the
  front itself is poor, and so is the scale. Infinity for an empty front.

  \throws std::invalid_argument when `coverage` is outside `(0, 1]`
  */
  double suggest_scale(double coverage = 0.99) const
  {
    if(!(coverage > 0 && coverage <= 1))
      throw std::invalid_argument("suggest_scale: coverage must be in (0, 1]");
    return scale_of_closing_values(local_closing_values(), coverage);
  }

  /*!
  The closing value of every vertex of the front, by `vertex_index()`: the
  smallest conformal value at which the finite Delaunay facets around the
  vertex that are in the complex hold a fan turning once around it (seen
  along the axis to its pole), the scale from which the surface can close
  around it. NaN for the vertices the front does not reach and for those
  with no such fan (on the convex hull, their outside open). A value of the
  vertex's star, not of the front's growth: the same in a piece of the
  cloud whose halo holds the star and its vertices' poles as in the whole
  cloud.
  */
  std::vector<double> closing_values() const
  {
    std::vector<double> closing(m_shape.number_of_vertices(), std::numeric_limits<double>::quiet_NaN());
    const std::vector<typename Shape::Vertex_handle> handle = internal::vertices_by_index(m_shape);
    std::vector<std::size_t> reached(m_soup.shape_vertex);
    std::sort(reached.begin(), reached.end());
    reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
    internal::for_each_index<CGAL::Parallel_if_available_tag>(
      reached.size(), [] { return internal::Closing_workspace<Shape>(); },
      [&](std::size_t i, internal::Closing_workspace<Shape>& workspace) {
        closing[reached[i]] = internal::vertex_closing_value(m_shape, handle[reached[i]], workspace);
      });
    return closing;
  }

  /*!
  The local closing value of every vertex of the shape, by
  `vertex_index()`: the upper quartile (the 19th smallest of 24) of the
  closing values of the vertex and its 23 nearest vertices of the front,
  of those that are not NaN; NaN where `closing_values()` is.
  `suggest_scale()` reads these, so the automatic scale of a sample split
  into pieces (tiles with a halo, the manual's "Tiled Processing on Dask")
  is `scale_of_closing_values()` of the pieces' values pooled.
  */
  std::vector<double> local_closing_values() const
  {
    typedef typename Shape::Geom_traits Kernel;
    typedef typename Kernel::Point_3 Point;
    typedef CGAL::Search_traits_adapter<std::size_t, typename CGAL::Pointer_property_map<Point>::type,
                                        CGAL::Search_traits_3<Kernel> > Traits;
    typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
    typedef typename Search::Tree Tree;
    const std::vector<double> closing = closing_values();
    std::vector<double> local(closing.size(), std::numeric_limits<double>::quiet_NaN());
    const std::size_t n = m_soup.shape_vertex.size();
    if(n == 0)
      return local;
    std::vector<Point> position(m_shape.number_of_vertices());
    for(typename Shape::Vertex_handle v : m_shape.finite_vertex_handles())
      position[v->vertex_index()] = v->point();
    const typename CGAL::Pointer_property_map<Point>::type position_map = CGAL::make_property_map(position);
    Tree tree(m_soup.shape_vertex.begin(), m_soup.shape_vertex.end(), typename Tree::Splitter(),
              Traits(position_map));
    tree.build();
    const typename Search::Distance distance(position_map);
    const unsigned int neighbors = unsigned((std::min)(n, std::size_t(24)));
    internal::for_each_index<CGAL::Parallel_if_available_tag>(
      n, [] { return std::vector<double>(); },
      [&](std::size_t i, std::vector<double>& values) {
        const std::size_t s = m_soup.shape_vertex[i];
        if(std::isnan(closing[s]))
          return;
        values.clear();
        for(const auto& found : Search(tree, position[s], neighbors, 0, true, distance))
          if(!std::isnan(closing[found.first]))
            values.push_back(closing[found.first]);
        const std::size_t upper_quartile = (3 * values.size()) / 4;
        std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(upper_quartile), values.end());
        local[s] = values[upper_quartile];
      });
    return local;
  }

  /*!
  Writes into `pmesh` the surface at scale `a`: the front less its faces
  whose conformal value exceeds `a` (their neighbors get a border there, and
  pieces of fewer than 8 faces left on their own are dropped), oriented as
  `extract_surface()` says, whose named parameters (but
  `surface_extraction`) it takes.
  */
  template <class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
  Surface_report extract_surface(double a, PolygonMesh& pmesh,
                                 const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    return surface_of_soup(internal::pruned_soup(m_soup, a), pmesh, np);
  }

private:
  // The soup's parts joined into sheets and oriented, written into `pmesh`.
  template <class PolygonMesh, class NamedParameters>
  Surface_report surface_of_soup(internal::Advancing_front_soup soup, PolygonMesh& pmesh,
                                 const NamedParameters& np) const
  {
    typedef typename Shape::Geom_traits::Vector_3 Vector;
    typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
    const Shape& cas = m_shape;
    const internal::Surface_output_maps<PolygonMesh, NamedParameters> output(pmesh, np);
    const std::vector<Vector> no_normals;
    const auto& reference_normals = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter_reference(np, internal_np_cas3::reference_normals), no_normals);

    Surface_report report;
    report.number_of_input_points = cas.number_of_input_points();
    report.number_of_points_off_surface = cas.number_of_input_points();
    if(cas.dimension() < 3)
      return report;

    const std::vector<typename Shape::Vertex_handle> shape_vertex = internal::vertices_by_index(cas);
    auto point = [&](std::size_t s) { return shape_vertex[soup.shape_vertex[s]]->point(); };
    const bool has_reference = !reference_normals.empty();
    auto given = [&](std::size_t s) {
      return Vector(reference_normals[*cas.input_indices(shape_vertex[soup.shape_vertex[s]]).begin()]);
    };
    std::vector<Vector> follow;
    if(has_reference)
      follow = internal::normals_to_follow<Vector>(soup, cas.number_of_vertices(), point, given,
                                                   report.number_of_sheets_with_inconsistent_normals);
    auto reference = [&](std::size_t s) { return follow[soup.shape_vertex[s]]; };
    // each step below is a pass over the soup: checked between them, and
    // within the passes that build the mesh
    internal::Interruption_point interruption;
    if(has_reference)
      internal::cut_at_reference_folds<Vector>(soup, point, reference);
    const internal::Soup_parts parts = internal::soup_parts(soup);
    interruption.throw_if_stopped();
    const internal::Soup_sheets sheets = internal::soup_sheets(soup, parts);
    interruption.throw_if_stopped();
    const internal::Sheet_groups groups = has_reference
      ? internal::Sheet_groups::one_per_sheet(sheets.size())
      : internal::join_open_sheets_across_gaps<Vector>(soup, parts, sheets, point);
    interruption.throw_if_stopped();
    const std::vector<char> reverse =
      internal::parts_to_reverse<Vector>(soup, parts, sheets, groups, point, reference, has_reference);
    interruption.throw_if_stopped();

    report.number_of_parts = sheets.size();
    for(std::size_t s = 0; s < sheets.size(); ++s)
      report.number_of_closed_parts += sheets.closed[s] ? 1 : 0;
    for(std::size_t p = 0; p < parts.size(); ++p)
      report.number_of_reversed_parts += reverse[p] ? 1 : 0;
    report.oriented_by_reference_normals = has_reference;

    std::vector<vertex_descriptor> mesh_vertex(soup.shape_vertex.size());
    for(std::size_t s = 0; s < soup.shape_vertex.size(); ++s)
    {
      if(s % 4096 == 0)
        interruption.throw_if_stopped();
      mesh_vertex[s] =
        output.new_vertex(pmesh, point(s), *cas.input_indices(shape_vertex[soup.shape_vertex[s]]).begin());
    }
    report.number_of_vertices = soup.shape_vertex.size();

    for(std::size_t t = 0; t < soup.triangles.size(); ++t)
    {
      if(t % 4096 == 0)
        interruption.throw_if_stopped();
      const std::array<std::size_t, 3>& tri = soup.triangles[t];
      const bool flip = reverse[parts.part_of_triangle[t]] != 0;
      const std::array<vertex_descriptor, 3> face = {mesh_vertex[tri[0]], mesh_vertex[flip ? tri[2] : tri[1]],
                                                     mesh_vertex[flip ? tri[1] : tri[2]]};
      const auto f = CGAL::Euler::add_face(face, pmesh);
      if(f == boost::graph_traits<PolygonMesh>::null_face())
        continue;
      ++report.number_of_faces;
      output.set_face_group(f, groups.group_of_sheet[sheets.sheet_of_part[parts.part_of_triangle[t]]]);
    }
    if(has_reference)
      report.reference_normal_agreement = internal::reference_agreement<Vector>(soup, parts, reverse, point, given);

    std::vector<char> on(cas.number_of_vertices(), 0);
    for(std::size_t s : soup.shape_vertex)
      on[s] = 1;
    report.number_of_points_off_surface = internal::number_of_points_off(cas, on);
    return report;
  }

  const Shape& m_shape;
  internal::Advancing_front_soup m_soup;
};

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_SURFACE_FRONT_H
