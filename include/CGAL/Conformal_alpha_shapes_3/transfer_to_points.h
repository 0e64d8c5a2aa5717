// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_TRANSFER_TO_POINTS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_TRANSFER_TO_POINTS_H

#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/input_index_table.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/sample_spacing.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Bbox_3.h>
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
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
Where the values of an input point at one scale come from.
*/
enum Point_source
{
  /// the fit at the point's own vertex of the surface
  SURFACE_VERTEX,
  /// the values of the surface at its point nearest to the input point,
  /// interpolated over the facet there: the point is not a vertex of the
  /// surface, or its own fit is undefined
  NEAREST_SURFACE_POINT,
  /// none: the point is farther from the surface than
  /// `far_from_surface()` local spacings, or the surface
  /// near it has no defined values; every number is NaN
  NO_VALUE
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
The curvature of the surface at one input point, at one scale and
neighborhood; every number is NaN where `source` is `NO_VALUE`.
*/
template <class Kernel>
struct Point_curvature
{
  Point_source source = NO_VALUE;
  /// from the (smoothed) point to the surface point whose values these are
  /// (0 on its own vertex; NaN when the surface is empty)
  double distance = std::numeric_limits<double>::quiet_NaN();
  /// the radius of the neighborhood of the fit (for rings: the farthest
  /// neighbor used); interpolated like the values
  double radius = std::numeric_limits<double>::quiet_NaN();
  typename Kernel::Vector_3 normal = typename Kernel::Vector_3(std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
  typename Kernel::FT mean_curvature = std::numeric_limits<double>::quiet_NaN();
  typename Kernel::FT gaussian_curvature = std::numeric_limits<double>::quiet_NaN();
  /// `max_curvature` is `k1`, `max_direction` `d1`; `min_curvature` is `k2`
  Principal_curvatures_and_directions<Kernel> principal;
  /// the standard uncertainties of `H`, `K` and the normal: those of the
  /// vertex, or interpolated like the values and grown with `distance` (the
  /// manual, section "Uncertainty")
  Curvature_uncertainty<Kernel> uncertainty;

  /// whether the values are the point's own vertex's
  bool on_surface() const { return source == SURFACE_VERTEX; }
};

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// How far, in local spacings, an input point may be from the surface and
/// still take its values in `transfer_to_points()`; the local spacing of a
/// point is the length of its vertex's third-shortest Delaunay edge.
constexpr double far_from_surface() { return 4; }

namespace internal {

// Where a vertex of the shape without a value of its own meets the surface:
// the nearest point of the surface, on `face`; `face` is null when the
// vertex is farther than `far_from_surface()` local spacings.
template <class Point, class Face>
struct Surface_foot
{
  std::size_t shape_vertex;  // vertex index
  Point point;
  Face face;
  double distance;
};

// The same curvature seen from the other side of the surface: the normal
// and the signs of the curvatures flip, the principal directions swap roles
// (so that d1 x d2 is still the normal).
template <class GT>
void take_other_side(Point_curvature<GT>& c)
{
  Principal_curvatures_and_directions<GT>& p = c.principal;
  c.normal = -c.normal;
  c.mean_curvature = -c.mean_curvature;
  const double max_curvature = -p.min_curvature;
  p.min_curvature = -p.max_curvature;
  p.max_curvature = max_curvature;
  std::swap(p.max_direction, p.min_direction);
}

// The uncertainty of values taken at the nearest surface point, `distance`
// away: the point's own place on the surface is unknown within about that
// distance, over which the values change at a rate that the curvature
// bounds in scale (|grad H| ~ k^2, the normal turns by k per unit length),
// added in quadrature.
template <class GT>
Curvature_uncertainty<GT> grown_uncertainty(const Curvature_uncertainty<GT>& u, double distance, double k1, double k2)
{
  const double k = (std::max)(std::abs(k1), std::abs(k2));
  const double d = std::isfinite(distance) ? distance : 0.;
  const double H = d * k * k, K = 2 * k * H, normal = d * k * (180 / 3.14159265358979323846);
  Curvature_uncertainty<GT> grown;
  grown.mean_curvature = std::sqrt(u.mean_curvature * u.mean_curvature + H * H);
  grown.gaussian_curvature = std::sqrt(u.gaussian_curvature * u.gaussian_curvature + K * K);
  grown.normal_degrees = std::sqrt(u.normal_degrees * u.normal_degrees + normal * normal);
  return grown;
}

// The value at the vertex of index `v` of the shape: its own surface
// vertex's (`own_vertex`), or else interpolated at the nearest point of the
// surface (`feet`, sorted by vertex), or none.
template <class GT, class PolygonMesh, class VertexPointMap, class VertexIndexMap, class Foot>
Point_curvature<GT> value_at_vertex(std::size_t v, std::size_t own_vertex, const PolygonMesh& pmesh,
                                    const VertexPointMap& vpm, const VertexIndexMap& vertex_index,
                                    const std::vector<Vertex_curvature<GT> >& values, const std::vector<Foot>& feet)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename GT::Vector_3 Vector;
  auto record = [](Point_source source, double distance, double r, const Vector& n, double max_k, double min_k,
                   const Vector& max_d, const Vector& min_d) {
    Point_curvature<GT> c;
    c.source = source;
    c.distance = distance;
    c.radius = r;
    c.normal = n;
    c.mean_curvature = (max_k + min_k) / 2;
    c.gaussian_curvature = max_k * min_k;
    c.principal = Principal_curvatures_and_directions<GT>{max_k, min_k, max_d, min_d};
    return c;
  };
  auto vec3 = [](const Vector& x) { return Vec3(x.x(), x.y(), x.z()); };
  auto vector = [](const Vec3& x) { return Vector(x.x(), x.y(), x.z()); };
  Point_curvature<GT> c;  // NaN everywhere

