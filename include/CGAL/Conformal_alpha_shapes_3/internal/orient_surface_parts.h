// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ORIENT_SURFACE_PARTS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ORIENT_SURFACE_PARTS_H

#include <CGAL/Conformal_alpha_shapes_3/internal/advancing_front_facets.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <tuple>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// With reference normals (a scanner's): cuts the soup where the side that
// the reference normals ask for changes inside a part, as where the front
// folded one sheet over both faces of a thin wall or over clutter seen from
// two sides. Each triangle asks for the side most of its corners' reference
// normals are on; the regions of triangles asking alike (a region smaller
// than `smallest_region` triangles takes its neighbours' side, so that a few
// grazing normals do not cut) become parts of their own: the links between
// regions are removed and a vertex shared by regions gets one copy per
// region. `point(s)` gives the position of soup vertex `s`, `reference(s)`
// its reference normal.
template <class Vector, class PointOf, class ReferenceOf>
void cut_at_reference_folds(Advancing_front_soup& soup, const PointOf& point, const ReferenceOf& reference)
{
  const std::size_t smallest_region = 64;
  const std::size_t n = soup.triangles.size(), none = Advancing_front_soup::no_neighbor;
  std::vector<int> side(n, 0);
  for(std::size_t t = 0; t < n; ++t)
  {
    const std::array<std::size_t, 3>& tri = soup.triangles[t];
    const Vector area_normal = CGAL::cross_product(point(tri[1]) - point(tri[0]), point(tri[2]) - point(tri[0]));
    int votes = 0;
    for(std::size_t s : tri)
    {
      const double d = CGAL::to_double(area_normal * reference(s));
      votes += d > 0 ? 1 : (d < 0 ? -1 : 0);
    }
    side[t] = votes > 0 ? 1 : (votes < 0 ? -1 : 0);
  }
  // regions: triangles linked across edges where their sides do not conflict
  std::vector<std::size_t> region(n);
  auto label_regions = [&]() {
    std::fill(region.begin(), region.end(), none);
    std::vector<std::size_t> stack;
    for(std::size_t seed = 0; seed < n; ++seed)
    {
      if(region[seed] != none)
        continue;
      region[seed] = seed;
      stack.push_back(seed);
      while(!stack.empty())
      {
        const std::size_t t = stack.back();
        stack.pop_back();
        for(std::size_t u : soup.neighbors[t])
          if(u != none && region[u] == none && side[u] * side[t] >= 0 && side[u] * side[seed] >= 0)
          {
            region[u] = seed;
            stack.push_back(u);
          }
      }
    }
  };
  label_regions();
  std::vector<std::size_t> size(n, 0);
  for(std::size_t t = 0; t < n; ++t)
    ++size[region[t]];
  std::vector<int> neighbours_side(n, 0);
  for(std::size_t t = 0; t < n; ++t)
    if(size[region[t]] < smallest_region)
      for(std::size_t u : soup.neighbors[t])
        if(u != none && region[u] != region[t] && size[region[u]] >= smallest_region)
          neighbours_side[region[t]] += side[u];
  for(std::size_t t = 0; t < n; ++t)
    if(size[region[t]] < smallest_region && neighbours_side[region[t]] != 0)
      side[t] = neighbours_side[region[t]] > 0 ? 1 : -1;
  label_regions();

  // cut between regions
  std::vector<std::size_t> owner(soup.shape_vertex.size(), none);
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> copy;  // (vertex, region) -> copy
  for(std::size_t t = 0; t < n; ++t)
  {
    for(std::size_t& u : soup.neighbors[t])
      if(u != none && region[u] != region[t])
        u = none;
    for(std::size_t& s : soup.triangles[t])
    {
      if(owner[s] == none)
        owner[s] = region[t];
      if(owner[s] == region[t])
        continue;
      const auto inserted = copy.emplace(std::make_pair(s, region[t]), soup.shape_vertex.size());
      if(inserted.second)
        soup.shape_vertex.push_back(soup.shape_vertex[s]);
      s = inserted.first->second;
    }
  }
}

