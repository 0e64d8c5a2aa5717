// Accuracy and speed of estimate_vertex_curvatures.
//   benchmark_curvature [--vertices N] [--csv FILE]
// Accuracy: median and 90th percentile relative error of H and K per surface,
// ring size and estimator, on clean meshes and with Gaussian noise of 0.1 mean
// edge length along the normal, beside CGAL's Monge_via_jet_fitting (degree
// 2 and 3) on the same k-ring vertices. Speed: time per vertex, against the
// Delaunay build of the mesh's vertices.
#include <CGAL/Conformal_alpha_shapes_3/estimate_vertex_curvatures.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Surface_mesh.h>

#include "cas3_benchmark.h"
#include "cas3_test_meshes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;

// A test surface: a mesh with the exact normal, H and K at each vertex.
typedef cas3_test::Mesh_with_truth<Mesh, Vector> Surface;

Surface ellipsoid(std::size_t n, double a, double b, double c)
{
  return cas3_test::irregular_ellipsoid_with_truth<Mesh, Point, Vector>(n, a, b, c);
}

Surface torus(std::size_t nu, std::size_t nv, double R, double r)
{
  return cas3_test::jittered_torus_with_truth<Mesh, Point, Vector>(nu, nv, R, r);
}

// Moves every vertex along its exact normal by Gaussian noise of `sigma`
// times the mean edge length.
void add_noise(Surface& s, double sigma)
{
  double mean_edge = 0;
  for(auto e : s.mesh.edges())
    mean_edge += std::sqrt(CGAL::squared_distance(s.mesh.point(s.mesh.vertex(e, 0)), s.mesh.point(s.mesh.vertex(e, 1))));
  mean_edge /= double(s.mesh.number_of_edges());
  std::mt19937 gen(11);
  std::normal_distribution<double> gauss(0.0, sigma * mean_edge);
  for(Vertex v : s.mesh.vertices())
    s.mesh.point(v) = s.mesh.point(v) + gauss(gen) * s.normal[v.idx()];
}

typedef cas3_test::Curvature_errors Errors;

Errors errors(const Surface& s, const std::vector<double>& H, const std::vector<double>& K)
{
  return cas3_test::curvature_errors(s, H, K);
}

Errors ours(const Surface& s, int rings, CAS3::Curvature_estimator e)
{
  auto h = get(CGAL::dynamic_vertex_property_t<double>(), s.mesh);
  auto k = get(CGAL::dynamic_vertex_property_t<double>(), s.mesh);
  CAS3::estimate_vertex_curvatures(s.mesh, CAS3::parameters::vertex_mean_curvature_map(h,
                                     CAS3::parameters::vertex_Gaussian_curvature_map(k,
                                     CAS3::parameters::ring_size(rings, CAS3::parameters::estimator(e)))));
  std::vector<double> H, Kv;
  for(Vertex v : s.mesh.vertices()) { H.push_back(get(h, v)); Kv.push_back(get(k, v)); }
  return errors(s, H, Kv);
}

Errors jet(const Surface& s, int rings, int degree)
{
  typedef CGAL::Monge_via_jet_fitting<K> Fitting;
  std::vector<double> H, Kv;
  const CAS3::internal::Vertex_graph graph =
    CAS3::internal::vertex_graph(s.mesh, s.mesh.points(), get(CGAL::vertex_index, s.mesh));
  CAS3::internal::Nested_neighborhood_search search(graph.size());
  for(Vertex v : s.mesh.vertices())
  {
    search.rings(graph, v.idx(), std::size_t(rings));
    std::vector<Point> pts = {s.mesh.point(v)};
    for(std::size_t u : search.vertices()) pts.push_back(s.mesh.point(Vertex(u)));
    if(pts.size() < std::size_t((degree + 1) * (degree + 2) / 2))
    {
      H.push_back(NAN); Kv.push_back(NAN);
      continue;
    }
    Fitting fit;
    Fitting::Monge_form form = fit(pts.begin(), pts.end(), degree, 2);
    form.comply_wrt_given_normal(s.normal[v.idx()]);
    // CGAL's Monge form counts curvature positive towards the normal
    const double k1 = -form.principal_curvatures(0), k2 = -form.principal_curvatures(1);
    H.push_back((k1 + k2) / 2);
    Kv.push_back(k1 * k2);
  }
  return errors(s, H, Kv);
}

