// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ORIENT_SURFACE_PARTS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ORIENT_SURFACE_PARTS_H

#include <CGAL/Conformal_alpha_shapes_3/internal/soup_sheets.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/triangle_soup.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

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

// How the sheets of a surface are oriented (the manual, "Orientation").

// With reference normals (a scanner's): cuts the soup where the side that
// the reference normals ask for changes inside a part, as where the front
// folded one sheet over both faces of a thin wall or over clutter seen from
// two sides. Each triangle asks for the side most of its corners' reference
// normals are on; the regions of triangles asking alike (a region smaller
// than `smallest_region` triangles takes its neighbors' side, so that a few
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
  std::vector<int> neighbors_side(n, 0);
  for(std::size_t t = 0; t < n; ++t)
    if(size[region[t]] < smallest_region)
      for(std::size_t u : soup.neighbors[t])
        if(u != none && region[u] != region[t] && size[region[u]] >= smallest_region)
          neighbors_side[region[t]] += side[u];
  for(std::size_t t = 0; t < n; ++t)
    if(size[region[t]] < smallest_region && neighbors_side[region[t]] != 0)
      side[t] = neighbors_side[region[t]] > 0 ? 1 : -1;
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

// Open sheets that continue each other across a gap that the front did not
// bridge (a strip the scan missed, a step whose riser it did not sample) are
// oriented alike, as the parts of one sheet are. Each border vertex of an
// open sheet looks for the nearest border vertex of another open sheet
// among its `neighbors` nearest border vertices; it votes for the two
// sheets to face alike (their normals there to agree) when that vertex is
// within `gap` times its local spacing (the mean length of its edges), the
// gap lies within 45 degrees of both vertices' tangent planes, and their
// normals are within 45 degrees of parallel. Sheets are joined in order of
// decreasing votes, from `fewest_votes` up, so that a few contradicting
// pairs are outvoted. Two faces of a thin wall (offset along the normal) or
// sheets that meet at an angle never vote: being near does not tell which
// way they face. Closed sheets stay alone: they point out of the volume
// they enclose; so do the open sheets that nearly close round their own
// center (`mark_sheets_round_own_centers()`): a blob beside a sheet does
// not continue it.
struct Sheet_groups
{
  std::vector<std::size_t> group_of_sheet;
  std::vector<char> reverse_in_group;  // by sheet: against its group's first sheet
  std::size_t number_of_groups = 0;
  // by sheet: whether it is open and nearly closes round its own center,
  // and then the signed volume of the cone from that center (its parts as
  // oriented in the sheet)
  std::vector<char> round_own_center;
  std::vector<double> own_cone_volume;

  // every sheet a group of its own
  static Sheet_groups one_per_sheet(std::size_t number_of_sheets)
  {
    Sheet_groups groups;
    groups.group_of_sheet.resize(number_of_sheets);
    std::iota(groups.group_of_sheet.begin(), groups.group_of_sheet.end(), std::size_t(0));
    groups.reverse_in_group.assign(number_of_sheets, 0);
    groups.number_of_groups = number_of_sheets;
    groups.round_own_center.assign(number_of_sheets, 0);
    groups.own_cone_volume.assign(number_of_sheets, 0.0);
    return groups;
  }
};

