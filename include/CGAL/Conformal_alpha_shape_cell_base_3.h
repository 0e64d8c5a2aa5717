// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPE_CELL_BASE_3_H
#define CGAL_CONFORMAL_ALPHA_SHAPE_CELL_BASE_3_H

#include <CGAL/Default.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>

#include <cstddef>
#include <cstdint>

namespace CGAL {

/*!
\ingroup PkgConformalAlphaShapes3Classes

The cell base of the triangulation underlying `Conformal_alpha_shape_3`.
It stores the ordinary alpha value (a radius, not squared) of the cell, which
of its facets are encroached by their opposite vertex (so that a facet's value
follows: its own circumradius when Gabriel, else its smaller cell's), and a
dense cell index used to address per-cell arrays: 16 bytes per cell.

\tparam Gt a geometric traits class, model of `DelaunayTriangulationTraits_3`.
\tparam Cb a cell base, model of `DelaunayTriangulationCellBase_3`
        (default: `Delaunay_triangulation_cell_base_3<Gt>`).

\cgalModels `DelaunayTriangulationCellBase_3`
*/
template <class Gt, class Cb_ = Default>
class Conformal_alpha_shape_cell_base_3
  : public Default::Get<Cb_, Delaunay_triangulation_cell_base_3<Gt> >::type
{
  typedef typename Default::Get<Cb_, Delaunay_triangulation_cell_base_3<Gt> >::type Cb;

public:
  typedef typename Cb::Vertex_handle Vertex_handle;
  typedef typename Cb::Cell_handle   Cell_handle;

  template <typename TDS2>
  struct Rebind_TDS
  {
    typedef typename Cb::template Rebind_TDS<TDS2>::Other      Cb2;
    typedef Conformal_alpha_shape_cell_base_3<Gt, Cb2>          Other;
  };

  Conformal_alpha_shape_cell_base_3() : Cb() {}
  Conformal_alpha_shape_cell_base_3(Vertex_handle v0, Vertex_handle v1,
                                    Vertex_handle v2, Vertex_handle v3)
    : Cb(v0, v1, v2, v3) {}
  Conformal_alpha_shape_cell_base_3(Vertex_handle v0, Vertex_handle v1,
                                    Vertex_handle v2, Vertex_handle v3,
                                    Cell_handle n0, Cell_handle n1,
                                    Cell_handle n2, Cell_handle n3)
    : Cb(v0, v1, v2, v3, n0, n1, n2, n3) {}

  /// circumradius of the cell
  double alpha() const { return m_alpha; }
  void set_alpha(double a) { m_alpha = a; }

  /// whether vertex `i` lies strictly inside the smallest ball circumscribing
  /// the facet opposite to it; a facet is Gabriel when neither of its two
  /// opposite vertices encroaches it
  bool encroaches_facet(int i) const { return (m_encroached >> i) & 1u; }
  void set_encroaches_facet(int i, bool b)
  {
    m_encroached = static_cast<unsigned char>(b ? (m_encroached | (1u << i))
                                                : (m_encroached & ~(1u << i)));
  }

  /// dense index in `[0, number_of_cells())`, infinite cells included
  std::size_t cell_index() const { return m_index; }
  void set_cell_index(std::size_t i) { m_index = static_cast<std::uint32_t>(i); }

private:
  double        m_alpha = 0;
  std::uint32_t m_index = 0;
  unsigned char m_encroached = 0;
};

} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPE_CELL_BASE_3_H