  if(own_vertex != std::size_t(-1))
  {
    const Vertex_curvature<GT>& e = values[own_vertex];
    Point_curvature<GT> own = record(SURFACE_VERTEX, 0, e.radius, e.normal, e.principal.max_curvature,
                                     e.principal.min_curvature, e.principal.max_direction, e.principal.min_direction);
    own.uncertainty = e.uncertainty;
    return own;
  }

  const auto foot = std::lower_bound(feet.begin(), feet.end(), v,
                                     [](const Foot& f, std::size_t x) { return f.shape_vertex < x; });
  if(foot == feet.end() || foot->shape_vertex != v)  // the surface is empty
    return c;
  c.distance = foot->distance;
  if(foot->face == typename boost::graph_traits<PolygonMesh>::face_descriptor())
    return c;
  vertex_descriptor corner[3];
  int i = 0;
  for(vertex_descriptor u : vertices_around_face(halfedge(foot->face, pmesh), pmesh))
    corner[i++] = u;
  auto value = [&](vertex_descriptor u) -> const Vertex_curvature<GT>& { return values[get(vertex_index, u)]; };
  // The vertices whose values the nearest point takes, with their weights:
  // the facet's corners with values, by barycentric weights; where the
  // nearest point is a corner (the other two weights vanish to rounding)
  // without a value, that corner's neighbors with values, alike, so that it
  // does not matter which of the corner's facets the search named.
  std::vector<std::pair<vertex_descriptor, double> > sources;
  double area[3];
  for(int j = 0; j < 3; ++j)
    area[j] = std::sqrt(CGAL::to_double(CGAL::squared_area(foot->point, get(vpm, corner[(j + 1) % 3]),
                                                           get(vpm, corner[(j + 2) % 3]))));
  for(int j = 0; j < 3 && sources.empty(); ++j)
    if(!value(corner[j]).is_defined() && area[j] > 0 && area[(j + 1) % 3] <= 1e-9 * area[j]
       && area[(j + 2) % 3] <= 1e-9 * area[j])
      for(vertex_descriptor u : vertices_around_target(corner[j], pmesh))
        if(value(u).is_defined())
          sources.emplace_back(u, 1.);
  if(sources.empty())
  {
    for(int j = 0; j < 3; ++j)
      if(value(corner[j]).is_defined() && area[j] > 0)
        sources.emplace_back(corner[j], area[j]);
    if(sources.empty())  // a degenerate facet: its corners with values, alike
      for(int j = 0; j < 3; ++j)
        if(value(corner[j]).is_defined())
          sources.emplace_back(corner[j], 1.);
  }
  if(sources.empty())
    return c;
  double total = 0;
  for(const auto& source : sources)
    total += source.second;
  Vec3 n = Vec3::Zero(), max_d = Vec3::Zero();
  double r = 0, max_k = 0, min_k = 0;
  const Vec3 reference_d1 = vec3(value(sources.front().first).principal.max_direction);
  for(const auto& source : sources)
  {
    const double w = source.second / total;
    const Vertex_curvature<GT>& source_value = value(source.first);
    n += w * vec3(source_value.normal);
    // a principal direction is a line: align signs before averaging
    const Vec3 d1 = vec3(source_value.principal.max_direction);
    max_d += (d1.dot(reference_d1) < 0 ? -w : w) * d1;
    r += w * source_value.radius;
    max_k += w * source_value.principal.max_curvature;
    min_k += w * source_value.principal.min_curvature;
  }
  // Sources whose normals nearly cancel (a fold of the surface) have no
  // meaningful average: the source of largest weight speaks for the point.
  if(!(n.norm() > 0.5))
  {
    const auto heaviest = std::max_element(sources.begin(), sources.end(),
                                           [](const auto& x, const auto& y) { return x.second < y.second; });
    const Vertex_curvature<GT>& e = value(heaviest->first);
    Point_curvature<GT> nearest = record(NEAREST_SURFACE_POINT, c.distance, e.radius, e.normal,
                                         e.principal.max_curvature, e.principal.min_curvature,
                                         e.principal.max_direction, e.principal.min_direction);
    nearest.uncertainty = grown_uncertainty(e.uncertainty, c.distance, e.principal.max_curvature,
                                            e.principal.min_curvature);
    return nearest;
  }
  Curvature_uncertainty<GT> u;
  u.mean_curvature = u.gaussian_curvature = u.normal_degrees = 0;
  for(const auto& source : sources)
  {
    const double w = source.second / total;
    const Curvature_uncertainty<GT>& s = value(source.first).uncertainty;
    u.mean_curvature += w * s.mean_curvature;
    u.gaussian_curvature += w * s.gaussian_curvature;
    u.normal_degrees += w * s.normal_degrees;
  }
  n.normalize();
  max_d = (max_d - max_d.dot(n) * n).normalized();
  Point_curvature<GT> nearest =
    record(NEAREST_SURFACE_POINT, c.distance, r, vector(n), max_k, min_k, vector(max_d), vector(n.cross(max_d)));
  nearest.uncertainty = grown_uncertainty(u, c.distance, max_k, min_k);
  return nearest;
}

// What the transfer reads of the shape, taken from it at once, so that a
// caller may free the shape before the values are written
// (`Multiscale_curvatures` does when it is consumed).
template <class Point>
struct Shape_vertex_table
{
  // per surface vertex, in the order of vertices(pmesh): its index in the
  // layers and its shape vertex (by vertex index)
  std::vector<std::pair<std::size_t, std::size_t> > index_and_shape_vertex;
  std::vector<Point> points;        // by vertex index
  Input_index_table input_indices;  // by vertex index