// The open sheets that nearly close round their own center (a blob with a
// small hole, as a knob of a statue can be): the cone from the surface's
// center over such a sheet's hole can outweigh the volume it encloses,
// and a nearby sheet's border can vote it to face like that sheet; both
// turned a 25-point blob of `oni.pwn` inwards. A sheet qualifies when the
// cone from its own center (the area-weighted mean of its triangles'
// centroids) holds at least half the volume of a sphere of the same area
// and mean radius: 3 |V| >= A r / 2, where a sphere gives 1 and a flat or
// gently curved sheet nearly 0.
template <class Vector, class PointOf>
void mark_sheets_round_own_centers(const Advancing_front_soup& soup, const Soup_parts& parts,
                                   const Soup_sheets& sheets, const PointOf& point, Sheet_groups& groups)
{
  const std::size_t ns = sheets.size();
  auto centroid_and_area = [&](std::size_t t, Vector& centroid) {
    const std::array<std::size_t, 3>& tri = soup.triangles[t];
    centroid = ((point(tri[0]) - CGAL::ORIGIN) + (point(tri[1]) - CGAL::ORIGIN) + (point(tri[2]) - CGAL::ORIGIN)) / 3.0;
    return std::sqrt(CGAL::to_double(
             CGAL::cross_product(point(tri[1]) - point(tri[0]), point(tri[2]) - point(tri[0])).squared_length()))
           / 2;
  };
  std::vector<double> area(ns, 0.0);
  std::vector<Vector> center(ns, Vector(0, 0, 0));
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const std::size_t sheet = sheets.sheet_of_part[parts.part_of_triangle[t]];
    Vector c;
    const double a = centroid_and_area(t, c);
    area[sheet] += a;
    center[sheet] = center[sheet] + a * c;
  }
  std::vector<double> radius(ns, 0.0);
  groups.own_cone_volume.assign(ns, 0.0);
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const std::size_t part = parts.part_of_triangle[t], sheet = sheets.sheet_of_part[part];
    if(sheets.closed[sheet] || !(area[sheet] > 0))
      continue;
    const Vector q = center[sheet] / area[sheet];
    Vector c;
    radius[sheet] += centroid_and_area(t, c) * std::sqrt(CGAL::to_double((c - q).squared_length()));
    const std::array<std::size_t, 3>& tri = soup.triangles[t];
    const Vector area_normal = CGAL::cross_product(point(tri[1]) - point(tri[0]), point(tri[2]) - point(tri[0]));
    groups.own_cone_volume[sheet] += (sheets.reverse_in_sheet[part] ? -1.0 : 1.0)
                                     * CGAL::to_double(area_normal * (point(tri[0]) - CGAL::ORIGIN - q)) / 6;
  }
  groups.round_own_center.assign(ns, 0);
  for(std::size_t sheet = 0; sheet < ns; ++sheet)
    groups.round_own_center[sheet] = char(!sheets.closed[sheet] && area[sheet] > 0
                                          && 3 * std::abs(groups.own_cone_volume[sheet]) >= 0.5 * radius[sheet]);
}

