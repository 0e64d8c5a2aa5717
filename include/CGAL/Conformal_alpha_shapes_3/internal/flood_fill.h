// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FLOOD_FILL_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FLOOD_FILL_H

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// In which order `flood_fill()` visits what it reaches.
enum class Flood_order
{
  // the element reached last is visited first; `work` ends empty
  depth_first,
  // elements are visited in the order they were reached; `work` ends holding
  // every element reached, in that order
  breadth_first
};

// The flood fill of the package (cells through facets, cells of a star,
// ...): visits the elements of `work` and everything reached from them.
// `spread(x, reach)` is called once per visited element `x`; it calls
// `reach(y)` for each neighbor `y` that it claims, and marks `y` itself so
// that it claims it once. The visiting order is part of the result where
// `spread` changes what later calls see (carving cells, say): each caller
// names the order it relies on.
template <class T, class Spread>
void flood_fill(std::vector<T>& work, Flood_order order, Spread spread)
{
  auto reach = [&work](const T& y) { work.push_back(y); };
  if(order == Flood_order::breadth_first)
  {
    for(std::size_t head = 0; head < work.size(); ++head)
    {
      const T x = work[head];  // a copy: `reach` may reallocate `work`
      spread(x, reach);
    }
    return;
  }
  while(!work.empty())
  {
    const T x = work.back();
    work.pop_back();
    spread(x, reach);
  }
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FLOOD_FILL_H
