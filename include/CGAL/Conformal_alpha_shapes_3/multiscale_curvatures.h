// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_MULTISCALE_CURVATURES_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_MULTISCALE_CURVATURES_H

#include <CGAL/Conformal_alpha_shape_3.h>
#include <CGAL/Conformal_alpha_shapes_3/denoise.h>
#include <CGAL/Conformal_alpha_shapes_3/estimate_noise.h>
#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>
#include <CGAL/Conformal_alpha_shapes_3/extract_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/input_hygiene.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/point_normals_to_follow.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/working_frame.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/scales_and_neighborhoods.h>
#include <CGAL/Conformal_alpha_shapes_3/suggest_scale.h>
#include <CGAL/Conformal_alpha_shapes_3/surface_front.h>
#include <CGAL/Conformal_alpha_shapes_3/transfer_to_points.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/function_property_map.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

Multi-scale curvature of a point cloud, the package's steps in a row: the
input is checked, recentered and rescaled, and isolated far outliers are
left out (the manual, section "Input Rules"); `estimate_noise()` and, when
it calls for it, `denoise()`; the `Conformal_alpha_shape_3` of these
working points, built once; then, for any scale, its surface
(`extract_surface()`, cut from one `Surface_front` grown once with the
default method), and for any neighborhoods its curvature
(`estimate_vertex_curvatures()`) given to every input point
(`transfer_to_points()`).

Everything given back is in the input's units and indices: surfaces lie at
the (smoothed) positions mapped back to input coordinates, radii and
distances are lengths of the input, curvatures are inverse lengths of the
input, and values are reported by input index. Only `shape()` is in the
working frame, the input recentered and scaled by a power of two, so that
no construction overflows or underflows whatever the input's magnitude.

Surfaces are `Surface_mesh` objects with the face property
`"f:orientation_group"` (`std::size_t`: the faces one vote oriented together,
see the named parameter `face_orientation_group_map` of `extract_surface()`;
`std::size_t(-1)` with the solid boundary), the vertex properties
`"v:input_index"` (`std::size_t`, an index of the input) and, after
`estimate_curvatures()`, `"v:normal"` (`Vector_3`), `"v:mean_curvature"`,
`"v:gaussian_curvature"`, `"v:k1"`, `"v:k2"`, `"v:radius"` (`double`),
`"v:d1"` and `"v:d2"` (`Vector_3`): `CGAL::IO::write_PLY()` writes the
first six.

\tparam Kernel a CGAL kernel with `double` coordinates
        (default: `Exact_predicates_inexact_constructions_kernel`)
*/
template <class Kernel = CGAL::Exact_predicates_inexact_constructions_kernel>
class Multiscale_curvatures
{
public:
  typedef typename Kernel::Point_3 Point;
  typedef typename Kernel::Vector_3 Vector;
  typedef CGAL::Triangulation_data_structure_3<Conformal_alpha_shape_vertex_base_3<Kernel>,
                                               Conformal_alpha_shape_cell_base_3<Kernel> > Tds;
  typedef Conformal_alpha_shape_3<Delaunay_triangulation_3<Kernel, Tds> > Shape;
  typedef CGAL::Surface_mesh<Point> Surface;
  typedef typename Surface::Vertex_index Surface_vertex;