template <class Vector, class PointOf>
Sheet_groups join_open_sheets_across_gaps(const Advancing_front_soup& soup, const Soup_parts& parts,
                                          const Soup_sheets& sheets, const PointOf& point)
{
  typedef typename CGAL::Kernel_traits<Vector>::Kernel Kernel;
  typedef typename Kernel::Point_3 Point;
  typedef CGAL::Search_traits_adapter<std::size_t, typename CGAL::Pointer_property_map<Point>::type,
                                      CGAL::Search_traits_3<Kernel> > Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef typename Search::Tree Tree;
  const double gap = 8, cos_45 = 0.7071;
  const unsigned int neighbors = 24;
  const std::size_t fewest_votes = 3, none = Advancing_front_soup::no_neighbor;

  // normals (as oriented in their sheet), local spacings and border vertices
  const std::size_t nv = soup.shape_vertex.size();
  std::vector<Vector> normal(nv, Vector(0, 0, 0));
  std::vector<double> spacing(nv, 0.0);
  std::vector<int> edges_at(nv, 0);
  std::vector<std::size_t> sheet_of_vertex(nv, none);
  std::vector<char> on_border(nv, 0);
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const std::array<std::size_t, 3>& tri = soup.triangles[t];
    const std::size_t part = parts.part_of_triangle[t], sheet = sheets.sheet_of_part[part];
    const Vector area_normal = CGAL::cross_product(point(tri[1]) - point(tri[0]), point(tri[2]) - point(tri[0]));
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t s = tri[k];
      normal[s] = normal[s] + (sheets.reverse_in_sheet[part] ? -area_normal : area_normal);
      sheet_of_vertex[s] = sheet;
      const double length = std::sqrt(CGAL::to_double((point(tri[(k + 1) % 3]) - point(s)).squared_length()));
      spacing[s] += length;
      spacing[tri[(k + 1) % 3]] += length;
      ++edges_at[s];
      ++edges_at[tri[(k + 1) % 3]];
      if(soup.neighbors[t][k] == none && !sheets.closed[sheet])
        on_border[tri[(k + 1) % 3]] = on_border[tri[(k + 2) % 3]] = 1;
    }
  }
  std::vector<std::size_t> border;
  std::vector<Point> position(nv);
  for(std::size_t s = 0; s < nv; ++s)
  {
    position[s] = point(s);
    if(on_border[s])
      border.push_back(s);
  }

  Sheet_groups groups;
  mark_sheets_round_own_centers<Vector>(soup, parts, sheets, point, groups);

  // votes between two sheets: (sheets, reversed relative to each other) -> count
  std::map<std::tuple<std::size_t, std::size_t, bool>, std::size_t> votes;
  if(!border.empty())
  {
    const typename CGAL::Pointer_property_map<Point>::type position_map = CGAL::make_property_map(position);
    Tree tree(border.begin(), border.end(), typename Tree::Splitter(), Traits(position_map));
    const typename Search::Distance distance(position_map);
    for(std::size_t u : border)
    {
      const Search search(tree, position[u], neighbors, 0, true, distance);
      for(const auto& found : search)
      {
        const std::size_t w = found.first;
        if(sheet_of_vertex[w] == sheet_of_vertex[u])
          continue;
        // the nearest border vertex of another sheet: near, in the tangent planes, parallel
        const Vector offset = position[w] - position[u];
        const double length = std::sqrt(CGAL::to_double(offset.squared_length()));
        const double nu = std::sqrt(CGAL::to_double(normal[u].squared_length()));
        const double nw = std::sqrt(CGAL::to_double(normal[w].squared_length()));
        if(!(nu > 0 && nw > 0) || groups.round_own_center[sheet_of_vertex[u]]
           || groups.round_own_center[sheet_of_vertex[w]])
          break;
        const double cos_normals = CGAL::to_double(normal[u] * normal[w]) / (nu * nw);
        if(length <= gap * spacing[u] / (std::max)(edges_at[u], 1)
           && std::abs(CGAL::to_double(offset * normal[u])) <= cos_45 * length * nu
           && std::abs(CGAL::to_double(offset * normal[w])) <= cos_45 * length * nw
           && std::abs(cos_normals) >= cos_45)
        {
          const std::size_t a = (std::min)(sheet_of_vertex[u], sheet_of_vertex[w]);
          const std::size_t b = (std::max)(sheet_of_vertex[u], sheet_of_vertex[w]);
          ++votes[std::make_tuple(a, b, cos_normals < 0)];
        }
        break;
      }
    }
  }
  std::vector<std::pair<std::size_t, std::tuple<std::size_t, std::size_t, bool> > > links;
  for(const auto& vote : votes)
    if(vote.second >= fewest_votes)
      links.emplace_back(vote.second, vote.first);
  std::sort(links.begin(), links.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  Parity_union_find classes(sheets.size());
  for(const auto& link : links)
    classes.join(std::get<0>(link.second), std::get<1>(link.second), std::get<2>(link.second));

  std::vector<std::size_t> group_of_root(sheets.size(), none);
  groups.group_of_sheet.resize(sheets.size());
  groups.reverse_in_group.resize(sheets.size());
  for(std::size_t sheet = 0; sheet < sheets.size(); ++sheet)
  {
    const std::pair<std::size_t, char> r = classes.find(sheet);
    if(group_of_root[r.first] == none)
      group_of_root[r.first] = groups.number_of_groups++;
    groups.group_of_sheet[sheet] = group_of_root[r.first];
    groups.reverse_in_group[sheet] = r.second;
  }
  return groups;
}

// A group of sheets whose cones' sum is less than this share of the sum of
// their sizes faces neither towards the center nor away from it (a terrain,
// whose roofs above the center and ground below it nearly cancel): the sign
// of such a sum follows the cloud's last bits and its sampling density, and
// a turn of the cloud about z could turn the sheet over. A cap of a convex
// object has nearly all its cones of one sign (a share near 1), and a closed
// sheet's area normals sum to zero, so neither falls under the rule below.
constexpr double nearly_flat_cone_share = 0.25;
// Such a group faces +z (up, as airborne and terrestrial scans are seen)
// when its area normals summed reach this share of its area; the rule is
// then one of the cloud's z axis: translations, scaling and turns about z
// keep it, tilts need not.
constexpr double mostly_along_z_share = 0.5;

