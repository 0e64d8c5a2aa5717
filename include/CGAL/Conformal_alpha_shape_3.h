// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPE_3_H
#define CGAL_CONFORMAL_ALPHA_SHAPE_3_H

// Over 500 lines: one class with the API of Alpha_shape_3 (classification
// of four kinds of simplex, with and without a scale, the spectrum, the
// filtration, an output function per kind), all reading the values stored in
// the triangulation's vertices and cells, and its reference documentation (a
// quarter of the lines). What stands alone is in internal/: the input checks
// (input_hygiene.h), the insertion order (order_free.h), the input-index
// table, the cell values, the critical values of classification, the poles
// and the local-feature-size policy (sample_spacing.h).

#include <CGAL/Conformal_alpha_shape_cell_base_3.h>
#include <CGAL/Conformal_alpha_shape_vertex_base_3.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/cell_values.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/critical_values.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/flood_fill.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/for_each_index.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/input_hygiene.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/input_index_table.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/order_free.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/poles.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/sample_spacing.h>
#include <CGAL/Conformal_alpha_shapes_3/named_parameters.h>

#include <CGAL/assertions.h>
#include <CGAL/determinant.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

/// \ingroup PkgConformalAlphaShapes3Classes
/// How `Conformal_alpha_shape_3` computes the local feature size of each vertex from
/// the Voronoi diagram of the points (named parameter `local_feature_size_estimator`).
enum Local_feature_size_estimator
{
  /// The paper's: the distance to the pole, the Amenta-Bern negative pole
  /// (see `Conformal_alpha_shape_3::pole()`). On noisy samples it collapses
  /// for points displaced inwards, once the noise exceeds the local sagitta.
  PAPER_POLE_DISTANCE,
  /// The distance to the pole, but at least 4 times the local sample
  /// spacing (the length of the vertex's 3rd shortest Delaunay edge: on a
  /// surface, a vertex has at least 3 neighbors at about the spacing): a
  /// sample cannot resolve features much smaller than its spacing, and the
  /// collapsed pole distances of noisy points are exactly such features.
  /// Identical to `PAPER_POLE_DISTANCE` on dense noiseless samples. The default.
  NOISE_ROBUST_POLE_DISTANCE
};

namespace internal {

// Whether T is a range rather than an iterator, to tell the two forms of
// the named parameter `local_feature_sizes` apart.
template <class T, class = void>
struct Is_range : std::false_type {};
template <class T>
struct Is_range<T, std::void_t<decltype(std::begin(std::declval<const T&>())),
                               decltype(std::end(std::declval<const T&>()))> > : std::true_type {};

} // namespace internal

} // namespace Conformal_alpha_shapes_3

