// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SURFACE_NEIGHBORHOODS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SURFACE_NEIGHBORHOODS_H

// The neighborhoods of the curvature fits, searched on a flat copy of the
// mesh's vertex graph: positions and adjacency in arrays indexed by vertex
// index, so that the searches, run once per vertex and possibly on several
// threads, touch contiguous memory and nothing of the mesh.

#include <CGAL/Conformal_alpha_shapes_3/internal/curvature_fits.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The vertex graph of a mesh: for vertex index v, its position and its
// neighbors' indices adjacent[first[v], first[v + 1]). Vertex indices are
// 32-bit: the searches are bound by memory latency, and half-size indices
// halve the adjacency and the searches' lists; offsets into `adjacent`
// stay 64-bit, as a surface has about six entries in it per vertex.
struct Vertex_graph
{
  typedef std::uint32_t Index;
  static constexpr std::size_t max_size = (std::numeric_limits<Index>::max)();

  std::vector<Vec3> points;
  std::vector<std::size_t> first;
  std::vector<Index> adjacent;

  std::size_t size() const { return points.size(); }
};

// Refuses a graph of more vertices than its indices can address.
inline void check_vertex_graph_size(std::size_t number_of_vertices)
{
  if(number_of_vertices > Vertex_graph::max_size)
    throw std::length_error("curvature estimation: a surface of " + std::to_string(number_of_vertices)
                            + " vertices, more than the " + std::to_string(Vertex_graph::max_size)
                            + " that its vertex graph can index");
}