// Which parts to reverse so that each faces the way the orientation rule of
// the manual says ("Orientation"):
// - with reference normals (a scanner's), each part (cut at the folds, see
//   `cut_at_reference_folds()`) agrees with the majority of the reference
//   normals at its vertices;
// - without, the cone that the sheet spans from the center of the surface's
//   vertices has positive volume: for a closed sheet that is the volume it
//   encloses, wherever the center, so it points outwards; an open sheet
//   points away from the center (outwards, for a single view of a convex
//   object or a building's facades), together with the open sheets it
//   continues across gaps (`groups`, see `join_open_sheets_across_gaps()`):
//   the cones of a group are summed; an open sheet that nearly closes round
//   its own center points out of it (`mark_sheets_round_own_centers()`);
//   a group whose cones nearly cancel (`nearly_flat_cone_share`) and that
//   mostly faces along z (`mostly_along_z_share`) faces +z.
// `point(s)` gives the position of soup vertex `s`, `reference(s)` its
// reference normal.
template <class Vector, class PointOf, class ReferenceOf>
std::vector<char> parts_to_reverse(const Advancing_front_soup& soup, const Soup_parts& parts,
                                   const Soup_sheets& sheets, const Sheet_groups& groups, const PointOf& point,
                                   const ReferenceOf& reference, bool has_reference)
{
  // against the first sheet of its group, when oriented by the cones
  auto reversed_in_group = [&](std::size_t part) {
    return char(sheets.reverse_in_sheet[part] ^ groups.reverse_in_group[sheets.sheet_of_part[part]]);
  };
  auto group_of_part = [&](std::size_t part) { return groups.group_of_sheet[sheets.sheet_of_part[part]]; };
  std::vector<double> vote(has_reference ? parts.size() : groups.number_of_groups, 0.0);
  // without reference normals, by group: the sum of the cones' sizes, the
  // area normals' z summed as the cones are, and the area
  std::vector<double> cone_sizes(vote.size(), 0.0), up(vote.size(), 0.0), area(vote.size(), 0.0);
  // the center of the soup's vertices: the apex of the cones
  Vector center(0, 0, 0);
  for(std::size_t s = 0; s < soup.shape_vertex.size(); ++s)
    center = center + (point(s) - CGAL::ORIGIN);
  if(!soup.shape_vertex.empty())
    center = center / double(soup.shape_vertex.size());

  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const std::array<std::size_t, 3>& tri = soup.triangles[t];
    const Vector p0 = point(tri[0]) - CGAL::ORIGIN - center;
    const Vector p1 = point(tri[1]) - CGAL::ORIGIN - center;
    const Vector p2 = point(tri[2]) - CGAL::ORIGIN - center;
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
    {
      const std::size_t g = group_of_part(part);
      const double sign = reversed_in_group(part) ? -1.0 : 1.0;
      const double cone = CGAL::to_double(area_normal * p0);  // six times the signed cone volume
      vote[g] += sign * cone;
      cone_sizes[g] += std::abs(cone);
      up[g] += sign * CGAL::to_double(area_normal.z());
      area[g] += std::sqrt(CGAL::to_double(area_normal.squared_length()));
    }
  }
  if(!has_reference)
  {
    for(std::size_t g = 0; g < vote.size(); ++g)
      if(std::abs(vote[g]) < nearly_flat_cone_share * cone_sizes[g]
         && std::abs(up[g]) >= mostly_along_z_share * area[g])
        vote[g] = up[g];
    for(std::size_t sheet = 0; sheet < sheets.size(); ++sheet)
      if(groups.round_own_center[sheet])  // alone in its group, see join_open_sheets_across_gaps()
        vote[groups.group_of_sheet[sheet]] = groups.own_cone_volume[sheet];
  }
  std::vector<char> reverse(parts.size(), 0);
  for(std::size_t p = 0; p < parts.size(); ++p)
    reverse[p] = has_reference ? char(vote[p] < 0 ? 1 : 0)
                               : char((vote[group_of_part(p)] < 0 ? 1 : 0) ^ reversed_in_group(p));
  return reverse;
}

