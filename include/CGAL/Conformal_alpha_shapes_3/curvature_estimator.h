// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_CURVATURE_ESTIMATOR_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_CURVATURE_ESTIMATOR_H

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/// \ingroup PkgConformalAlphaShapes3Curvature
/// How `estimate_vertex_curvatures()` estimates curvature at a vertex from
/// its neighborhood. See the manual for the measured accuracy of each.
enum Curvature_estimator
{
  /// The paper's method: Chen-Wu vertex normals, a normal curvature per
  /// neighbor from normal differences, and the Euler fit with `a` fixed to
  /// the largest normal curvature and `b`, `c` by least squares.
  PAPER_EULER_FIT,
  /// The same normal curvatures, with all three Euler coefficients fitted by
  /// least squares.
  EULER_LEAST_SQUARES_FIT,
  /// A quadric height function fitted by least squares to the positions of
  /// the neighborhood in the frame of the Chen-Wu normal, with linear terms; the
  /// output normal is the fitted surface's. The default.
  QUADRIC_FIT
};

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_CURVATURE_ESTIMATOR_H