  std::size_t number_of_shape_vertices() const { return points.size(); }
};

// The table of `cas` and its surface `pmesh` (on TBB's threads as the tag
// says: each surface vertex's shape vertex is a walk through its input index).
template <class ConcurrencyTag, class Cas, class PolygonMesh, class InputIndexMap, class VertexIndexMap>
Shape_vertex_table<typename Cas::Point> shape_vertex_table(const Cas& cas, const PolygonMesh& pmesh,
                                                           const InputIndexMap& input_index,
                                                           const VertexIndexMap& vertex_index)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  Shape_vertex_table<typename Cas::Point> table;
  const std::vector<vertex_descriptor> surface_vertices(vertices(pmesh).first, vertices(pmesh).second);
  table.index_and_shape_vertex.resize(surface_vertices.size());
  for_each_index<ConcurrencyTag>(surface_vertices.size(), []() { return 0; }, [&](std::size_t k, int&) {
    const vertex_descriptor v = surface_vertices[k];
    table.index_and_shape_vertex[k] = std::make_pair(std::size_t(get(vertex_index, v)),
                                                     std::size_t(cas.input_vertex(get(input_index, v))->vertex_index()));
  });
  table.points.resize(cas.number_of_vertices());
  for(const typename Cas::Vertex_handle v : cas.finite_vertex_handles())
    table.points[v->vertex_index()] = v->point();
  std::vector<std::size_t> vertex_of_input(cas.number_of_input_points());
  for_each_index<ConcurrencyTag>(vertex_of_input.size(), []() { return 0; }, [&](std::size_t i, int&) {
    vertex_of_input[i] = cas.input_vertex(i)->vertex_index();
  });
  table.input_indices.assign(vertex_of_input, cas.number_of_vertices());
  return table;
}

// For every vertex of the shape (by vertex index), the surface vertex whose
// value in `values` it takes: its own first; at a pinch, the first one
// whose value is defined; none (-1) when none is.
template <class Point, class Value>
std::vector<std::size_t> own_vertices(const Shape_vertex_table<Point>& table, const std::vector<Value>& values)
{
  std::vector<std::size_t> own(table.number_of_shape_vertices(), std::size_t(-1));
  for(const std::pair<std::size_t, std::size_t>& v : table.index_and_shape_vertex)
  {
    std::size_t& o = own[v.second];
    if(o == std::size_t(-1) && values[v.first].is_defined())
      o = v.first;
  }
  return own;
}

// Whether each vertex of the shape (by vertex index) takes its value from
// its foot on the surface in some layer of `layers`.
template <class Point, class Value>
std::vector<bool> needs_foot(const Shape_vertex_table<Point>& table, const std::vector<std::vector<Value> >& layers)
{
  std::vector<bool> needs(table.number_of_shape_vertices(), false);
  for(const std::vector<Value>& values : layers)
  {
    const std::vector<std::size_t> own = own_vertices(table, values);
    for(std::size_t v = 0; v < own.size(); ++v)
      if(own[v] == std::size_t(-1))
        needs[v] = true;
  }
  return needs;
}

// The faces of `pmesh` that may hold a point within `reach[k]` of
// `queries[k]` for some k, in the order of `all` (the faces of `pmesh`):
// every face whose bounding box meets a grid cell that a query's ball's box
// meets, and every face across many cells: a superset; all of them when a
// reach is not finite.
template <class ConcurrencyTag, class Point, class PolygonMesh, class VertexPointMap>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>
faces_within_reach(const PolygonMesh& pmesh, const VertexPointMap& vpm,
                   const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& all,
                   const CGAL::Bbox_3& box, const std::vector<Point>& queries, const std::vector<double>& reach)
{
  double largest = 0;
  for(double r : reach)
    largest = (std::max)(largest, r);
  if(!std::isfinite(largest))
    return all;
  // cells as wide as the largest reach, at most 256 along the box's longest side
  const double extent = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  const double cell = (std::max)({largest, extent / 256, (std::numeric_limits<double>::min)()});
  int size[3];
  for(int i = 0; i < 3; ++i)
    size[i] = int(std::floor((box.max(i) - box.min(i)) / cell)) + 1;
  auto cell_of = [&](double x, int i) {  // clamped before the conversion, which could overflow
    return int((std::min)(double(size[i] - 1), (std::max)(0., std::floor((x - box.min(i)) / cell))));
  };
  auto at = [&](int x, int y, int z) {
    return (std::size_t(x) * std::size_t(size[1]) + std::size_t(y)) * std::size_t(size[2]) + std::size_t(z);
  };
  std::vector<char> marked(std::size_t(size[0]) * std::size_t(size[1]) * std::size_t(size[2]), 0);
  for(std::size_t k = 0; k < queries.size(); ++k)
  {
    const CGAL::Bbox_3 q = queries[k].bbox();
    for(int x = cell_of(q.xmin() - reach[k], 0); x <= cell_of(q.xmax() + reach[k], 0); ++x)
      for(int y = cell_of(q.ymin() - reach[k], 1); y <= cell_of(q.ymax() + reach[k], 1); ++y)
        for(int z = cell_of(q.zmin() - reach[k], 2); z <= cell_of(q.zmax() + reach[k], 2); ++z)
          marked[at(x, y, z)] = 1;
  }
  std::vector<char> kept(all.size(), 0);
  for_each_index<ConcurrencyTag>(all.size(), []() { return 0; }, [&](std::size_t f, int) {
    CGAL::Bbox_3 b;
    for(auto v : CGAL::vertices_around_face(halfedge(all[f], pmesh), pmesh))
      b += get(vpm, v).bbox();
    const int from[3] = {cell_of(b.xmin(), 0), cell_of(b.ymin(), 1), cell_of(b.zmin(), 2)};
    const int to[3] = {cell_of(b.xmax(), 0), cell_of(b.ymax(), 1), cell_of(b.zmax(), 2)};
    // a face across many cells is kept unchecked
    kept[f] = (to[0] - from[0] + 1) * (to[1] - from[1] + 1) * (to[2] - from[2] + 1) > 64;
    for(int x = from[0]; x <= to[0] && !kept[f]; ++x)
      for(int y = from[1]; y <= to[1] && !kept[f]; ++y)
        for(int z = from[2]; z <= to[2] && !kept[f]; ++z)
          kept[f] = marked[at(x, y, z)];
  });
  std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> within;
  for(std::size_t f = 0; f < all.size(); ++f)
    if(kept[f])
      within.push_back(all[f]);
  return within;
}

// The feet on `pmesh` of the shape's vertices that `needs` flags, sorted by
// vertex (the far ones are dropped by drop_far_feet()); none when `pmesh`
// is empty. A vertex's foot does not depend on which others are searched
// with it, but for which of several faces equally near it names. The
// search tree is built over the faces within `reach` (by flagged vertex,
// in the same order; infinite for the whole surface) of the vertices, and
// again with twice the reach for those whose nearest face there is
// farther: a point nearer than the reach is on a face within it. A few
// points off a large surface then do not pay for a tree over all of it;
// the search tree is freed on return.
template <class ConcurrencyTag, class GT, class PolygonMesh, class VertexPointMap>
std::vector<Surface_foot<typename GT::Point_3, typename boost::graph_traits<PolygonMesh>::face_descriptor> >
surface_feet(const Shape_vertex_table<typename GT::Point_3>& table, const PolygonMesh& pmesh,
             const VertexPointMap& vpm, const std::vector<bool>& needs, std::vector<double> reach)
{
  typedef typename GT::Point_3 Point;
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  typedef Surface_foot<Point, face_descriptor> Foot;
  std::vector<std::size_t> footless;
  for(std::size_t v = 0; v < needs.size(); ++v)
    if(needs[v])
      footless.push_back(v);
  CGAL_precondition(reach.size() == footless.size());
  const std::vector<face_descriptor> all(faces(pmesh).first, faces(pmesh).second);
  if(footless.empty() || all.empty())
    return std::vector<Foot>();
  CGAL::Bbox_3 box;
  for(auto v : vertices(pmesh))
    box += get(vpm, v).bbox();
  const double smallest_reach =
    (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()}) / 256;
  std::vector<Foot> feet(footless.size());
  std::vector<std::size_t> pending(footless.size());
  for(std::size_t k = 0; k < pending.size(); ++k)
    pending[k] = k;
  while(!pending.empty())
  {
    std::vector<Point> queries;
    std::vector<double> pending_reach;
    for(std::size_t k : pending)
    {
      queries.push_back(table.points[footless[k]]);
      pending_reach.push_back(reach[k]);
    }
    const std::vector<face_descriptor> within =
      faces_within_reach<ConcurrencyTag>(pmesh, vpm, all, box, queries, pending_reach);
    const bool whole_surface = within.size() == all.size();
    std::vector<char> found(pending.size(), 0);
    if(!within.empty())
    {
      typedef CGAL::AABB_face_graph_triangle_primitive<PolygonMesh, VertexPointMap> Primitive;
      CGAL::AABB_tree<CGAL::AABB_traits<GT, Primitive> > tree;
      tree.insert(within.begin(), within.end(), pmesh, vpm);
      // the search tree of the faces in their order, then the hierarchy,
      // which sorts them: where several faces are nearest, the one found
      // depends on that order
      tree.accelerate_distance_queries();
      tree.build();
      for_each_index<ConcurrencyTag>(pending.size(), []() { return 0; }, [&](std::size_t j, int&) {
        const auto nearest = tree.closest_point_and_primitive(queries[j]);
        const double distance = std::sqrt(CGAL::to_double(CGAL::squared_distance(queries[j], nearest.first)));
        if(whole_surface || distance <= pending_reach[j])
        {
          feet[pending[j]] = Foot{footless[pending[j]], nearest.first, nearest.second, distance};
          found[j] = 1;
        }
      });
    }
    std::vector<std::size_t> farther;
    for(std::size_t j = 0; j < pending.size(); ++j)
      if(!found[j])
      {
        farther.push_back(pending[j]);
        reach[pending[j]] = (std::max)(2 * reach[pending[j]], smallest_reach);
      }
    pending.swap(farther);
  }
  return feet;
}

