// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_WORKING_FRAME_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_WORKING_FRAME_H

// Between the input of Multiscale_curvatures (its units and its indices,
// outliers and copies included) and the working frame of its shape (the
// points kept, recentered and scaled by a power of two): what is given goes
// in, what is given back comes out.

#include <CGAL/Conformal_alpha_shapes_3/estimate_noise.h>
#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/input_hygiene.h>
#include <CGAL/Conformal_alpha_shapes_3/point_curvature.h>
#include <CGAL/Conformal_alpha_shapes_3/scales_and_neighborhoods.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_report.h>

#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {
namespace internal {

// A given estimate in the working frame, checked first. The frame's scale
// is a power of two, so the spacing of a run's `noise()` given back to a
// run on the same points comes back to the same bits.
template <class Kernel>
Noise_estimate working_noise(const Noise_estimate& given, const Normalized_input<Kernel>& input)
{
  if(!(std::isfinite(given.spacing) && given.spacing > 0))
    throw std::invalid_argument("Multiscale_curvatures: the noise_estimate's spacing must be finite and positive, not "
                                + std::to_string(given.spacing));
  if(!(given.noise >= 0 && given.noise_24 >= 0))
    throw std::invalid_argument("Multiscale_curvatures: the noise_estimate's noise must be a number, 0 or more, not "
                                + std::to_string(given.noise) + " (16 neighbors) and "
                                + std::to_string(given.noise_24) + " (24 neighbors)");
  Noise_estimate working = given;
  working.spacing = input.length_from_input(given.spacing);
  if(!(std::isfinite(working.spacing) && working.spacing > 0))
    throw std::invalid_argument("Multiscale_curvatures: the noise_estimate's spacing " + std::to_string(given.spacing)
                                + " is out of scale with these points (of size "
                                + std::to_string(input.size()) + ")");
  return working;
}

// The neighborhoods in the working frame: radii scaled, the others as given.
template <class Kernel>
std::vector<Neighborhood> working_neighborhoods(const std::vector<Neighborhood>& neighborhoods,
                                                const Normalized_input<Kernel>& input)
{
  std::vector<Neighborhood> working;
  for(const Neighborhood& n : neighborhoods)
    working.push_back(
      n.kind() == Neighborhood::RADIUS ? Neighborhood::radius(input.length_from_input(n.value())) : n);
  return working;
}

// By input index, the index among the kept points of the point, or of the
// point it is a copy of; -1 for outliers.
template <class Kernel>
std::vector<std::size_t> kept_indices(const Normalized_input<Kernel>& input)
{
  std::vector<std::size_t> kept(input.is_outlier.size(), std::size_t(-1));
  for(std::size_t i = 0; i < input.input_index.size(); ++i)
    kept[input.input_index[i]] = i;
  for(const std::pair<std::size_t, std::size_t>& copy : input.copies)
    kept[copy.first] = kept[copy.second];
  return kept;
}

// The reference normals of the kept points, from `given`, one per input
// point or none (checked).
template <class Kernel>
std::vector<typename Kernel::Vector_3> kept_reference_normals(std::vector<typename Kernel::Vector_3> given,
                                                              const Normalized_input<Kernel>& input)
{
  if(given.empty())
    return given;
  if(given.size() != input.is_outlier.size())
    throw std::invalid_argument("Multiscale_curvatures: " + std::to_string(given.size())
                                + " reference normals for " + std::to_string(input.is_outlier.size())
                                + " points");
  for(std::size_t i = 0; i < input.input_index.size(); ++i)
    given[i] = given[input.input_index[i]];
  given.resize(input.input_index.size());
  return given;
}

// Moves `surface`, extracted from the shape with the kept index of each
// vertex in `input_index`, to the input's units and indices, and counts in
// `report` the input points the shape does not hold: the outliers, off
// every surface, and the copies of points, where their first is.
template <class Kernel, class InputIndexMap>
void surface_to_input(CGAL::Surface_mesh<typename Kernel::Point_3>& surface, InputIndexMap input_index,
                      const Normalized_input<Kernel>& input, Surface_report& report)
{
  for(auto v : surface.vertices())
  {
    input_index[v] = input.input_index[input_index[v]];
    surface.point(v) = input.to_input(surface.point(v));
  }
  std::vector<bool> on_surface(input.is_outlier.size(), false);
  for(auto v : surface.vertices())
    on_surface[input_index[v]] = true;
  for(const std::pair<std::size_t, std::size_t>& copy : input.copies)
    if(!on_surface[copy.second])
      ++report.number_of_points_off_surface;
  report.number_of_points_off_surface += input.outliers.size();
  report.number_of_input_points += input.outliers.size() + input.copies.size();
}

// Values by vertex of the shape `cas` given back by input index, each held
// by the first of the input points its vertex stands for (coincident points
// share a vertex); NaN for the others and for outliers.
template <class Kernel, class Cas>
std::vector<double> by_first_input_point(const std::vector<double>& by_vertex, const Cas& cas,
                                         const Normalized_input<Kernel>& input)
{
  std::vector<double> by_input(input.is_outlier.size(), std::numeric_limits<double>::quiet_NaN());
  std::vector<bool> taken(by_vertex.size(), false);
  for(std::size_t k = 0; k < input.input_index.size(); ++k)
  {
    const std::size_t v = cas.input_vertex(k)->vertex_index();
    if(!taken[v])
      by_input[input.input_index[k]] = by_vertex[v];
    taken[v] = true;
  }
  return by_input;
}

// Writes the values of the shape's input point `i` at its input index, in input units.
template <class Kernel>
struct Input_units_writer
{
  const Normalized_input<Kernel>* input;
  std::vector<Point_curvature<Kernel> >* layer;

