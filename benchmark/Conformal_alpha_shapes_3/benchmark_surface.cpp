// Time of suggest_scale and extract_surface with the solid boundary against the Delaunay
// build of the same points, and the share of the points on the surface.
//   benchmark_surface [--sizes 100000,1000000] [--csv FILE] [FILE...]
// Without FILE: noisy ellipsoids (0.01% and 0.1% radial noise) of the given
// sizes and the bundled bunny. FILE: any point file CGAL reads.
#include <CGAL/Conformal_alpha_shape_3.h>
#include <CGAL/Conformal_alpha_shapes_3/extract_surface.h>
#include <CGAL/Conformal_alpha_shapes_3/suggest_scale.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "cas3_benchmark.h"
#include "cas3_test_shapes.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Triangulation_data_structure_3<CGAL::Conformal_alpha_shape_vertex_base_3<K>,
                                             CGAL::Conformal_alpha_shape_cell_base_3<K> > Tds;
typedef CGAL::Conformal_alpha_shape_3<CGAL::Delaunay_triangulation_3<K, Tds> > Cas;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;

void run(const std::string& name, const std::vector<Point>& pts, std::ofstream& csv)
{
  double dt_seconds = 0;
  {
    cas3_benchmark::Phase phase;
    CGAL::Delaunay_triangulation_3<K> dt(pts.begin(), pts.end());
    dt_seconds = phase.seconds();
  }
  cas3_benchmark::Phase build;
  const Cas cas(pts.begin(), pts.end());
  const double build_seconds = build.seconds();
  cas3_benchmark::Phase search;
  const auto solid = CAS3::parameters::surface_extraction(CAS3::SOLID_BOUNDARY);
  const double suggested = CAS3::suggest_scale(cas, solid);
  const double search_seconds = search.seconds();
  std::printf("%s: %zu points, Delaunay %.3f s, conformal shape %.3f s (%.2fx), suggest_scale %.3f s (%.2fx)\n",
              name.c_str(), pts.size(), dt_seconds, build_seconds, build_seconds / dt_seconds, search_seconds,
              search_seconds / dt_seconds);
  std::printf("  %-10s %12s %10s %10s %9s %9s %8s\n", "scale", "a", "extract s", "x Delaunay", "faces",
              "on surf.", "pinched");
  struct Scale { std::string label; double alpha; };
  std::vector<Scale> scales = {{"suggested", suggested}};
  for(double q : {0.10, 0.25, 0.35, 0.50})
    scales.push_back({std::to_string(int(100 * q + 0.5)) + "%", cas.alpha_at_quantile(q)});
  for(const Scale& s : scales)
  {
    Mesh mesh;
    cas3_benchmark::Phase extract;
    const CAS3::Surface_report r = CAS3::extract_surface(cas, s.alpha, mesh, solid);
    const double seconds = extract.seconds();
    std::printf("  %-10s %12.5g %10.3f %10.2f %9zu %8.2f%% %8zu\n", s.label.c_str(), s.alpha, seconds,
                seconds / dt_seconds, r.number_of_faces, 100 * r.fraction_of_points_on_surface(),
                r.number_of_pinched_vertices);
    csv << cas3_benchmark::csv_field(name) << ',' << pts.size() << ',' << dt_seconds << ',' << build_seconds << ','
        << search_seconds << ',' << s.label << ',' << s.alpha << ',' << seconds << ',' << r.number_of_faces << ','
        << r.fraction_of_points_on_surface() << ',' << r.number_of_pinched_vertices << std::endl;
  }
  std::fflush(stdout);
}

int main(int argc, char* argv[])
{
  const cas3_benchmark::Arguments args = cas3_benchmark::parse_arguments(argc, argv);
  std::ofstream csv = cas3_benchmark::open_csv(args.csv, argc, argv,
                                               "input,n,delaunay_s,conformal_s,suggest_scale_s,scale,alpha,"
                                               "extract_s,faces,fraction_on_surface,pinched_vertices");
  for(std::size_t n : args.sizes)
    for(double noise : {1e-4, 1e-3})
      run("ellipsoid 1:0.7:0.4, " + std::to_string(noise * 100).substr(0, 4) + "% noise",
          cas3_test::ellipsoid_sample<Point>(n, 1, 0.7, 0.4, noise), csv);
  return cas3_benchmark::for_each_point_file<Point>(
           args.files, [&](const std::string& name, const std::vector<Point>& pts) { run(name, pts, csv); })
           ? EXIT_SUCCESS
           : EXIT_FAILURE;
}
