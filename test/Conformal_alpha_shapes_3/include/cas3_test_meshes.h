// Triangle meshes of analytic surfaces, built into any MutableFaceGraph.
#ifndef CAS3_TEST_MESHES_H
#define CAS3_TEST_MESHES_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <random>
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

} // namespace cas3_test

#endif // CAS3_TEST_MESHES_H
