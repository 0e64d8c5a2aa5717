// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ADVANCING_FRONT_FACETS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ADVANCING_FRONT_FACETS_H

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Advancing_front_surface_reconstruction_cell_base_3.h>
#include <CGAL/Advancing_front_surface_reconstruction_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Unique_hash_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// A triangle soup grown facet by facet over the finite Delaunay facets (the
// manual, "The Advancing Front"), by CGAL's
// Advancing_front_surface_reconstruction with the conformal value of a facet
// as its priority: smaller values first, with no bound on the scale. The
// front only grows where the surface stays an oriented 2-manifold, so the
// soup is one sheet per part of the sampled surface, closed or with a
// border, consistently oriented within each part. The soup at a scale `a`
// is cut from it (`pruned_soup()`), so that one front serves every scale.
//
// The advancing front removes the vertices it cannot attach from the
// triangulation it works on, so it runs on a copy of the shape's
// triangulation (a combinatorial copy: no predicate is evaluated again) whose
// cells carry the conformal values of their facets.
struct Advancing_front_soup
{
  // vertex of the shape (its `vertex_index()`) of each soup vertex; a shape
  // vertex where the front met itself appears once per sheet through it
  std::vector<std::size_t> shape_vertex;
  // triangles over soup vertices, consistently oriented in each part
  std::vector<std::array<std::size_t, 3> > triangles;
  // for each triangle, its three neighbours across the edges opposite to its
  // vertices (an index into `triangles`), or `no_neighbor` on a border
  std::vector<std::array<std::size_t, 3> > neighbors;
  // the conformal value of each triangle's facet
  std::vector<double> values;
  static constexpr std::size_t no_neighbor = std::size_t(-1);
};

// The conformal values of an advancing-front cell's facets; cells the front
// creates while removing a vertex have none (infinite: never a candidate).
struct Conformal_cell_values
{
  std::array<double, 4> facet{{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}};
};

// Each new part of the front starts from the smallest facet whose vertices
// are all off the surface, found by a scan over every facet. Where the front
// finds only small pockets (points it could not attach, a sponge of noise)
// those scans would make it quadratic: seeding stops once the last 16 parts
// held fewer than 8 faces each on average (they are pockets too small to
// carry curvature), or after 64 + n / 1000 parts.
struct Front_seeding
{
  int maximum_parts;
  std::vector<int> faces_before_part;  // by part, the front's faces when it was seeded
  bool stopped = false;

  explicit Front_seeding(std::size_t number_of_vertices) : maximum_parts(64 + int(number_of_vertices / 1000)) {}

  // Called with every seed candidate: false once seeding has stopped.
  template <class AdvancingFront>
  bool may_seed(const AdvancingFront& front)
  {
    const int part = front.number_of_connected_components();
    if(!stopped && part > int(faces_before_part.size()))
    {
      faces_before_part.push_back(front.number_of_facets());
      const std::size_t n = faces_before_part.size();
      stopped = int(n) > maximum_parts
                || (n > 16 && faces_before_part[n - 1] - faces_before_part[n - 17] < 16 * 8);
    }
    return !stopped;
  }
};

// A number in [0, 1) that depends only on the three vertices of a facet:
// the front orders equal priorities by memory address, so that exact ties
// (frequent on regular samples) would make the surface depend on how the
// input was allocated; a relative nudge of 1e-12 by this number breaks them
// the same way on every run.
inline double facet_tie_breaker(std::size_t u, std::size_t v, std::size_t w)
{
  if(u > v) std::swap(u, v);
  if(v > w) std::swap(v, w);
  if(u > v) std::swap(u, v);
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for(std::uint64_t x : {std::uint64_t(u), std::uint64_t(v), std::uint64_t(w)})
  {
    h ^= x + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    h ^= h >> 31;
  }
  return double(h >> 11) / 9007199254740992.0;  // 2^53
}

// The front's priority: the conformal value of a facet (infinite facets and
// the cells the front creates have an infinite value: never taken); no seed
// is taken once seeding has stopped.
struct Conformal_priority
{
  Front_seeding* seeding;

