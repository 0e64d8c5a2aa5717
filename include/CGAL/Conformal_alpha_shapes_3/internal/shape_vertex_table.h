// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SHAPE_VERTEX_TABLE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SHAPE_VERTEX_TABLE_H

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/input_index_table.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/sample_spacing.h>
#include <CGAL/Conformal_alpha_shapes_3/point_curvature.h>

#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// What the transfer reads of the shape, taken from it at once, so that a
// caller may free the shape before the values are written (with the named
// parameter `release_shape`).
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

// For every vertex of the shape (by vertex index), the surface vertices
// whose values in `values` are defined (several where the vertex is
// pinched): those of shape vertex `v` are `vertices[first[v]]` up to
// `vertices[first[v + 1]]`, in the order of the surface's vertices.
struct Own_vertices
{
  std::vector<std::size_t> first, vertices;
};

template <class Point, class Value>
Own_vertices own_vertices(const Shape_vertex_table<Point>& table, const std::vector<Value>& values)
{
  Own_vertices own;
  own.first.assign(table.number_of_shape_vertices() + 1, 0);
  for(const std::pair<std::size_t, std::size_t>& v : table.index_and_shape_vertex)
    if(values[v.first].is_defined())
      ++own.first[v.second + 1];
  for(std::size_t v = 0; v + 1 < own.first.size(); ++v)
    own.first[v + 1] += own.first[v];
  own.vertices.resize(own.first.back());
  std::vector<std::size_t> next(own.first.begin(), own.first.end() - 1);
  for(const std::pair<std::size_t, std::size_t>& v : table.index_and_shape_vertex)
    if(values[v.first].is_defined())
      own.vertices[next[v.second]++] = v.first;
  return own;
}

// Whether each vertex of the shape (by vertex index) stands for no vertex of
// the surface: in every layer, it takes the values of its foot on the surface.
template <class Point>
std::vector<bool> vertices_off_surface(const Shape_vertex_table<Point>& table)
{
  std::vector<bool> off(table.number_of_shape_vertices(), true);
  for(const std::pair<std::size_t, std::size_t>& v : table.index_and_shape_vertex)
    off[v.second] = false;
  return off;
}

// Whether each vertex of the shape (by vertex index) takes its value from
// its foot on the surface in some layer of `layers`.
template <class Point, class Value>
std::vector<bool> needs_foot(const Shape_vertex_table<Point>& table, const std::vector<std::vector<Value> >& layers)
{
  std::vector<bool> needs(table.number_of_shape_vertices(), false);
  for(const std::vector<Value>& values : layers)
  {
    const Own_vertices own = own_vertices(table, values);
    for(std::size_t v = 0; v < needs.size(); ++v)
      if(own.first[v] == own.first[v + 1])
        needs[v] = true;
  }
  return needs;
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

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SHAPE_VERTEX_TABLE_H