// For each vertex that `needs` flags (by increasing vertex index), the
// distance beyond which it is far from the surface: `far_from_surface()`
// local spacings in `cas`, serially (CGAL's walks over the shape mark the
// vertices they visit).
template <class Cas>
std::vector<double> far_distances(const Cas& cas, const Shape_vertex_table<typename Cas::Point>& table,
                                  const std::vector<bool>& needs)
{
  typedef Local_feature_size_policy Policy;
  std::vector<double> far;
  for(std::size_t v = 0; v < needs.size(); ++v)
    if(needs[v])
      far.push_back(far_from_surface()
                    * kth_shortest_edge_length<Policy::spacing_edge_rank>(
                        cas, cas.input_vertex(*table.input_indices.of_vertex(v).begin())));
  return far;
}

// Makes none the feet (from surface_feet()) beyond their vertex's distance
// in `far` (from far_distances(), of the same vertices).
template <class Foot>
void drop_far_feet(std::vector<Foot>& feet, const std::vector<double>& far)
{
  for(std::size_t k = 0; k < feet.size(); ++k)
    if(feet[k].distance > far[k])
      feet[k].face = decltype(feet[k].face)();
}

// Writes the layers' values at the input points (see transfer_to_points()),
// given the feet of every vertex that needs_foot() flags, sorted by vertex.
template <class ConcurrencyTag, class GT, class PolygonMesh, class VertexPointMap, class VertexIndexMap,
          class Foot, class PointCurvatureMaps, class NormalRange>
