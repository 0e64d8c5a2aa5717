// End-to-end time and peak memory of multi-scale curvature (the conformal
// alpha shape, then for each of 4 scales its surface and the curvature at 2
// ring sizes, one layer at a time as conformal_curvature does, without file
// output), against the Delaunay build of the same points alone.
//   benchmark_end_to_end [--sizes 100000,1000000] [FILE...]
// Without FILE: noisy ellipsoids (0.1% radial noise) of the given sizes and
// the bundled bunny.
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cas3_benchmark.h"
#include "cas3_test_shapes.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;

void run(const std::string& name, const std::vector<Point>& pts)
{
  double dt_seconds = 0, dt_mib = 0;
  {
    cas3_benchmark::Phase phase;
    CGAL::Delaunay_triangulation_3<K> dt(pts.begin(), pts.end());
    dt_seconds = phase.seconds();
    dt_mib = phase.peak_mib();
  }
  cas3_benchmark::Phase total;
  double build_seconds = 0;
  std::size_t on_surface = 0;
  {
    const CAS3::Multiscale_curvatures<K> analysis(pts.begin(), pts.end());
    build_seconds = total.seconds();
    for(double q : {0.10, 0.25, 0.35, 0.50})
    {
      CAS3::Multiscale_curvatures<K>::Surface surface;
      analysis.extract_surface(analysis.alpha(CAS3::Scale::quantile(q)), surface);
      for(int rings : {1, 2})
        for(const auto& p : analysis.estimate_curvatures(surface, CAS3::Neighborhood::rings(rings)))
          on_surface += p.on_surface() ? 1 : 0;
    }
  }
  const double seconds = total.seconds(), mib = total.peak_mib();
  std::printf("%-34s %8zu points | Delaunay %7.3f s %7.1f MiB | end to end %7.3f s (%.2fx) %7.1f MiB (%.2fx)"
              " | of which shape %.3f s | %.1f%% of point-layers on a surface\n",
              name.c_str(), pts.size(), dt_seconds, dt_mib, seconds, seconds / dt_seconds, mib, mib / dt_mib,
              build_seconds, 100.0 * double(on_surface) / double(8 * pts.size()));
  std::fflush(stdout);
}

int main(int argc, char* argv[])
{
  const cas3_benchmark::Arguments args = cas3_benchmark::parse_arguments(argc, argv);
  std::cout << "4 scales (10%, 25%, 35%, 50%) x 2 ring sizes (1, 2); memory is the peak resident memory each\n"
               "phase adds\n";
  for(std::size_t n : args.sizes)
    run("ellipsoid 1:0.7:0.4, 0.1% noise", cas3_test::ellipsoid_sample<Point>(n, 1, 0.7, 0.4, 0.001));
  return cas3_benchmark::for_each_point_file<Point>(args.files, run) ? EXIT_SUCCESS : EXIT_FAILURE;
}
