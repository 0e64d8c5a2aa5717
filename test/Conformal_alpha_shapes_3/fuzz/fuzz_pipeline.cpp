// libFuzzer target: the whole pipeline on small clouds. The bytes become at
// most 60 points: in mode 0 (first byte even) each point is 3 raw doubles
// (NaN, infinities, 1e300 and subnormals included); in mode 1 each point is
// 3 signed bytes on a small grid, times a scale 2^(s - 64) read from the
// second byte (duplicates, coplanar and cospherical sets are common). Then:
// input hygiene, the conformal alpha shape, the automatic scale and a
// quantile, surface extraction (the advancing front of
// Multiscale_curvatures and the solid boundary of extract_surface()) and
// curvature at 1 and 2 rings, 4 spacings and the automatic radius.
//
// What is asserted for every input accepted (see check_surface() and
// check_values()): each surface is a valid, consistently oriented triangle
// mesh without a face repeating an input point, whose vertices name input
// points (not outliers), with the report's counts; the solid boundary is
// closed; every point value that is not NO_VALUE, and every surface vertex
// value that is defined, has a unit normal, k1 >= k2, H = (k1 + k2) / 2,
// K = k1 k2 and a positive radius, all finite; outliers get NO_VALUE. The
// only exception allowed is the documented std::invalid_argument, and an
// input with a NaN or infinite coordinate must raise it. A failed check
// prints what failed and aborts, which libFuzzer reports as a crash.
#include <CGAL/Conformal_alpha_shapes_3/extract_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
typedef CAS3::Multiscale_curvatures<K> Analysis;
typedef Analysis::Surface Surface;

