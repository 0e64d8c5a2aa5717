// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FIT_CENTERS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FIT_CENTERS_H

// Large neighborhoods fitted at a subset of the vertices, the centers, and
// carried to every vertex by interpolation with linear precision (the
// manual, "Neighborhoods", large radii). A ball of 16 sample spacings holds
// about 800 vertices: fitting it at every vertex costs 800 neighbor visits
// per vertex, while the fitted curvature changes little between vertices a
// seventh of the radius apart. This header chooses the centers and the
// weights that carry their values to a vertex.

#include <CGAL/Conformal_alpha_shapes_3/internal/curvature_fits.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/order_free.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/surface_neighborhoods.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// The median length of the edges of `g`, from at most about 100,000 of
// them spread over the vertices; 0 without edges.
inline double median_edge_length(const Vertex_graph& g)
{
  std::vector<double> lengths;
  const std::size_t step = (std::max)(std::size_t(1), g.size() / 20000);
  for(std::size_t v = 0; v < g.size(); v += step)
    for(std::size_t e = g.first[v]; e < g.first[v + 1]; ++e)
      lengths.push_back((g.points[g.adjacent[e]] - g.points[v]).norm());
  if(lengths.empty())
    return 0;
  std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2), lengths.end());
  return lengths[lengths.size() / 2];
}

// A key per vertex of `g` from the shape of its star alone: the lengths of
// its edges divided by the longest, in increasing order, each rounded to
// 2^-20 and mixed into a hash. Rigid motions, uniform scaling, the
// vertices' numbering and the part of the surface held (away from its
// border) leave a key unchanged, but where a ratio lies within rounding of
// a step, so the centers chosen in the order of these keys are those of any
// copy of the same surface.
inline std::vector<std::uint64_t> star_shape_keys(const Vertex_graph& g)
{
  std::vector<std::uint64_t> keys(g.size());
  std::vector<double> lengths;
  for(std::size_t v = 0; v < g.size(); ++v)
  {
    lengths.clear();
    for(std::size_t e = g.first[v]; e < g.first[v + 1]; ++e)
      lengths.push_back((g.points[g.adjacent[e]] - g.points[v]).norm());
    std::sort(lengths.begin(), lengths.end());
    std::uint64_t h = mix_hash(0, lengths.size());
    for(double l : lengths)
      h = mix_hash(h, std::uint64_t(std::ldexp(l / lengths.back(), 20)));
    keys[v] = h;
  }
  return keys;
}

// Centers more than `spacing` apart such that every vertex is within
// `spacing` of one, connected to it inside that ball, chosen greedily in
// the order of `keys` (by vertex; ties by position). Any order gives a
// valid cover; a pseudo-random one makes whether a vertex is a center
// depend only on the keys of the vertices a few centers around it, so
// that the same keys choose the same centers on any numbering of the
// vertices and on any part of the surface that holds those vertices. Each
// vertex belongs to the nearest center that covers it. Two centers are
// adjacent when an edge joins vertices belonging to them: the centers
// around a vertex are its own and those adjacent to it.
struct Fit_centers
{
  std::vector<std::size_t> vertex;          // by center: its vertex
  std::vector<std::uint32_t> center_of;     // by vertex: the center it belongs to
  std::vector<std::size_t> first, adjacent;  // by center: adjacent centers

  std::size_t size() const { return vertex.size(); }

  Fit_centers(const Vertex_graph& g, double spacing, const std::vector<std::uint64_t>& keys)
    : center_of(g.size(), unassigned)
  {
    std::vector<double> squared_distance(g.size(), std::numeric_limits<double>::infinity());
    Nested_neighborhood_search search(g.size());
    const std::vector<double> radius(1, spacing);
    for(std::size_t v : permutation_by_hash(keys, g.points))
    {
      if(center_of[v] != unassigned)
        continue;
      const std::uint32_t c = std::uint32_t(vertex.size());
      vertex.push_back(v);
      center_of[v] = c;
      squared_distance[v] = 0;
      search.balls(g, v, radius);
      for(std::size_t k = 0; k < search.vertices().size(); ++k)
      {
        const std::size_t w = search.vertices()[k];
        if(search.squared_distances()[k] < squared_distance[w])
        {
          squared_distance[w] = search.squared_distances()[k];
          center_of[w] = c;
        }
      }
    }
    // numbered in vertex order, so that the fits at consecutive centers read
    // nearby memory (the pipeline's vertices are spatially sorted)
    std::vector<std::uint32_t> number(vertex.size());
    std::uint32_t next = 0;
    for(std::size_t v = 0; v < g.size(); ++v)
      if(vertex[center_of[v]] == v)
        number[center_of[v]] = next++;
    std::vector<std::size_t> chosen(vertex.size());
    for(std::size_t c = 0; c < vertex.size(); ++c)
      chosen[number[c]] = vertex[c];
    vertex.swap(chosen);
    for(std::uint32_t& c : center_of)
      c = number[c];

    std::vector<std::pair<std::uint32_t, std::uint32_t> > pairs;
    for(std::size_t v = 0; v < g.size(); ++v)
      for(std::size_t e = g.first[v]; e < g.first[v + 1]; ++e)
        if(center_of[v] != center_of[g.adjacent[e]])
          pairs.emplace_back(center_of[v], center_of[g.adjacent[e]]);
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    first.assign(vertex.size() + 1, 0);
    for(const auto& p : pairs)
      ++first[p.first + 1];
    for(std::size_t c = 0; c < vertex.size(); ++c)
      first[c + 1] += first[c];
    adjacent.reserve(pairs.size());
    for(const auto& p : pairs)
      adjacent.push_back(p.second);
  }

private:
  static constexpr std::uint32_t unassigned = (std::numeric_limits<std::uint32_t>::max)();
};