/*!
\ingroup PkgConformalAlphaShapes3Classes

The conformal alpha shape filtration of a 3D point set (Cazals, Giesen, Pauly
and Zomorodian, 2005), built on its Delaunay triangulation.

Every vertex `p` carries a local feature size `alpha_p+` (by default derived from the
distance to its pole, see `local_feature_size()`). A finite simplex `s` with ordinary alpha value
`alpha(s)` (the radius, not squared, of its smallest empty circumscribing
ball, attached to its cofaces when that ball is not empty) gets the conformal
value `a(s) = alpha(s) / min_{p in s} alpha_p+`; vertices get 0. The conformal
alpha complex at internal scale `a` is the set of simplices with `a(s) <= a`.
Every value handled by this class is such a dimensionless ratio of radii:
with all local feature sizes equal to 1 the complex at `a` is the ordinary alpha
complex of `CGAL::Alpha_shape_3` at its (squared) parameter `a*a`.

Classification follows `CGAL::Alpha_shape_3` in `GENERAL` mode: a simplex is
`EXTERIOR` when not in the complex, `INTERIOR` when all its incident cells
are in it, `REGULAR` when it is in the complex, is a face of a
higher-dimensional simplex of the complex and is not interior, and `SINGULAR`
when it is in the complex but is a face of no higher-dimensional simplex of the
complex. For a facet, `REGULAR` means exactly one of its two cells is in the
complex; a surface sample's surface first appears as `SINGULAR` facets.

Values are kept in the triangulation's own vertices and cells: each cell keeps
its radius and which of its facets are Gabriel (16 bytes per cell), each vertex
its local feature size and pole. Facet and edge values follow from these when asked
for. The sorted spectrum is computed on first use.

The triangulation must not be modified after construction: its values would
no longer be valid. Use `make_conformal_alpha_shape()` to rebuild. The class
can be neither copied nor moved (as `Alpha_shape_3`): a copy of the
triangulation would keep handles into the original.

Range of the input: the values are computed in `double` from circumcenters,
whose coordinates are quotients of fourth and third powers of coordinate
differences. The construction therefore rejects, with `std::invalid_argument`,
points whose coordinates exceed `1e75` in magnitude, point sets whose
bounding box is larger than `1e75` or smaller than `1e-75` along its longest
axis, and, as a last guard, any point set on which a circumcenter or a
circumradius is not a finite positive `double`, or on which the determinant
that the kernel divides by to construct a circumcenter or a facet radius is
0 in `double` (a tetrahedron or triangle flat to rounding, far smaller than
the bounding box, say: exact predicates accept it, inexact constructions
cannot handle it). Normalize such data first: the pipeline (see the manual, section on
input rules) recenters and rescales the points, and flags isolated far
outliers, before building this class.

\tparam Dt a `Delaunay_triangulation_3` whose geometric traits class is a
        CGAL kernel with `double` as field type (such as
        `Exact_predicates_inexact_constructions_kernel`) and whose vertex and
        cell bases are `Conformal_alpha_shape_vertex_base_3` and
        `Conformal_alpha_shape_cell_base_3` (or derive from them).
        Predicates are evaluated by the kernel (exactly with `Epick`);
        values are computed and stored as `double`.
*/
template <class Dt>
class Conformal_alpha_shape_3 : public Dt
{
public:
  typedef Dt                                  Triangulation;
  typedef typename Dt::Geom_traits            Gt;
  typedef typename Gt::FT                     FT;
  typedef typename Dt::Point                  Point;
  typedef typename Dt::Vertex_handle          Vertex_handle;
  typedef typename Dt::Cell_handle            Cell_handle;
  typedef typename Dt::Facet                  Facet;
  typedef typename Dt::Edge                   Edge;
  typedef typename Dt::Simplex                Simplex;
  typedef std::size_t                         size_type;

  static_assert(std::is_same<FT, double>::value,
                "Conformal_alpha_shape_3 needs a kernel with double coordinates, "
                "such as Exact_predicates_inexact_constructions_kernel");

  /// Same meaning as in `Alpha_shape_3`.
  enum Classification_type { EXTERIOR, SINGULAR, REGULAR, INTERIOR };

  /// Iterator over the sorted distinct conformal values.
  typedef typename std::vector<FT>::const_iterator Alpha_iterator;

  /// Range of the indices of the input points a vertex stands for.
  typedef Conformal_alpha_shapes_3::internal::Input_index_table::Range Input_index_range;

  /// \name Creation
  /// @{

  /// An empty shape at scale `alpha` (see `set_alpha()`); fill it with
  /// `make_conformal_alpha_shape()`.
  /// \throws std::invalid_argument when `alpha` is negative or NaN.
  explicit Conformal_alpha_shape_3(FT alpha = FT(0)) : m_alpha(alpha) { check_alpha(alpha); }

  // Neither copyable nor movable: vertices and cells hold handles, and the
  // input-vertex table points into this triangulation.
  Conformal_alpha_shape_3(const Conformal_alpha_shape_3&) = delete;
  Conformal_alpha_shape_3& operator=(const Conformal_alpha_shape_3&) = delete;
  Conformal_alpha_shape_3(Conformal_alpha_shape_3&&) = delete;
  Conformal_alpha_shape_3& operator=(Conformal_alpha_shape_3&&) = delete;

  /// The largest coordinate magnitude and bounding-box extent accepted.
  static constexpr double max_coordinate_magnitude()
  { return Conformal_alpha_shapes_3::internal::max_coordinate_magnitude; }
  /// The smallest bounding-box extent (along the longest axis) accepted.
  static constexpr double min_extent() { return Conformal_alpha_shapes_3::internal::min_coordinate_extent; }

  /// The shape of the points in `[first, last)`, as
  /// `make_conformal_alpha_shape(first, last, np)` builds it.
  /// \throws std::invalid_argument as `make_conformal_alpha_shape()`.
  template <class InputIterator, class NamedParameters = parameters::Default_named_parameters>
  Conformal_alpha_shape_3(InputIterator first, InputIterator last,
                          const NamedParameters& np = parameters::default_values())
    : m_alpha(0)
  {
    make_conformal_alpha_shape(first, last, np);
  }

