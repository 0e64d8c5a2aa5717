// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_JET_SMOOTHING_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_JET_SMOOTHING_H

// The smoothing of `denoise()` (the manual, "Noise"): degree-2 jet
// smoothing with the meaning of CGAL's `jet_smooth_point_set()`, by
// fixed-size normal equations.

#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>

#include <CGAL/Euclidean_distance.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// Degree-2 jet smoothing of one point, the meaning of CGAL's
// `jet_smooth_point_set()` with degree 2 jets and degree 2 Monge forms:
// `offsets` are the query point's nearest points (itself included) less the
// query point; in their principal frame (the normal along the smallest
// eigenvalue of their covariance) a quadratic height function
// z = a0 + a1 x + a2 y + a3 x^2 + a4 x y + a5 y^2 is fitted by least
// squares, and the query point moves to the fitted surface above it, by a0
// along the normal (the Monge origin). Fixed-size normal equations on the
// moments of x, y scaled by their root mean square (the monomials are then
// of order 1). Returns false, leaving `shift` alone, when the fit is
// degenerate: coincident or collinear points, or points on one conic of the
// tangent plane (the quadratic not determined).
inline bool quadratic_jet_shift(const Eigen::Vector3d* offsets, std::size_t count, Eigen::Vector3d& shift)
{
  if(count < 6)
    return false;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for(std::size_t i = 0; i < count; ++i)
    mean += offsets[i];
  mean /= double(count);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(std::size_t i = 0; i < count; ++i)
  {
    const Eigen::Vector3d d = offsets[i] - mean;
    covariance.noalias() += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> frame;
  frame.computeDirect(covariance);  // ascending eigenvalues, as CGAL's diagonalization
  const Eigen::Vector3d& values = frame.eigenvalues();
  if(!(values(2) > 0) || !(values(1) > 1e-12 * values(2)) || !std::isfinite(values(2)))
    return false;  // coincident or collinear: no tangent plane
  const Eigen::Vector3d n = frame.eigenvectors().col(0), u = frame.eigenvectors().col(2),
                        v = frame.eigenvectors().col(1);
  double tangential = 0;
  for(std::size_t i = 0; i < count; ++i)
    tangential += CGAL::square(offsets[i].dot(u)) + CGAL::square(offsets[i].dot(v));
  if(!(tangential > 0))
    return false;
  const double scale = 1.0 / std::sqrt(tangential / double(count));
  // moments x^a y^b (a + b <= 4) and z x^a y^b (a + b <= 2)
  double m00 = 0, m10 = 0, m01 = 0, m20 = 0, m11 = 0, m02 = 0, m30 = 0, m21 = 0, m12 = 0, m03 = 0,
         m40 = 0, m31 = 0, m22 = 0, m13 = 0, m04 = 0;
  double z00 = 0, z10 = 0, z01 = 0, z20 = 0, z11 = 0, z02 = 0;
  for(std::size_t i = 0; i < count; ++i)
  {
    const double x = offsets[i].dot(u) * scale, y = offsets[i].dot(v) * scale, z = offsets[i].dot(n);
    const double xx = x * x, xy = x * y, yy = y * y;
    m00 += 1; m10 += x; m01 += y; m20 += xx; m11 += xy; m02 += yy;
    m30 += xx * x; m21 += xx * y; m12 += x * yy; m03 += yy * y;
    m40 += xx * xx; m31 += xx * xy; m22 += xx * yy; m13 += xy * yy; m04 += yy * yy;
    z00 += z; z10 += z * x; z01 += z * y; z20 += z * xx; z11 += z * xy; z02 += z * yy;
  }
  // monomials 1, x, y, x^2, x y, y^2
  Eigen::Matrix<double, 6, 6> normal;
  normal << m00, m10, m01, m20, m11, m02,
            m10, m20, m11, m30, m21, m12,
            m01, m11, m02, m21, m12, m03,
            m20, m30, m21, m40, m31, m22,
            m11, m21, m12, m31, m22, m13,
            m02, m12, m03, m22, m13, m04;
  Eigen::Matrix<double, 6, 1> right;
  right << z00, z10, z01, z20, z11, z02;
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(normal);
  const Eigen::Matrix<double, 6, 1> pivots = solver.vectorD();
  if(solver.info() != Eigen::Success || !(pivots.minCoeff() > 1e-10 * pivots.maxCoeff()))
    return false;  // the quadratic is not determined by these points
  const double height = solver.solve(right)(0);
  if(!std::isfinite(height))
    return false;
  shift = height * n;
  return true;
}

// One pass of degree-2 jet smoothing: `smoothed[i]` is `points[i]` (which
// must be distinct) moved onto the jet fitted to its `k` nearest neighbors
// and itself (CGAL's convention: `k + 1` points), or left in place when that
// fit is degenerate. Each result depends only on `points`: the parallel
// run (with TBB) gives the serial run's result bit for bit. Neighbors from a
// kd-tree (`Orthogonal_k_neighbor_search`); the points should be in a
// spatial order (queries in that order hit the cache).
template <class ConcurrencyTag, class Point>
void jet_smooth_pass(const std::vector<Point>& points, unsigned int k, std::vector<Point>& smoothed)
{
  typedef typename Kernel_traits<Point>::Kernel Kernel;
  typedef CGAL::Search_traits_3<Kernel> Traits;
  typedef CGAL::Sliding_midpoint<Traits> Splitter;
  typedef CGAL::Kd_tree<Traits, Splitter, CGAL::Tag_true, CGAL::Tag_true> Tree;
  typedef CGAL::Euclidean_distance<Traits> Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance, Splitter, Tree> Search;
  smoothed = points;
  if(points.size() <= std::size_t(k))
    return;
  Tree tree(points.begin(), points.end(), Splitter(16));  // buckets of 16: a little faster than 10 at k = 24..64
  // on TBB's threads the same tree (its nodes are split alike), so the same hits
  tree.template build<ConcurrencyTag>();
  internal::for_each_index<ConcurrencyTag>(points.size(),
    [k]() {
      std::vector<Eigen::Vector3d> offsets;
      offsets.reserve(std::size_t(k) + 1);
      return offsets;
    },
    [&](std::size_t i, std::vector<Eigen::Vector3d>& offsets) {
      const Point& p = points[i];
      const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y()), pz = CGAL::to_double(p.z());
      offsets.clear();
      // unsorted (the sort took a quarter of the search): the hits come in
      // the search's own order, the same on every run
      const Search search(tree, p, k + 1, 0, true, Distance(), false);
      for(const auto& hit : search)
        offsets.emplace_back(CGAL::to_double(hit.first.x()) - px, CGAL::to_double(hit.first.y()) - py,
                             CGAL::to_double(hit.first.z()) - pz);
      Eigen::Vector3d shift;
      if(quadratic_jet_shift(offsets.data(), offsets.size(), shift))
        smoothed[i] = Point(px + shift(0), py + shift(1), pz + shift(2));
    });
}

// `passes` passes of `jet_smooth_pass()` over `points` (distinct), in
// place; the points are visited in Hilbert order (found once: the
// results do not depend on the order, the time does).
template <class ConcurrencyTag, class Point>
void jet_smooth_points(std::vector<Point>& points, unsigned int k, int passes)
{
  typedef typename Kernel_traits<Point>::Kernel Kernel;
  typedef CGAL::Spatial_sort_traits_adapter_3<Kernel, typename CGAL::Pointer_property_map<Point>::type>
    Sort_traits;
  if(passes <= 0 || points.size() <= std::size_t(k))
    return;
  std::vector<std::size_t> order(points.size());
  for(std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  CGAL::hilbert_sort<ConcurrencyTag>(order.begin(), order.end(), Sort_traits(CGAL::make_property_map(points)));
  std::vector<Point> current(points.size()), smoothed;
  for(std::size_t i = 0; i < order.size(); ++i)
    current[i] = points[order[i]];
  for(int pass = 0; pass < passes; ++pass)
  {
    jet_smooth_pass<ConcurrencyTag>(current, k, smoothed);
    current.swap(smoothed);
  }
  for(std::size_t i = 0; i < order.size(); ++i)
    points[order[i]] = current[i];
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_JET_SMOOTHING_H
