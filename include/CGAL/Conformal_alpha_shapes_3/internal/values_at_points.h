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

// The value that the surface vertices `sources` (by index in `values`,
// with weights) give together, at `distance` from the surface: their
// weighted mean, the principal directions aligned first; where their
// normals nearly cancel (a fold of the surface, their weighted sum shorter
// than one half), the values of the one of largest weight.
template <class GT>
Point_curvature<GT> weighted_value(const std::vector<std::pair<std::size_t, double> >& sources, Point_source source,
                                   double distance, const std::vector<Vertex_curvature<GT> >& values)
{
  typedef typename GT::Vector_3 Vector;
  auto vec3 = [](const Vector& x) { return Vec3(x.x(), x.y(), x.z()); };
  auto vector = [](const Vec3& x) { return Vector(x.x(), x.y(), x.z()); };
  auto record = [&](double r, const Vector& n, double max_k, double min_k, const Vector& max_d, const Vector& min_d,
                    const Curvature_uncertainty<GT>& u) {
    Point_curvature<GT> c;
    c.source = source;
    c.distance = distance;
    c.radius = r;
    c.normal = n;
    c.mean_curvature = (max_k + min_k) / 2;
    c.gaussian_curvature = max_k * min_k;
    c.principal = Principal_curvatures_and_directions<GT>{max_k, min_k, max_d, min_d};
    c.uncertainty = distance > 0 ? grown_uncertainty(u, distance, max_k, min_k) : u;
    return c;
  };
  auto one = [&](const Vertex_curvature<GT>& e) {
    return record(e.radius, e.normal, e.principal.max_curvature, e.principal.min_curvature,
                  e.principal.max_direction, e.principal.min_direction, e.uncertainty);
  };
  if(sources.size() == 1)
    return one(values[sources.front().first]);
  double total = 0;
  for(const auto& s : sources)
    total += s.second;
  Vec3 n = Vec3::Zero(), max_d = Vec3::Zero();
  double r = 0, max_k = 0, min_k = 0;
  Curvature_uncertainty<GT> u;
  u.mean_curvature = u.gaussian_curvature = u.normal_degrees = u.mean_curvature_noise = 0;
  const Vec3 reference_d1 = vec3(values[sources.front().first].principal.max_direction);
  for(const auto& s : sources)
  {
    const double w = s.second / total;
    const Vertex_curvature<GT>& e = values[s.first];
    n += w * vec3(e.normal);
    // a principal direction is a line: align signs before averaging
    const Vec3 d1 = vec3(e.principal.max_direction);
    max_d += (d1.dot(reference_d1) < 0 ? -w : w) * d1;
    r += w * e.radius;
    max_k += w * e.principal.max_curvature;
    min_k += w * e.principal.min_curvature;
    u.mean_curvature += w * e.uncertainty.mean_curvature;
    u.gaussian_curvature += w * e.uncertainty.gaussian_curvature;
    u.normal_degrees += w * e.uncertainty.normal_degrees;
    u.mean_curvature_noise += w * e.uncertainty.mean_curvature_noise;
  }
  if(!(n.norm() > 0.5))
    return one(values[std::max_element(sources.begin(), sources.end(), [](const auto& x, const auto& y) {
                        return x.second < y.second;
                      })->first]);
  n.normalize();
  max_d = (max_d - max_d.dot(n) * n).normalized();
  return record(r, vector(n), max_k, min_k, vector(max_d), vector(n.cross(max_d)), u);
}