  /*!
  Clears the shape, then builds it for the points in `[first, last)`.
  Duplicate points collapse into one vertex that remembers all their
  indices. Returns the number of input points. Poles are always computed;
  the local feature sizes come from them, or from the caller.

  \cgalNamedParamsBegin
    \cgalParamNBegin{local_feature_size_estimator}
      \cgalParamDescription{how the local feature size of each vertex is computed from the Voronoi diagram (ignored when `local_feature_sizes` is given)}
      \cgalParamType{`Conformal_alpha_shapes_3::Local_feature_size_estimator`}
      \cgalParamDefault{`Conformal_alpha_shapes_3::NOISE_ROBUST_POLE_DISTANCE`}
    \cgalParamNEnd
    \cgalParamNBegin{local_feature_sizes}
      \cgalParamDescription{the caller's local feature sizes, one per input point, in input order: the
                             local feature size of input point `i` is its `i`-th value; a vertex standing
                             for duplicate points takes the smallest of their sizes}
      \cgalParamType{an input iterator to the first size, or a range of the sizes (then of the
                      same size as `[first, last)`), with values convertible to `double`}
      \cgalParamDefault{sizes from the poles, as `local_feature_size_estimator` says}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \throws std::invalid_argument, leaving the shape empty, when a coordinate
  is NaN or infinite (the message names the first such index), when a
  coordinate's magnitude exceeds `max_coordinate_magnitude()` (the message
  names the index), when the bounding box is longer than
  `max_coordinate_magnitude()` or shorter than `min_extent()` along its
  longest axis, when a circumcenter or circumradius overflows or underflows
  in `double`, or when the points do not span 3D (empty input, fewer than 4
  distinct points, all coplanar or collinear): the filtration needs a 3D
  triangulation. With `local_feature_sizes`, also when a size is not finite and
  positive (the message names its index) or when the range of sizes is not
  as long as the input.
  \throws Conformal_alpha_shapes_3::Interrupted, leaving the shape empty, when
  the calling thread's `Conformal_alpha_shapes_3::Scoped_interruption_check`
  asks it to stop.
  */
  template <class InputIterator, class NamedParameters = parameters::Default_named_parameters>
  size_type make_conformal_alpha_shape(InputIterator first, InputIterator last,
                                       const NamedParameters& np = parameters::default_values())
  {
    static_assert(Conformal_alpha_shapes_3::internal::Is_named_function_parameters<NamedParameters>::value,
                  "the third argument is a pack of named parameters: pass one size per point as "
                  "Conformal_alpha_shapes_3::parameters::local_feature_sizes(scales_first)");
    using parameters::choose_parameter;
    using parameters::get_parameter;
    namespace CAS3 = Conformal_alpha_shapes_3;
    const CAS3::Local_feature_size_estimator estimator = choose_parameter(
      get_parameter(np, CAS3::internal_np_cas3::local_feature_size_estimator), CAS3::NOISE_ROBUST_POLE_DISTANCE);

    try
    {
      insert_points(first, last);
      // the passes below run over the cells by index: listed once
      const std::vector<Cell_handle> cells = index_cells();
      std::vector<Point> centers;
      if(!CAS3::internal::store_cell_values(*this, cells, centers))
      {
        clear();
        throw std::invalid_argument("Conformal_alpha_shape_3: a circumcenter or circumradius of the Delaunay "
                                    "tetrahedra overflows or underflows in double, or divides by a "
                                    "determinant that is 0 in double (tetrahedra or triangles flat to "
                                    "rounding, of very different sizes); normalize the coordinates and "
                                    "remove far outliers");
      }
      const std::vector<Pole> poles = CAS3::internal::compute_poles(*this, cells, centers);
      for(Vertex_handle v : this->finite_vertex_handles())
      {
        v->set_pole_cell(poles[v->vertex_index()].cell);
        v->set_local_feature_size(poles[v->vertex_index()].distance);
      }
      if constexpr(!parameters::is_default_parameter<NamedParameters,
                                                     CAS3::internal_np_cas3::local_feature_sizes_t>::value)
      {
        set_caller_local_feature_sizes(get_parameter(np, CAS3::internal_np_cas3::local_feature_sizes));
      }
      else if(estimator == CAS3::NOISE_ROBUST_POLE_DISTANCE)
      {
        const std::vector<double> floors = CAS3::internal::local_feature_size_floors(*this, cells);
        for(Vertex_handle v : this->finite_vertex_handles())
          v->set_local_feature_size((std::max)(v->local_feature_size(), floors[v->vertex_index()]));
      }
    }
    catch(const CAS3::Interrupted&)
    {
      clear();  // a shape is whole or empty
      throw;
    }
    return m_input_vertices.size();
  }

