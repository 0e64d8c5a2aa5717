// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_MULTISCALE_CURVATURES_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_MULTISCALE_CURVATURES_H

// Over 400 lines: the pipeline class, whose named parameters are documented
// here at length, and the filling of points that are not surface vertices
// (a private member: it reads the shape's vertices and the surface's
// properties together). The types of a layer are in
// scales_and_neighborhoods.h.

#include <CGAL/Conformal_alpha_shape_3.h>
#include <CGAL/Conformal_alpha_shapes_3/denoise.h>
#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>
#include <CGAL/Conformal_alpha_shapes_3/extract_boundary_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/extract_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>
#include <CGAL/Conformal_alpha_shapes_3/scales_and_neighborhoods.h>
#include <CGAL/Conformal_alpha_shapes_3/suggest_alpha.h>
#include <CGAL/Conformal_alpha_shapes_3/suggest_scale.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/input_hygiene.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/sample_spacing.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

Multi-scale curvature of a point cloud: the input is checked, recentered
and rescaled, and isolated far outliers are left out (the manual, section
"Input Rules"); the noise of the points is estimated (`estimate_noise()`)
and, when it matters, the points are smoothed (`denoise()`); the conformal
alpha shape of these working points is built once; then, for any scale,
its surface is extracted (`extract_surface()` by default, or
`extract_boundary_surface()`), and for any neighborhood the curvature
estimated on that surface (`estimate_vertex_curvatures()`) is given back
per input point.

Everything given back is in the input's units and indices: surfaces lie at
the (smoothed) positions mapped back to input coordinates, radii and
distances are lengths of the input, curvatures are inverse lengths of the
input, and values are reported by input index. Only `shape()` is in the
working frame, the input recentered and scaled by a power of two, so that
no construction overflows or underflows whatever the input's magnitude.