// The parts of a soup: the classes of triangles connected across edges.
struct Soup_parts
{
  std::vector<std::size_t> part_of_triangle;
  std::size_t number_of_parts = 0;
  std::size_t size() const { return number_of_parts; }
};

inline Soup_parts soup_parts(const Advancing_front_soup& soup)
{
  Soup_parts parts;
  const std::size_t none = std::size_t(-1);
  parts.part_of_triangle.assign(soup.triangles.size(), none);
  std::vector<std::size_t> stack;
  for(std::size_t seed = 0; seed < soup.triangles.size(); ++seed)
  {
    if(parts.part_of_triangle[seed] != none)
      continue;
    const std::size_t part = parts.number_of_parts++;
    parts.part_of_triangle[seed] = part;
    stack.push_back(seed);
    while(!stack.empty())
    {
      const std::size_t t = stack.back();
      stack.pop_back();
      for(std::size_t n : soup.neighbors[t])
      {
        if(n != Advancing_front_soup::no_neighbor && parts.part_of_triangle[n] == none)
        {
          parts.part_of_triangle[n] = part;
          stack.push_back(n);
        }
      }
    }
  }
  return parts;
}

// Parts that meet along border edges (the front grew them from different
// seeds) are one sheet of the sampled surface: they are oriented alike, each
// edge shared by two parts being passed in opposite directions. Each part is
// joined to its sheet across the part it shares most edges with, in order
// of decreasing counts, so that a few contradicting edges are outvoted.
struct Soup_sheets
{
  std::vector<std::size_t> sheet_of_part;
  std::vector<char> reverse_in_sheet;  // by part: against its sheet's first part
  std::vector<char> closed;            // by sheet: every border edge shared
  std::size_t size() const { return closed.size(); }
};

inline Soup_sheets soup_sheets(const Advancing_front_soup& soup, const Soup_parts& parts)
{
  // border edges as (smaller shape vertex, larger one, part, same direction)
  struct Border_edge { std::size_t u, v, part; bool forward; };
  std::vector<Border_edge> edges;
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
    for(int k = 0; k < 3; ++k)
      if(soup.neighbors[t][k] == Advancing_front_soup::no_neighbor)
      {
        const std::size_t a = soup.shape_vertex[soup.triangles[t][(k + 1) % 3]];
        const std::size_t b = soup.shape_vertex[soup.triangles[t][(k + 2) % 3]];
        edges.push_back(Border_edge{(std::min)(a, b), (std::max)(a, b), parts.part_of_triangle[t], a < b});
      }
  std::sort(edges.begin(), edges.end(), [](const Border_edge& x, const Border_edge& y) {
    return std::tie(x.u, x.v, x.part) < std::tie(y.u, y.v, y.part);
  });

  // votes between two parts: (parts, reversed relative to each other) -> count
  std::map<std::tuple<std::size_t, std::size_t, bool>, std::size_t> votes;
  std::vector<char> part_has_unshared(parts.size(), 0);
  for(std::size_t i = 0; i < edges.size();)
  {
    std::size_t j = i + 1;
    while(j < edges.size() && edges[j].u == edges[i].u && edges[j].v == edges[i].v)
      ++j;
    if(j - i == 2 && edges[i].part != edges[i + 1].part)
      ++votes[std::make_tuple(edges[i].part, edges[i + 1].part, edges[i].forward == edges[i + 1].forward)];
    else
      for(std::size_t k = i; k < j; ++k)
        part_has_unshared[edges[k].part] = 1;
    i = j;
  }
  std::vector<std::pair<std::size_t, std::tuple<std::size_t, std::size_t, bool> > > links;
  for(const auto& vote : votes)
    links.emplace_back(vote.second, vote.first);
  std::sort(links.begin(), links.end(), [](const auto& x, const auto& y) { return x.first > y.first; });

  // union-find with the orientation of each part relative to its root
  std::vector<std::size_t> root(parts.size());
  std::vector<char> flip(parts.size(), 0);
  std::iota(root.begin(), root.end(), std::size_t(0));
  auto find = [&](std::size_t p) {
    char f = 0;
    while(root[p] != p) { f ^= flip[p]; p = root[p]; }
    return std::make_pair(p, f);
  };
  for(const auto& link : links)
  {
    const auto a = find(std::get<0>(link.second));
    const auto b = find(std::get<1>(link.second));
    if(a.first == b.first)
      continue;
    root[b.first] = a.first;
    flip[b.first] = char(a.second ^ b.second ^ (std::get<2>(link.second) ? 1 : 0));
  }

  Soup_sheets sheets;
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> sheet_of_root(parts.size(), none);
  sheets.sheet_of_part.resize(parts.size());
  sheets.reverse_in_sheet.resize(parts.size());
  for(std::size_t p = 0; p < parts.size(); ++p)
  {
    const auto r = find(p);
    if(sheet_of_root[r.first] == none)
    {
      sheet_of_root[r.first] = sheets.closed.size();
      sheets.closed.push_back(1);
    }
    sheets.sheet_of_part[p] = sheet_of_root[r.first];
    sheets.reverse_in_sheet[p] = r.second;
    if(part_has_unshared[p])
      sheets.closed[sheets.sheet_of_part[p]] = 0;
  }
  return sheets;
}

