// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPE_CELL_BASE_3_H
#define CGAL_CONFORMAL_ALPHA_SHAPE_CELL_BASE_3_H

#include <CGAL/Default.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>

#include <array>
#include <cstddef>

namespace CGAL {

/*!
\ingroup PkgConformalAlphaShapes3Classes

The cell base of the triangulation underlying `Conformal_alpha_shape_3`.
It stores the ordinary alpha value (a radius, not squared) of the cell and of
its four facets, and a dense cell index used to address per-cell arrays.
A facet's value is stored in both cells that share it. Conformal values are
derived from these and the vertices' local scales, so the storage is five
doubles and one index per cell.

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

  /// ordinary alpha value of the facet opposite to vertex `i`
  double facet_alpha(int i) const { return m_facet_alpha[i]; }
  void set_facet_alpha(int i, double a) { m_facet_alpha[i] = a; }

  /// dense index in `[0, number_of_cells())`, infinite cells included
  std::size_t cell_index() const { return m_index; }
  void set_cell_index(std::size_t i) { m_index = i; }

private:
  double                m_alpha = 0;
  std::array<double, 4> m_facet_alpha = {{0, 0, 0, 0}};
  std::size_t           m_index = 0;
};

} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPE_CELL_BASE_3_H