void write_at_points(const Shape_vertex_table<typename GT::Point_3>& table, const PolygonMesh& pmesh,
                     const VertexPointMap& vpm, const VertexIndexMap& vertex_index,
                     std::vector<std::vector<Vertex_curvature<GT> > >& layers, const std::vector<Foot>& feet,
                     PointCurvatureMaps point_curvatures, const NormalRange& reference_normals)
{
  // vertex by vertex of the shape, whose order the surface's follows: the
  // reads are then in memory order, one scattered store per point
  for(std::size_t k = 0; k < layers.size(); ++k)
  {
    const std::vector<Vertex_curvature<GT> >& values = layers[k];
    const std::vector<std::size_t> own = own_vertices(table, values);
    const auto point_map = point_curvatures(k);
    for_each_index<ConcurrencyTag>(own.size(), []() { return 0; }, [&](std::size_t v, int&) {
      const Point_curvature<GT> value = value_at_vertex<GT>(v, own[v], pmesh, vpm, vertex_index, values, feet);
      for(const std::size_t i : table.input_indices.of_vertex(v))
      {
        Point_curvature<GT> c = value;
        if(!reference_normals.empty() && c.normal * reference_normals[i] < 0)
          take_other_side(c);
        put(point_map, i, c);
      }
    });
    std::vector<Vertex_curvature<GT> >().swap(layers[k]);
  }
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