  /// Empties the shape and frees its memory.
  void clear()
  {
    Dt::clear();
    std::vector<Vertex_handle>().swap(m_input_vertices);
    m_input_indices.clear();
    std::vector<FT>().swap(m_spectrum);
    m_spectrum_ready = false;
  }
  /// @}

  /// \name Input points
  /// @{
  size_type number_of_input_points() const { return m_input_vertices.size(); }

  /// The vertex standing for input point `i`.
  /// \pre `i < number_of_input_points()`.
  Vertex_handle input_vertex(size_type i) const
  {
    CGAL_precondition(i < number_of_input_points());
    return m_input_vertices[i];
  }

  /// The indices of the input points that `v` stands for, increasing.
  Input_index_range input_indices(Vertex_handle v) const
  {
    CGAL_precondition(!this->is_infinite(v));
    return m_input_indices.of_vertex(v->vertex_index());
  }
  /// @}

  /// \name Local feature sizes
  /// @{

  /// The pole of `v`: the Voronoi vertex (circumcenter of a finite cell)
  /// farthest from `v` on the side opposite to `v`'s positive pole direction
  /// (the Amenta-Bern negative pole). On an unbounded Voronoi cell the
  /// positive direction is the mean outward normal of the incident convex hull
  /// facets. When no Voronoi vertex lies on the opposite side, the farthest
  /// Voronoi vertex.
  Point pole(Vertex_handle v) const
  {
    const Cell_handle c = v->pole_cell();
    return this->geom_traits().construct_circumcenter_3_object()(
      c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point());
  }

  /// The local feature size `alpha_p+` of `v` (an estimate of the distance to
  /// the medial axis): its distance to `pole(v)`, floored at 4 sample spacings by
  /// default (see `Conformal_alpha_shapes_3::Local_feature_size_estimator`: under
  /// radial noise above the local sagitta, about spacing^2 / (8R), the bare
  /// pole distance collapses for points displaced inwards), or the size
  /// supplied by the caller.
  FT local_feature_size(Vertex_handle v) const { return v->local_feature_size(); }
  /// @}

  /// \name Values
  /// Conformal values of finite simplices; infinite ones get `+infinity`, and
  /// so do the finite facets whose radius is beyond `double`'s range (far,
  /// nearly collinear hull facets).
  /// @{
  FT conformal_alpha(Vertex_handle v) const
  { return this->is_infinite(v) ? infinity() : FT(0); }

  FT conformal_alpha(Cell_handle c) const
  { return this->is_infinite(c) ? infinity() : c->alpha() / min_local_feature_size(c); }

  FT conformal_alpha(const Facet& f) const { return conformal_alpha(f.first, f.second); }
  FT conformal_alpha(Cell_handle c, int i) const
  { return this->is_infinite(c, i) ? infinity() : ordinary_alpha(c, i) / min_local_feature_size(c, i); }

  FT conformal_alpha(const Edge& e) const { return conformal_alpha(e.first, e.second, e.third); }
  FT conformal_alpha(Cell_handle c, int i, int j) const
  {
    return this->is_infinite(c, i, j) ? infinity() : Conformal_alpha_shapes_3::internal::edge_status(*this, c, i, j).own;
  }

