// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_VALUES_AT_POINTS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_VALUES_AT_POINTS_H

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/shape_vertex_table.h>
#include <CGAL/Conformal_alpha_shapes_3/point_curvature.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

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
  grown.mean_curvature_noise = u.mean_curvature_noise;
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
  u.mean_curvature = u.gaussian_curvature = u.normal_degrees = u.mean_curvature_noise = 0;
  for(const auto& source : sources)
  {
    const double w = source.second / total;
    const Curvature_uncertainty<GT>& s = value(source.first).uncertainty;
    u.mean_curvature += w * s.mean_curvature;
    u.gaussian_curvature += w * s.gaussian_curvature;
    u.normal_degrees += w * s.normal_degrees;
    u.mean_curvature_noise += w * s.mean_curvature_noise;
  }
  n.normalize();
  max_d = (max_d - max_d.dot(n) * n).normalized();
  Point_curvature<GT> nearest =
    record(NEAREST_SURFACE_POINT, c.distance, r, vector(n), max_k, min_k, vector(max_d), vector(n.cross(max_d)));
  nearest.uncertainty = grown_uncertainty(u, c.distance, max_k, min_k);
  return nearest;
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
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_VALUES_AT_POINTS_H