  /*!
  Builds the conformal alpha shape of the points in `[first, last)`.

  \cgalNamedParamsBegin
    \cgalParamNBegin{reference_normals}
      \cgalParamDescription{a normal per input point (a scanner's), or an empty vector: each sheet of a surface on which they are consistent is oriented by the majority of its points' normals, and each of its points' values by the point's own normal (see `transfer_to_points()`); a sheet on which they are not (random signs) is oriented as without normals, and its points' values follow it}
      \cgalParamType{`std::vector<Vector>`}
      \cgalParamDefault{empty}
    \cgalParamNEnd
    \cgalParamNBegin{orient_each_point}
      \cgalParamDescription{with `reference_normals`, whether the values of the points of sheets with consistent normals are turned to each point's own normal's side; `false`: every point's values follow its sheet}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{noise_estimate}
      \cgalParamDescription{the spacing (in input units) and noise (in spacings) of a larger cloud these points are part of, such as the `noise()` of a run on the whole cloud when each tile is run alone: used instead of an estimate on these points, so that `noise()`, radii in spacings, the automatic radius, the noise level of the curvature fits and the denoising decision are those of the larger run}
      \cgalParamType{`Noise_estimate`}
      \cgalParamDefault{`estimate_noise()` of these points (after outliers are left out)}
    \cgalParamNEnd
    \cgalParamNBegin{denoising}
      \cgalParamDescription{whether the points are smoothed first}
      \cgalParamType{`Denoising`}
      \cgalParamDefault{`AUTOMATIC_DENOISING`: as `denoising_plan()` says for the noise (estimated or `noise_estimate`)}
    \cgalParamNEnd
    \cgalParamNBegin{denoising_neighbors}
      \cgalParamDescription{the neighbors of the smoothing jet fit}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{as `denoising_plan()` says for the noise (at least 24)}
    \cgalParamNEnd
    \cgalParamNBegin{surface_extraction}
      \cgalParamDescription{how surfaces are extracted}
      \cgalParamType{`Surface_extraction`}
      \cgalParamDefault{`ADVANCING_FRONT`}
    \cgalParamNEnd
    \cgalParamNBegin{local_feature_size_estimator}
      \cgalParamDescription{the local feature sizes of the shape}
      \cgalParamType{`Local_feature_size_estimator`}
      \cgalParamDefault{`NOISE_ROBUST_POLE_DISTANCE`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \throws std::invalid_argument naming the first input point with a NaN or
  infinite coordinate; when `reference_normals` is neither empty nor one
  per point; when `noise_estimate`'s spacing is not finite and positive
  (or out of scale with the points) or its noise is negative or NaN; and as
  `Conformal_alpha_shape_3` when the points left do not span 3D.
  */
  template <class InputIterator, class NamedParameters = CGAL::parameters::Default_named_parameters>
  Multiscale_curvatures(InputIterator first, InputIterator last,
                        const NamedParameters& np = CGAL::parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    m_extraction = choose_parameter(get_parameter(np, internal_np_cas3::surface_extraction), ADVANCING_FRONT);
    m_orient_each_point = choose_parameter(get_parameter(np, internal_np_cas3::orient_each_point), true);
    m_input = internal::normalize_input<Kernel>(std::vector<Point>(first, last));
    m_reference_normals = internal::kept_reference_normals(
      choose_parameter(get_parameter(np, internal_np_cas3::reference_normals), std::vector<Vector>()), m_input);
    m_kept_index = internal::kept_indices(m_input);
    std::vector<Point> points = std::move(m_input.points);
    m_input.points = std::vector<Point>();

    if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, internal_np_cas3::noise_estimate_t>::value)
      m_noise = estimate_noise(points);
    else
      m_noise = internal::working_noise(get_parameter(np, internal_np_cas3::noise_estimate), m_input);
    m_denoising = denoising_plan(m_noise, choose_parameter(get_parameter(np, internal_np_cas3::denoising),
                                                           AUTOMATIC_DENOISING),
                                 choose_parameter(get_parameter(np, internal_np_cas3::denoising_neighbors), 0u));
    if(m_denoising.passes > 0)
      denoise(points, m_denoising);
    if(points.size() < 4)  // the shape's own message would count the points without their copies
      throw std::invalid_argument("Multiscale_curvatures: the " + std::to_string(points.size() + m_input.copies.size())
                                  + " input points (" + std::to_string(points.size())
                                  + " distinct) span dimension " + std::to_string(int(points.size()) - 1)
                                  + " at most; a conformal alpha shape needs 4 points that are not coplanar");
    m_shape.make_conformal_alpha_shape(points.begin(), points.end(), parameters::local_feature_size_estimator(
      choose_parameter(get_parameter(np, internal_np_cas3::local_feature_size_estimator), NOISE_ROBUST_POLE_DISTANCE)));
  }

  /// the conformal alpha shape, in the working frame (see above): its
  /// input indices are those of the points kept (not outliers), in input order
  const Shape& shape() const { return m_shape; }
  /// the number of input points
  std::size_t number_of_input_points() const { return m_input.is_outlier.size(); }
  /// the number of input points equal to an earlier input point, merged
  /// into it before any estimate: they get the values of that point
  std::size_t number_of_merged_points() const { return m_input.number_of_copies; }
  /// the input indices of the isolated far outliers, left off every surface (increasing)
  const std::vector<std::size_t>& outliers() const { return m_input.outliers; }
  /// whether input point `i` is an isolated far outlier
  bool is_outlier(std::size_t i) const { return m_input.is_outlier[i]; }
  /// the noise of the input points (`estimate_noise()`, or the `noise_estimate`
  /// given); `spacing` in input units
  Noise_estimate noise() const
  {
    Noise_estimate n = m_noise;
    n.spacing = m_input.length_to_input(n.spacing);
    return n;
  }
  /// how the points were smoothed before the shape was built (`passes` is 0 when they were not)
  const Denoising_plan& denoising() const { return m_denoising; }
  /// how surfaces are extracted
  Surface_extraction extraction() const { return m_extraction; }
  /// whether reference normals orient the surfaces
  bool has_reference_normals() const { return !m_reference_normals.empty(); }

  /// The value of `a` for a requested scale (the automatic one, `suggest_scale()`, is computed once).
  double scale_value(const Scale& scale) const
  {
    switch(scale.kind())
    {
      case Scale::ABSOLUTE: return scale.value();
      case Scale::QUANTILE: require_shape("scale_value"); return m_shape.alpha_at_quantile(scale.value());
      case Scale::AUTOMATIC: break;
    }
    if(!(m_suggested >= 0))
    {
      require_shape("scale_value");
      m_suggested = m_extraction == ADVANCING_FRONT
                      ? front().suggest_scale()
                      : Conformal_alpha_shapes_3::suggest_scale(m_shape, parameters::surface_extraction(m_extraction));
    }
    return m_suggested;
  }

  /// Per input point, the local closing value of its vertex in the
  /// advancing front grown once (`Surface_front::local_closing_values()`),
  /// held by the first of the input points a vertex stands for (coincident
  /// points share a vertex); NaN for the others, for outliers and where
  /// `Surface_front::local_closing_values()` is NaN. The automatic scale
  /// with `ADVANCING_FRONT` is `scale_of_closing_values()` of these with
  /// coverage 0.99.
  std::vector<double> closing_values() const
  {
    require_shape("closing_values");
    return internal::by_first_input_point(front().local_closing_values(), m_shape, m_input);
  }

  /// Replaces `surface` with the surface at scale `a` (`extract_surface()`),
  /// in input units and indices. With the advancing front, every scale is
  /// cut from one `Surface_front`, grown at the first call of this or of
  /// `scale_value()` with the automatic scale and kept.
  Surface_report surface(double a, Surface& surface) const
  {
    require_shape("surface");
    surface.clear();
    auto input_index = surface.template add_property_map<Surface_vertex, std::size_t>("v:input_index").first;
    auto group = surface.template add_property_map<typename Surface::Face_index, std::size_t>(
      "f:orientation_group", std::size_t(-1)).first;
    Surface_report report =
      m_extraction == ADVANCING_FRONT
        ? front().extract_surface(a, surface, parameters::vertex_input_index_map(
            input_index, parameters::face_orientation_group_map(
              group, parameters::reference_normals(std::cref(m_reference_normals)))))
        : extract_surface(m_shape, a, surface,
                          parameters::vertex_input_index_map(input_index, parameters::surface_extraction(m_extraction)));
    internal::surface_to_input(surface, input_index, m_input, report);
    return report;
  }

  /// The radius of a neighborhood of kind `Neighborhood::RADIUS` or
  /// `Neighborhood::SPACINGS`, in input units.
  double radius(const Neighborhood& neighborhood) const
  {
    return neighborhood.kind() == Neighborhood::SPACINGS
             ? m_input.length_to_input(neighborhood.value() * m_noise.spacing)
             : neighborhood.value();
  }

  /*!
  Estimates the curvature of `surface` (from `surface()`) with each of
  `neighborhoods` (`estimate_vertex_curvatures()`, given the sample's noise
  before smoothing) and gives it to every input point
  (`transfer_to_points()`, with the reference normals): one result per
  neighborhood, in their order, by input index; outliers get `NO_VALUE`.
  The surface's properties (see the class description) hold the last
  neighborhood's values. With TBB (`CGAL_LINKED_WITH_TBB`) the vertices
  and points run on its threads, with the same results. All layers are
  held at once: the overload with a `layer_done` function object gives
  each as soon as it is made.

  Called on an rvalue, as in `std::move(analysis).estimate_curvatures(...)`,
  the object is consumed: it frees its shape and its front before the
  fits, so that they are not held with the fits' values (the job's peak
  memory, see the manual's section "Performance"), and the values are the
  same. Afterwards `shape()` is empty and what needs it throws
  `std::logic_error`: `surface()`, `closing_values()`,
  `estimate_curvatures()`, and `scale_value()` of a quantile or of an
  automatic scale not asked for before; the other members answer as before.
  */
  std::vector<std::vector<Point_curvature<Kernel> > >
  estimate_curvatures(Surface& surface, const std::vector<Neighborhood>& neighborhoods,
                      Curvature_estimator estimator = QUADRIC_FIT) const &
  {
    std::vector<std::vector<Point_curvature<Kernel> > > layers(neighborhoods.size());
    estimate_curvatures(surface, neighborhoods, estimator, keep_in(layers));
    return layers;
  }
  /// the same, the object consumed (see above)
  std::vector<std::vector<Point_curvature<Kernel> > >
  estimate_curvatures(Surface& surface, const std::vector<Neighborhood>& neighborhoods,
                      Curvature_estimator estimator = QUADRIC_FIT) &&
  {
    std::vector<std::vector<Point_curvature<Kernel> > > layers(neighborhoods.size());
    std::move(*this).estimate_curvatures(surface, neighborhoods, estimator, keep_in(layers));
    return layers;
  }

  /*!
  The same estimate, each neighborhood's result given to `layer_done` as
  soon as it is made, in their order, rather than all returned at the end:
  `layer_done(k, values)` receives the index `k` of the neighborhood and its
  values by input index, as an rvalue that it may keep (moved out) or let
  go. This function holds one such layer at a time, besides the vertex
  values of the neighborhoods not yet given to the points, so that a caller
  that keeps each layer in a smaller form (or writes it out) never holds
  them all in double.

  \tparam LayerDone a function object callable as
          `layer_done(std::size_t k, std::vector<Point_curvature<Kernel> >&& values)`,
          called on the calling thread
  */
  template <class LayerDone>
  void estimate_curvatures(Surface& surface, const std::vector<Neighborhood>& neighborhoods,
                           Curvature_estimator estimator, LayerDone layer_done) const &
  {
    estimate_and_transfer(surface, neighborhoods, estimator, layer_done, []() {});
  }
  /// the same, the object consumed (see above)
  template <class LayerDone>
  void estimate_curvatures(Surface& surface, const std::vector<Neighborhood>& neighborhoods,
                           Curvature_estimator estimator, LayerDone layer_done) &&
  {
    estimate_and_transfer(surface, neighborhoods, estimator, layer_done, [this]() {
      m_front.reset();
      m_shape.clear();
      m_consumed = true;
    });
  }

