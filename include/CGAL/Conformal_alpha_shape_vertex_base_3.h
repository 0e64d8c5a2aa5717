// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPE_VERTEX_BASE_3_H
#define CGAL_CONFORMAL_ALPHA_SHAPE_VERTEX_BASE_3_H

#include <CGAL/Default.h>
#include <CGAL/Triangulation_vertex_base_3.h>

#include <cstddef>

namespace CGAL {

/*!
\ingroup PkgConformalAlphaShapes3Classes

The vertex base of the triangulation underlying `Conformal_alpha_shape_3`.
It stores what the filtration needs per vertex: the vertex's local feature size
`alpha_p+`, the cell whose circumcenter is the vertex's pole, and a dense
vertex index used to address per-vertex arrays of the shape.

\tparam Gt a geometric traits class, model of `DelaunayTriangulationTraits_3`.
\tparam Vb a vertex base, model of `TriangulationVertexBase_3`
        (default: `Triangulation_vertex_base_3<Gt>`).

\cgalModels `TriangulationVertexBase_3`
*/
template <class Gt, class Vb_ = Default>
class Conformal_alpha_shape_vertex_base_3
  : public Default::Get<Vb_, Triangulation_vertex_base_3<Gt> >::type
{
  typedef typename Default::Get<Vb_, Triangulation_vertex_base_3<Gt> >::type Vb;

public:
  typedef typename Vb::Cell_handle Cell_handle;
  typedef typename Vb::Point       Point;

  template <typename TDS2>
  struct Rebind_TDS
  {
    typedef typename Vb::template Rebind_TDS<TDS2>::Other      Vb2;
    typedef Conformal_alpha_shape_vertex_base_3<Gt, Vb2>        Other;
  };

  Conformal_alpha_shape_vertex_base_3() : Vb() {}
  Conformal_alpha_shape_vertex_base_3(const Point& p) : Vb(p) {}
  Conformal_alpha_shape_vertex_base_3(const Point& p, Cell_handle c) : Vb(p, c) {}
  Conformal_alpha_shape_vertex_base_3(Cell_handle c) : Vb(c) {}

  /// the local feature size `alpha_p+` (a length)
  double local_feature_size() const { return m_local_feature_size; }
  void set_local_feature_size(double s) { m_local_feature_size = s; }

  /// the finite cell whose circumcenter is this vertex's pole
  Cell_handle pole_cell() const { return m_pole_cell; }
  void set_pole_cell(Cell_handle c) { m_pole_cell = c; }

  /// dense index in `[0, number_of_vertices())`
  std::size_t vertex_index() const { return m_index; }
  void set_vertex_index(std::size_t i) { m_index = i; }

private:
  double      m_local_feature_size = 0;
  Cell_handle m_pole_cell   = Cell_handle();
  std::size_t m_index       = 0;
};

} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPE_VERTEX_BASE_3_H
