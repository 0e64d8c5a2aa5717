// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_TRIANGLE_SOUP_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_TRIANGLE_SOUP_H

// The surface as the advancing front leaves it (conformal_front.h),
// a soup of triangles with their neighbors, and what is done to it before
// it becomes a mesh: a canonical order, and the cut at a scale. The passes
// per vertex group and per triangle, and the sorts, run on TBB's threads when
// CGAL_LINKED_WITH_TBB, with the same results.

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <deque>
#include <functional>
#include <numeric>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// A surface as triangles over vertices of a conformal alpha shape, with
// each triangle's neighbors and conformal value.
struct Advancing_front_soup
{
  // vertex of the shape (its `vertex_index()`) of each soup vertex; a shape
  // vertex where the front met itself appears once per sheet through it
  std::vector<std::size_t> shape_vertex;
  // triangles over soup vertices, consistently oriented in each part
  std::vector<std::array<std::size_t, 3> > triangles;
  // for each triangle, its three neighbors across the edges opposite to its
  // vertices (an index into `triangles`), or `no_neighbor` on a border
  std::vector<std::array<std::size_t, 3> > neighbors;
  // the conformal value of each triangle's facet
  std::vector<double> values;
  static constexpr std::size_t no_neighbor = std::size_t(-1);
};

// The soup vertex of the shape's vertex `v`, numbered when first met:
// `soup_vertex` has an entry per shape vertex, `no_neighbor` until then.
inline std::size_t soup_vertex_of(Advancing_front_soup& soup, std::vector<std::size_t>& soup_vertex, std::size_t v)
{
  std::size_t& s = soup_vertex[v];
  if(s == Advancing_front_soup::no_neighbor)
  {
    s = soup.shape_vertex.size();
    soup.shape_vertex.push_back(v);
  }
  return s;
}