private:
  static auto keep_in(std::vector<std::vector<Point_curvature<Kernel> > >& layers)
  {
    return [&layers](std::size_t k, std::vector<Point_curvature<Kernel> >&& values) { layers[k] = std::move(values); };
  }

  void require_shape(const char* member) const
  {
    if(m_consumed)
      throw std::logic_error(std::string("Multiscale_curvatures::") + member
                             + ": the shape was freed by estimate_curvatures() on an rvalue");
  }

  // estimate_curvatures(), calling `release_shape()` once the shape is no
  // longer read
  template <class LayerDone, class ReleaseShape>
  void estimate_and_transfer(Surface& surface, const std::vector<Neighborhood>& neighborhoods,
                             Curvature_estimator estimator, LayerDone& layer_done, ReleaseShape release_shape) const
  {
    require_shape("estimate_curvatures");
    // the fits and the nearest-surface search run in the working frame
    const auto working = get(CGAL::dynamic_vertex_property_t<Point>(), surface);
    for(Surface_vertex v : surface.vertices())
      put(working, v, m_input.to_normalized(surface.point(v)));
    const std::vector<Neighborhood> in_working_frame = internal::working_neighborhoods(neighborhoods, m_input);
    const auto input_index = surface.template property_map<Surface_vertex, std::size_t>("v:input_index").first;
    auto shape_index = [&](Surface_vertex v) { return m_kept_index[input_index[v]]; };
    const std::vector<Vector> follow = m_orient_each_point
                                         ? internal::point_normals_to_follow(surface, m_reference_normals, m_kept_index)
                                         : std::vector<Vector>();

    // the fits are made when the transfer asks for them, once it has read
    // the shape and searched the surface for the points off it, so that
    // their values are held with neither
    std::vector<std::vector<Vertex_curvature<Kernel> > > values;
    auto fits = [&]() -> auto& {
      values = estimate_vertex_curvatures<CGAL::Parallel_if_available_tag>(
        surface, in_working_frame,
        parameters::sample_spacing(m_noise.spacing, parameters::noise_level(m_noise.noise * m_noise.spacing,
          parameters::smoothing_radius(m_denoising.smoothing_radius_in_spacings() * m_noise.spacing,
          parameters::smoothing_passes(m_denoising.passes,
          parameters::estimator(estimator).vertex_point_map(working))))));
      return values;
    };
    std::vector<Point_curvature<Kernel> > layer;
    auto hand_over = [&](std::size_t k) {
      for(const std::pair<std::size_t, std::size_t>& copy : m_input.copies)
        layer[copy.first] = layer[copy.second];
      layer_done(k, std::move(layer));
      std::vector<Point_curvature<Kernel> >().swap(layer);  // in case `layer_done` did not take it
    };
    transfer_to_points<CGAL::Parallel_if_available_tag>(
      m_shape, surface, fits,
      [&](std::size_t k) {
        // asked for layer k once layer k - 1 is written, and before the
        // vertex values of layer k are freed: the surface's properties
        // are set from the last layer's then, when the others' are gone
        if(k > 0)
          hand_over(k - 1);
        if(k + 1 == values.size())
          internal::set_surface_properties(surface, values[k], m_input);
        layer.resize(number_of_input_points());
        return internal::Input_units_writer<Kernel>{&m_input, &layer};
      },
      parameters::vertex_input_index_map(boost::make_function_property_map<Surface_vertex>(shape_index),
        parameters::reference_normals(std::cref(follow), parameters::release_shape(release_shape)))
        .vertex_point_map(working));
    if(!values.empty())
      hand_over(values.size() - 1);
  }

  // The front grown with no bound, once.
  const Surface_front<Shape>& front() const
  {
    if(!m_front)
      m_front = std::make_unique<Surface_front<Shape> >(m_shape);
    return *m_front;
  }

  internal::Normalized_input<Kernel> m_input;  // the working frame and the outliers (its points moved out)
  std::vector<std::size_t> m_kept_index;       // input index -> index among the kept points
  Shape m_shape;
  Surface_extraction m_extraction = ADVANCING_FRONT;
  std::vector<Vector> m_reference_normals;
  bool m_orient_each_point = true;
  Noise_estimate m_noise;
  Denoising_plan m_denoising;
  mutable double m_suggested = -1;
  mutable std::unique_ptr<Surface_front<Shape> > m_front;  // see front()
  bool m_consumed = false;  // see estimate_curvatures()
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
The curvature of every input point at one scale and neighborhood.
*/
template <class Kernel>
struct Curvature_layer
{
  Scale scale;                        ///< as requested
  double a;                           ///< its value
  Neighborhood neighborhood;          ///< as requested
  Surface_report surface;             ///< what the extraction did
  std::vector<Point_curvature<Kernel> > points;  ///< by input index
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

For each requested scale and neighborhood, the curvature of every input
point (see the manual, section "Multi-scale Curvature of a Point Cloud"),
from one conformal alpha shape of the points. The layers come scale by
scale, neighborhoods inside. For large inputs, where all layers do not fit
in memory, use `Multiscale_curvatures`, whose `estimate_curvatures()` gives
each layer as soon as it is made, to be kept in a smaller form or written out.

\tparam PointRange a range of `Kernel::Point_3`
\tparam NamedParameters a sequence of named parameters

\cgalNamedParamsBegin
  \cgalParamNBegin{scales}
    \cgalParamDescription{the scales; the paper's figures use the quantiles 10%, 25%, 35% and 50%}
    \cgalParamType{`std::vector<Scale>`}
    \cgalParamDefault{`default_scales()`}
  \cgalParamNEnd
  \cgalParamNBegin{neighborhoods}
    \cgalParamDescription{the neighborhoods of the curvature fits}
    \cgalParamType{`std::vector<Neighborhood>`}
    \cgalParamDefault{`default_neighborhoods()`}
  \cgalParamNEnd
  \cgalParamNBegin{estimator}
    \cgalParamDescription{the curvature estimator}
    \cgalParamType{`Curvature_estimator`}
    \cgalParamDefault{`QUADRIC_FIT`}
  \cgalParamNEnd
  \cgalParamNBegin{reference_normals, noise_estimate, denoising, denoising_neighbors, surface_extraction, local_feature_size_estimator}
    \cgalParamDescription{as for `Multiscale_curvatures`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument as `Multiscale_curvatures` and
`estimate_vertex_curvatures()`.
*/
template <class PointRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<Curvature_layer<typename Kernel_traits<typename PointRange::value_type>::Kernel> >
multiscale_curvatures(const PointRange& points, const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename Kernel_traits<typename PointRange::value_type>::Kernel Kernel;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const std::vector<Scale> scales = choose_parameter(get_parameter(np, internal_np_cas3::scales), default_scales());
  const std::vector<Neighborhood> neighborhoods =
    choose_parameter(get_parameter(np, internal_np_cas3::neighborhoods), default_neighborhoods());
  const Curvature_estimator estimator = choose_parameter(get_parameter(np, internal_np_cas3::estimator), QUADRIC_FIT);

  Multiscale_curvatures<Kernel> analysis(points.begin(), points.end(), np);
  std::vector<Curvature_layer<Kernel> > layers;
  for(const Scale& scale : scales)
  {
    typename Multiscale_curvatures<Kernel>::Surface surface;
    const double a = analysis.scale_value(scale);
    const Surface_report report = analysis.surface(a, surface);
    auto layer_done = [&](std::size_t k, std::vector<Point_curvature<Kernel> >&& values) {
      layers.push_back(Curvature_layer<Kernel>{scale, a, neighborhoods[k], report, std::move(values)});
    };
    // the shape is freed before the last scale's fits
    if(&scale == &scales.back())
      std::move(analysis).estimate_curvatures(surface, neighborhoods, estimator, layer_done);
    else
      analysis.estimate_curvatures(surface, neighborhoods, estimator, layer_done);
  }
  return layers;
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_MULTISCALE_CURVATURES_H