  template <class AdvancingFront, class Cell_handle>
  double operator()(const AdvancingFront& front, Cell_handle& c, const int& i) const
  {
    const double value = c->info().facet[i];
    const bool seed = c->vertex((i + 1) & 3)->is_exterior() && c->vertex((i + 2) & 3)->is_exterior()
                      && c->vertex((i + 3) & 3)->is_exterior();
    if(seed && !seeding->may_seed(front))
      return std::numeric_limits<double>::infinity();
    return value * (1 + 1e-12 * facet_tie_breaker(c->vertex((i + 1) & 3)->id(), c->vertex((i + 2) & 3)->id(),
                                                  c->vertex((i + 3) & 3)->id()));
  }
};

// Puts the soup in an order that depends only on its triangles, not on the
// order in which the front grew them (which follows memory addresses where
// the front's own criteria tie): vertices by shape vertex, triangles
// lexicographically, each starting at its smallest vertex.
inline void put_in_canonical_order(Advancing_front_soup& soup)
{
  const std::size_t nv = soup.shape_vertex.size(), nt = soup.triangles.size();
  typedef std::array<std::size_t, 3> Key;
  auto sorted = [&](const std::array<std::size_t, 3>& t) {
    Key k = {{soup.shape_vertex[t[0]], soup.shape_vertex[t[1]], soup.shape_vertex[t[2]]}};
    std::sort(k.begin(), k.end());
    return k;
  };
  // a vertex standing for a shape vertex more than once is told apart by
  // the smallest triangle it is on
  const std::size_t big = std::size_t(-1);
  std::vector<Key> first_triangle(nv, Key{{big, big, big}});
  for(const std::array<std::size_t, 3>& t : soup.triangles)
    for(std::size_t v : t)
      first_triangle[v] = (std::min)(first_triangle[v], sorted(t));
  std::vector<std::size_t> vertex_order(nv);
  std::iota(vertex_order.begin(), vertex_order.end(), std::size_t(0));
  std::sort(vertex_order.begin(), vertex_order.end(), [&](std::size_t x, std::size_t y) {
    return std::tie(soup.shape_vertex[x], first_triangle[x]) < std::tie(soup.shape_vertex[y], first_triangle[y]);
  });
  std::vector<std::size_t> new_vertex(nv);
  std::vector<std::size_t> shape_vertex(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    new_vertex[vertex_order[i]] = i;
    shape_vertex[i] = soup.shape_vertex[vertex_order[i]];
  }

  // triangles renumbered and rotated to start at their smallest vertex,
  // with their neighbours (opposite to each vertex) rotated alike
  std::vector<std::array<std::size_t, 3> > triangles(nt), neighbors(nt);
  for(std::size_t t = 0; t < nt; ++t)
  {
    std::array<std::size_t, 3> v;
    for(int k = 0; k < 3; ++k)
      v[k] = new_vertex[soup.triangles[t][k]];
    const int r = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
    for(int k = 0; k < 3; ++k)
    {
      triangles[t][k] = v[(k + r) % 3];
      neighbors[t][k] = soup.neighbors[t][(k + r) % 3];
    }
  }
  std::vector<std::size_t> triangle_order(nt);
  std::iota(triangle_order.begin(), triangle_order.end(), std::size_t(0));
  std::sort(triangle_order.begin(), triangle_order.end(),
            [&](std::size_t x, std::size_t y) { return triangles[x] < triangles[y]; });
  std::vector<std::size_t> new_triangle(nt);
  for(std::size_t i = 0; i < nt; ++i)
    new_triangle[triangle_order[i]] = i;
  Advancing_front_soup ordered;
  ordered.shape_vertex = std::move(shape_vertex);
  ordered.triangles.reserve(nt);
  ordered.neighbors.reserve(nt);
  ordered.values.reserve(nt);
  for(std::size_t t : triangle_order)
  {
    ordered.triangles.push_back(triangles[t]);
    std::array<std::size_t, 3> n = neighbors[t];
    for(std::size_t& x : n)
      if(x != Advancing_front_soup::no_neighbor)
        x = new_triangle[x];
    ordered.neighbors.push_back(n);
    ordered.values.push_back(soup.values[t]);
  }
  soup = std::move(ordered);
}

// The soup at scale `a` cut from the soup grown with no bound: the
// triangles whose value exceeds `a` are removed and their neighbours get a
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
  std::sort(fans.begin(), fans.end());
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