  friend void put(const Input_units_writer& w, std::size_t i, Point_curvature<Kernel> c)
  {
    const Normalized_input<Kernel>& input = *w.input;
    c.distance = input.length_to_input(c.distance);
    c.radius = input.length_to_input(c.radius);
    c.mean_curvature = input.curvature_to_input(c.mean_curvature);
    c.gaussian_curvature = input.gaussian_curvature_to_input(c.gaussian_curvature);
    c.principal.max_curvature = input.curvature_to_input(c.principal.max_curvature);
    c.principal.min_curvature = input.curvature_to_input(c.principal.min_curvature);
    c.uncertainty.mean_curvature = input.curvature_to_input(c.uncertainty.mean_curvature);
    c.uncertainty.gaussian_curvature = input.gaussian_curvature_to_input(c.uncertainty.gaussian_curvature);
    c.uncertainty.mean_curvature_noise = input.curvature_to_input(c.uncertainty.mean_curvature_noise);
    (*w.layer)[input.input_index[i]] = c;
  }
};

// Sets the surface's properties (see Multiscale_curvatures) from `values`,
// in input units.
template <class Kernel>
void set_surface_properties(CGAL::Surface_mesh<typename Kernel::Point_3>& surface,
                            const std::vector<Vertex_curvature<Kernel> >& values,
                            const Normalized_input<Kernel>& input)
{
  typedef typename CGAL::Surface_mesh<typename Kernel::Point_3>::Vertex_index Surface_vertex;
  typedef typename Kernel::Vector_3 Vector;
  auto normal = surface.template add_property_map<Surface_vertex, Vector>("v:normal").first;
  auto mean = surface.template add_property_map<Surface_vertex, double>("v:mean_curvature").first;
  auto gaussian = surface.template add_property_map<Surface_vertex, double>("v:gaussian_curvature").first;
  auto used_radius = surface.template add_property_map<Surface_vertex, double>("v:radius").first;
  auto k1 = surface.template add_property_map<Surface_vertex, double>("v:k1").first;
  auto k2 = surface.template add_property_map<Surface_vertex, double>("v:k2").first;
  auto d1 = surface.template add_property_map<Surface_vertex, Vector>("v:d1").first;
  auto d2 = surface.template add_property_map<Surface_vertex, Vector>("v:d2").first;
  for(Surface_vertex v : surface.vertices())
  {
    Vertex_curvature<Kernel> c = values[v.idx()];
    c.principal.max_curvature = input.curvature_to_input(c.principal.max_curvature);
    c.principal.min_curvature = input.curvature_to_input(c.principal.min_curvature);
    normal[v] = c.normal;
    mean[v] = c.mean_curvature();
    gaussian[v] = c.gaussian_curvature();
    used_radius[v] = input.length_to_input(c.radius);
    k1[v] = c.principal.max_curvature;
    k2[v] = c.principal.min_curvature;
    d1[v] = c.principal.max_direction;
    d2[v] = c.principal.min_direction;
  }
}

} // namespace internal
} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_INTERNAL_WORKING_FRAME_H