// Sets the soup's neighbors from its triangles as CGAL's advancing-front
// surface pairs its faces: the faces on an edge are paired in their order,
// the first with the second, the third with the fourth, and a face left
// alone has a border there. The front leaves at most two faces on an edge,
// so in practice this is: the two triangles on an edge are neighbors. The
// triangles must be in the front's order (`conformal_front_triangles()`). Edges are
// grouped by their smaller vertex (a counting sort), then sorted by the
// other vertex and by triangle, so that a vertex of very high degree (the
// center of a fan) costs `d log d`, not `d^2`.
inline void pair_neighbors(Advancing_front_soup& soup)
{
  const std::size_t none = Advancing_front_soup::no_neighbor;
  const std::size_t nt = soup.triangles.size();
  // the edge of corner c = 3 t + k is the one opposite to vertex k of t
  auto ends = [&](std::size_t c) {
    const std::array<std::size_t, 3>& t = soup.triangles[c / 3];
    const std::size_t a = t[(c % 3 + 1) % 3], b = t[(c % 3 + 2) % 3];
    return std::make_pair((std::min)(a, b), (std::max)(a, b));
  };
  std::vector<std::size_t> first(soup.shape_vertex.size() + 1, 0);
  for(std::size_t c = 0; c < 3 * nt; ++c)
    ++first[ends(c).first + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<std::size_t> by_vertex(3 * nt);
  {
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for(std::size_t c = 0; c < 3 * nt; ++c)
      by_vertex[next[ends(c).first]++] = c;
  }
  soup.neighbors.assign(nt, {{none, none, none}});
  // each vertex's corners only: its group is sorted and paired on its own
  for_each_index<Parallel_if_available_tag>(first.size() - 1, []() { return 0; }, [&](std::size_t v, int&) {
    const auto begin = by_vertex.begin() + std::ptrdiff_t(first[v]);
    const auto end = by_vertex.begin() + std::ptrdiff_t(first[v + 1]);
    // corners of one triangle have different edges, so the corner orders
    // the faces of an edge as their triangles
    std::sort(begin, end, [&](std::size_t c, std::size_t d) {
      return std::make_pair(ends(c).second, c) < std::make_pair(ends(d).second, d);
    });
    for(auto i = begin; i != end && i + 1 != end;)
      if(ends(*i).second == ends(*(i + 1)).second)
      {
        soup.neighbors[*i / 3][*i % 3] = *(i + 1) / 3;
        soup.neighbors[*(i + 1) / 3][*(i + 1) % 3] = *i / 3;
        i += 2;
      }
      else
        ++i;
  });
}

// Puts the soup in an order that depends only on its triangles, not on the
// order in which the front grew them (which follows memory addresses where
// the front's own criteria tie): vertices by shape vertex, triangles
// lexicographically, each starting at its smallest vertex. The front's
// orientation of a part follows those addresses too (at 3,000,000 points
// a part came out either way from one run to the next, with the same
// triangles): each part is turned so that its smallest triangle runs up
// from its smallest vertex. The extraction orients the parts afterwards
// (orient_surface_parts.h); this only makes the order canonical. The soup
// is rewritten in place and permuted one array at a time: this runs next
// to the whole shape, near the job's peak of memory.
inline void put_in_canonical_order(Advancing_front_soup& soup)
{
  const std::size_t nv = soup.shape_vertex.size(), nt = soup.triangles.size();
  const std::size_t none = Advancing_front_soup::no_neighbor;
  typedef std::array<std::size_t, 3> Triple;
  auto sorted = [&](const Triple& t) {
    Triple k = {{soup.shape_vertex[t[0]], soup.shape_vertex[t[1]], soup.shape_vertex[t[2]]}};
    std::sort(k.begin(), k.end());
    return k;
  };

  // the new vertex numbers; a vertex standing for a shape vertex more than
  // once is told apart by the smallest triangle it is on
  {
    std::vector<Triple> first_triangle(nv, Triple{{none, none, none}});
    for(const Triple& t : soup.triangles)
      for(std::size_t v : t)
        first_triangle[v] = (std::min)(first_triangle[v], sorted(t));
    std::vector<std::size_t> vertex_order(nv);
    std::iota(vertex_order.begin(), vertex_order.end(), std::size_t(0));
    sort_distinct<Parallel_if_available_tag>(vertex_order.begin(), vertex_order.end(), [&](std::size_t x, std::size_t y) {
      return std::tie(soup.shape_vertex[x], first_triangle[x], x) < std::tie(soup.shape_vertex[y], first_triangle[y], y);
    });
    std::vector<std::size_t> new_vertex(nv), shape_vertex(nv);
    for(std::size_t i = 0; i < nv; ++i)
    {
      new_vertex[vertex_order[i]] = i;
      shape_vertex[i] = soup.shape_vertex[vertex_order[i]];
    }
    for(Triple& t : soup.triangles)
      for(std::size_t& v : t)
        v = new_vertex[v];
    soup.shape_vertex = std::move(shape_vertex);
  }

  // whether each triangle is turned with its part: a first walk over the
  // part finds its smallest triangle, a second one marks the part (a
  // breadth-first walk, whose queue stays a front across the part). Not
  // soup_parts() (soup_sheets.h): its part index per triangle and its
  // depth-first stack would add to the front's memory peak.
  auto smallest_corner = [](const Triple& v) {
    return v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
  };
  auto sorted_new = [](Triple t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  enum : char { unseen, seen, kept, turned };
  std::vector<char> state(nt, unseen);
  std::deque<std::size_t> queue;
  auto walk_part = [&](std::size_t seed, char from, char to, auto&& visit) {
    state[seed] = to;
    queue.push_back(seed);
    while(!queue.empty())
    {
      const std::size_t t = queue.front();
      queue.pop_front();
      visit(t);
      for(std::size_t n : soup.neighbors[t])
        if(n != none && state[n] == from)
        {
          state[n] = to;
          queue.push_back(n);
        }
    }
  };
  for(std::size_t seed = 0; seed < nt; ++seed)
  {
    if(state[seed] != unseen)
      continue;
    std::size_t smallest = seed;
    Triple smallest_key = sorted_new(soup.triangles[seed]);
    walk_part(seed, unseen, seen, [&](std::size_t t) {
      const Triple key = sorted_new(soup.triangles[t]);
      if(key < smallest_key)
      {
        smallest = t;
        smallest_key = key;
      }
    });
    const Triple& v = soup.triangles[smallest];
    const int r = smallest_corner(v);
    walk_part(seed, seen, v[(r + 1) % 3] > v[(r + 2) % 3] ? turned : kept, [](std::size_t) {});
  }

  // each triangle turned with its part and rotated to start at its
  // smallest vertex, with its neighbors (opposite to each vertex) moved
  // alike
  for_each_index<Parallel_if_available_tag>(nt, []() { return 0; }, [&](std::size_t t, int&) {
    Triple v = soup.triangles[t], n = soup.neighbors[t];
    if(state[t] == turned)
    {
      std::swap(v[1], v[2]);
      std::swap(n[1], n[2]);
    }
    const int r = smallest_corner(v);
    for(int k = 0; k < 3; ++k)
    {
      soup.triangles[t][k] = v[(k + r) % 3];
      soup.neighbors[t][k] = n[(k + r) % 3];
    }
  });
  state = std::vector<char>();

  std::vector<std::size_t> triangle_order(nt);
  std::iota(triangle_order.begin(), triangle_order.end(), std::size_t(0));
  sort_distinct<Parallel_if_available_tag>(triangle_order.begin(), triangle_order.end(), [&](std::size_t x, std::size_t y) {
    return std::tie(soup.triangles[x], x) < std::tie(soup.triangles[y], y);
  });
  auto permuted = [&](const auto& by_old) {
    typename std::decay<decltype(by_old)>::type by_new(nt);
    for_each_index<Parallel_if_available_tag>(nt, []() { return 0; }, [&](std::size_t i, int&) {
      by_new[i] = by_old[triangle_order[i]];
    });
    return by_new;
  };
  soup.triangles = permuted(soup.triangles);
  soup.neighbors = permuted(soup.neighbors);
  soup.values = permuted(soup.values);
  std::vector<std::size_t> new_triangle(nt);
  for_each_index<Parallel_if_available_tag>(nt, []() { return 0; }, [&](std::size_t i, int&) {
    new_triangle[triangle_order[i]] = i;
  });
  triangle_order = std::vector<std::size_t>();
  for_each_index<Parallel_if_available_tag>(nt, []() { return 0; }, [&](std::size_t t, int&) {
    for(std::size_t& x : soup.neighbors[t])
      if(x != none)
        x = new_triangle[x];
  });
}

// The soup at scale `a` cut from the soup grown with no bound: the
// triangles whose value exceeds `a` are removed and their neighbors get a
// border there; a vertex whose triangles fall apart into several fans gets
// one copy per fan (as where the front met itself), so that each soup vertex
// keeps one umbrella; the parts left with fewer than 8 triangles are
// dropped (a facet or a few that the front grew past a larger one: bounded
// at `a`, it would not reach them, and they are too small to carry
// curvature); vertices left without triangles are dropped. Vertices keep
// their order (copies of one vertex by their first triangle), triangles
// theirs, so the cut of a canonical soup is canonical.
inline Advancing_front_soup pruned_soup(const Advancing_front_soup& soup, double a)
{
  const std::size_t smallest_part = 8;
  const std::size_t none = Advancing_front_soup::no_neighbor;
  const std::size_t nt = soup.triangles.size();
  std::vector<char> keep(nt, 0);
  for(std::size_t t = 0; t < nt; ++t)
    keep[t] = soup.values[t] <= a ? 1 : 0;
  auto kept_neighbor = [&](std::size_t t, int k) {
    const std::size_t u = soup.neighbors[t][k];
    return u != none && keep[u] ? u : none;
  };

  // parts across kept edges, the small ones dropped
  std::vector<char> seen(nt, 0);
  std::vector<std::size_t> members;
  for(std::size_t seed = 0; seed < nt; ++seed)
  {
    if(!keep[seed] || seen[seed])
      continue;
    members.assign(1, seed);
    seen[seed] = 1;
    for(std::size_t i = 0; i < members.size(); ++i)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t u = kept_neighbor(members[i], k);
        if(u != none && !seen[u])
        {
          seen[u] = 1;
          members.push_back(u);
        }
      }
    if(members.size() < smallest_part)
      for(std::size_t t : members)
        keep[t] = 0;
  }

  // fans: the corners (3 t + k) of each vertex joined across kept edges
  std::vector<std::size_t> root(3 * nt);
  std::iota(root.begin(), root.end(), std::size_t(0));
  auto find = [&](std::size_t c) {
    while(root[c] != c)
      c = root[c] = root[root[c]];
    return c;
  };
  for(std::size_t t = 0; t < nt; ++t)
    for(int k = 0; k < 3 && keep[t]; ++k)
      for(int e : {(k + 1) % 3, (k + 2) % 3})  // the two edges at corner k
      {
        const std::size_t u = kept_neighbor(t, e);
        if(u == none)
          continue;
        for(int j = 0; j < 3; ++j)
          if(soup.triangles[u][j] == soup.triangles[t][k])
          {
            const std::size_t x = find(3 * t + k), y = find(3 * u + j);
            root[(std::max)(x, y)] = (std::min)(x, y);
          }
      }

  // one vertex per fan, by old vertex and then by first corner
  std::vector<std::pair<std::size_t, std::size_t> > fans;  // (old vertex, first corner)
  for(std::size_t t = 0; t < nt; ++t)
    for(int k = 0; k < 3 && keep[t]; ++k)
      if(find(3 * t + k) == 3 * t + k)
        fans.emplace_back(soup.triangles[t][k], 3 * t + k);
  sort_distinct<Parallel_if_available_tag>(fans.begin(), fans.end(), std::less<>());
  Advancing_front_soup pruned;
  std::vector<std::size_t> vertex_of_fan(3 * nt, none);
  for(const std::pair<std::size_t, std::size_t>& fan : fans)
  {
    vertex_of_fan[fan.second] = pruned.shape_vertex.size();
    pruned.shape_vertex.push_back(soup.shape_vertex[fan.first]);
  }
  std::vector<std::size_t> new_triangle(nt, none);
  for(std::size_t t = 0; t < nt; ++t)
    if(keep[t])
    {
      new_triangle[t] = pruned.values.size();
      pruned.values.push_back(soup.values[t]);
    }
  pruned.triangles.reserve(pruned.values.size());
  pruned.neighbors.reserve(pruned.values.size());
  for(std::size_t t = 0; t < nt; ++t)
    if(keep[t])
    {
      std::array<std::size_t, 3> triangle, neighbor;
      for(int k = 0; k < 3; ++k)
      {
        triangle[k] = vertex_of_fan[find(3 * t + k)];
        neighbor[k] = soup.neighbors[t][k] == none ? none : new_triangle[soup.neighbors[t][k]];
      }
      pruned.triangles.push_back(triangle);
      pruned.neighbors.push_back(neighbor);
    }
  return pruned;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_TRIANGLE_SOUP_H
