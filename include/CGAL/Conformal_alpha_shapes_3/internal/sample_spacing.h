// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SAMPLE_SPACING_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SAMPLE_SPACING_H

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/vertices_by_index.h>

#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The length of the edge (p, q) from its squared length kept in float. A
// squared length beyond float's range (lengths above 1.8e19 or below 4e-23,
// as far outliers give) is taken again in double: an infinite spacing would
// make the local feature size infinite and the values NaN.
template <class Dt>
double edge_length(const Dt& dt, float squared_length, typename Dt::Vertex_handle p, typename Dt::Vertex_handle q)
{
  if(squared_length > 0 && squared_length < std::numeric_limits<float>::infinity())
    return std::sqrt(double(squared_length));
  return std::sqrt(CGAL::to_double(dt.geom_traits().compute_squared_distance_3_object()(p->point(), q->point())));
}

// The local sample spacing at each finite vertex (by `v->vertex_index()`):
// the length of its K-th shortest Delaunay edge (its longest one when it has
// fewer). One pass over `cells` (every cell of `dt`; the infinite ones are
// skipped), keeping the K shortest edges per vertex; an edge seen from
// several cells is kept once. Edges of equal length are ordered by their
// other end, so that what is kept does not depend on the order of the
// cells: the pass runs in chunks of cells on TBB's threads when available,
// whose partial results are merged.
template <std::size_t K, class Dt>
std::vector<double> kth_shortest_edge_lengths(const Dt& dt, const std::vector<typename Dt::Cell_handle>& cells)
{
  // squared length and other end, in 8 bytes: the arrays are visited in
  // random order, so their size is what costs
  typedef std::pair<float, std::uint32_t> Edge_to;
  typedef std::vector<std::array<Edge_to, K> > Shortest;
  const Edge_to none(std::numeric_limits<float>::infinity(), std::uint32_t(-1));
  const std::size_t nv = dt.number_of_vertices();
  auto keep = [&](std::array<Edge_to, K>& s, const Edge_to& e) {
    if(!(e < s[K - 1]))
      return;
    for(const Edge_to& kept : s)
      if(kept.second == e.second)
        return;
    std::size_t k = K - 1;
    for(; k > 0 && e < s[k - 1]; --k)
      s[k] = s[k - 1];
    s[k] = e;
  };
  const auto squared_distance = dt.geom_traits().compute_squared_distance_3_object();
  std::vector<Shortest> partial = partial_results_in_chunks<Parallel_if_available_tag>(
    cells.size(),
    [&]() {
      std::array<Edge_to, K> empty;
      empty.fill(none);
      return Shortest(nv, empty);
    },
    [&](std::size_t begin, std::size_t end, Shortest& shortest) {
      for(std::size_t index = begin; index < end; ++index)
      {
        const typename Dt::Cell_handle c = cells[index];
        if(dt.is_infinite(c))
          continue;
        for(int i = 0; i < 4; ++i)
          for(int j = i + 1; j < 4; ++j)
          {
            const typename Dt::Vertex_handle p = c->vertex(i), q = c->vertex(j);
            const float length = float(CGAL::to_double(squared_distance(p->point(), q->point())));
            keep(shortest[p->vertex_index()], Edge_to(length, std::uint32_t(q->vertex_index())));
            keep(shortest[q->vertex_index()], Edge_to(length, std::uint32_t(p->vertex_index())));
          }
      }
    });
  Shortest& shortest = partial.front();
  for(std::size_t k = 1; k < partial.size(); ++k)
    for(std::size_t v = 0; v < nv; ++v)
      for(const Edge_to& e : partial[k][v])
        if(e.second != none.second)
          keep(shortest[v], e);

  const std::vector<typename Dt::Vertex_handle> vertex = vertices_by_index(dt);
  std::vector<double> spacing(nv);
  for(std::size_t v = 0; v < nv; ++v)
  {
    std::size_t k = K - 1;
    while(k > 0 && shortest[v][k].second == none.second)
      --k;
    const Edge_to& e = shortest[v][k];
    spacing[v] = e.second == none.second ? std::sqrt(double(e.first))
                                         : edge_length(dt, e.first, vertex[v], vertex[e.second]);
  }
  return spacing;
}

// The same length at the single finite vertex `v`, from its adjacent
// vertices: for the few vertices that need it after the construction, where
// a pass over every cell would cost more than their neighborhoods. Lengths
// are compared in float, as there, so that both give the same value.
template <std::size_t K, class Dt>
double kth_shortest_edge_length(const Dt& dt, typename Dt::Vertex_handle v)
{
  const auto squared_distance = dt.geom_traits().compute_squared_distance_3_object();
  std::vector<std::pair<float, typename Dt::Vertex_handle> > edges;
  dt.finite_adjacent_vertices(v, boost::make_function_output_iterator([&](typename Dt::Vertex_handle q) {
    edges.emplace_back(float(CGAL::to_double(squared_distance(v->point(), q->point()))), q);
  }));
  if(edges.empty())
    return 0;
  const std::size_t k = std::min(K, edges.size()) - 1;
  std::nth_element(edges.begin(), edges.begin() + k, edges.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  return edge_length(dt, edges[k].first, v, edges[k].second);
}

// The local-feature-size policy of `NOISE_ROBUST_POLE_DISTANCE` (the manual, section
// "Poles and Local Feature Sizes"): the local feature size of a vertex is its pole distance
// (poles.h), but at least `spacing_floor_factor` times its sample spacing,
// the length of its `spacing_edge_rank`-th shortest Delaunay edge (on a
// surface, a vertex has at least 3 neighbors at about the spacing). A sample
// cannot resolve features much smaller than its spacing, and the pole
// distances that noise collapses are such features.
struct Local_feature_size_policy
{
  static constexpr std::size_t spacing_edge_rank = 3;
  static constexpr double spacing_floor_factor = 4;
};

// The floor of the local feature size of each finite vertex (by `v->vertex_index()`)
// under `Local_feature_size_policy`; `cells` as for kth_shortest_edge_lengths().
template <class Dt>
std::vector<double> local_feature_size_floors(const Dt& dt, const std::vector<typename Dt::Cell_handle>& cells)
{
  std::vector<double> floors = kth_shortest_edge_lengths<Local_feature_size_policy::spacing_edge_rank>(dt, cells);
  for(double& f : floors)
    f *= Local_feature_size_policy::spacing_floor_factor;
  return floors;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SAMPLE_SPACING_H
