// The smoothing of denoise(): CGAL's jet_smooth_point_set() against the
// package's own degree-2 jet smoothing (internal::jet_smooth_points(), what
// denoise() calls), on a noisy ellipsoid, with the Delaunay build of the same
// points as the unit of time.
//
//   benchmark_denoise [--sizes 100000,1000000] [--k 24,50] [--noise 0.1]
//                     [--passes 1] [--runs LIST] [--no-compare] [--csv FILE]
//
// Input: the ellipsoid 1 : 0.7 : 0.4 sampled uniformly in area
// (cas3_analytic_surfaces.h, seed 11), Gaussian noise of --noise x the
// spacing along the true normal (seed 21), as benchmark_pipeline.
// Runs (--runs, default all, in this order):
//   delaunay    CGAL::Delaunay_triangulation_3<Epick> of the points
//   cgal_seq    CGAL::jet_smooth_point_set<Sequential_tag>(points, k), --passes times
//   cgal_par    the same with Parallel_tag (only when built with TBB)
//   search      the k + 1 nearest points of every point alone, with the kd-tree
//               jet_smooth_point_set builds (CGAL's Neighbor_query), input order
//   fast_seq    internal::jet_smooth_points<Sequential_tag>(points, k, passes)
//   fast_par    the same with Parallel_tag (only when built with TBB)
//   denoise     CAS3::denoise(points, Denoising_plan{k, passes}) as the pipeline
//               calls it (coincident points merged first; parallel with TBB)
//   fast_search the searches of fast_seq alone (its kd-tree, Hilbert order,
//               unsorted hits)
// Times: processor time (std::clock, all threads of the process) and wall
// time, in seconds, and the processor time over the Delaunay build's.
// Unless --no-compare: the distance between fast_seq's and cgal_seq's
// smoothed points (max, median, 99th percentile, over the spacing), whether
// fast_par equals fast_seq bit for bit, and for the input and each result the
// median and 90th percentile of the offset along the true normal from the
// true surface point (the noise left, over the spacing).
#include <CGAL/Conformal_alpha_shapes_3/denoise.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/jet_smooth_point_set.h>

#include "cas3_analytic_surfaces.h"
#include "cas3_benchmark.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;

namespace {

template <class T>
std::vector<T> parse_list(const std::string& text)
{
  std::vector<T> out;
  std::stringstream list(text);
  std::string item;
  while(std::getline(list, item, ','))
  {
    std::stringstream value(item);
    T v;
    value >> v;
    out.push_back(v);
  }
  return out;
}

struct Timing
{
  double cpu = 0, wall = 0;
};

Timing measure(const std::function<void()>& f)
{
  const std::clock_t c0 = std::clock();
  const auto w0 = std::chrono::steady_clock::now();
  f();
  Timing t;
  t.cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  return t;
}

double quantile(std::vector<double> v, double q)
{
  if(v.empty())
    return 0;
  const std::size_t i = std::min(v.size() - 1, std::size_t(q * double(v.size())));
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(i), v.end());
  return v[i];
}

// searches only, as jet_smooth_point_set does them
std::size_t cgal_searches(std::vector<Point>& points, unsigned int k)
{
  typedef CGAL::Point_set_processing_3::internal::Neighbor_query<Kernel, std::vector<Point>&,
                                                                  CGAL::Identity_property_map<Point>> Query;
  Query query(points, CGAL::Identity_property_map<Point>());
  std::size_t found = 0;
  std::vector<Point> neighbors;
  for(const Point& p : points)
  {
    neighbors.clear();
    query.get_points(p, k, 0, std::back_inserter(neighbors), 6);
    found += neighbors.size();
  }
  return found;
}

// searches only, as internal::jet_smooth_pass does them (Hilbert order)
std::size_t fast_searches(const std::vector<Point>& input, unsigned int k)
{
  typedef CGAL::Search_traits_3<Kernel> Traits;
  typedef CGAL::Sliding_midpoint<Traits> Splitter;
  typedef CGAL::Kd_tree<Traits, Splitter, CGAL::Tag_true, CGAL::Tag_true> Tree;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, CGAL::Euclidean_distance<Traits>, Splitter, Tree> Search;
  std::vector<Point> points = input;
  CGAL::hilbert_sort(points.begin(), points.end());
  Tree tree(points.begin(), points.end(), Splitter(16));
  tree.build();
  std::size_t found = 0;
  double sum = 0;
  for(const Point& p : points)
  {
    const Search search(tree, p, k + 1, 0, true, CGAL::Euclidean_distance<Traits>(), false);
    for(const auto& hit : search)
    {
      ++found;
      sum += hit.second;
    }
  }
  return found + (sum < 0);
}