namespace {

[[noreturn]] void fail(const char* what, const char* where)
{
  std::fprintf(stderr, "fuzz_pipeline: %s (%s)\n", what, where);
  std::abort();
}

#define CHECK(condition, where) \
  do { if(!(condition)) fail(#condition, where); } while(false)

// Finite values are asserted only where the input's units can hold them: in
// mode 0, a coordinate beyond 1e100 or below 1e-100 in magnitude may take a
// length or a curvature out of double's range on the way back to input units
// (Multiscale_curvatures computes in a normalized frame; its documentation
// says that at extreme scales the Gaussian curvature may fall out of range).
bool in_representable_range(const std::vector<Point>& points)
{
  for(const Point& p : points)
    for(int d = 0; d < 3; ++d)
    {
      const double x = std::abs(p[d]);
      if(x != 0 && !(x >= 1e-100 && x <= 1e100))
        return false;
    }
  return true;
}

bool is_unit(const Vector& n)
{
  return std::isfinite(n.x()) && std::isfinite(n.y()) && std::isfinite(n.z())
         && std::abs(std::sqrt(n.squared_length()) - 1) <= 1e-6;
}

// The curvature values of one point or vertex: what every defined value
// satisfies by the definitions of Vertex_curvature and Point_curvature.
// `what` names the value (which point, which source) in the message.
void check_values(const Vector& normal, double k1, double k2, double H, double Kg, double radius, bool finite,
                  const char* where, const std::string& what)
{
  bool ok = !std::isnan(k1) && !std::isnan(k2) && !std::isnan(radius) && is_unit(normal) && k1 >= k2 && radius >= 0;
  // H and K are computed from k1 and k2, possibly in another frame
  if(ok && finite)
    ok = std::isfinite(k1) && std::isfinite(k2) && std::isfinite(H) && std::isfinite(Kg) && std::isfinite(radius)
         && radius > 0 && std::abs(H - (k1 + k2) / 2) <= 1e-9 * (std::abs(k1) + std::abs(k2))
         && std::abs(Kg - k1 * k2) <= 1e-9 * std::abs(k1 * k2) + 1e-300;
  if(ok)
    return;
  std::fprintf(stderr, "fuzz_pipeline: %s, %s: normal (%.17g %.17g %.17g) k1 %.17g k2 %.17g H %.17g K %.17g radius %.17g\n",
               where, what.c_str(), normal.x(), normal.y(), normal.z(), k1, k2, H, Kg, radius);
  std::abort();
}

// A surface as extract_surface() documents it: a valid triangle mesh, each
// edge's halfedges running in opposite directions (one orientation per
// sheet), no face with two corners on one input point, every vertex an
// input point (`number_of_points` of them) that is not an outlier.
template <class IsOutlier>
void check_surface(const Surface& surface, const CAS3::Surface_report& report, std::size_t number_of_points,
                   const IsOutlier& is_outlier, const char* where)
{
  typedef boost::graph_traits<Surface>::halfedge_descriptor halfedge_descriptor;
  CHECK(CGAL::is_valid_polygon_mesh(surface), where);
  CHECK(CGAL::is_empty(surface) || CGAL::is_triangle_mesh(surface), where);
  CHECK(report.number_of_faces == surface.number_of_faces(), where);
  CHECK(report.number_of_vertices == surface.number_of_vertices(), where);
  CHECK(report.empty() == (surface.number_of_faces() == 0), where);
  CHECK(report.number_of_closed_parts <= report.number_of_parts, where);
  CHECK(report.number_of_points_off_surface <= report.number_of_input_points, where);
  CHECK(report.number_of_input_points == number_of_points, where);
  for(const auto e : surface.edges())
  {
    const halfedge_descriptor h = surface.halfedge(e), o = surface.opposite(h);
    CHECK(surface.source(h) == surface.target(o) && surface.target(h) == surface.source(o), where);
    CHECK(surface.source(h) != surface.target(h), where);
  }
  const auto input_index = surface.property_map<Analysis::Surface_vertex, std::size_t>("v:input_index");
  CHECK(input_index.second, where);
  for(const Analysis::Surface_vertex v : surface.vertices())
  {
    CHECK(input_index.first[v] < number_of_points, where);
    CHECK(!is_outlier(input_index.first[v]), where);
  }
  for(const auto f : surface.faces())
  {
    std::set<Analysis::Surface_vertex> corners;
    std::set<std::size_t> indices;
    for(const Analysis::Surface_vertex v : vertices_around_face(surface.halfedge(f), surface))
    {
      corners.insert(v);
      indices.insert(input_index.first[v]);
    }
    CHECK(corners.size() == 3 && indices.size() == 3, where);
  }
}

bool has_non_finite_coordinate(const std::vector<Point>& points)
{
  for(const Point& p : points)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return true;
  return false;
}

void run(const std::vector<Point>& points, bool finite)
{
  const Analysis analysis(points.begin(), points.end());
  CHECK(!has_non_finite_coordinate(points), "a NaN or infinite coordinate accepted");
  CHECK(analysis.number_of_input_points() == points.size(), "construction");
  const auto is_outlier = [&](std::size_t i) { return analysis.is_outlier(i); };
  for(const CAS3::Scale& scale : {CAS3::Scale::automatic(), CAS3::Scale::quantile(0.5)})
  {
    const double a = analysis.scale_value(scale);
    Surface surface;
    const CAS3::Surface_report report = analysis.surface(a, surface);
    check_surface(surface, report, points.size(), is_outlier, "advancing front");
    if(finite)
      for(const Analysis::Surface_vertex v : surface.vertices())
        CHECK(std::isfinite(surface.point(v).x()) && std::isfinite(surface.point(v).y())
                && std::isfinite(surface.point(v).z()), "advancing front: vertex position");

    // the solid boundary, in the shape's frame and indices
    Surface solid;
    auto solid_index = solid.add_property_map<Analysis::Surface_vertex, std::size_t>("v:input_index").first;
    const CAS3::Surface_report solid_report = CAS3::extract_surface(
      analysis.shape(), a, solid,
      CAS3::parameters::surface_extraction(CAS3::SOLID_BOUNDARY, CAS3::parameters::vertex_input_index_map(solid_index)));
    check_surface(solid, solid_report, analysis.shape().number_of_input_points(),
                  [](std::size_t) { return false; }, "solid boundary");
    CHECK(CGAL::is_closed(solid), "solid boundary: closed");

    for(const CAS3::Neighborhood& neighborhood : {CAS3::Neighborhood::rings(1), CAS3::Neighborhood::rings(2),
                                                  CAS3::Neighborhood::spacings(4), CAS3::Neighborhood::automatic()})
    {
      const std::vector<CAS3::Point_curvature<K> > curvatures =
        analysis.estimate_curvatures(surface, {neighborhood}).front();
      CHECK(curvatures.size() == points.size(), "point values");
      for(std::size_t i = 0; i < curvatures.size(); ++i)
      {
        const CAS3::Point_curvature<K>& c = curvatures[i];
        if(analysis.is_outlier(i))
          CHECK(c.source == CAS3::NO_VALUE, "point values: outlier");
        if(c.source == CAS3::NO_VALUE)
          continue;
        CHECK(!surface.is_empty(), "point values: a value without a surface");
        check_values(c.normal, c.principal.max_curvature, c.principal.min_curvature, c.mean_curvature,
                     c.gaussian_curvature, c.radius, finite, "point values",
                     "scale " + std::to_string(int(scale.kind())) + " a " + std::to_string(a) + ", neighborhood "
                       + std::to_string(int(neighborhood.kind())) + " " + std::to_string(neighborhood.value()) + ", point "
                       + std::to_string(i) + " of " + std::to_string(points.size()) + ", source "
                       + std::to_string(int(c.source)) + ", distance " + std::to_string(c.distance) + ", surface of "
                       + std::to_string(surface.number_of_faces()) + " faces");
        CHECK(c.source != CAS3::SURFACE_VERTEX || c.distance == 0, "point values: distance");
        CHECK(c.distance >= 0, "point values: distance");
      }
      // the surface's properties hold the same neighborhood's vertex values
      const auto normal = surface.property_map<Analysis::Surface_vertex, Vector>("v:normal");
      const auto mean = surface.property_map<Analysis::Surface_vertex, double>("v:mean_curvature");
      const auto gaussian = surface.property_map<Analysis::Surface_vertex, double>("v:gaussian_curvature");
      const auto k1 = surface.property_map<Analysis::Surface_vertex, double>("v:k1");
      const auto k2 = surface.property_map<Analysis::Surface_vertex, double>("v:k2");
      const auto radius = surface.property_map<Analysis::Surface_vertex, double>("v:radius");
      CHECK(normal.second && mean.second && gaussian.second && k1.second && k2.second && radius.second,
            "vertex values: properties");
      for(const Analysis::Surface_vertex v : surface.vertices())
        if(std::isfinite(k1.first[v]) && std::isfinite(k2.first[v]))  // defined
          check_values(normal.first[v], k1.first[v], k2.first[v], mean.first[v], gaussian.first[v],
                       radius.first[v], finite, "vertex values", "vertex " + std::to_string(std::size_t(v)));
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 2)
    return 0;
  std::vector<Point> points;
  const bool raw = data[0] % 2 == 0;
  if(raw)
  {
    for(std::size_t at = 1; at + 24 <= size && points.size() < 60; at += 24)
    {
      double c[3];
      std::memcpy(c, data + at, 24);
      points.emplace_back(c[0], c[1], c[2]);
    }
  }
  else
  {
    const double scale = std::ldexp(1.0, int(data[1]) - 64);
    for(std::size_t at = 2; at + 3 <= size && points.size() < 60; at += 3)
      points.emplace_back(scale * static_cast<std::int8_t>(data[at]), scale * static_cast<std::int8_t>(data[at + 1]),
                          scale * static_cast<std::int8_t>(data[at + 2]));
  }
  try
  {
    run(points, !raw || in_representable_range(points));
  }
  catch(const std::invalid_argument& e)
  {
    CHECK(std::strlen(e.what()) > 0, "an empty message");
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "fuzz_pipeline: exception other than std::invalid_argument: %s\n", e.what());
    std::abort();
  }
  catch(...)
  {
    fail("an exception not derived from std::exception", "pipeline");
  }
  return 0;
}