// The fit of one large neighborhood at a center, in the form that
// interpolates: the shape operator as a symmetric 3D tensor
// k1 d1 d1' + k2 d2 d2' (no sign ambiguity of the directions), the unit
// normal, and the fit's uncertainty.
struct Center_fit
{
  Eigen::Matrix3d shape = Eigen::Matrix3d::Zero();
  Vec3 normal = Vec3::Zero();
  Quadric_fit_error error;
  bool defined = false;

  void set(const Local_curvature& c, const Quadric_fit_error& e)
  {
    shape = c.k1 * c.d1 * c.d1.transpose() + c.k2 * c.d2 * c.d2.transpose();
    normal = c.normal;
    error = e;
    defined = true;
  }
};

// The curvature at a vertex (at p, normal n) from the fits of the centers
// around it, interpolated by a weighted linear least-squares fit in the
// vertex's tangent plane: exact for values that vary linearly along the
// surface, so that the vertex does not take the curvature of a center a
// seventh of a radius away. With fewer than four defined centers, centers
// nearly on a line, or weights that extrapolate (their absolute values
// summing to more than 3: the vertex outside its centers, at a border),
// the weighted mean. A center seen from the other side (its normal
// against n: a thin part, a sheet close to itself) counts with its normal
// and shape operator negated, which describe the same surface. The
// uncertainty is always the weighted mean. `reach` sets the weights
// (1 - d^2 / reach^2)^2, with a floor so that every center around counts
// a little. The weights depend only on where the centers are and which of
// them have a fit: `Center_weights` computes them once for all the radii
// of a set of centers whose fits are defined at the same centers.
struct Center_weights
{
  std::vector<double> interpolating, mean;  // by center around; 0 where not defined

  // false when no center has a defined fit
  bool compute(const Vec3& p, const Vec3& n, const std::vector<Vec3>& centers, const std::vector<char>& defined,
               double reach)
  {
    const Tangent_frame f = frame_from_normal(n);
    // a center's weight and its row (1, x, y) in the vertex's tangent plane
    auto weight_and_row = [&](const Vec3& center, Eigen::Vector3d& phi) {
      const Vec3 o = (center - p) / reach;
      phi = Eigen::Vector3d(1, o.dot(f.e1), o.dot(f.e2));
      const double u = (std::max)(0., 1 - o.squaredNorm());
      return u * u + 1e-6;
    };
    Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
    Eigen::Vector3d phi;
    double total = 0;
    std::size_t count = 0;
    for(std::size_t i = 0; i < centers.size(); ++i)
    {
      if(!defined[i])
        continue;
      const double w = weight_and_row(centers[i], phi);
      moments += w * phi * phi.transpose();
      total += w;
      ++count;
    }
    if(count == 0)
      return false;
    // weight of center i in the interpolated value: w_i e0' M^-1 phi_i
    Eigen::Vector3d solution = Eigen::Vector3d::Zero();
    bool linear = false;
    if(count >= 4)
    {
      const Eigen::LDLT<Eigen::Matrix3d> ldlt(moments);
      const auto pivots = ldlt.vectorD();
      linear = ldlt.info() == Eigen::Success && pivots.minCoeff() > 1e-3 * pivots.maxCoeff();
      if(linear)
      {
        solution = ldlt.solve(Eigen::Vector3d(1, 0, 0));
        double spread = 0;
        for(std::size_t i = 0; i < centers.size(); ++i)
          if(defined[i])
          {
            const double w = weight_and_row(centers[i], phi);
            spread += std::abs(w * solution.dot(phi));
          }
        linear = spread <= 3;
      }
    }
    interpolating.assign(centers.size(), 0.);
    mean.assign(centers.size(), 0.);
    for(std::size_t i = 0; i < centers.size(); ++i)
    {
      if(!defined[i])
        continue;
      const double w = weight_and_row(centers[i], phi);
      interpolating[i] = linear ? w * solution.dot(phi) : w / total;
      mean[i] = w / total;
    }
    return true;
  }
};

// The interpolated curvature at a vertex of normal n from `fits`, the
// centers' fits in the order of `weights`; false when the interpolated
// normal does not face n's side.
inline bool interpolate_center_fits(const Vec3& n, const std::vector<const Center_fit*>& fits,
                                    const Center_weights& weights, Local_curvature& out, Quadric_fit_error& error)
{
  Eigen::Matrix3d shape = Eigen::Matrix3d::Zero();
  Vec3 normal = Vec3::Zero();
  error = Quadric_fit_error();
  for(std::size_t i = 0; i < fits.size(); ++i)
  {
    const Center_fit& c = *fits[i];
    if(!c.defined)
      continue;
    const double lambda = weights.interpolating[i];
    const double side = c.normal.dot(n) < 0 ? -1. : 1.;
    shape += (side * lambda) * c.shape;
    normal += (side * lambda) * c.normal;
    const double mean = weights.mean[i];
    error.noise += mean * c.error.noise;
    error.degrees_of_freedom += mean * c.error.degrees_of_freedom;
    error.per_noise += mean * c.error.per_noise;
    error.per_noise_K += mean * c.error.per_noise_K;
    error.per_squared_noise_K += mean * c.error.per_squared_noise_K;
    error.per_noise_normal += mean * c.error.per_noise_normal;
  }
  if(!(normal.dot(n) > 0))
    return false;
  const Tangent_frame g = frame_from_normal(normal.normalized());
  const double a = g.e1.dot(shape * g.e1), b = 2 * g.e1.dot(shape * g.e2), c = g.e2.dot(shape * g.e2);
  out = from_tangent_form(g, a, b, c);
  return std::isfinite(out.k1) && std::isfinite(out.k2);
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_FIT_CENTERS_H