// One row of the accuracy table, printed and written to `csv`.
void print(std::ofstream& csv, const char* surface, const char* method, int rings, const Errors& e)
{
  std::printf("| %-16s | %-22s | %d | %6.2f%% | %7.2f%% | %7.2f%% | %8.2f%% |\n", surface, method, rings,
              100 * e.h50, 100 * e.h90, 100 * e.k50, 100 * e.k90);
  csv << "accuracy," << cas3_benchmark::csv_field(surface) << ',' << cas3_benchmark::csv_field(method) << ','
      << rings << ",," << e.h50 << ',' << e.h90 << ',' << e.k50 << ',' << e.k90 << ",,\n";
}

int main(int argc, char* argv[])
{
  std::size_t n = 20000;
  std::string csv_path;
  for(int i = 1; i + 1 < argc; ++i)
    if(std::string(argv[i]) == "--vertices") n = std::stoul(argv[++i]);
    else if(std::string(argv[i]) == "--csv") csv_path = argv[++i];
  std::ofstream csv = cas3_benchmark::open_csv(csv_path, argc, argv,
                                               "measure,surface,method,rings,vertices,H_median,H_p90,K_median,"
                                               "K_p90,seconds,x_delaunay");

  const char* names[] = {"paper Euler fit", "Euler least squares", "quadric fit"};
  std::printf("| surface | method | rings | H median | H 90th | K median | K 90th |\n|---|---|---|---|---|---|---|\n");
  for(int noisy = 0; noisy < 2; ++noisy)
  {
    std::vector<Surface> surfaces;
    surfaces.push_back(ellipsoid(5000, 1.0, 0.8, 0.5));
    surfaces.push_back(torus(160, 60, 1.0, 0.35));
    for(Surface& s : surfaces)
    {
      if(noisy) { add_noise(s, 0.1); s.name += " +noise"; }
      for(int rings = 1; rings <= 7; ++rings)
        for(CAS3::Curvature_estimator e : {CAS3::PAPER_EULER_FIT, CAS3::EULER_LEAST_SQUARES_FIT, CAS3::QUADRIC_FIT})
          print(csv, s.name.c_str(), names[e], rings, ours(s, rings, e));
      for(int rings = 2; rings <= 7; ++rings)
        for(int degree : {2, 3})
          print(csv, s.name.c_str(), degree == 2 ? "jet fitting, degree 2" : "jet fitting, degree 3", rings,
                jet(s, rings, degree));
    }
  }

  // speed on an irregular sphere mesh of n vertices
  Mesh mesh;
  cas3_test::irregular_sphere<Mesh, Point>(n, 1.0, mesh);
  std::vector<Point> pts(mesh.points().begin(), mesh.points().end());
  double dt_seconds;
  {
    cas3_benchmark::Phase phase;
    CGAL::Delaunay_triangulation_3<K> dt(pts.begin(), pts.end());
    dt_seconds = phase.seconds();
  }
  auto h = mesh.add_property_map<Vertex, double>("v:H").first;
  std::printf("\nspeed, %zu vertices; Delaunay build of the same points %.3f s\n", std::size_t(mesh.number_of_vertices()),
              dt_seconds);
  for(int rings = 1; rings <= 3; ++rings)
    for(CAS3::Curvature_estimator e : {CAS3::PAPER_EULER_FIT, CAS3::EULER_LEAST_SQUARES_FIT, CAS3::QUADRIC_FIT})
    {
      cas3_benchmark::Phase phase;
      CAS3::estimate_vertex_curvatures(mesh, CAS3::parameters::vertex_mean_curvature_map(h,
                                         CAS3::parameters::ring_size(rings, CAS3::parameters::estimator(e))));
      const double s = phase.seconds();
      std::printf("%-20s rings %d: %.3f s, %.2f us per vertex, %.2fx the Delaunay build\n", names[e], rings, s,
                  1e6 * s / double(mesh.number_of_vertices()), s / dt_seconds);
      csv << "speed,irregular sphere," << names[e] << ',' << rings << ',' << mesh.number_of_vertices() << ",,,,,"
          << s << ',' << s / dt_seconds << '\n';
    }
  return 0;
}