// The soup grown with no bound on the scale.
template <class Cas>
Advancing_front_soup advancing_front_soup(const Cas& cas)
{
  typedef typename Cas::Geom_traits Gt;
  typedef Advancing_front_surface_reconstruction_vertex_base_3<Gt> Vb;
  typedef Advancing_front_surface_reconstruction_cell_base_3<
    Gt, Triangulation_cell_base_with_info_3<Conformal_cell_values, Gt, Delaunay_triangulation_cell_base_3<Gt> > > Cb;
  typedef Delaunay_triangulation_3<Gt, Triangulation_data_structure_3<Vb, Cb> > Front_triangulation;
  typedef Advancing_front_surface_reconstruction<Front_triangulation, Conformal_priority> Front;
  typedef typename Front_triangulation::Vertex Front_vertex;
  typedef typename Front_triangulation::Cell Front_cell;
  typedef typename Cas::Triangulation_data_structure::Vertex Shape_vertex;
  typedef typename Cas::Triangulation_data_structure::Cell Shape_cell;

  Advancing_front_soup soup;
  if(cas.dimension() < 3)
    return soup;

  const std::size_t no_vertex = std::size_t(-1);
  const Shape_vertex* const infinite = &*cas.infinite_vertex();
  struct Convert_vertex
  {
    const Shape_vertex* infinite;
    std::size_t no_vertex;
    Front_vertex operator()(const Shape_vertex& v) const { return Front_vertex(v.point()); }
    void operator()(const Shape_vertex& v, Front_vertex& w) const
    {
      w.id() = &v == infinite ? no_vertex : v.vertex_index();
    }
  };
  struct Convert_cell
  {
    const Cas* cas;
    Front_cell operator()(const Shape_cell&) const { return Front_cell(); }
    void operator()(const Shape_cell& c, Front_cell& d) const
    {
      const typename Cas::Cell_handle h = cas->tds().cells().iterator_to(const_cast<Shape_cell&>(c));
      Conformal_cell_values& values = d.info();
      for(int i = 0; i < 4; ++i)
        values.facet[i] = cas->is_infinite(h, i) ? std::numeric_limits<double>::infinity()
                                                 : double(cas->conformal_alpha(h, i));
    }
  };

  Front_triangulation triangulation(cas.geom_traits());
  triangulation.set_infinite_vertex(
    triangulation.tds().copy_tds(cas.tds(), cas.infinite_vertex(), Convert_vertex{infinite, no_vertex},
                                 Convert_cell{&cas}));
  Front_seeding seeding(cas.number_of_vertices());
  Front front(triangulation, Conformal_priority{&seeding});
  front.run();

  typedef typename Front::Triangulation_data_structure_2 Tds_2;
  const Tds_2& tds = front.triangulation_data_structure_2();
  CGAL::Unique_hash_map<typename Tds_2::Vertex_handle, std::size_t> soup_vertex(no_vertex);
  CGAL::Unique_hash_map<typename Tds_2::Face_handle, std::size_t> soup_triangle(no_vertex);
  for(auto f = tds.faces_begin(); f != tds.faces_end(); ++f)
  {
    if(!f->is_on_surface())
      continue;
    soup_triangle[f] = soup.triangles.size();
    std::array<std::size_t, 3> triangle;
    for(int k = 0; k < 3; ++k)
    {
      std::size_t& s = soup_vertex[f->vertex(k)];
      if(s == no_vertex)
      {
        s = soup.shape_vertex.size();
        soup.shape_vertex.push_back(f->vertex(k)->vertex_3()->id());
      }
      triangle[k] = s;
    }
    soup.triangles.push_back(triangle);
    soup.values.push_back(f->facet().first->info().facet[f->facet().second]);
  }
  soup.neighbors.reserve(soup.triangles.size());
  for(auto f = tds.faces_begin(); f != tds.faces_end(); ++f)
  {
    if(!f->is_on_surface())
      continue;
    std::array<std::size_t, 3> n;
    for(int k = 0; k < 3; ++k)
      n[k] = f->neighbor(k)->is_on_surface() ? soup_triangle[f->neighbor(k)] : Advancing_front_soup::no_neighbor;
    soup.neighbors.push_back(n);
  }
  put_in_canonical_order(soup);
  return soup;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ADVANCING_FRONT_FACETS_H