template <typename Point>
Vec3 to_vec3(const Point& p)
{
  return Vec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

template <typename PolygonMesh, typename VPM, typename VertexIndexMap>
Vertex_graph vertex_graph(const PolygonMesh& pmesh, const VPM& vpm, const VertexIndexMap& vertex_index)
{
  Vertex_graph g;
  const std::size_t n = num_vertices(pmesh);
  check_vertex_graph_size(n);
  g.points.resize(n);
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> by_index(n);
  for(auto v : vertices(pmesh))
  {
    by_index[get(vertex_index, v)] = v;
    g.points[get(vertex_index, v)] = to_vec3(get(vpm, v));
  }
  g.first.reserve(n + 1);
  g.first.push_back(0);
  for(auto v : by_index)
  {
    if(halfedge(v, pmesh) != boost::graph_traits<PolygonMesh>::null_halfedge())
      for(auto u : CGAL::vertices_around_target(v, pmesh))
        g.adjacent.push_back(Vertex_graph::Index(get(vertex_index, u)));
    g.first.push_back(g.adjacent.size());
  }
  return g;
}

// The part of the vertex graph that the searches around v can reach: the
// vertices fewer than `rings` edges away and those within distance
// `radius` of v that the others lead to, with their adjacency, and their other
// neighbors without. v has index 0; `by_index` receives the vertices.
template <typename PolygonMesh, typename VPM>
Vertex_graph local_vertex_graph(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                                const PolygonMesh& pmesh, const VPM& vpm, std::size_t rings, double radius,
                                std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& by_index)
{
  Vertex_graph g;
  std::unordered_map<typename boost::graph_traits<PolygonMesh>::vertex_descriptor, Vertex_graph::Index> index;
  std::vector<std::size_t> hops(1, 0);
  by_index.assign(1, v);
  index[v] = 0;
  g.points.push_back(to_vec3(get(vpm, v)));
  g.first.push_back(0);
  for(std::size_t k = 0; k < by_index.size(); ++k)
  {
    const auto u = by_index[k];
    const bool expanded = hops[k] < rings || (g.points[k] - g.points[0]).norm() <= radius;
    if(expanded && halfedge(u, pmesh) != boost::graph_traits<PolygonMesh>::null_halfedge())
      for(auto w : CGAL::vertices_around_target(u, pmesh))
      {
        auto inserted = index.emplace(w, Vertex_graph::Index(by_index.size()));
        if(inserted.second)
        {
          check_vertex_graph_size(by_index.size() + 1);
          by_index.push_back(w);
          hops.push_back(hops[k] + 1);
          g.points.push_back(to_vec3(get(vpm, w)));
        }
        g.adjacent.push_back(inserted.first->second);
      }
    g.first.push_back(g.adjacent.size());
  }
  return g;
}

// The vertices around a vertex v, each with a level: the smallest index j
// such that it is connected to v by surface edges inside the j-th of
// nested neighborhoods (balls of increasing radii, or rings of increasing
// size), so that the j-th neighborhood is every vertex of level <= j.
// A search reuses its buffers from vertex to vertex; one per thread.
class Nested_neighborhood_search
{
public:
  explicit Nested_neighborhood_search(std::size_t number_of_vertices) : m_stamp(number_of_vertices, 0) {}

  // The vertices found (v excluded), by increasing level, and where each
  // level's neighborhood ends: vertices()[0, end(j)) is the j-th.
  const std::vector<Vertex_graph::Index>& vertices() const { return m_found; }
  const std::vector<double>& squared_distances() const { return m_squared_distance; }
  std::size_t end(std::size_t level) const { return m_end[level]; }
  // how many levels were searched
  std::size_t levels_found() const { return m_levels_found; }

  // Balls of the given increasing radii around v, cut to what is connected
  // to v inside each: a vertex's level is the smallest radius at which a
  // path of edges joins it to v without leaving the ball (a thin part or a
  // nearby sheet across the ball does not leak in). Levels are visited in
  // increasing order, so a vertex is first reached from the lowest level
  // that reaches it, which is its level. Distances are compared squared:
  // the search runs once per vertex over hundreds of vertices, and a square
  // root per vertex reached was a tenth of its time.
  // The first `levels` of them (all by default); more_balls() finds the
  // others, as they would have been found at once.
  void balls(const Vertex_graph& g, std::size_t v, const std::vector<double>& radii,
             std::size_t levels = std::size_t(-1))
  {
    start(v, radii.size());
    m_center = v;
    m_squared_radii.resize(radii.size());
    for(std::size_t level = 0; level < radii.size(); ++level)
      m_squared_radii[level] = radii[level] * radii[level];
    m_pending[0].push(Vertex_graph::Index(v), 0);
    m_levels_found = 0;
    more_balls(g, levels);
  }

  // The levels of the balls up to `levels` (excluded) that balls() left.
  void more_balls(const Vertex_graph& g, std::size_t levels)
  {
    const std::size_t v = m_center, count = m_squared_radii.size();
    const Vec3& p = g.points[v];
    for(std::size_t level = m_levels_found; level < (std::min)(levels, count); ++level)
    {
      // the pending list of this level grows while it is walked
      const Pending& pending = m_pending[level];
      for(std::size_t k = 0; k < pending.vertices.size(); ++k)
      {
        const Vertex_graph::Index u = pending.vertices[k];
        if(u != v)
        {
          m_found.push_back(u);
          m_squared_distance.push_back(pending.squared_distances[k]);
        }
        const std::size_t reached = mark_neighbors(g, u);
        for(std::size_t e = 0; e < reached; ++e)
        {
          const Vertex_graph::Index w = m_reached[e];
          const double d2 = (g.points[w] - p).squaredNorm();
          std::size_t at = level;
          while(at < count && d2 > m_squared_radii[at])
            ++at;
          if(at < count)  // else outside every ball
            m_pending[at].push(w, d2);
        }
      }
      m_end[level] = m_found.size();
      m_levels_found = level + 1;
    }
  }

  // The rings 1, ..., rings around v: a vertex's level is its edge
  // distance to v less one.
  void rings(const Vertex_graph& g, std::size_t v, std::size_t rings)
  {
    start(v, rings);
    std::size_t begin = 0;
    m_found.push_back(Vertex_graph::Index(v));  // the first frontier; removed below
    m_squared_distance.push_back(0);
    for(std::size_t ring = 0; ring < rings; ++ring)
    {
      const std::size_t end = m_found.size();
      for(std::size_t k = begin; k < end; ++k)
      {
        const std::size_t reached = mark_neighbors(g, m_found[k]);
        for(std::size_t e = 0; e < reached; ++e)
        {
          m_found.push_back(m_reached[e]);
          m_squared_distance.push_back((g.points[m_reached[e]] - g.points[v]).squaredNorm());
        }
      }
      begin = end;
      m_end[ring] = m_found.size() - 1;
    }
    m_found.erase(m_found.begin());
    m_squared_distance.erase(m_squared_distance.begin());
    m_levels_found = rings;
  }

private:
  void start(std::size_t v, std::size_t levels)
  {
    if(++m_current == 0)
    {
      std::fill(m_stamp.begin(), m_stamp.end(), 0);
      m_current = 1;
    }
    m_found.clear();
    m_squared_distance.clear();
    m_end.assign(levels, 0);
    m_pending.resize((std::max)(levels, m_pending.size()));
    for(Pending& pending : m_pending)
      pending.clear();
    m_stamp[v] = m_current;
  }

  // Marks the neighbors of u as reached by the current search and puts
  // those it had not reached before in m_reached[0, returned count). Every
  // neighbor is stamped and written, and the count advanced by whether it
  // is new: a branch on that is taken unpredictably, and mispredicted
  // branches dominated the ball search. Stamps of 32 bits keep the array small (it is read
  // for every edge the search walks), and are cleared when the counter
  // wraps.
  std::size_t mark_neighbors(const Vertex_graph& g, std::size_t u)
  {
    const Vertex_graph::Index* neighbor = g.adjacent.data() + g.first[u];
    const std::size_t degree = g.first[u + 1] - g.first[u];
    if(m_reached.size() < degree)
      m_reached.resize(degree);
    std::uint32_t* stamp = m_stamp.data();
    const std::uint32_t current = m_current;  // the stamps' stores could alias the member
    Vertex_graph::Index* reached = m_reached.data();
    std::size_t count = 0;
    for(std::size_t e = 0; e < degree; ++e)
    {
      const Vertex_graph::Index w = neighbor[e];
      const bool is_new = stamp[w] != current;
      stamp[w] = current;
      reached[count] = w;
      count += is_new;
    }
    return count;
  }

  std::vector<std::uint32_t> m_stamp;  // the search that last marked each vertex
  std::vector<Vertex_graph::Index> m_reached;  // see mark_neighbors()
  std::uint32_t m_current = 0;
  std::vector<Vertex_graph::Index> m_found;
  std::vector<double> m_squared_distance;
  std::vector<std::size_t> m_end;
  std::vector<double> m_squared_radii;
  std::size_t m_center = 0, m_levels_found = 0;  // the search's vertex, and its levels searched
  // Reached, not yet walked. Two arrays rather than one of pairs: a pair
  // built from two registers was stored and read back whole, which stalls
  // (a fifth of the search's time).
  struct Pending
  {
    std::vector<Vertex_graph::Index> vertices;
    std::vector<double> squared_distances;

    void push(Vertex_graph::Index vertex, double squared_distance)
    {
      vertices.push_back(vertex);
      squared_distances.push_back(squared_distance);
    }
    void clear()
    {
      vertices.clear();
      squared_distances.clear();
    }
  };
  std::vector<Pending> m_pending;  // by level
};

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SURFACE_NEIGHBORHOODS_H