  /// The ordinary alpha value (a radius) of a finite cell, facet or edge.
  FT ordinary_alpha(Cell_handle c) const { return c->alpha(); }
  FT ordinary_alpha(const Facet& f) const { return ordinary_alpha(f.first, f.second); }
  FT ordinary_alpha(Cell_handle c, int i) const
  {
    const Cell_handle n = c->neighbor(i);
    // a hull facet is measured from its finite cell, in the vertex order
    // that constructions_are_defined() checked (from the infinite cell the
    // kernel's determinant can be 0 in double where the checked one is not)
    if(this->is_infinite(c))
      return ordinary_alpha(n, n->index(c));
    if(c->encroaches_facet(i) || n->encroaches_facet(n->index(c)))
      return (std::min)(c->alpha(), n->alpha());
    // the radius in the order of the vertices' indices, so that a facet has
    // the same value in its last bits from either of its cells
    std::array<Vertex_handle, 3> v{{c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)}};
    std::sort(v.begin(), v.end(), [](Vertex_handle a, Vertex_handle b) { return a->vertex_index() < b->vertex_index(); });
    // the kernel's denominator (|pr x qr|^2 as a determinant), which its
    // assertions refuse at 0: a facet nearly collinear in double, of radius
    // +infinity, as the division by 0 gives where assertions are off
    const auto& p = v[0]->point();
    const auto& q = v[1]->point();
    const auto& r = v[2]->point();
    const double prx = p.x() - r.x(), pry = p.y() - r.y(), prz = p.z() - r.z();
    const double qrx = q.x() - r.x(), qry = q.y() - r.y(), qrz = q.z() - r.z();
    if(CGAL::determinant(prx, pry, prz, qrx, qry, qrz, pry * qrz - prz * qry, prz * qrx - prx * qrz,
                         prx * qry - pry * qrx) == 0)
      return infinity();
    const FT radius = std::sqrt(this->geom_traits().compute_squared_radius_3_object()(p, q, r));
    // a nearly collinear hull facet far out may have a radius beyond
    // double's range: +infinity, or NaN (infinity times 0) made +infinity,
    // so that every value stays ordered
    return std::isnan(radius) ? infinity() : radius;
  }
  FT ordinary_alpha(const Edge& e) const
  {
    return Conformal_alpha_shapes_3::internal::edge_ordinary_alpha(*this, e.first, e.first->vertex(e.second),
                                                                   e.first->vertex(e.third));
  }
  /// @}

  /// \name Classification
  /// @{
  /// Sets the scale used by the members without a scale argument; returns
  /// the previous one.
  /// \throws std::invalid_argument when `alpha` is negative or NaN.
  FT set_alpha(const FT& alpha)
  {
    check_alpha(alpha);
    FT previous = m_alpha;
    m_alpha = alpha;
    return previous;
  }
  const FT& get_alpha() const { return m_alpha; }

  Classification_type classify(Cell_handle c) const { return classify(c, m_alpha); }
  Classification_type classify(Cell_handle c, const FT& alpha) const
  { return conformal_alpha(c) <= alpha ? INTERIOR : EXTERIOR; }

  Classification_type classify(const Facet& f) const { return classify(f, m_alpha); }
  Classification_type classify(const Facet& f, const FT& alpha) const
  { return classify(f.first, f.second, alpha); }
  Classification_type classify(Cell_handle c, int i) const { return classify(c, i, m_alpha); }
  Classification_type classify(Cell_handle c, int i, const FT& alpha) const
  {
    if(this->is_infinite(c, i))
      return EXTERIOR;
    return classify(Conformal_alpha_shapes_3::internal::facet_status(*this, c, i), alpha);
  }

  Classification_type classify(const Edge& e) const { return classify(e, m_alpha); }
  Classification_type classify(const Edge& e, const FT& alpha) const
  { return classify(e.first, e.second, e.third, alpha); }
  Classification_type classify(Cell_handle c, int i, int j) const
  { return classify(c, i, j, m_alpha); }
  Classification_type classify(Cell_handle c, int i, int j, const FT& alpha) const
  {
    if(this->is_infinite(c, i, j))
      return EXTERIOR;
    return classify(Conformal_alpha_shapes_3::internal::edge_status(*this, c, i, j), alpha);
  }

  Classification_type classify(Vertex_handle v) const { return classify(v, m_alpha); }
  Classification_type classify(Vertex_handle v, const FT& alpha) const
  {
    if(this->is_infinite(v))
      return EXTERIOR;
    return classify(Conformal_alpha_shapes_3::internal::vertex_status(*this, v), alpha);
  }
  /// @}

  /// \name The spectrum
  /// The sorted distinct conformal values of all finite simplices (0 for the
  /// vertices included). Computed on first use; not thread-safe until then.
  /// @{
  Alpha_iterator alpha_begin() const { return spectrum().begin(); }
  Alpha_iterator alpha_end() const { return spectrum().end(); }
  size_type number_of_alphas() const { return spectrum().size(); }

  /// The `n`-th value of the spectrum, counting from 1 as `Alpha_shape_3`.
  const FT& get_nth_alpha(size_type n) const
  {
    CGAL_precondition(n > 0 && n <= number_of_alphas());
    return spectrum()[n - 1];
  }

  /// First value of the spectrum that is `>= alpha`.
  Alpha_iterator alpha_lower_bound(const FT& alpha) const
  { return std::lower_bound(alpha_begin(), alpha_end(), alpha); }
  /// First value of the spectrum that is `> alpha`.
  Alpha_iterator alpha_upper_bound(const FT& alpha) const
  { return std::upper_bound(alpha_begin(), alpha_end(), alpha); }

  /*!
  Writes the values of the finite facets that are `REGULAR` or `SINGULAR`
  for some scale (those whose own value is below the larger value of their
  two cells, or that lie on the convex hull), in no particular order: the
  "regular face alpha values" of the paper, on which `alpha_at_quantile()`
  reads its quantiles.
  */
  template <class OutputIterator>
  OutputIterator boundary_facet_alphas(OutputIterator out) const
  {
    for(const Facet& f : this->finite_facets())
    {
      const Conformal_alpha_shapes_3::internal::Critical_values<FT> s =
        Conformal_alpha_shapes_3::internal::facet_status(*this, f.first, f.second);
      if(s.own < s.max || s.on_hull)
        *out++ = s.own;
    }
    return out;
  }

  /*!
  The paper's "q of the range of regular facet values": the values written by
  `boundary_facet_alphas()`, sorted increasingly, read at rank
  `round(q * (n - 1))`.
  \throws std::invalid_argument when `q` is not in `[0, 1]` (NaN included),
  or when the shape is empty (`dimension() < 3`).
  */
  FT alpha_at_quantile(double q) const
  {
    if(!(q >= 0 && q <= 1))
      throw std::invalid_argument("Conformal_alpha_shape_3::alpha_at_quantile: the quantile "
                                  + std::to_string(q) + " is not in [0, 1]");
    if(this->dimension() != 3)
      throw std::invalid_argument("Conformal_alpha_shape_3::alpha_at_quantile: the shape is empty");
    std::vector<FT> values;
    values.reserve(this->number_of_finite_facets());
    boundary_facet_alphas(std::back_inserter(values));
    CGAL_assertion(!values.empty());  // a 3D triangulation has hull facets
    const auto nth = values.begin() + static_cast<std::ptrdiff_t>(
                       std::floor(q * double(values.size() - 1) + 0.5));
    std::nth_element(values.begin(), nth, values.end());
    return *nth;
  }
  /// @}

  /// \name Filtration and simplices
  /// @{

  /*!
  Writes every finite simplex once, as `std::pair<Simplex, FT>` (the simplex
  and its conformal value), in filtration order: by value, then by dimension,
  so that a face precedes its cofaces.
  */
  template <class OutputIterator>
  OutputIterator filtration_with_alpha_values(OutputIterator out) const
  {
    struct Entry { FT value; int dimension; Simplex simplex; };
    std::vector<Entry> entries;
    entries.reserve(this->number_of_vertices() + this->number_of_finite_edges()
                    + this->number_of_finite_facets() + this->number_of_finite_cells());
    for(Vertex_handle v : this->finite_vertex_handles())
      entries.push_back(Entry{FT(0), 0, Simplex(v)});
    for(const Edge& e : this->finite_edges())
      entries.push_back(Entry{conformal_alpha(e), 1, Simplex(e)});
    for(const Facet& f : this->finite_facets())
      entries.push_back(Entry{conformal_alpha(f), 2, Simplex(f)});
    for(Cell_handle c : this->finite_cell_handles())
      entries.push_back(Entry{conformal_alpha(c), 3, Simplex(c)});
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
      return a.value < b.value || (a.value == b.value && a.dimension < b.dimension);
    });
    for(const Entry& e : entries)
      *out++ = std::make_pair(e.simplex, e.value);
    return out;
  }

  /// Writes the finite cells of classification `type` at `alpha`.
  template <class OutputIterator>
  OutputIterator get_conformal_alpha_shape_cells(OutputIterator out, Classification_type type) const
  { return get_conformal_alpha_shape_cells(out, type, m_alpha); }
  template <class OutputIterator>
  OutputIterator get_conformal_alpha_shape_cells(OutputIterator out, Classification_type type,
                                                 const FT& alpha) const
  {
    return copy_classified(this->finite_cell_handles(), out, type, alpha);
  }

  /// Writes the finite facets of classification `type` at `alpha`, each once.
  template <class OutputIterator>
  OutputIterator get_conformal_alpha_shape_facets(OutputIterator out, Classification_type type) const
  { return get_conformal_alpha_shape_facets(out, type, m_alpha); }
  template <class OutputIterator>
  OutputIterator get_conformal_alpha_shape_facets(OutputIterator out, Classification_type type,
                                                  const FT& alpha) const
  {
    return copy_classified(this->finite_facets(), out, type, alpha);
  }

  /// Writes the finite edges of classification `type` at `alpha`, each once.
  template <class OutputIterator>
  OutputIterator get_conformal_alpha_shape_edges(OutputIterator out, Classification_type type) const
  { return get_conformal_alpha_shape_edges(out, type, m_alpha); }
  template <class OutputIterator>
  OutputIterator get_conformal_alpha_shape_edges(OutputIterator out, Classification_type type,
                                                 const FT& alpha) const
  {
    return copy_classified(this->finite_edges(), out, type, alpha);
  }

  /// Writes the finite vertices of classification `type` at `alpha`.
  template <class OutputIterator>
  OutputIterator get_conformal_alpha_shape_vertices(OutputIterator out, Classification_type type) const
  { return get_conformal_alpha_shape_vertices(out, type, m_alpha); }
  template <class OutputIterator>
  OutputIterator get_conformal_alpha_shape_vertices(OutputIterator out, Classification_type type,
                                                    const FT& alpha) const
  {
    return copy_classified(this->finite_vertex_handles(), out, type, alpha);
  }

  /// The number of connected components of the `INTERIOR` cells at `alpha`,
  /// two cells being connected when they share a facet.
  size_type number_of_solid_components() const { return number_of_solid_components(m_alpha); }
  size_type number_of_solid_components(const FT& alpha) const
  {
    std::vector<bool> seen(this->number_of_cells(), false);
    std::vector<Cell_handle> work;
    size_type components = 0;
    for(Cell_handle c : this->finite_cell_handles())
    {
      if(seen[c->cell_index()] || classify(c, alpha) != INTERIOR)
        continue;
      ++components;
      seen[c->cell_index()] = true;
      work.assign(1, c);
      Conformal_alpha_shapes_3::internal::flood_fill(
        work, Conformal_alpha_shapes_3::internal::Flood_order::depth_first, [&](Cell_handle d, auto&& reach) {
          for(int i = 0; i < 4; ++i)
          {
            const Cell_handle n = d->neighbor(i);
            if(!seen[n->cell_index()] && classify(n, alpha) == INTERIOR)
            {
              seen[n->cell_index()] = true;
              reach(n);
            }
          }
        });
    }
    return components;
  }
  /// @}