// The value at the vertex of index `v` of the shape: that of its surface
// vertices with values (`own`; several where the vertex is pinched, each
// weighted by its share of its facets' area, so that no order of the
// surface's vertices decides), or else interpolated at the nearest point of
// the surface (`feet`, sorted by vertex), or none.
template <class GT, class PolygonMesh, class VertexPointMap, class VertexIndexMap, class Foot>
Point_curvature<GT> value_at_vertex(std::size_t v, const std::vector<std::pair<std::size_t, double> >& own,
                                    const PolygonMesh& pmesh, const VertexPointMap& vpm,
                                    const VertexIndexMap& vertex_index,
                                    const std::vector<Vertex_curvature<GT> >& values, const std::vector<Foot>& feet)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  if(!own.empty())
    return weighted_value<GT>(own, SURFACE_VERTEX, 0, values);

  Point_curvature<GT> c;  // NaN everywhere
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
  auto index = [&](vertex_descriptor u) { return std::size_t(get(vertex_index, u)); };
  // The vertices whose values the nearest point takes, with their weights:
  // the facet's corners with values, by barycentric weights; where the
  // nearest point is a corner (the other two weights vanish to rounding)
  // without a value, that corner's neighbors with values, alike, so that it
  // does not matter which of the corner's facets the search named.
  std::vector<std::pair<std::size_t, double> > sources;
  double area[3];
  for(int j = 0; j < 3; ++j)
    area[j] = std::sqrt(CGAL::to_double(CGAL::squared_area(foot->point, get(vpm, corner[(j + 1) % 3]),
                                                           get(vpm, corner[(j + 2) % 3]))));
  for(int j = 0; j < 3 && sources.empty(); ++j)
    if(!values[index(corner[j])].is_defined() && area[j] > 0 && area[(j + 1) % 3] <= 1e-9 * area[j]
       && area[(j + 2) % 3] <= 1e-9 * area[j])
      for(vertex_descriptor u : vertices_around_target(corner[j], pmesh))
        if(values[index(u)].is_defined())
          sources.emplace_back(index(u), 1.);
  if(sources.empty())
  {
    for(int j = 0; j < 3; ++j)
      if(values[index(corner[j])].is_defined() && area[j] > 0)
        sources.emplace_back(index(corner[j]), area[j]);
    if(sources.empty())  // a degenerate facet: its corners with values, alike
      for(int j = 0; j < 3; ++j)
        if(values[index(corner[j])].is_defined())
          sources.emplace_back(index(corner[j]), 1.);
  }
  if(sources.empty())
    return c;
  return weighted_value<GT>(sources, NEAREST_SURFACE_POINT, c.distance, values);
}

// A third of the area of each surface vertex's facets, by vertex index.
template <class PolygonMesh, class VertexPointMap, class VertexIndexMap>
std::vector<double> vertex_areas(const PolygonMesh& pmesh, const VertexPointMap& vpm,
                                 const VertexIndexMap& vertex_index)
{
  std::vector<double> area(num_vertices(pmesh), 0.);
  for(const auto f : faces(pmesh))
  {
    const auto h = halfedge(f, pmesh);
    const auto p = source(h, pmesh), q = target(h, pmesh), r = target(next(h, pmesh), pmesh);
    const double third = std::sqrt(CGAL::to_double(CGAL::squared_area(get(vpm, p), get(vpm, q), get(vpm, r)))) / 3;
    for(const auto u : {p, q, r})
      area[get(vertex_index, u)] += third;
  }
  return area;
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
  const std::vector<double> weight = vertex_areas(pmesh, vpm, vertex_index);
  for(std::size_t k = 0; k < layers.size(); ++k)
  {
    const std::vector<Vertex_curvature<GT> >& values = layers[k];
    const Own_vertices own = own_vertices(table, values);
    const auto point_map = point_curvatures(k);
    for_each_index<ConcurrencyTag>(table.number_of_shape_vertices(), []() {
      return std::vector<std::pair<std::size_t, double> >();
    }, [&](std::size_t v, std::vector<std::pair<std::size_t, double> >& sources) {
      sources.clear();
      for(std::size_t j = own.first[v]; j < own.first[v + 1]; ++j)
        sources.emplace_back(own.vertices[j], weight[own.vertices[j]]);
      const Point_curvature<GT> value = value_at_vertex<GT>(v, sources, pmesh, vpm, vertex_index, values, feet);
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
