// Triangle meshes of analytic surfaces, built into any MutableFaceGraph.
#ifndef CAS3_TEST_MESHES_H
#define CAS3_TEST_MESHES_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace cas3_test {

template <class Mesh, class Point>
void soup_to_mesh(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 3> >& faces,
                  Mesh& mesh)
{
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, mesh);
}

// Icosahedron subdivided `levels` times, projected on the sphere of radius r.
template <class Mesh, class Point>
void icosphere(int levels, double r, Mesh& mesh)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3> > v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::size_t, 3> > f = {
    {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
    {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
    {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for(int l = 0; l < levels; ++l)
  {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
    auto middle = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if(it != mid.end()) return it->second;
      v.push_back({(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2});
      return mid[key] = v.size() - 1;
    };
    std::vector<std::array<std::size_t, 3> > g;
    for(const auto& tri : f)
    {
      const std::size_t a = middle(tri[0], tri[1]), b = middle(tri[1], tri[2]), c = middle(tri[2], tri[0]);
      g.push_back({tri[0], a, c}); g.push_back({tri[1], b, a});
      g.push_back({tri[2], c, b}); g.push_back({a, b, c});
    }
    f.swap(g);
  }
  std::vector<Point> pts;
  for(const auto& p : v)
  {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    pts.push_back(Point(r * p[0] / n, r * p[1] / n, r * p[2] / n));
  }
  soup_to_mesh(pts, f, mesh);
}

// The convex hull of random points on the sphere: an irregular Delaunay-like
// triangulation of the sphere, outward oriented.
template <class Mesh, class Point>
void irregular_sphere(std::size_t n, double r, Mesh& mesh, unsigned seed = 5)
{
  std::mt19937 gen(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Point> pts;
  for(std::size_t i = 0; i < n; ++i)
  {
    double x = gauss(gen), y = gauss(gen), z = gauss(gen);
    const double len = std::sqrt(x * x + y * y + z * z);
    pts.push_back(Point(r * x / len, r * y / len, r * z / len));
  }
  CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
}

// A parametric surface over a grid of nu x nv samples of [0,1]^2, with the
// parameters jittered by `jitter` cells (interior samples only when a
// direction is open), triangulated along alternating diagonals. `closed_u`
// and `closed_v` glue the last column/row to the first.
template <class Mesh, class Point>
void parametric_grid(std::size_t nu, std::size_t nv, bool closed_u, bool closed_v, double jitter,
                     const std::function<Point(double, double)>& surface, Mesh& mesh, unsigned seed = 9)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-jitter, jitter);
  const std::size_t cu = closed_u ? nu : nu - 1, cv = closed_v ? nv : nv - 1;
  std::vector<Point> pts;
  for(std::size_t j = 0; j < nv; ++j)
    for(std::size_t i = 0; i < nu; ++i)
    {
      const bool border_u = !closed_u && (i == 0 || i + 1 == nu);
      const bool border_v = !closed_v && (j == 0 || j + 1 == nv);
      const double u = (double(i) + (border_u ? 0 : d(gen))) / double(cu);
      const double v = (double(j) + (border_v ? 0 : d(gen))) / double(cv);
      pts.push_back(surface(u, v));
    }
  std::vector<std::array<std::size_t, 3> > faces;
  for(std::size_t j = 0; j < cv; ++j)
    for(std::size_t i = 0; i < cu; ++i)
    {
      const std::size_t i1 = (i + 1) % nu, j1 = (j + 1) % nv;
      const std::size_t a = j * nu + i, b = j * nu + i1, c = j1 * nu + i1, e = j1 * nu + i;
      if((i + j) % 2 == 0) { faces.push_back({a, b, c}); faces.push_back({a, c, e}); }
      else                 { faces.push_back({a, b, e}); faces.push_back({b, c, e}); }
    }
  soup_to_mesh(pts, faces, mesh);
}

// A mesh of an analytic surface with the exact outward normal, H and K at
// each vertex, in vertex order: the meshes of the manual's "Measured
// Accuracy" table (benchmark_curvature, and a test).
template <class Mesh, class Vector>
struct Mesh_with_truth
{
  std::string name;
  Mesh mesh;
  std::vector<Vector> normal;
  std::vector<double> H, K;
};

// The irregular sphere of `n` vertices (`irregular_sphere()`) stretched into
// the ellipsoid with semi-axes a, b, c.
template <class Mesh, class Point, class Vector>
Mesh_with_truth<Mesh, Vector> irregular_ellipsoid_with_truth(std::size_t n, double a, double b, double c)
{
  Mesh_with_truth<Mesh, Vector> s;
  s.name = "ellipsoid " + std::to_string(int(a * 10)) + ":" + std::to_string(int(b * 10)) + ":" +
           std::to_string(int(c * 10));
  irregular_sphere<Mesh, Point>(n, 1.0, s.mesh);
  for(auto v : vertices(s.mesh))
  {
    const Point q = get(CGAL::vertex_point, s.mesh, v);
    const Point p(a * q.x(), b * q.y(), c * q.z());
    put(CGAL::vertex_point, s.mesh, v, p);
    const double x = p.x(), y = p.y(), z = p.z();
    const double h = std::sqrt(x * x / std::pow(a, 4) + y * y / std::pow(b, 4) + z * z / std::pow(c, 4));
    const double abc2 = a * a * b * b * c * c;
    s.normal.push_back(Vector(x / (a * a * h), y / (b * b * h), z / (c * c * h)));
    s.K.push_back(1 / (abc2 * std::pow(h, 4)));
    s.H.push_back(std::abs(x * x + y * y + z * z - a * a - b * b - c * c) / (2 * abc2 * std::pow(h, 3)));
  }
  return s;
}

// The torus with radii R > r on a `nu` x `nv` grid whose parameters are
// jittered by 0.3 cells (`parametric_grid()`).
template <class Mesh, class Point, class Vector>
Mesh_with_truth<Mesh, Vector> jittered_torus_with_truth(std::size_t nu, std::size_t nv, double R, double r)
{
  Mesh_with_truth<Mesh, Vector> s;
  s.name = "torus 1:0.35";
  parametric_grid<Mesh, Point>(nu, nv, true, true, 0.3, [&](double u, double v) {
    const double a = 2 * M_PI * u, b = 2 * M_PI * v;
    return Point((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b));
  }, s.mesh);
  for(auto v : vertices(s.mesh))
  {
    const Point p = get(CGAL::vertex_point, s.mesh, v);
    const double rho = std::sqrt(p.x() * p.x() + p.y() * p.y());
    const double t = std::atan2(p.z(), rho - R);
    const double k1 = 1 / r, k2 = std::cos(t) / (R + r * std::cos(t));
    s.normal.push_back(Vector(std::cos(t) * p.x() / rho, std::cos(t) * p.y() / rho, std::sin(t)));
    s.H.push_back((k1 + k2) / 2);
    s.K.push_back(k1 * k2);
  }
  return s;
}

// Median and 90th percentile of the relative errors of H and K (relative to
// the larger of the value and the surface's largest curvature scale there,
// so that K near 0 on the torus does not blow up; NaN counts as a huge error).
struct Curvature_errors { double h50, h90, k50, k90; };

template <class MeshWithTruth>
Curvature_errors curvature_errors(const MeshWithTruth& s, const std::vector<double>& H, const std::vector<double>& K)
{
  std::vector<double> eh, ek;
  for(std::size_t i = 0; i < H.size(); ++i)
  {
    const double kmax = std::abs(s.H[i]) + std::sqrt((std::max)(0.0, s.H[i] * s.H[i] - s.K[i]));
    eh.push_back(std::isfinite(H[i]) ? std::abs(H[i] - s.H[i]) / (std::max)(std::abs(s.H[i]), 0.5 * kmax) : 1e9);
    ek.push_back(std::isfinite(K[i]) ? std::abs(K[i] - s.K[i]) / (std::max)(std::abs(s.K[i]), 0.25 * kmax * kmax) : 1e9);
  }
  auto quantile = [](std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    return v.empty() ? NAN : v[std::size_t(q * double(v.size() - 1))];
  };
  return {quantile(eh, 0.5), quantile(eh, 0.9), quantile(ek, 0.5), quantile(ek, 0.9)};
}

// Removes the faces of `surface` (a Surface_mesh) with a vertex above
// height `z`: a cap cut off, so that the points under it are off the surface.
template <class SurfaceMesh>
void remove_cap_above(SurfaceMesh& surface, double z)
{
  std::vector<typename SurfaceMesh::Face_index> cap;
  for(auto f : surface.faces())
    for(auto v : CGAL::vertices_around_face(surface.halfedge(f), surface))
      if(surface.point(v).z() > z)
      {
        cap.push_back(f);
        break;
      }
  for(auto f : cap)
    CGAL::Euler::remove_face(surface.halfedge(f), surface);
  surface.collect_garbage();
}

} // namespace cas3_test

#endif // CAS3_TEST_MESHES_H