// |g| / |grad g| for g = x^2 + (y / 0.7)^2 + (z / 0.4)^2 - 1: the distance to
// the ellipsoid to first order (exact to the square of the distance)
double ellipsoid_distance(const Point& p)
{
  const double a2 = 1, b2 = 0.49, c2 = 0.16;
  const double x = p.x(), y = p.y(), z = p.z();
  const double g = x * x / a2 + y * y / b2 + z * z / c2 - 1;
  const double gx = 2 * x / a2, gy = 2 * y / b2, gz = 2 * z / c2;
  return std::abs(g) / std::sqrt(gx * gx + gy * gy + gz * gz);
}

} // namespace

int main(int argc, char* argv[])
{
  std::vector<std::size_t> sizes = {100000, 1000000};
  std::vector<unsigned int> ks = {24, 50};
  double noise = 0.1;
  int passes = 1;
  bool compare = true;
  std::string csv_path;
  std::vector<std::string> runs = {"delaunay", "cgal_seq", "cgal_par", "search", "fast_seq", "fast_par", "denoise", "fast_search"};
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg == "--sizes" && i + 1 < argc) sizes = parse_list<std::size_t>(argv[++i]);
    else if(arg == "--k" && i + 1 < argc) ks = parse_list<unsigned int>(argv[++i]);
    else if(arg == "--noise" && i + 1 < argc) noise = std::stod(argv[++i]);
    else if(arg == "--passes" && i + 1 < argc) passes = std::stoi(argv[++i]);
    else if(arg == "--runs" && i + 1 < argc) runs = parse_list<std::string>(argv[++i]);
    else if(arg == "--no-compare") compare = false;
    else if(arg == "--csv" && i + 1 < argc) csv_path = argv[++i];
    else
    {
      std::cerr << "usage: benchmark_denoise [--sizes N,...] [--k K,...] [--noise R] [--passes P] [--runs LIST] [--no-compare]\n"
                   "                         [--csv FILE]\n";
      return 1;
    }
  }
  auto wanted = [&](const std::string& name) { return std::find(runs.begin(), runs.end(), name) != runs.end(); };
#ifdef CGAL_LINKED_WITH_TBB
  const bool tbb = true;
#else
  const bool tbb = false;
