// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SAMPLE_SPACING_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SAMPLE_SPACING_H

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

// The local sample spacing at each finite vertex (by `v->vertex_index()`):
// the length of its K-th shortest Delaunay edge (its longest one when it has
// fewer). One pass over the finite cells, keeping the K shortest edges per
// vertex; an edge seen from several cells is kept once.
template <std::size_t K, class Dt>
std::vector<double> kth_shortest_edge_lengths(const Dt& dt)
{
  // squared length and other end, in 8 bytes: the arrays are visited in
  // random order, so their size is what costs
  typedef std::pair<float, std::uint32_t> Edge_to;
  const Edge_to none(std::numeric_limits<float>::infinity(), std::uint32_t(-1));
  std::vector<std::array<Edge_to, K> > shortest(dt.number_of_vertices());
  for(auto& s : shortest)
    s.fill(none);
  auto keep = [&](std::size_t v, const Edge_to& e) {
    std::array<Edge_to, K>& s = shortest[v];
    if(e.first > s[K - 1].first)
      return;
    for(const Edge_to& kept : s)
      if(kept.second == e.second)
        return;
    std::size_t k = K - 1;
    for(; k > 0 && s[k - 1].first > e.first; --k)
      s[k] = s[k - 1];
    s[k] = e;
  };
  const auto squared_distance = dt.geom_traits().compute_squared_distance_3_object();
  std::vector<typename Dt::Vertex_handle> vertex(shortest.size());  // by vertex index
  for(const typename Dt::Cell_handle c : dt.finite_cell_handles())
    for(int i = 0; i < 4; ++i)
    {
      vertex[c->vertex(i)->vertex_index()] = c->vertex(i);
      for(int j = i + 1; j < 4; ++j)
      {
        const typename Dt::Vertex_handle p = c->vertex(i), q = c->vertex(j);
        const float length = float(CGAL::to_double(squared_distance(p->point(), q->point())));
        keep(p->vertex_index(), Edge_to(length, std::uint32_t(q->vertex_index())));
        keep(q->vertex_index(), Edge_to(length, std::uint32_t(p->vertex_index())));
      }
    }
  std::vector<double> spacing(shortest.size());
  for(std::size_t v = 0; v < shortest.size(); ++v)
  {
    std::size_t k = K - 1;
    while(k > 0 && shortest[v][k].second == none.second)
      --k;
    const Edge_to& e = shortest[v][k];
    spacing[v] = std::sqrt(double(e.first));
    // a squared length beyond float's range (lengths above 1.8e19 or below
    // 4e-23, as far outliers give) is taken again in double: an infinite
    // spacing would make the local scale infinite and the values NaN
    if(e.second != none.second && !(e.first > 0 && e.first < std::numeric_limits<float>::infinity()))
      spacing[v] = std::sqrt(CGAL::to_double(squared_distance(vertex[v]->point(), vertex[e.second]->point())));
  }
  return spacing;
}

// The local-scale policy of `NOISE_ROBUST_POLE_DISTANCE` (the manual, section
// "Poles and Local Scales"): the local scale of a vertex is its pole distance
// (poles.h), but at least `spacing_floor_factor` times its sample spacing,
// the length of its `spacing_edge_rank`-th shortest Delaunay edge (on a
// surface, a vertex has at least 3 neighbors at about the spacing). A sample
// cannot resolve features much smaller than its spacing, and the pole
// distances that noise collapses are such features.
struct Local_scale_policy
{
  static constexpr std::size_t spacing_edge_rank = 3;
  static constexpr double spacing_floor_factor = 4;
};

// The floor of the local scale of each finite vertex (by `v->vertex_index()`)
// under `Local_scale_policy`.
template <class Dt>
std::vector<double> local_scale_floors(const Dt& dt)
{
  std::vector<double> floors = kth_shortest_edge_lengths<Local_scale_policy::spacing_edge_rank>(dt);
  for(double& f : floors)
    f *= Local_scale_policy::spacing_floor_factor;
  return floors;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SAMPLE_SPACING_H