// Which parts to reverse so that each faces the way the orientation rule of
// the manual says ("Orientation"):
// - with reference normals (a scanner's), each part (cut at the folds, see
//   `cut_at_reference_folds()`) agrees with the majority of the reference
//   normals at its vertices;
// - without, the cone that the sheet spans from the centre of the surface's
//   vertices has positive volume: for a closed sheet that is the volume it
//   encloses, wherever the centre, so it points outwards; an open sheet
//   points away from the centre (outwards, for a single view of a convex
//   object or a building's facades).
// `point(s)` gives the position of soup vertex `s`, `reference(s)` its
// reference normal.
template <class Vector, class PointOf, class ReferenceOf>
std::vector<char> parts_to_reverse(const Advancing_front_soup& soup, const Soup_parts& parts,
                                   const Soup_sheets& sheets, const PointOf& point,
                                   const ReferenceOf& reference, bool has_reference)
{
  std::vector<double> vote(has_reference ? parts.size() : sheets.size(), 0.0);
  // the centre of the soup's vertices: the apex of the cones
  Vector centre(0, 0, 0);
  for(std::size_t s = 0; s < soup.shape_vertex.size(); ++s)
    centre = centre + (point(s) - CGAL::ORIGIN);
  if(!soup.shape_vertex.empty())
    centre = centre / double(soup.shape_vertex.size());

  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const std::array<std::size_t, 3>& tri = soup.triangles[t];
    const Vector p0 = point(tri[0]) - CGAL::ORIGIN - centre;
    const Vector p1 = point(tri[1]) - CGAL::ORIGIN - centre;
    const Vector p2 = point(tri[2]) - CGAL::ORIGIN - centre;
    const Vector area_normal = CGAL::cross_product(p1 - p0, p2 - p0);
    const std::size_t part = parts.part_of_triangle[t];
    if(has_reference)
    {
      for(std::size_t s : tri)
      {
        const double d = CGAL::to_double(area_normal * reference(s));
        vote[part] += d > 0 ? 1.0 : (d < 0 ? -1.0 : 0.0);
      }
    }
    else
      vote[sheets.sheet_of_part[part]] += (sheets.reverse_in_sheet[part] ? -1.0 : 1.0)
                                          * CGAL::to_double(area_normal * p0);  // six times the signed cone volume
  }
  std::vector<char> reverse(parts.size(), 0);
  for(std::size_t p = 0; p < parts.size(); ++p)
    reverse[p] = has_reference ? char(vote[p] < 0 ? 1 : 0)
                               : char((vote[sheets.sheet_of_part[p]] < 0 ? 1 : 0) ^ sheets.reverse_in_sheet[p]);
  return reverse;
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ORIENT_SURFACE_PARTS_H