Surfaces are `Surface_mesh` objects with the vertex properties
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
      \cgalParamDescription{a normal per input point (a scanner's), or an empty vector: each part of a surface is oriented by the majority of its points' normals, and each point's values by its own normal (see `estimate_curvatures()`)}
      \cgalParamType{`std::vector<Vector>`}
      \cgalParamDefault{empty}
    \cgalParamNEnd
    \cgalParamNBegin{denoising}
      \cgalParamDescription{whether the points are smoothed first}
      \cgalParamType{`Denoising`}
      \cgalParamDefault{`AUTOMATIC_DENOISING`: as `denoising_plan()` says, when `Noise_estimate::calls_for_denoising()`}
    \cgalParamNEnd
    \cgalParamNBegin{denoising_neighbors}
      \cgalParamDescription{the neighbors of the smoothing jet fit}
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

  \throws std::invalid_argument naming the first input point with a NaN or
  infinite coordinate; when `reference_normals` is neither empty nor one
  per point; and as `Conformal_alpha_shape_3` when the points left do not
  span 3D.
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
    m_input = internal::normalize_input<Kernel>(std::vector<Point>(first, last));
    if(!m_reference_normals.empty() && m_reference_normals.size() != m_input.is_outlier.size())
      throw std::invalid_argument("Multiscale_curvatures: " + std::to_string(m_reference_normals.size())
                                  + " reference normals for " + std::to_string(m_input.is_outlier.size())
                                  + " points");
    if(!m_reference_normals.empty())  // those of the kept points
    {
      for(std::size_t i = 0; i < m_input.input_index.size(); ++i)
        m_reference_normals[i] = m_reference_normals[m_input.input_index[i]];
      m_reference_normals.resize(m_input.input_index.size());
    }
    m_kept_index.assign(m_input.is_outlier.size(), std::size_t(-1));
    for(std::size_t i = 0; i < m_input.input_index.size(); ++i)
      m_kept_index[m_input.input_index[i]] = i;
    std::vector<Point> points = std::move(m_input.points);
    m_input.points = std::vector<Point>();
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

  /// the conformal alpha shape, in the working frame (see above): its
  /// input indices are those of the points kept (not outliers), in input order
  const Shape& shape() const { return m_shape; }
  /// the number of input points
  std::size_t number_of_input_points() const { return m_input.is_outlier.size(); }
  /// the input indices of the isolated far outliers, left off every surface (increasing)
  const std::vector<std::size_t>& outliers() const { return m_input.outliers; }
  /// whether input point `i` is an isolated far outlier
  bool is_outlier(std::size_t i) const { return m_input.is_outlier[i]; }
  /// the noise of the input points (`estimate_noise()`); `spacing` in input units
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

  /// The value of `a` for a requested scale (the automatic one is computed once).
  double scale_value(const Scale& scale) const
  {
    switch(scale.kind())
    {
      case Scale::ABSOLUTE: return scale.value();
      case Scale::QUANTILE: return m_shape.alpha_at_quantile(scale.value());
      case Scale::AUTOMATIC: break;
    }
    if(!(m_suggested >= 0))  // suggest_scale() with its default coverage, on the front grown once
      m_suggested = m_extraction == ADVANCING_FRONT ? internal::suggest_scale(front(), 0.99) : suggest_alpha(m_shape);
    return m_suggested;
  }

  /// Replaces `surface` with the surface at scale `a`, in input units and
  /// indices. With the advancing front, every scale is cut from one front
  /// grown with no bound (see `Conformal_alpha_shapes_3::extract_surface()`),
  /// grown at the first call of this or of `scale_value()` with the automatic
  /// scale and kept.
  Surface_report extract_surface(double a, Surface& surface) const
  {
    surface.clear();
    auto input_index = surface.template add_property_map<Surface_vertex, std::size_t>("v:input_index").first;
    Surface_report report;
    if(m_extraction == ADVANCING_FRONT)
      report = internal::surface_of_soup(m_shape, internal::pruned_soup(front(), a), surface,
        parameters::vertex_input_index_map(input_index, parameters::reference_normals(std::cref(m_reference_normals))));
    else
    {
      static_cast<Surface_counts&>(report) =
        extract_boundary_surface(m_shape, a, surface, parameters::vertex_input_index_map(input_index));
      auto part = get(CGAL::dynamic_face_property_t<std::size_t>(), surface);
      report.number_of_parts = CGAL::Polygon_mesh_processing::connected_components(surface, part);
      report.number_of_closed_parts = report.number_of_parts;  // the boundary of a solid is closed
    }
    for(Surface_vertex v : surface.vertices())
    {
      input_index[v] = m_input.input_index[input_index[v]];
      surface.point(v) = m_input.to_input(surface.point(v));
    }
    // the outliers are input points too, off every surface
    report.number_of_points_off_surface += m_input.outliers.size();
    report.number_of_input_points += m_input.outliers.size();
    return report;
  }

  /// The radius of a neighborhood of kind `Neighborhood::RADIUS` or
  /// `Neighborhood::SPACINGS`, in input units.
  double radius(const Neighborhood& neighborhood) const
  {
    return m_input.length_to_input(working_radius(neighborhood));
  }

  /// How far, in local spacings, an input point may be from the surface and
  /// still take its values (see `Point_source`); the local spacing of a
  /// point is the length of its vertex's third-shortest Delaunay edge.
  static constexpr double far_from_surface() { return 4; }

  /*!
  Estimates the curvature of `surface` (from `extract_surface()`) with the
  neighborhood `neighborhood` into its properties, and returns it for every
  input point: a vertex of the surface has its own fit; any other point
  takes the values at its nearest point on the surface, interpolated over
  the facet there, unless it is farther than `far_from_surface()` local
  spacings (see `Point_source`). With reference normals, a point whose
  reference normal points to the other side of the surface gets the values
  seen from that side: normal and mean and principal curvatures negated,
  principal directions swapped; the surface's own properties keep the
  orientation of its part.
  */
  std::vector<Point_curvature<Kernel> > estimate_curvatures(Surface& surface, const Neighborhood& neighborhood,
                                                            Curvature_estimator estimator = QUADRIC_FIT) const
  {
    return estimate_curvatures(surface, std::vector<Neighborhood>(1, neighborhood), estimator).front();
  }

  /*!
  The same for several neighborhoods at once, one result per
  neighborhood (in their order), the surface's properties holding the
  last one's. Cheaper than one call per neighborhood: each vertex's
  neighborhoods are found by one search, the largest, and each fit runs
  on a part of it. With TBB (`CGAL_LINKED_WITH_TBB`) the vertices are
  estimated in parallel, with the same results.
  */
  std::vector<std::vector<Point_curvature<Kernel> > >
  estimate_curvatures(Surface& surface, const std::vector<Neighborhood>& neighborhoods,
                      Curvature_estimator estimator = QUADRIC_FIT) const
  {
    std::vector<internal::Neighborhood_rule> rules(neighborhoods.size());
    for(std::size_t r = 0; r < neighborhoods.size(); ++r)
    {
      switch(neighborhoods[r].kind())
      {
        case Neighborhood::RINGS: rules[r].rings = int(neighborhoods[r].value()); break;
        case Neighborhood::RADIUS:
        case Neighborhood::SPACINGS: rules[r].radius = working_radius(neighborhoods[r]); break;
        case Neighborhood::AUTOMATIC:
          for(double m : Neighborhood::automatic_radii())
            rules[r].candidates.push_back(m * m_noise.spacing);
          break;
      }
      internal::check_neighborhood_rule(rules[r], estimator);
    }
    const Working_point_map working = working_points(surface);
    std::vector<std::vector<internal::Vertex_estimate> > estimates;
    {
      // the graph is freed before the layers are made (80 MB at 1,000,000
      // points, at the top of the stage's memory)
      const auto vertex_index = get(CGAL::vertex_index, surface);
      const internal::Vertex_graph graph = internal::vertex_graph(surface, working, vertex_index);
      estimates = internal::estimate_at_every_vertex<CGAL::Parallel_if_available_tag>(
        graph, internal::chen_wu_normals<CGAL::Parallel_if_available_tag>(surface, working, vertex_index), rules,
        estimator, m_noise.noise * m_noise.spacing);
    }
    if(!estimates.empty())
      set_surface_properties(surface, estimates.back());

    const std::vector<Surface_foot> feet = surface_feet(surface, working, estimates);
    // the layers are filled vertex by vertex of the shape, whose order the
    // surface's follows: the reads are then in memory order and each point
    // costs one scattered store (point by point, its vertex, its surface
    // vertex and its estimate were three dependent cache misses)
    std::vector<typename Shape::Vertex_handle> shape_vertex(m_shape.number_of_vertices());  // by vertex index
    for(const typename Shape::Vertex_handle v : m_shape.finite_vertex_handles())
      shape_vertex[v->vertex_index()] = v;
    // each neighborhood's estimates are freed once its layer is made, so
    // that the estimates and the layers are not all held at once
    std::vector<std::vector<Point_curvature<Kernel> > > layers;
    for(std::vector<internal::Vertex_estimate>& by_surface_vertex : estimates)
    {
      const std::vector<std::size_t> own = surface_vertex_of_shape_vertex(surface, by_surface_vertex);
      std::vector<Point_curvature<Kernel> > per_point(number_of_input_points());
      internal::for_each_index<CGAL::Parallel_if_available_tag>(
        shape_vertex.size(), []() { return 0; }, [&](std::size_t k, int&) {
          const Point_curvature<Kernel> value =
            in_input_units(value_at_vertex(k, own, surface, working, by_surface_vertex, feet));
          for(const std::size_t i : m_shape.input_indices(shape_vertex[k]))
          {
            Point_curvature<Kernel>& c = per_point[m_input.input_index[i]];
            c = value;
            if(!m_reference_normals.empty() && c.normal * m_reference_normals[i] < 0)
              take_other_side(c);
          }
        });
      std::vector<internal::Vertex_estimate>().swap(by_surface_vertex);
      layers.push_back(std::move(per_point));
    }
    return layers;
  }

private:
  typedef typename CGAL::dynamic_vertex_property_t<Point> Working_point_tag;

  // The advancing front grown with no bound, once.
  const internal::Advancing_front_soup& front() const
  {
    if(!m_front_grown)
    {
      m_front = internal::advancing_front_soup(m_shape);
      m_front_grown = true;
    }
    return m_front;
  }

  typedef typename boost::property_map<Surface, Working_point_tag>::const_type Working_point_map;

  // The surface's points in the working frame: the fits and the
  // nearest-surface search run there (see the class description).
  Working_point_map working_points(const Surface& surface) const
  {
    auto working = get(Working_point_tag(), surface);
    for(Surface_vertex v : surface.vertices())
      put(working, v, m_input.to_normalized(surface.point(v)));
    return working;
  }

  // The radius of a neighborhood in the working frame.
  double working_radius(const Neighborhood& neighborhood) const
  {
    return neighborhood.kind() == Neighborhood::SPACINGS ? neighborhood.value() * m_noise.spacing
                                                         : m_input.length_from_input(neighborhood.value());
  }

  static Vector to_vector(const internal::Vec3& v) { return Vector(v.x(), v.y(), v.z()); }

  // The surface's properties (see the class description) from the
  // estimates at its vertices, in input units.
  void set_surface_properties(Surface& surface, const std::vector<internal::Vertex_estimate>& estimates) const
  {
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
      const internal::Vertex_estimate& e = estimates[v.idx()];
      normal[v] = to_vector(e.curvature.normal);
      k1[v] = m_input.curvature_to_input(e.curvature.k1);
      k2[v] = m_input.curvature_to_input(e.curvature.k2);
      mean[v] = (k1[v] + k2[v]) / 2;
      gaussian[v] = k1[v] * k2[v];
      used_radius[v] = m_input.length_to_input(e.radius);
      d1[v] = to_vector(e.curvature.d1);
      d2[v] = to_vector(e.curvature.d2);
    }
  }

  // The same curvature seen from the other side of the surface: the
  // normal and the signs of the curvatures flip, the principal directions
  // swap roles (so that d1 x d2 is still the normal). With reference
  // normals, every point's values are taken on its reference's side: a
  // surface part is oriented by the majority of its points, and this makes
  // the few points that disagree with their part follow their own normal.
  static void take_other_side(Point_curvature<Kernel>& c)
  {
    Principal_curvatures_and_directions<Kernel>& p = c.principal;
    c.normal = -c.normal;
    c.mean_curvature = -c.mean_curvature;
    const double max_curvature = -p.min_curvature;
    p.min_curvature = -p.max_curvature;
    p.max_curvature = max_curvature;
    std::swap(p.max_direction, p.min_direction);
  }

  // Lengths and curvatures of the working frame in input units.
  Point_curvature<Kernel> in_input_units(Point_curvature<Kernel> c) const
  {
    c.distance = m_input.length_to_input(c.distance);
    c.radius = m_input.length_to_input(c.radius);
    c.mean_curvature = m_input.curvature_to_input(c.mean_curvature);
    c.gaussian_curvature = m_input.gaussian_curvature_to_input(c.gaussian_curvature);
    c.principal.max_curvature = m_input.curvature_to_input(c.principal.max_curvature);
    c.principal.min_curvature = m_input.curvature_to_input(c.principal.min_curvature);
    return c;
  }

  // Where a vertex of the shape without a value of its own meets the
  // surface: the nearest point of the surface, on `face`; `face` is null
  // when the vertex is farther than `far_from_surface()` local spacings.
  typedef typename Surface::Face_index Surface_face;
  struct Surface_foot
  {
    std::size_t shape_vertex;  // vertex index
    Point point;
    Surface_face face;
    double distance;
  };

  // The feet of the shape's vertices that take their values from the
  // nearest point of the surface in some neighborhood (off the surface, or
  // on vertices whose fits all failed), by vertex index: found once for
  // all neighborhoods, so that the search tree over the surface's faces
  // (about 200 MB at 1,000,000 points, for usually few vertices) is freed
  // before the layers are made.
  std::vector<Surface_foot> surface_feet(const Surface& surface, const Working_point_map& working,
                                         const std::vector<std::vector<internal::Vertex_estimate> >& estimates) const
  {
    std::vector<Surface_foot> feet;
    if(CGAL::is_empty(surface))
      return feet;
    std::vector<bool> needs_foot(m_shape.number_of_vertices(), false);
    for(const std::vector<internal::Vertex_estimate>& by_surface_vertex : estimates)
    {
      const std::vector<std::size_t> own = surface_vertex_of_shape_vertex(surface, by_surface_vertex);
      for(std::size_t v = 0; v < own.size(); ++v)
        if(own[v] == no_surface_vertex)
          needs_foot[v] = true;
    }
    std::vector<typename Shape::Vertex_handle> vertices;
    for(std::size_t i = 0; i < m_input.input_index.size(); ++i)
    {
      const typename Shape::Vertex_handle v = m_shape.input_vertex(i);
      if(needs_foot[v->vertex_index()])
      {
        needs_foot[v->vertex_index()] = false;
        vertices.push_back(v);
      }
    }
    if(vertices.empty())
      return feet;

    typedef CGAL::AABB_face_graph_triangle_primitive<Surface, Working_point_map> Primitive;
    CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> > tree;
    tree.insert(faces(surface).first, faces(surface).second, surface, working);
    // the search tree of the faces in their order, then the hierarchy,
    // which sorts them: where several faces are nearest, the one found
    // depends on that order
    tree.accelerate_distance_queries();
    tree.build();
    feet.resize(vertices.size());
    internal::for_each_index<CGAL::Parallel_if_available_tag>(
      vertices.size(), []() { return 0; }, [&](std::size_t k, int&) {
        const Point& p = vertices[k]->point();
        const auto nearest = tree.closest_point_and_primitive(p);
        feet[k] = Surface_foot{vertices[k]->vertex_index(), nearest.first, nearest.second,
                               std::sqrt(CGAL::to_double(CGAL::squared_distance(p, nearest.first)))};
      });
    // far against the local spacing of the local-scale rule; serially:
    // CGAL's walks over the shape mark the vertices they visit
    typedef internal::Local_scale_policy Policy;
    for(std::size_t k = 0; k < feet.size(); ++k)
      if(feet[k].distance
         > far_from_surface() * internal::kth_shortest_edge_length<Policy::spacing_edge_rank>(m_shape, vertices[k]))
        feet[k].face = Surface_face();
    std::sort(feet.begin(), feet.end(),
              [](const Surface_foot& x, const Surface_foot& y) { return x.shape_vertex < y.shape_vertex; });
    return feet;
  }

  // For every vertex of the shape (by vertex index), the surface vertex
  // whose estimate it takes: its own first; at a pinch (a vertex standing
  // for several surface vertices), the first one whose estimate is defined;
  // `no_surface_vertex` when none is.
  static constexpr std::size_t no_surface_vertex = std::size_t(-1);
  std::vector<std::size_t> surface_vertex_of_shape_vertex(const Surface& surface,
                                                          const std::vector<internal::Vertex_estimate>& estimates) const
  {
    auto input_index = surface.template property_map<Surface_vertex, std::size_t>("v:input_index").first;
    std::vector<std::size_t> own(m_shape.number_of_vertices(), no_surface_vertex);
    for(Surface_vertex v : surface.vertices())
    {
      std::size_t& o = own[m_shape.input_vertex(m_kept_index[input_index[v]])->vertex_index()];
      if(o == no_surface_vertex && estimates[v.idx()].defined())
        o = v.idx();
    }
    return own;
  }

  // The value of the fits on `surface` (`estimates`, by surface vertex
  // index) at the vertex of index `v` of the shape, in the working frame (see
  // `estimate_curvatures()`): its own surface vertex's (`own`, from
  // `surface_vertex_of_shape_vertex()`), or else interpolated at the
  // nearest point of the surface (`feet`, from `surface_feet()`). Made
  // as each layer is filled rather than kept per vertex: a layer of values
  // for every vertex was the top of the curvature stage's memory.
  Point_curvature<Kernel> value_at_vertex(std::size_t v, const std::vector<std::size_t>& own,
                                          const Surface& surface, const Working_point_map& working,
                                          const std::vector<internal::Vertex_estimate>& estimates,
                                          const std::vector<Surface_foot>& feet) const
  {
    auto estimate = [&](Surface_vertex u) -> const internal::Vertex_estimate& { return estimates[u.idx()]; };
    auto record = [&](Point_source source, double distance, double r, const Vector& n, double max_k, double min_k,
                      const Vector& max_d, const Vector& min_d) {
      Point_curvature<Kernel> c;
      c.source = source;
      c.distance = distance;
      c.radius = r;
      c.normal = n;
      c.mean_curvature = (max_k + min_k) / 2;
      c.gaussian_curvature = max_k * min_k;
      c.principal = Principal_curvatures_and_directions<Kernel>{max_k, min_k, max_d, min_d};
      return c;
    };
    Point_curvature<Kernel> c;  // NaN everywhere

    const std::size_t own_vertex = own[v];
    if(own_vertex != no_surface_vertex)
    {
      const internal::Vertex_estimate& e = estimates[own_vertex];
      return record(SURFACE_VERTEX, 0, e.radius, to_vector(e.curvature.normal), e.curvature.k1, e.curvature.k2,
                    to_vector(e.curvature.d1), to_vector(e.curvature.d2));
    }

    // from the nearest point of the surface
    const auto foot = std::lower_bound(feet.begin(), feet.end(), v,
                                       [](const Surface_foot& f, std::size_t x) { return f.shape_vertex < x; });
    if(foot == feet.end() || foot->shape_vertex != v)  // the surface is empty
      return c;
    c.distance = foot->distance;
    if(foot->face == Surface_face())
      return c;
    // barycentric weights of the nearest point, over the corners with values
    Surface_vertex corner[3];
    int i = 0;
    for(Surface_vertex u : vertices_around_face(surface.halfedge(foot->face), surface))
      corner[i++] = u;
    double weight[3], total = 0;
    for(int j = 0; j < 3; ++j)
    {
      weight[j] = estimate(corner[j]).defined()
        ? std::sqrt(CGAL::to_double(CGAL::squared_area(foot->point, get(working, corner[(j + 1) % 3]),
                                                       get(working, corner[(j + 2) % 3]))))
        : 0.;
      total += weight[j];
    }
    if(!(total > 0))  // a degenerate facet: its corners with values, alike
      for(int j = 0; j < 3; ++j)
        total += (weight[j] = estimate(corner[j]).defined() ? 1. : 0.);
    if(!(total > 0))
      return c;
    internal::Vec3 n = internal::Vec3::Zero(), max_d = internal::Vec3::Zero();
    double r = 0, max_k = 0, min_k = 0;
    int reference = -1;
    for(int j = 0; j < 3; ++j)
    {
      if(!(weight[j] > 0))
        continue;
      const double w = weight[j] / total;
      const internal::Local_curvature& corner_curvature = estimate(corner[j]).curvature;
      if(reference < 0)
        reference = j;
      n += w * corner_curvature.normal;
      // a principal direction is a line: align signs before averaging
      const internal::Vec3& reference_d1 = estimate(corner[reference]).curvature.d1;
      max_d += (corner_curvature.d1.dot(reference_d1) < 0 ? -w : w) * corner_curvature.d1;
      r += w * estimate(corner[j]).radius;
      max_k += w * corner_curvature.k1;
      min_k += w * corner_curvature.k2;
    }
    n.normalize();
    max_d = (max_d - max_d.dot(n) * n).normalized();
    return record(NEAREST_SURFACE_POINT, c.distance, r, to_vector(n), max_k, min_k, to_vector(max_d),
                  to_vector(n.cross(max_d)));
  }

  internal::Normalized_input<Kernel> m_input;  // the working frame and the outliers (its points moved out)
  std::vector<std::size_t> m_kept_index;       // input index -> index among the kept points
  Shape m_shape;
  Surface_extraction m_extraction = ADVANCING_FRONT;
  std::vector<Vector> m_reference_normals;
  Noise_estimate m_noise;
  Denoising_plan m_denoising;
  mutable double m_suggested = -1;
  mutable internal::Advancing_front_soup m_front;  // see front()
  mutable bool m_front_grown = false;
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
The curvature of every input point at one scale and ring size.
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

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// The scales of `multiscale_curvatures()` and of the program when none are
/// named: the automatic one (see the manual for why coarser conformal scales
/// are not in the default: above the automatic scale the advancing front
/// gives nearly the same surface; the neighborhood radius is what coarsens).
inline std::vector<Scale> default_scales() { return {Scale::automatic()}; }

/// \ingroup PkgConformalAlphaShapes3Multiscale
/// The neighborhoods of `multiscale_curvatures()` and of the program when
/// none are named: the automatic one, then radii of 2, 4, 8 and 16 sample
/// spacings, from the finest detail to a summary of larger regions.
inline std::vector<Neighborhood> default_neighborhoods()
{
  return {Neighborhood::automatic(), Neighborhood::spacings(2), Neighborhood::spacings(4),
          Neighborhood::spacings(8), Neighborhood::spacings(16)};
}

/*!
\ingroup PkgConformalAlphaShapes3Multiscale

For each requested scale and neighborhood, the curvature of every input
point (see the manual, section "Multi-scale Curvature of a Point Cloud"),
from one conformal alpha shape of the points. The layers come scale by
scale, neighborhoods inside. For large inputs, where all layers do not fit
in memory, use `Multiscale_curvatures` one layer at a time.

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
  \cgalParamNBegin{reference_normals, denoising, denoising_neighbors, surface_extraction, local_scale_estimator}
    \cgalParamDescription{as for `Multiscale_curvatures`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument as `Conformal_alpha_shape_3` and
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

  const Multiscale_curvatures<Kernel> analysis(points.begin(), points.end(), np);
  std::vector<Curvature_layer<Kernel> > layers;
  for(const Scale& scale : scales)
  {
    typename Multiscale_curvatures<Kernel>::Surface surface;
    const double a = analysis.scale_value(scale);
    const Surface_report report = analysis.extract_surface(a, surface);
    for(const Neighborhood& neighborhood : neighborhoods)
      layers.push_back(Curvature_layer<Kernel>{scale, a, neighborhood, report,
                                               analysis.estimate_curvatures(surface, neighborhood, estimator)});
  }
  return layers;
}

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_MULTISCALE_CURVATURES_H