#endif
  std::printf("noise %g spacings, %d pass(es), TBB %s; cpu = processor time (s, all threads), xDT = cpu / Delaunay cpu\n",
              noise, passes, tbb ? "on" : "off");
  std::printf("%-9s %-4s %-12s %9s %9s %7s\n", "n", "k", "run", "cpu", "wall", "xDT");
  std::ofstream csv = cas3_benchmark::open_csv(csv_path, argc, argv, "n,k,run,cpu_s,wall_s,cpu_x_delaunay");
  for(std::size_t n : sizes)
  {
    auto sample = cas3_analytic::ellipsoid_truth_sample<Point, Vector>(n, 1, 0.7, 0.4);
    cas3_analytic::add_normal_noise(sample, noise, 21);
    const std::vector<Point>& input = sample.points;
    double delaunay_cpu = 0;
    if(wanted("delaunay"))
    {
      const Timing t = measure([&] {
        CGAL::Delaunay_triangulation_3<Kernel> dt(input.begin(), input.end());
        if(dt.number_of_vertices() == 0) std::printf("?\n");
      });
      delaunay_cpu = t.cpu;
      std::printf("%-9zu %-4s %-12s %9.3f %9.3f %7s\n", n, "-", "delaunay", t.cpu, t.wall, "1");
      csv << n << ",,delaunay," << t.cpu << ',' << t.wall << ",1\n";
    }
    auto report = [&](unsigned int k, const char* name, const Timing& t) {
      char ratio[32] = "-";
      if(delaunay_cpu > 0) std::snprintf(ratio, sizeof(ratio), "%.2f", t.cpu / delaunay_cpu);
      std::printf("%-9zu %-4u %-12s %9.3f %9.3f %7s\n", n, k, name, t.cpu, t.wall, ratio);
      csv << n << ',' << k << ',' << name << ',' << t.cpu << ',' << t.wall << ',' << (delaunay_cpu > 0 ? ratio : "")
          << '\n';
      std::fflush(stdout);
    };
    for(unsigned int k : ks)
    {
      std::vector<Point> cgal_seq, fast_seq, fast_par;
      if(wanted("cgal_seq"))
      {
        cgal_seq = input;
        report(k, "cgal_seq", measure([&] {
          for(int p = 0; p < passes; ++p) CGAL::jet_smooth_point_set<CGAL::Sequential_tag>(cgal_seq, k);
        }));
      }
#ifdef CGAL_LINKED_WITH_TBB
      if(wanted("cgal_par"))
      {
        std::vector<Point> cgal_par = input;
        report(k, "cgal_par", measure([&] {
          for(int p = 0; p < passes; ++p) CGAL::jet_smooth_point_set<CGAL::Parallel_tag>(cgal_par, k);
        }));
        if(!cgal_seq.empty())
          std::printf("  cgal_par %s cgal_seq bit for bit\n", cgal_par == cgal_seq ? "equals" : "DIFFERS FROM");
      }
#endif
      if(wanted("search"))
      {
        std::vector<Point> points = input;
        report(k, "search", measure([&] { if(cgal_searches(points, k) == 0) std::printf("?\n"); }));
      }
      if(wanted("fast_seq"))
      {
        fast_seq = input;
        report(k, "fast_seq", measure([&] {
          CAS3::internal::jet_smooth_points<CGAL::Sequential_tag>(fast_seq, k, passes);
        }));
      }
#ifdef CGAL_LINKED_WITH_TBB
      if(wanted("fast_par"))
      {
        fast_par = input;
        report(k, "fast_par", measure([&] {
          CAS3::internal::jet_smooth_points<CGAL::Parallel_tag>(fast_par, k, passes);
        }));
        if(!fast_seq.empty())
          std::printf("  fast_par %s fast_seq bit for bit\n", fast_par == fast_seq ? "equals" : "DIFFERS FROM");
      }
#endif
      if(wanted("denoise"))
      {
        std::vector<Point> points = input;
        report(k, "denoise", measure([&] { CAS3::denoise(points, CAS3::Denoising_plan{k, passes}); }));
        if(!fast_seq.empty())
          std::printf("  denoise %s fast_seq bit for bit\n", points == fast_seq ? "equals" : "DIFFERS FROM");
      }
      if(wanted("fast_search"))
        report(k, "fast_search", measure([&] { if(fast_searches(input, k) == 0) std::printf("?\n"); }));
      if(!compare)
        continue;
      auto noise_left = [&](const std::vector<Point>& points, const char* name) {
        if(points.empty())
          return;
        std::vector<double> d(points.size());
        for(std::size_t i = 0; i < points.size(); ++i)
          d[i] = ellipsoid_distance(points[i]) / sample.spacing;
        std::printf("  distance to the ellipsoid / spacing, %-9s median %.4f, 90%% %.4f, max %.3f\n", name,
                    quantile(d, 0.5), quantile(d, 0.9), *std::max_element(d.begin(), d.end()));
      };
      noise_left(input, "input:");
      noise_left(cgal_seq, "cgal_seq:");
      noise_left(fast_seq, "fast_seq:");
      if(!cgal_seq.empty() && !fast_seq.empty())
      {
        std::vector<double> d(input.size());
        for(std::size_t i = 0; i < input.size(); ++i)
          d[i] = std::sqrt(CGAL::squared_distance(cgal_seq[i], fast_seq[i])) / sample.spacing;
        std::printf("  |fast_seq - cgal_seq| / spacing: median %.3g, 99%% %.3g, max %.3g\n", quantile(d, 0.5),
                    quantile(d, 0.99), *std::max_element(d.begin(), d.end()));
      }
    }
  }
  return 0;
}