// With reference normals, which of them to follow: the soup is first
// oriented as without them; on each sheet the given normals are consistent
// when at least `consistent_share` of its triangles' corners agree with that
// orientation, or as many disagree (a scanner's normals, an oriented
// reconstruction's, flipped or not; random signs agree at about half).
// Returns by shape vertex (`soup.shape_vertex`) the normal to follow: the
// given one on a consistent sheet, else the vertex's normal in that first
// orientation, so that such a sheet is oriented as without reference
// normals; `inconsistent_sheets` counts those sheets.
constexpr double consistent_share = 0.75;

template <class Vector, class PointOf, class ReferenceOf>
std::vector<Vector> normals_to_follow(const Advancing_front_soup& soup, std::size_t number_of_shape_vertices,
                                      const PointOf& point, const ReferenceOf& reference,
                                      std::size_t& inconsistent_sheets)
{
  const Soup_parts parts = soup_parts(soup);
  const Soup_sheets sheets = soup_sheets(soup, parts);
  const Sheet_groups groups = join_open_sheets_across_gaps<Vector>(soup, parts, sheets, point);
  const std::vector<char> reverse = parts_to_reverse<Vector>(soup, parts, sheets, groups, point, reference, false);
  std::vector<std::size_t> agree(sheets.size(), 0), disagree(sheets.size(), 0);
  std::vector<std::size_t> sheet_of_vertex(soup.shape_vertex.size(), 0);
  std::vector<Vector> oriented(soup.shape_vertex.size(), Vector(0, 0, 0));
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const std::array<std::size_t, 3>& tri = soup.triangles[t];
    const std::size_t part = parts.part_of_triangle[t];
    Vector area_normal = CGAL::cross_product(point(tri[1]) - point(tri[0]), point(tri[2]) - point(tri[0]));
    if(reverse[part])
      area_normal = -area_normal;
    const std::size_t sheet = sheets.sheet_of_part[part];
    for(std::size_t s : tri)
    {
      const double d = CGAL::to_double(area_normal * reference(s));
      agree[sheet] += d > 0 ? 1 : 0;
      disagree[sheet] += d < 0 ? 1 : 0;
      oriented[s] = oriented[s] + area_normal;
      sheet_of_vertex[s] = sheet;
    }
  }
  std::vector<char> consistent(sheets.size(), 0);
  inconsistent_sheets = 0;
  for(std::size_t sheet = 0; sheet < sheets.size(); ++sheet)
  {
    const double votes = double(agree[sheet] + disagree[sheet]);
    consistent[sheet] = votes > 0 && double((std::max)(agree[sheet], disagree[sheet])) >= consistent_share * votes;
    inconsistent_sheets += consistent[sheet] ? 0 : 1;
  }
  std::vector<Vector> follow(number_of_shape_vertices, Vector(0, 0, 0));
  for(std::size_t s = 0; s < soup.shape_vertex.size(); ++s)
    follow[soup.shape_vertex[s]] = consistent[sheet_of_vertex[s]] ? Vector(reference(s)) : oriented[s];
  return follow;
}

// The share of the soup's vertices whose reference normal points to the
// side their sheet faces once the parts in `reverse` are turned.
template <class Vector, class PointOf, class ReferenceOf>
double reference_agreement(const Advancing_front_soup& soup, const Soup_parts& parts,
                           const std::vector<char>& reverse, const PointOf& point, const ReferenceOf& reference)
{
  std::vector<Vector> oriented(soup.shape_vertex.size(), Vector(0, 0, 0));
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const std::array<std::size_t, 3>& tri = soup.triangles[t];
    Vector area_normal = CGAL::cross_product(point(tri[1]) - point(tri[0]), point(tri[2]) - point(tri[0]));
    if(reverse[parts.part_of_triangle[t]])
      area_normal = -area_normal;
    for(std::size_t s : tri)
      oriented[s] = oriented[s] + area_normal;
  }
  std::size_t agreeing = 0;
  for(std::size_t s = 0; s < soup.shape_vertex.size(); ++s)
    agreeing += CGAL::to_double(oriented[s] * reference(s)) > 0 ? 1 : 0;
  return soup.shape_vertex.empty() ? 1.0 : double(agreeing) / double(soup.shape_vertex.size());
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_ORIENT_SURFACE_PARTS_H
