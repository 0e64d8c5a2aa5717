// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOUP_SHEETS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOUP_SHEETS_H

// The parts of a triangle soup (triangles connected across edges) and the
// sheets they form (parts that meet along border edges), with the relative
// orientation of the parts of a sheet.

#include <CGAL/Conformal_alpha_shapes_3/internal/triangle_soup.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

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

// Union-find over elements (parts, sheets) that also keeps whether each
// element is reversed relative to the root of its class.
struct Parity_union_find
{
  std::vector<std::size_t> root;
  std::vector<char> flip;

  explicit Parity_union_find(std::size_t n) : root(n), flip(n, 0)
  {
    std::iota(root.begin(), root.end(), std::size_t(0));
  }

  // (root, reversed relative to it)
  std::pair<std::size_t, char> find(std::size_t x) const
  {
    char f = 0;
    while(root[x] != x) { f ^= flip[x]; x = root[x]; }
    return std::make_pair(x, f);
  }

  // puts `x` and `y` in one class, `y` reversed relative to `x` when
  // `reversed`; nothing when they already are in one class
  void join(std::size_t x, std::size_t y, bool reversed)
  {
    const std::pair<std::size_t, char> a = find(x), b = find(y);
    if(a.first == b.first)
      return;
    root[b.first] = a.first;
    flip[b.first] = char(a.second ^ b.second ^ (reversed ? 1 : 0));
  }
};

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

  Parity_union_find classes(parts.size());
  for(const auto& link : links)
    classes.join(std::get<0>(link.second), std::get<1>(link.second), std::get<2>(link.second));

  Soup_sheets sheets;
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> sheet_of_root(parts.size(), none);
  sheets.sheet_of_part.resize(parts.size());
  sheets.reverse_in_sheet.resize(parts.size());
  for(std::size_t p = 0; p < parts.size(); ++p)
  {
    const std::pair<std::size_t, char> r = classes.find(p);
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

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_SOUP_SHEETS_H
