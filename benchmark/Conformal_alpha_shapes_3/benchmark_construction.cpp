// Construction time and peak memory of Delaunay_triangulation_3 alone, of
// Conformal_alpha_shape_3, and of Alpha_shape_3 in GENERAL mode, on the same
// points in one process.
//   benchmark_construction [--sizes 100000,1000000] [--no-alpha-shape] [--csv FILE] [FILE...]
// Without FILE: noisy ellipsoids (0.1% radial noise) of the given sizes and the
// bundled bunny. FILE: any point file CGAL reads (.xyz, .off, .ply, ...).
#include <CGAL/Conformal_alpha_shape_3.h>

#include <CGAL/Alpha_shape_3.h>
#include <CGAL/Alpha_shape_cell_base_3.h>
#include <CGAL/Alpha_shape_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

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
typedef CGAL::Delaunay_triangulation_3<K> Plain_dt;
typedef CGAL::Triangulation_data_structure_3<CGAL::Conformal_alpha_shape_vertex_base_3<K>,
                                             CGAL::Conformal_alpha_shape_cell_base_3<K> > Tds;
typedef CGAL::Conformal_alpha_shape_3<CGAL::Delaunay_triangulation_3<K, Tds> > Cas;
typedef CGAL::Triangulation_data_structure_3<CGAL::Alpha_shape_vertex_base_3<K>,
                                             CGAL::Alpha_shape_cell_base_3<K> > As_tds;
typedef CGAL::Alpha_shape_3<CGAL::Delaunay_triangulation_3<K, As_tds> > Alpha_shape;

struct Measure { double seconds, mib; };

template <class Build>
Measure measure(Build build)
{
  cas3_benchmark::Phase phase;
  {
    auto object = build();
    const Measure m{phase.seconds(), phase.peak_mib()};
    if(object->number_of_vertices() == 0) std::abort();
    return m;
  }
}

void run(const std::string& name, const std::vector<Point>& pts, bool with_alpha_shape, std::ofstream& csv)
{
  const Measure dt = measure([&] { return std::make_unique<Plain_dt>(pts.begin(), pts.end()); });
  const Measure cas = measure([&] { return std::make_unique<Cas>(pts.begin(), pts.end()); });
  const Measure spectrum = measure([&] {
    auto c = std::make_unique<Cas>(pts.begin(), pts.end());
    if(c->number_of_alphas() == 0) std::abort();
    return c;
  });
  std::printf("%-28s %9zu  DT %7.3f s %7.1f MiB | conformal %7.3f s (%.2fx) %7.1f MiB (%.2fx)"
              " | +spectrum %7.3f s (%.2fx) %7.1f MiB (%.2fx)",
              name.c_str(), pts.size(), dt.seconds, dt.mib, cas.seconds, cas.seconds / dt.seconds,
              cas.mib, cas.mib / dt.mib, spectrum.seconds, spectrum.seconds / dt.seconds,
              spectrum.mib, spectrum.mib / dt.mib);
  csv << cas3_benchmark::csv_field(name) << ',' << pts.size() << ',' << dt.seconds << ',' << dt.mib << ','
      << cas.seconds << ',' << cas.mib << ',' << spectrum.seconds << ',' << spectrum.mib;
  if(with_alpha_shape)
  {
    const Measure as = measure([&] {
      return std::make_unique<Alpha_shape>(pts.begin(), pts.end(), 0, Alpha_shape::GENERAL);
    });
    std::printf(" | Alpha_shape_3 %7.3f s (%.2fx) %7.1f MiB (%.2fx)", as.seconds,
                as.seconds / dt.seconds, as.mib, as.mib / dt.mib);
    csv << ',' << as.seconds << ',' << as.mib;
  }
  else
    csv << ",,";
  csv << std::endl;
  std::printf("\n");
  std::fflush(stdout);
}

int main(int argc, char* argv[])
{
  const cas3_benchmark::Arguments args = cas3_benchmark::parse_arguments(argc, argv);
  const bool with_alpha_shape = !args.has("--no-alpha-shape");
  std::ofstream csv = cas3_benchmark::open_csv(args.csv, argc, argv,
                                               "input,n,delaunay_s,delaunay_mib,conformal_s,conformal_mib,"
                                               "spectrum_s,spectrum_mib,alpha_shape_s,alpha_shape_mib");
  std::cout << "ratios are against the Delaunay build alone; memory is the peak resident memory\n"
               "each phase adds; '+spectrum' builds the shape and its sorted spectrum\n";
  for(std::size_t n : args.sizes)
    run("ellipsoid 1:0.7:0.4, 0.1% noise", cas3_test::ellipsoid_sample<Point>(n, 1, 0.7, 0.4, 0.001),
        with_alpha_shape, csv);
  return cas3_benchmark::for_each_point_file<Point>(args.files, [&](const std::string& name, const std::vector<Point>& pts) {
    run(name, pts, with_alpha_shape, csv);
  }) ? EXIT_SUCCESS : EXIT_FAILURE;
}
