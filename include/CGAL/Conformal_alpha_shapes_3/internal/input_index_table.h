// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_INPUT_INDEX_TABLE_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_INPUT_INDEX_TABLE_H

#include <CGAL/Iterator_range.h>

#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The input indices that each vertex stands for (several for duplicate
// points), increasing, as compressed rows by vertex index.
class Input_index_table
{
public:
  typedef Iterator_range<const std::size_t*> Range;

  // From the vertex index of each input point, among `number_of_vertices`.
  void assign(const std::vector<std::size_t>& vertex_of_input, std::size_t number_of_vertices)
  {
    m_offsets.assign(number_of_vertices + 1, 0);
    for(std::size_t v : vertex_of_input)
      ++m_offsets[v + 1];
    std::partial_sum(m_offsets.begin(), m_offsets.end(), m_offsets.begin());
    m_indices.resize(vertex_of_input.size());
    std::vector<std::size_t> fill(m_offsets.begin(), m_offsets.end() - 1);
    for(std::size_t i = 0; i < vertex_of_input.size(); ++i)
      m_indices[fill[vertex_of_input[i]]++] = i;
  }

  void clear()
  {
    std::vector<std::size_t>().swap(m_offsets);
    std::vector<std::size_t>().swap(m_indices);
  }

  Range of_vertex(std::size_t v) const
  {
    const std::size_t* base = m_indices.data();
    return Range(base + m_offsets[v], base + m_offsets[v + 1]);
  }

private:
  std::vector<std::size_t> m_offsets;  // vertex index -> its row of m_indices
  std::vector<std::size_t> m_indices;
};

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_INPUT_INDEX_TABLE_H