private:
  // the simplices of `range` (cells, facets, edges or vertices) of
  // classification `type` at `alpha`
  template <class Range, class OutputIterator>
  OutputIterator copy_classified(const Range& range, OutputIterator out, Classification_type type,
                                 const FT& alpha) const
  {
    for(const auto& simplex : range)
      if(classify(simplex, alpha) == type)
        *out++ = simplex;
    return out;
  }

  typedef Conformal_alpha_shapes_3::internal::Pole<Cell_handle> Pole;

  static FT infinity() { return std::numeric_limits<FT>::infinity(); }

  static void check_alpha(const FT& alpha)
  {
    if(!(alpha >= 0))
      throw std::invalid_argument("Conformal_alpha_shape_3: the scale alpha must be a number >= 0");
  }

  // The named parameter `local_feature_sizes`: a range, or an iterator to the first
  // size.
  template <class Scales>
  void set_caller_local_feature_sizes(const Scales& scales)
  {
    if constexpr(Conformal_alpha_shapes_3::internal::Is_range<Scales>::value)
    {
      if(size_type(std::distance(std::begin(scales), std::end(scales))) != m_input_vertices.size())
      {
        clear();
        throw std::invalid_argument("Conformal_alpha_shape_3: the range of local feature sizes is not as long as "
                                    "the input");
      }
      set_caller_local_feature_sizes(std::begin(scales));
    }
    else
    {
      Scales it = scales;
      for(Vertex_handle v : this->finite_vertex_handles())
        v->set_local_feature_size(infinity());
      for(size_type i = 0; i < m_input_vertices.size(); ++i, ++it)
      {
        const double s = CGAL::to_double(*it);
        if(!(std::isfinite(s) && s > 0))
        {
          clear();
          throw std::invalid_argument("Conformal_alpha_shape_3: local feature size of input point "
                                      + std::to_string(i) + " is not finite and positive");
        }
        Vertex_handle v = m_input_vertices[i];
        v->set_local_feature_size((std::min)(v->local_feature_size(), s));
      }
    }
  }

  Classification_type classify(const Conformal_alpha_shapes_3::internal::Critical_values<FT>& s, const FT& alpha) const
  {
    if(!s.on_hull && alpha >= s.max) return INTERIOR;
    if(alpha >= s.mid)               return REGULAR;
    if(alpha >= s.own)               return SINGULAR;
    return EXTERIOR;
  }

  FT min_local_feature_size(Cell_handle c) const
  {
    return (std::min)((std::min)(c->vertex(0)->local_feature_size(), c->vertex(1)->local_feature_size()),
                      (std::min)(c->vertex(2)->local_feature_size(), c->vertex(3)->local_feature_size()));
  }
  FT min_local_feature_size(Cell_handle c, int i) const
  {
    return (std::min)({c->vertex((i + 1) & 3)->local_feature_size(), c->vertex((i + 2) & 3)->local_feature_size(),
                       c->vertex((i + 3) & 3)->local_feature_size()});
  }

  const std::vector<FT>& spectrum() const
  {
    if(m_spectrum_ready)
      return m_spectrum;
    m_spectrum.clear();
    if(this->number_of_vertices() > 0)
      m_spectrum.push_back(FT(0));
    for(const Edge& e : this->finite_edges())
      m_spectrum.push_back(conformal_alpha(e));
    for(const Facet& f : this->finite_facets())
      m_spectrum.push_back(conformal_alpha(f));
    for(Cell_handle c : this->finite_cell_handles())
      m_spectrum.push_back(conformal_alpha(c));
    std::sort(m_spectrum.begin(), m_spectrum.end());
    m_spectrum.erase(std::unique(m_spectrum.begin(), m_spectrum.end()), m_spectrum.end());
    m_spectrum.shrink_to_fit();
    m_spectrum_ready = true;
    return m_spectrum;
  }

  // Inserts the points in an order that depends on the points alone,
  // remembering which vertex stands for which input point.
  template <class InputIterator>
  void insert_points(InputIterator first, InputIterator last)
  {
    namespace CAS3 = Conformal_alpha_shapes_3;
    clear();
    std::vector<Point> points(first, last);
    CAS3::internal::check_coordinates(points, "Conformal_alpha_shape_3: ", true);
    const std::vector<std::pair<Point, size_type> > order =
      CAS3::internal::order_free_insertion_order<Gt>(points);
    std::vector<Point>().swap(points);

    m_input_vertices.assign(order.size(), Vertex_handle());
    // the vertex index of each input point, kept beside its handle: the
    // table below reads them in input order, and reading them through the
    // handles was a cache miss each
    std::vector<size_type> vertex_index_of_input(order.size());
    Vertex_handle hint;
    CAS3::internal::Interruption_point interruption;
    for(const std::pair<Point, size_type>& p : order)
    {
      if(this->number_of_vertices() % 1024 == 0)
        interruption.throw_if_stopped();
      const size_type before = this->number_of_vertices();
      hint = Dt::insert(p.first, hint);
      if(this->number_of_vertices() > before)
        hint->set_vertex_index(before);
      m_input_vertices[p.second] = hint;
      vertex_index_of_input[p.second] = hint->vertex_index();
    }

    if(this->dimension() < 3)
    {
      const std::string why = "Conformal_alpha_shape_3: the " + std::to_string(order.size())
        + " input points (" + std::to_string(this->number_of_vertices())
        + " distinct) span dimension " + std::to_string(this->dimension())
        + "; a conformal alpha shape needs 4 points that are not coplanar";
      clear();
      throw std::invalid_argument(why);
    }
    m_input_indices.assign(vertex_index_of_input, this->number_of_vertices());
  }

  // Every cell, its index set to its place in the list.
  std::vector<Cell_handle> index_cells()
  {
    std::vector<Cell_handle> cells;
    cells.reserve(this->number_of_cells());
    for(Cell_handle c : this->all_cell_handles())
    {
      c->set_cell_index(cells.size());
      cells.push_back(c);
    }
    return cells;
  }

  FT m_alpha;
  std::vector<Vertex_handle> m_input_vertices;  // input index -> vertex
  Conformal_alpha_shapes_3::internal::Input_index_table m_input_indices;
  mutable std::vector<FT> m_spectrum;
  mutable bool m_spectrum_ready = false;
};

} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPE_3_H
