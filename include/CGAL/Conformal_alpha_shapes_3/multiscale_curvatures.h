// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_MULTISCALE_CURVATURES_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_MULTISCALE_CURVATURES_H

#include <CGAL/Conformal_alpha_shape_3.h>
#include <CGAL/Conformal_alpha_shapes_3/denoise.h>
#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>
#include <CGAL/Conformal_alpha_shapes_3/extract_boundary_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/extract_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/suggest_alpha.h>
#include <CGAL/Conformal_alpha_shapes_3/suggest_scale.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
A requested internal scale `a`: an absolute value, a quantile of the facet
values (the paper's "10%, 25%, 35%, 50%", see
`Conformal_alpha_shape_3::alpha_at_quantile()`), or automatic
(`suggest_scale()`, or `suggest_alpha()` for the solid boundary).
*/
class Scale
{
public:
  enum Kind { ABSOLUTE, QUANTILE, AUTOMATIC };

  static Scale absolute(double a) { return Scale(ABSOLUTE, a); }
  static Scale quantile(double q) { return Scale(QUANTILE, q); }
  static Scale automatic() { return Scale(AUTOMATIC, 0); }

  /// Parses `0.35` (absolute), `25%` (quantile) or `auto`.
  /// \throws std::invalid_argument on anything else, on a negative or
  /// non-finite value, and on a percentage outside `[0, 100]`.
  static Scale from_string(const std::string& text)
  {
    if(text == "auto")
      return automatic();
    const bool percent = !text.empty() && text.back() == '%';
    const std::string number = percent ? text.substr(0, text.size() - 1) : text;
    std::size_t used = 0;
    double value = std::numeric_limits<double>::quiet_NaN();
    try { value = std::stod(number, &used); }
    catch(const std::exception&) { used = 0; }
    if(number.empty() || used != number.size() || !std::isfinite(value) || value < 0 || (percent && value > 100))
      throw std::invalid_argument("not a scale: '" + text + "' (expected a value >= 0, a percentage or 'auto')");
    return percent ? quantile(value / 100) : absolute(value);
  }

  Kind kind() const { return m_kind; }
  /// the absolute value or the quantile in `[0, 1]`
  double value() const { return m_value; }

  /// `0.35`, `25%` or `auto`, as `from_string()` reads it
  std::string label() const
  {
    if(m_kind == AUTOMATIC)
      return "auto";
    std::string s = std::to_string(m_kind == QUANTILE ? 100 * m_value : m_value);
    s.erase(s.find_last_not_of('0') + 1);
    if(s.back() == '.')
      s.pop_back();
    return m_kind == QUANTILE ? s + "%" : s;
  }

private:
  Scale(Kind kind, double value) : m_kind(kind), m_value(value) {}
  Kind m_kind;
  double m_value;
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
The curvature of the surface at one input point, at one scale and ring size;
`on_surface` is `false`, and every number NaN, where the point is not on
that surface, or is on it where its curvature is undefined (see
`estimate_vertex_curvatures()`: a vertex of a pocket too small for the fit).
*/
template <class Kernel>
struct Point_curvature
{
  bool on_surface = false;
  typename Kernel::Vector_3 normal;
  typename Kernel::FT mean_curvature = std::numeric_limits<double>::quiet_NaN();
  typename Kernel::FT gaussian_curvature = std::numeric_limits<double>::quiet_NaN();
  /// `max_curvature` is `k1`, `max_direction` `d1`; `min_curvature` is `k2`
  Principal_curvatures_and_directions<Kernel> principal;
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

Multi-scale curvature of a point cloud: the noise of the points is
estimated (`estimate_noise()`) and, when it matters, the points are
smoothed (`denoise()`); the conformal alpha shape of the (smoothed) points
is built once; then, for any scale, its surface is extracted
(`extract_surface()` by default, or `extract_boundary_surface()`), and for
any ring size the curvature estimated on that surface
(`estimate_vertex_curvatures()`) is given back per input point. Surfaces
are built on the smoothed positions; values are reported by input index.

Surfaces are `Surface_mesh` objects with the vertex properties
`"v:input_index"` (`std::size_t`) and, after `estimate_curvatures()`,
`"v:normal"` (`Vector_3`), `"v:mean_curvature"`, `"v:gaussian_curvature"`,
`"v:k1"`, `"v:k2"` (`double`), `"v:d1"` and `"v:d2"` (`Vector_3`):
`CGAL::IO::write_PLY()` writes the first six.

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
      \cgalParamDescription{a normal per input point (a scanner's) that the surfaces' orientation follows, or an empty vector}
      \cgalParamType{`std::vector<Vector>`}
      \cgalParamDefault{empty}
    \cgalParamNEnd
    \cgalParamNBegin{denoising}
      \cgalParamDescription{whether the points are smoothed first}
      \cgalParamType{`Denoising`}
      \cgalParamDefault{`AUTOMATIC_DENOISING`: as `denoising_plan()` says, when `Noise_estimate::calls_for_denoising()`}
    \cgalParamNEnd
    \cgalParamNBegin{denoising_neighbors}
      \cgalParamDescription{the neighbours of the smoothing jet fit}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{as `denoising_plan()` says for the estimated noise (at least 24)}
    \cgalParamNEnd
    \cgalParamNBegin{surface_extraction}
      \cgalParamDescription{how surfaces are extracted}
      \cgalParamType{`Surface_extraction`}
      \cgalParamDefault{`ADVANCING_FRONT`}
    \cgalParamNEnd
    \cgalParamNBegin{local_scale_estimator}
      \cgalParamDescription{the local scales of the shape}
      \cgalParamType{`Local_scale_estimator`}
      \cgalParamDefault{`NOISE_ROBUST_POLE_DISTANCE`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \throws std::invalid_argument as `Conformal_alpha_shape_3`, and when
  `reference_normals` is neither empty nor one per point.
  */
  template <class InputIterator, class NamedParameters = CGAL::parameters::Default_named_parameters>
  Multiscale_curvatures(InputIterator first, InputIterator last,
                        const NamedParameters& np = CGAL::parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    m_extraction = choose_parameter(get_parameter(np, internal_np_cas3::surface_extraction), ADVANCING_FRONT);
    m_reference_normals = choose_parameter(get_parameter(np, internal_np_cas3::reference_normals),
                                           std::vector<Vector>());
    std::vector<Point> points(first, last);
    if(!m_reference_normals.empty() && m_reference_normals.size() != points.size())
      throw std::invalid_argument("Multiscale_curvatures: " + std::to_string(m_reference_normals.size())
                                  + " reference normals for " + std::to_string(points.size()) + " points");
    const Denoising denoising = choose_parameter(get_parameter(np, internal_np_cas3::denoising),
                                                 AUTOMATIC_DENOISING);
    m_noise = estimate_noise(points);
    if(denoising == ALWAYS_DENOISE || (denoising == AUTOMATIC_DENOISING && m_noise.calls_for_denoising()))
    {
      m_denoising = denoising_plan(m_noise.noise);
      m_denoising.passes = (std::max)(m_denoising.passes, 1);
      m_denoising.neighbors = choose_parameter(get_parameter(np, internal_np_cas3::denoising_neighbors),
                                               (std::max)(m_denoising.neighbors, 24u));
      denoise(points, m_denoising);
    }
    m_shape.make_conformal_alpha_shape(points.begin(), points.end(), parameters::local_scale_estimator(
      choose_parameter(get_parameter(np, internal_np_cas3::local_scale_estimator), NOISE_ROBUST_POLE_DISTANCE)));
  }

  const Shape& shape() const { return m_shape; }
  /// the noise of the input points (`estimate_noise()`)
  const Noise_estimate& noise() const { return m_noise; }
  /// how the points were smoothed before the shape was built (`passes` is 0 when they were not)
  const Denoising_plan& denoising() const { return m_denoising; }
  /// how surfaces are extracted
  Surface_extraction extraction() const { return m_extraction; }
  /// whether reference normals orient the surfaces
  bool has_reference_normals() const { return !m_reference_normals.empty(); }

  /// The absolute value of a requested scale (the automatic one is computed once).
  double alpha(const Scale& scale) const
  {
    switch(scale.kind())
    {
      case Scale::ABSOLUTE: return scale.value();
      case Scale::QUANTILE: return m_shape.alpha_at_quantile(scale.value());
      case Scale::AUTOMATIC: break;
    }
    if(!(m_suggested >= 0))
      m_suggested = m_extraction == ADVANCING_FRONT ? suggest_scale(m_shape) : suggest_alpha(m_shape);
    return m_suggested;
  }

  /// Replaces `surface` with the surface at `alpha`.
  Surface_report extract_surface(double alpha, Surface& surface) const
  {
    surface.clear();
    auto input_index = surface.template add_property_map<Surface_vertex, std::size_t>("v:input_index").first;
    if(m_extraction == ADVANCING_FRONT)
      return Conformal_alpha_shapes_3::extract_surface(m_shape, alpha, surface,
        parameters::vertex_input_index_map(input_index, parameters::reference_normals(std::cref(m_reference_normals))));
    const Boundary_surface_report solid =
      extract_boundary_surface(m_shape, alpha, surface, parameters::vertex_input_index_map(input_index));
    Surface_report report;
    static_cast<Surface_counts&>(report) = solid;
    auto part = get(CGAL::dynamic_face_property_t<std::size_t>(), surface);
    report.number_of_parts = CGAL::Polygon_mesh_processing::connected_components(surface, part);
    report.number_of_closed_parts = report.number_of_parts;  // the boundary of a solid is closed
    return report;
  }

  /// Estimates the curvature of `surface` (from `extract_surface()`) at ring
  /// size `ring_size` into its properties, and returns it per input point.
  std::vector<Point_curvature<Kernel> > estimate_curvatures(Surface& surface, int ring_size,
                                                            Curvature_estimator estimator = QUADRIC_FIT) const
  {
    auto normal = surface.template add_property_map<Surface_vertex, Vector>("v:normal").first;
    auto mean = surface.template add_property_map<Surface_vertex, double>("v:mean_curvature").first;
    auto gaussian = surface.template add_property_map<Surface_vertex, double>("v:gaussian_curvature").first;
    auto principal = get(CGAL::dynamic_vertex_property_t<Principal_curvatures_and_directions<Kernel> >(), surface);
    estimate_vertex_curvatures(surface, parameters::vertex_mean_curvature_map(mean,
                                        parameters::vertex_Gaussian_curvature_map(gaussian,
                                        parameters::vertex_principal_curvatures_and_directions_map(principal,
                                        parameters::ring_size(ring_size, parameters::estimator(estimator)))))
                                          .vertex_normal_map(normal));
    auto k1 = surface.template add_property_map<Surface_vertex, double>("v:k1").first;
    auto k2 = surface.template add_property_map<Surface_vertex, double>("v:k2").first;
    auto d1 = surface.template add_property_map<Surface_vertex, Vector>("v:d1").first;
    auto d2 = surface.template add_property_map<Surface_vertex, Vector>("v:d2").first;
    auto input_index = surface.template property_map<Surface_vertex, std::size_t>("v:input_index").first;

    // by vertex of the shape: at a pinch, the first umbrella's defined estimate
    const std::size_t none = std::size_t(-1);
    std::vector<std::size_t> record_of_vertex(m_shape.number_of_vertices(), none);
    std::vector<Point_curvature<Kernel> > records;
    records.reserve(surface.number_of_vertices());
    for(Surface_vertex v : surface.vertices())
    {
      const Principal_curvatures_and_directions<Kernel> p = get(principal, v);
      k1[v] = p.max_curvature;
      k2[v] = p.min_curvature;
      d1[v] = p.max_direction;
      d2[v] = p.min_direction;
      std::size_t& r = record_of_vertex[m_shape.input_vertex(input_index[v])->vertex_index()];
      if(r != none || !std::isfinite(p.max_curvature))
        continue;
      r = records.size();
      Point_curvature<Kernel> record;
      record.on_surface = true;
      record.normal = normal[v];
      record.mean_curvature = mean[v];
      record.gaussian_curvature = gaussian[v];
      record.principal = p;
      records.push_back(record);
    }

    const double nan = std::numeric_limits<double>::quiet_NaN();
    Point_curvature<Kernel> off;
    off.normal = Vector(nan, nan, nan);
    off.principal = Principal_curvatures_and_directions<Kernel>{nan, nan, off.normal, off.normal};
    std::vector<Point_curvature<Kernel> > per_point(m_shape.number_of_input_points(), off);
    for(std::size_t i = 0; i < per_point.size(); ++i)
    {
      const std::size_t r = record_of_vertex[m_shape.input_vertex(i)->vertex_index()];
      if(r != none)
        per_point[i] = records[r];
    }
    return per_point;
  }

private:
  Shape m_shape;
  Surface_extraction m_extraction = ADVANCING_FRONT;
  std::vector<Vector> m_reference_normals;
  Noise_estimate m_noise;
  Denoising_plan m_denoising;
  mutable double m_suggested = -1;
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
The curvature of every input point at one scale and ring size.
*/
template <class Kernel>
struct Curvature_layer
{
  Scale scale;                        ///< as requested
  double alpha;                       ///< its absolute value
  int ring_size;
  Surface_report surface;             ///< what the extraction did
  std::vector<Point_curvature<Kernel> > points;  ///< by input index
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

For each requested scale and ring size, the curvature of every input point
(METHOD: section 6), from one conformal alpha shape of the points. The
layers come scale by scale, ring sizes inside. For large inputs, where all
layers do not fit in memory, use `Multiscale_curvatures` one layer at a time.

\tparam PointRange a range of `Kernel::Point_3`
\tparam NamedParameters a sequence of named parameters

\cgalNamedParamsBegin
  \cgalParamNBegin{scales}
    \cgalParamDescription{the scales}
    \cgalParamType{`std::vector<Scale>`}
    \cgalParamDefault{the quantiles 10%, 25%, 35% and 50%, as in the paper's figures}
  \cgalParamNEnd
  \cgalParamNBegin{ring_sizes}
    \cgalParamDescription{the ring sizes}
    \cgalParamType{`std::vector<int>`}
    \cgalParamDefault{1 and 2}
  \cgalParamNEnd
  \cgalParamNBegin{estimator}
    \cgalParamDescription{the curvature estimator}
    \cgalParamType{`Curvature_estimator`}
    \cgalParamDefault{`QUADRIC_FIT`}
  \cgalParamNEnd
  \cgalParamNBegin{reference_normals, denoising, denoising_neighbors, surface_extraction, local_scale_estimator}
    \cgalParamDescription{as for `Multiscale_curvatures`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument as `Conformal_alpha_shape_3`, and when a ring
size is below 1.
*/
template <class PointRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<Curvature_layer<typename Kernel_traits<typename PointRange::value_type>::Kernel> >
multiscale_curvatures(const PointRange& points, const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename Kernel_traits<typename PointRange::value_type>::Kernel Kernel;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const std::vector<Scale> scales = choose_parameter(
    get_parameter(np, internal_np_cas3::scales),
    std::vector<Scale>{Scale::quantile(0.10), Scale::quantile(0.25), Scale::quantile(0.35), Scale::quantile(0.50)});
  const std::vector<int> ring_sizes = choose_parameter(get_parameter(np, internal_np_cas3::ring_sizes),
                                                       std::vector<int>{1, 2});
  for(int k : ring_sizes)
    if(k < 1)
      throw std::invalid_argument("multiscale_curvatures: ring size " + std::to_string(k) + " is below 1");
  const Curvature_estimator estimator = choose_parameter(get_parameter(np, internal_np_cas3::estimator), QUADRIC_FIT);

  const Multiscale_curvatures<Kernel> analysis(points.begin(), points.end(), np);
  std::vector<Curvature_layer<Kernel> > layers;
  for(const Scale& scale : scales)
  {
    typename Multiscale_curvatures<Kernel>::Surface surface;
    const double alpha = analysis.alpha(scale);
    const Surface_report report = analysis.extract_surface(alpha, surface);
    for(int k : ring_sizes)
      layers.push_back(Curvature_layer<Kernel>{scale, alpha, k, report,
                                               analysis.estimate_curvatures(surface, k, estimator)});
  }
  return layers;
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_MULTISCALE_CURVATURES_H
