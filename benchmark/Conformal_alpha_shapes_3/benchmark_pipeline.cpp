// The default job of the program conformal_curvature, stage by stage, against
// the Delaunay build of the same points and CGAL jet fitting with 120
// neighbors: wall and processor time, and peak resident memory from the
// operating system.
//
//   benchmark_pipeline [--sizes 100000,300000,1000000] [--surfaces noisy,clean]
//                      [--csv FILE] [--time-limit SECONDS] [--jet-max N] [--no-jet]
//                      [--no-bunny] [--no-pipeline] [--no-parts] [--threads N] [--program PATH]
//                      [--tmp DIR] [--write-points DIR] [FILE...]
//
// Inputs: an ellipsoid with semi-axes 1, 0.7, 0.4 sampled uniformly in area
// (cas3_analytic_surfaces.h), clean, and noisy (Gaussian noise of 0.1 x the
// spacing along the true normal), at each size; then each FILE (default: the
// bundled bunny), read with the program's reader.
//
// Each measured thing runs in a child process of its own (fork), so that its
// peak memory is its own:
//   delaunay   CGAL::Delaunay_triangulation_3<Epick> of the input points
//   jet        CGAL::Monge_via_jet_fitting (jet degree 2, Monge degree 2) per
//              point on its 120 nearest neighbors from a kd-tree
//              (Orthogonal_k_neighbor_search), serial; inputs above --jet-max
//              points (default 3000000) are skipped
//   parts      the parts of the Multiscale_curvatures construction, called
//              from outside the way its constructor calls them: input
//              hygiene (internal::normalize_input), estimate_noise, denoise
//              (when the plan calls for it), the Conformal_alpha_shape_3
//              of the (smoothed) points, and its advancing front grown by
//              CGAL's Advancing_front_surface_reconstruction (on a copy of
//              the triangulation, internal/cgal_front.h) and by the
//              package's own (internal/conformal_front.h), compared
//   pipeline   the default job as conformal_curvature runs it:
//              Multiscale_curvatures construction, alpha(Scale::automatic()),
//              extract_surface, estimate_curvatures for
//              default_neighborhoods() (the fits and the nearest-surface
//              filling) on the consumed analysis (its shape freed before
//              the fits), each layer made the program's, in float with its
//              summary statistics, as estimate_curvatures gives it (one
//              stage, as in the program: the layers in double are never
//              all held), the surface PLY with the layers, and the binary PLY point
//              cloud, through the program's code (cas3_curvature_output.h,
//              cas3_curvature_summary.h, cas3_layer_names.h;
//              reading an input file is not timed). The curvature of all
//              neighborhoods is one stage: one search per vertex serves them all.
//   program    (--program PATH) the conformal_curvature binary on the
//              points written as .xyz, timed from outside (wall; processor
//              time and peak memory from wait4); it also reads the text file.
// --no-pipeline and --no-parts leave those processes out (the peers'
// benchmark, benchmark_peers.py, needs only the unit, jet fitting and the
// program). --write-points DIR keeps what a comparison of accuracy needs:
// each ellipsoid as DIR/ellipsoid_<noisy|clean>_<n>.xyz, its truth per point
// as ..._truth.txt (a line `# spacing S`, then `H nx ny nz`, the true mean
// curvature and outward unit normal), jet fitting's mean curvature per point
// as ..._jet_H.txt (its sign is the arbitrary one of the fitted frame) and,
// with --program, the program's output folder ..._program/.
// --threads N limits TBB to N threads (tbb::global_control) in every child:
// `--threads 1` runs the parallel stages serially in the same binary, for
// the serial-versus-parallel speedup (the Delaunay build and jet fitting are
// serial either way). Without TBB the option is refused.
// Like the program, it has malloc ask for transparent huge pages where the
// kernel gives them only on request, unless GLIBC_TUNABLES names
// glibc.malloc.hugetlb already, and keeps malloc to one arena unless
// MALLOC_ARENA_MAX is set (cas3_malloc_policy.h); both settings are printed.
// Huge pages change every stage's time, the Delaunay build's too.
// Within a child, the peak of each stage comes from VmHWM after resetting it
// (/proc/self/clear_refs 5) at the stage's start; "added" is that peak less
// the resident memory when the child started (the input points). The job's
// peak is the largest stage peak. Children are killed after --time-limit
// seconds (default: 900, or 300 microseconds per point where that is more,
// since the whole job of 10,000,000 points took about 1,000 s).
#include <CGAL/Conformal_alpha_shapes_3/internal/cgal_front.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/conformal_front.h>
#include <CGAL/Conformal_alpha_shapes_3/internal/input_hygiene.h>
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include "cas3_analytic_surfaces.h"
#include "cas3_benchmark.h"
#include "cas3_curvature_output.h"
#include "cas3_curvature_summary.h"
#include "cas3_layer_names.h"
#include "cas3_malloc_policy.h"
#include "cas3_read_point_cloud.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <malloc.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
typedef CAS3::Multiscale_curvatures<K> Analysis;
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------
// Options

struct Options
{
  std::vector<std::size_t> sizes = {100000, 300000, 1000000};
  std::vector<std::string> surfaces = {"noisy", "clean"};
  std::vector<std::string> files;
  std::string csv;
  std::string program;
  std::string tmp;
  std::string write_points;
  double time_limit = 0;  // 0: by the number of points (time_limit_for())
  std::size_t jet_max = 3000000;
  std::size_t threads = 0;  // 0: TBB's default
  bool jet = true, bunny = true, pipeline = true, parts = true;
};

std::vector<std::string> split_list(const std::string& s)
{
  std::vector<std::string> items;
  std::stringstream in(s);
  std::string item;
  while(std::getline(in, item, ','))
    if(!item.empty()) items.push_back(item);
  return items;
}

Options parse(int argc, char* argv[])
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) { std::cerr << arg << " needs a value\n"; std::exit(EXIT_FAILURE); }
      return argv[++i];
    };
    if(arg == "--sizes")
    {
      o.sizes.clear();
      for(const std::string& s : split_list(value())) o.sizes.push_back(std::stoul(s));
    }
    else if(arg == "--surfaces") o.surfaces = split_list(value());
    else if(arg == "--csv") o.csv = value();
    else if(arg == "--program") o.program = value();
    else if(arg == "--tmp") o.tmp = value();
    else if(arg == "--time-limit") o.time_limit = std::stod(value());
    else if(arg == "--jet-max") o.jet_max = std::stoul(value());
    else if(arg == "--no-jet") o.jet = false;
    else if(arg == "--no-bunny") o.bunny = false;
    else if(arg == "--no-pipeline") o.pipeline = false;
    else if(arg == "--no-parts") o.parts = false;
    else if(arg == "--write-points") o.write_points = value();
    else if(arg == "--threads") o.threads = std::stoul(value());
    else if(arg == "--help" || arg == "-h")
    {
      std::cout << "benchmark_pipeline [--sizes N,N,...] [--surfaces noisy,clean] [--csv FILE]\n"
                   "  [--time-limit SECONDS] [--jet-max N] [--no-jet] [--no-bunny] [--no-pipeline]\n"
                   "  [--no-parts] [--threads N] [--program PATH] [--tmp DIR] [--write-points DIR] [FILE...]\n";
      std::exit(EXIT_SUCCESS);
    }
    else if(arg.rfind("--", 0) == 0) { std::cerr << "unknown option " << arg << "\n"; std::exit(EXIT_FAILURE); }
    else o.files.push_back(arg);
  }
  if(o.files.empty() && o.bunny) o.files.push_back(CGAL_CAS3_DEFAULT_INPUT);
  if(o.tmp.empty()) o.tmp = fs::temp_directory_path().string();
  return o;
}

// ---------------------------------------------------------------------------
// Measuring, in a child process: one line per stage on a pipe to the parent.

double cpu_seconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double wall_seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Record
{
  std::string kind;   // delaunay, jet, parts, pipeline, program
  std::string stage;
  std::string group;  // reference, stage, part, extra, total, failure
  double wall = NAN, cpu = NAN, peak_added = NAN, peak_process = NAN;  // s, s, MiB, MiB
  std::string note;
};

class Child_meter
{
public:
  Child_meter(int fd, const std::string& kind) : m_fd(fd), m_kind(kind)
  {
    // the parent's freed heap, resident in the child too until trimmed as
    // every stage starts, is not the child's base (after 3,000,000 points
    // the bunny's stages came out at -73 MiB)
    malloc_trim(0);
    m_base_kib = cas3_benchmark::kib_field("VmRSS");
  }
  // Runs f as one stage and reports it.
  template <class F>
  void stage(const std::string& name, const std::string& group, F f)
  {
    malloc_trim(0);
    std::ofstream("/proc/self/clear_refs") << "5";
    const double w0 = wall_seconds(), c0 = cpu_seconds();
    std::string note = f();
    const double wall = wall_seconds() - w0, cpu = cpu_seconds() - c0;
    const double hwm = cas3_benchmark::kib_field("VmHWM");
    m_max_hwm_kib = (std::max)(m_max_hwm_kib, hwm);
    if(group == "stage")
    {
      m_sum_wall += wall;
      m_sum_cpu += cpu;
      m_stage_max_hwm_kib = (std::max)(m_stage_max_hwm_kib, hwm);
    }
    send(name, group, wall, cpu, (hwm - m_base_kib) / 1024, hwm / 1024, note);
  }
  // The sum of the "stage" stages, with their largest peak.
  void total(const std::string& name)
  {
    send(name, "total", m_sum_wall, m_sum_cpu, (m_stage_max_hwm_kib - m_base_kib) / 1024, m_stage_max_hwm_kib / 1024,
         "sum of the stages; peak: the largest stage peak");
  }
  void send(const std::string& name, const std::string& group, double wall, double cpu, double added,
            double process, const std::string& note)
  {
    char line[1024];
    const int n = std::snprintf(line, sizeof line, "%s\t%s\t%s\t%.6f\t%.6f\t%.3f\t%.3f\t%s\n", m_kind.c_str(),
                                name.c_str(), group.c_str(), wall, cpu, added, process, note.c_str());
    if(::write(m_fd, line, std::size_t((std::min)(n, int(sizeof line) - 1))) < 0) std::perror("write");
  }

private:
  int m_fd;
  std::string m_kind;
  double m_base_kib = 0, m_max_hwm_kib = 0, m_stage_max_hwm_kib = 0;
  double m_sum_wall = 0, m_sum_cpu = 0;
};

std::vector<Record> parse_records(const std::string& text)
{
  std::vector<Record> out;
  std::stringstream in(text);
  std::string line;
  while(std::getline(in, line))
  {
    std::vector<std::string> f;
    std::stringstream fields(line);
    std::string item;
    while(std::getline(fields, item, '\t')) f.push_back(item);
    if(f.size() < 7) continue;
    Record r;
    r.kind = f[0];
    r.stage = f[1];
    r.group = f[2];
    r.wall = std::stod(f[3]);
    r.cpu = std::stod(f[4]);
    r.peak_added = std::stod(f[5]);
    r.peak_process = std::stod(f[6]);
    r.note = f.size() > 7 ? f[7] : "";
    out.push_back(r);
  }
  return out;
}

// Runs body(meter) in a child with a time limit; the records it sent, and a
// failure record when it did not end normally.
std::vector<Record> in_child(const std::string& kind, double time_limit, const std::function<void(Child_meter&)>& body)
{
  std::fflush(stdout);
  std::cout.flush();
  int fds[2];
  if(::pipe(fds) != 0) { std::perror("pipe"); std::exit(EXIT_FAILURE); }
  const pid_t pid = ::fork();
  if(pid == 0)
  {
    ::close(fds[0]);
    ::alarm(unsigned(std::ceil(time_limit)));
    int status = 0;
    try
    {
      Child_meter meter(fds[1], kind);
      body(meter);
    }
    catch(const std::exception& e)
    {
      Child_meter(fds[1], kind).send("exception", "failure", NAN, NAN, NAN, NAN, e.what());
      status = 2;
    }
    ::close(fds[1]);
    std::fflush(stdout);
    ::_exit(status);
  }
  ::close(fds[1]);
  std::string text;
  char buffer[4096];
  for(;;)
  {
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if(n < 0 && errno == EINTR) continue;
    if(n <= 0) break;
    text.append(buffer, std::size_t(n));
  }
  ::close(fds[0]);
  int status = 0;
  rusage usage;
  ::wait4(pid, &status, 0, &usage);
  std::vector<Record> records = parse_records(text);
  if(WIFSIGNALED(status))
  {
    Record r;
    r.kind = kind;
    r.stage = "not finished";
    r.group = "failure";
    r.note = WTERMSIG(status) == SIGALRM ? "killed at the time limit of " + std::to_string(int(time_limit)) + " s"
                                         : "killed by signal " + std::to_string(WTERMSIG(status));
    r.peak_process = double(usage.ru_maxrss) / 1024;
    records.push_back(r);
  }
  return records;
}

// ---------------------------------------------------------------------------
// The measured things

struct Input
{
  std::string name;
  std::vector<Point> points;
  std::vector<Vector> normals;  // a file's, else empty (the program's .xyz has none)
  std::string kept;  // with --write-points: the path of the written .xyz less ".xyz", else empty
};

void write_xyz(const std::vector<Point>& points, const std::string& path)
{
  std::string text;
  for(const Point& p : points)
  {
    char line[96];
    const int n = std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    text.append(line, std::size_t(n));
  }
  std::ofstream out(path);
  out << text;
  if(!out)
    throw std::runtime_error("cannot write " + path);
}

std::string number(double x, const char* format = "%.4g")
{
  char text[64];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

void measure_delaunay(Child_meter& m, const Input& in)
{
  m.stage("Delaunay_triangulation_3<Epick>", "reference", [&] {
    CGAL::Delaunay_triangulation_3<K> dt(in.points.begin(), in.points.end());
    return std::to_string(dt.number_of_finite_cells()) + " finite cells";
  });
}

void measure_jet(Child_meter& m, const Input& in)
{
  std::vector<double> mean_curvatures;  // kept for --write-points only
  m.stage("jet fitting, 120 neighbors", "reference", [&] {
    typedef CGAL::Search_traits_3<K> Traits;
    typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
    typedef CGAL::Monge_via_jet_fitting<K> Fitting;
    const Search::Tree tree(in.points.begin(), in.points.end());
    std::vector<Point> neighbors;
    neighbors.reserve(120);
    double sum = 0;
    if(!in.kept.empty())
      mean_curvatures.reserve(in.points.size());
    for(const Point& p : in.points)
    {
      neighbors.clear();
      const Search search(tree, p, 120);
      for(auto it = search.begin(); it != search.end(); ++it) neighbors.push_back(it->first);
      Fitting fitting;
      const Fitting::Monge_form form = fitting(neighbors.begin(), neighbors.end(), 2, 2);
      sum += form.principal_curvatures(0) + form.principal_curvatures(1);
      if(!in.kept.empty())
        mean_curvatures.push_back(0.5 * (form.principal_curvatures(0) + form.principal_curvatures(1)));
    }
    return "Monge_via_jet_fitting(2, 2) per point, kd-tree k-NN; checksum " + number(sum);
  });
  if(!in.kept.empty())
  {
    std::ofstream out(in.kept + "_jet_H.txt");
    out.precision(17);
    for(double H : mean_curvatures) out << H << '\n';
    if(!out)
      throw std::runtime_error("cannot write " + in.kept + "_jet_H.txt");
  }
}

void measure_parts(Child_meter& m, const Input& in)
{
  std::vector<Point> points;
  m.stage("input hygiene (internal::normalize_input)", "part", [&] {
    CAS3::internal::Normalized_input<K> input = CAS3::internal::normalize_input<K>(in.points);
    points = std::move(input.points);
    return std::to_string(input.outliers.size()) + " outliers";
  });
  CAS3::Noise_estimate noise;
  m.stage("estimate_noise", "part", [&] {
    noise = CAS3::estimate_noise(points);
    return "noise " + number(noise.noise) + " x spacing, noise_24 " + number(noise.noise_24);
  });
  if(noise.calls_for_denoising())
    m.stage("denoise", "part", [&] {
      CAS3::Denoising_plan plan = CAS3::denoising_plan(noise.noise);
      plan.passes = (std::max)(plan.passes, 1);
      plan.neighbors = (std::max)(plan.neighbors, 24u);
      CAS3::denoise(points, plan);
      return std::to_string(plan.passes) + " pass(es) over " + std::to_string(plan.neighbors) + " neighbors";
    });
  else
    m.send("denoise", "part", 0, 0, 0, 0, "not called for");
  std::unique_ptr<Analysis::Shape> shape;
  m.stage("Conformal_alpha_shape_3 construction", "part", [&] {
    shape = std::make_unique<Analysis::Shape>();
    shape->make_conformal_alpha_shape(points.begin(), points.end(),
      CAS3::parameters::local_feature_size_estimator(CAS3::NOISE_ROBUST_POLE_DISTANCE));
    return std::to_string(shape->number_of_finite_cells()) + " finite cells";
  });
  // the soups are compared by a digest, so that neither is held while the other grows
  auto digest = [](const CAS3::internal::Advancing_front_soup& soup) {
    std::uint64_t h = 0;
    for(const std::array<std::size_t, 3>& t : soup.triangles)
      for(std::size_t v : t) h = CAS3::internal::mix_hash(h, soup.shape_vertex[v]);
    for(const std::array<std::size_t, 3>& n : soup.neighbors)
      for(std::size_t t : n) h = CAS3::internal::mix_hash(h, t);
    for(double value : soup.values)
    {
      std::uint64_t bits;
      std::memcpy(&bits, &value, sizeof bits);
      h = CAS3::internal::mix_hash(h, bits);
    }
    return h;
  };
  std::uint64_t cgal_digest = 0;
  m.stage("advancing front: CGAL's, on a copy of the triangulation", "part", [&] {
    const CAS3::internal::Advancing_front_soup soup = CAS3::internal::cgal_front_soup(*shape);
    cgal_digest = digest(soup);
    return std::to_string(soup.triangles.size()) + " triangles";
  });
  m.stage("advancing front: the package's (the default)", "part", [&] {
    const CAS3::internal::Advancing_front_soup soup = CAS3::internal::conformal_front_soup(*shape);
    return std::to_string(soup.triangles.size()) + " triangles, "
           + (digest(soup) == cgal_digest ? "the same soup as CGAL's" : "NOT the same soup as CGAL's");
  });
  m.stage("Delaunay_triangulation_3<Epick> (same points, same process)", "part", [&] {
    CGAL::Delaunay_triangulation_3<K> dt(points.begin(), points.end());
    return std::to_string(dt.number_of_finite_cells()) + " finite cells";
  });
}

void measure_pipeline(Child_meter& m, const Input& in, const std::string& tmp)
{
  const std::vector<Point>& points = in.points;
  const fs::path dir = fs::path(tmp) / ("benchmark_pipeline_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::unique_ptr<Analysis> analysis;
  m.stage("Multiscale_curvatures construction (input hygiene included)", "stage", [&] {
    const auto np = CAS3::parameters::reference_normals(std::cref(in.normals),
      CAS3::parameters::denoising(CAS3::AUTOMATIC_DENOISING,
                                  CAS3::parameters::surface_extraction(CAS3::ADVANCING_FRONT)));
    analysis = std::make_unique<Analysis>(points.begin(), points.end(), np);
    return "noise " + number(analysis->noise().noise) + ", " + std::to_string(analysis->denoising().passes)
           + " smoothing pass(es), " + std::to_string(analysis->outliers().size()) + " outliers";
  });
  const CAS3::Scale scale = CAS3::Scale::automatic();
  double a = 0;
  m.stage("scale_value(Scale::automatic())", "stage", [&] {
    a = analysis->scale_value(scale);
    return "a = " + number(a);
  });
  Analysis::Surface surface;
  m.stage("extract_surface", "stage", [&] {
    const CAS3::Surface_report report = analysis->surface(a, surface);
    return std::to_string(report.number_of_faces) + " faces, " + std::to_string(report.number_of_parts)
           + " parts, " + std::to_string(report.number_of_points_off_surface) + " points off";
  });
  m.stage("program: return freed memory (malloc_trim)", "stage", [&] {
    cas3::return_freed_memory();
    return std::string();
  });
  std::vector<cas3::Layer> layers;
  const std::vector<CAS3::Neighborhood> neighborhoods = CAS3::default_neighborhoods();
  m.stage("estimate_curvatures (" + std::to_string(neighborhoods.size())
            + " neighborhoods), the shape freed first and each layer made the program's (float, summary) as it comes",
          "stage", [&] {
    std::string summaries;
    std::move(*analysis).estimate_curvatures(
      surface, neighborhoods, CAS3::QUADRIC_FIT,
      [&](std::size_t r, std::vector<CAS3::Point_curvature<K> >&& curvatures) {
        const CAS3::Neighborhood& neighborhood = neighborhoods[r];
        cas3::Layer layer(curvatures);
        layer.label = cas3::layer_label(scale, neighborhood, false);
        layer.description = cas3::layer_description(*analysis, a, scale, neighborhood, layer.label);
        summaries += (summaries.empty() ? "" : "; ") + cas3::summary_row(layer.label, a, curvatures);
        layers.push_back(std::move(layer));
      });
    return summaries;
  });
  m.stage("write surface PLY (binary, 5 layers, colors)", "stage", [&] {
    std::ofstream ply(dir / "surface_auto.ply", std::ios::binary);
    cas3::write_surface(ply, surface, points, layers.data(), layers.data() + layers.size());
    ply.close();
    if(!ply) throw std::runtime_error("cannot write the surface PLY");
    return std::to_string(fs::file_size(dir / "surface_auto.ply") >> 20) + " MiB";
  });
  m.stage("write point cloud PLY (binary)", "stage", [&] {
    std::ofstream ply(dir / "curvatures.ply", std::ios::binary);
    std::vector<bool> is_outlier(points.size(), false);
    for(std::size_t i : analysis->outliers()) is_outlier[i] = true;
    cas3::write_point_cloud(ply, points, is_outlier, layers);
    ply.close();
    if(!ply) throw std::runtime_error("cannot write the point cloud PLY");
    return std::to_string(fs::file_size(dir / "curvatures.ply") >> 20) + " MiB";
  });
  m.total("default job (sum of the stages)");
  std::error_code ignored;
  fs::remove_all(dir, ignored);
}

// The program binary on the points written as .xyz.
std::vector<Record> measure_program(const std::string& program, const Input& in, const std::string& tmp,
                                    double time_limit)
{
  const fs::path dir = fs::path(tmp) / ("benchmark_pipeline_program_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string xyz = in.kept.empty() ? (dir / "points.xyz").string() : in.kept + ".xyz";
  if(in.kept.empty())
    write_xyz(in.points, xyz);
  const std::string out = in.kept.empty() ? (dir / "out").string() : in.kept + "_program";
  const double w0 = wall_seconds();
  const pid_t pid = ::fork();
  if(pid == 0)
  {
    ::alarm(unsigned(std::ceil(time_limit)));
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::execl(program.c_str(), program.c_str(), xyz.c_str(), "--output", out.c_str(), "--quiet", (char*)nullptr);
    ::_exit(127);
  }
  int status = 0;
  rusage usage;
  ::wait4(pid, &status, 0, &usage);
  Record r;
  r.kind = "program";
  r.stage = "conformal_curvature binary, default job (reads .xyz)";
  r.group = "program";
  r.wall = wall_seconds() - w0;
  r.cpu = double(usage.ru_utime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec) + double(usage.ru_stime.tv_sec)
          + 1e-6 * double(usage.ru_stime.tv_usec);
  r.peak_process = double(usage.ru_maxrss) / 1024;
  r.note = WIFEXITED(status) && WEXITSTATUS(status) == 0 ? "ru_maxrss of the process"
         : "failed: status " + std::to_string(status);
  if(!(WIFEXITED(status) && WEXITSTATUS(status) == 0)) r.group = "failure";
  std::error_code ignored;
  fs::remove_all(dir, ignored);
  return {r};
}

// ---------------------------------------------------------------------------
// Report

std::string load_average()
{
  std::ifstream in("/proc/loadavg");
  double one = 0;
  in >> one;
  return number(one, "%.2f");
}

using cas3_benchmark::csv_field;

void report(std::ofstream& csv, const std::string& input_name, std::size_t n,
            const std::string& load_before, const std::vector<Record>& records)
{
  double dt_wall = NAN, dt_cpu = NAN, dt_peak = NAN;
  for(const Record& r : records)
    if(r.kind == "delaunay" && r.group == "reference")
    {
      dt_wall = r.wall;
      dt_cpu = r.cpu;
      dt_peak = r.peak_added;
    }
  const std::string load_after = load_average();
  std::printf("\n== %s, %zu points (load average %s before, %s after)\n", input_name.c_str(), n,
              load_before.c_str(), load_after.c_str());
  std::printf("%-62s %9s %9s %7s %7s %9s %9s %6s %9s  %s\n", "stage", "wall s", "cpu s", "xDT wal", "xDT cpu",
              "peak+ MiB", "proc MiB", "xDT", "us/point", "note");
  for(const Record& r : records)
  {
    const bool timed = std::isfinite(r.wall);
    const std::string name = (r.group == "part" ? "  part: " : "") + r.stage;
    std::printf("%-62s %9s %9s %7s %7s %9s %9s %6s %9s  %s\n", name.substr(0, 62).c_str(),
                timed ? number(r.wall, "%.3f").c_str() : "-", timed ? number(r.cpu, "%.3f").c_str() : "-",
                timed ? number(r.wall / dt_wall, "%.2f").c_str() : "-",
                timed ? number(r.cpu / dt_cpu, "%.2f").c_str() : "-",
                std::isfinite(r.peak_added) ? number(r.peak_added, "%.1f").c_str() : "-",
                std::isfinite(r.peak_process) ? number(r.peak_process, "%.1f").c_str() : "-",
                std::isfinite(r.peak_added) ? number(r.peak_added / dt_peak, "%.2f").c_str() : "-",
                timed ? number(1e6 * r.wall / double(n), "%.3f").c_str() : "-", r.note.c_str());
    if(csv)
      csv << csv_field(input_name) << ',' << n << ',' << r.kind << ',' << csv_field(r.stage) << ',' << r.group << ','
          << number(r.wall, "%.6f") << ',' << number(r.cpu, "%.6f") << ','
          << number(r.peak_added, "%.3f") << ',' << number(r.peak_process, "%.3f") << ','
          << number(1e6 * r.wall / double(n), "%.4f") << ',' << number(1e6 * r.cpu / double(n), "%.4f") << ','
          << number(r.wall / dt_wall, "%.4f") << ',' << number(r.cpu / dt_cpu, "%.4f") << ','
          << number(r.peak_added / dt_peak, "%.4f") << ',' << load_before << ',' << load_after << ','
          << csv_field(r.note) << '\n';
  }
  if(csv) csv.flush();
  std::fflush(stdout);
}

double time_limit_for(const Options& o, std::size_t n)
{
  return o.time_limit > 0 ? o.time_limit : (std::max)(900., 3e-4 * double(n));
}

void run(const Options& o, std::ofstream& csv, const Input& in)
{
  const double time_limit = time_limit_for(o, in.points.size());
  const std::string load_before = load_average();
  std::vector<Record> records;
  auto add = [&](const std::vector<Record>& more) { records.insert(records.end(), more.begin(), more.end()); };
  add(in_child("delaunay", time_limit, [&](Child_meter& m) { measure_delaunay(m, in); }));
  if(o.pipeline)
    add(in_child("pipeline", time_limit, [&](Child_meter& m) { measure_pipeline(m, in, o.tmp); }));
  if(o.parts)
    add(in_child("parts", time_limit, [&](Child_meter& m) { measure_parts(m, in); }));
  if(o.jet && in.points.size() <= o.jet_max)
    add(in_child("jet", time_limit, [&](Child_meter& m) { measure_jet(m, in); }));
  if(!o.program.empty())
    add(measure_program(o.program, in, o.tmp, time_limit));
  report(csv, in.name, in.points.size(), load_before, records);
}

// The truth of a sample for --write-points: `# spacing S`, then `H nx ny nz` per point.
template <class Sample>
void write_truth(const Sample& sample, const std::string& path)
{
  std::ofstream truth(path);
  truth.precision(17);
  truth << "# spacing " << sample.spacing << '\n';
  for(std::size_t i = 0; i < sample.normals.size(); ++i)
    truth << sample.mean_curvature[i] << ' ' << sample.normals[i].x() << ' ' << sample.normals[i].y() << ' '
          << sample.normals[i].z() << '\n';
  if(!truth)
    throw std::runtime_error("cannot write " + path);
}

} // namespace

int main(int argc, char* argv[])
{
  // as the program does; inherited by every child
  cas3::use_transparent_huge_pages(argv);
  cas3::use_one_malloc_arena();
  const Options o = parse(argc, argv);
#ifdef CGAL_LINKED_WITH_TBB
  // set before any child is forked, so that every child inherits it
  std::unique_ptr<tbb::global_control> thread_limit;
  if(o.threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, o.threads);
#else
  if(o.threads > 0)
  {
    std::cerr << "--threads needs a build with TBB\n";
    return EXIT_FAILURE;
  }
#endif
  std::printf("threads: %s\n", o.threads > 0 ? std::to_string(o.threads).c_str() : "TBB's default");
  // whether malloc asks for huge pages changes every stage's time where
  // the kernel gives them only on request (the manual, "The allocator")
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const char* arenas = std::getenv("MALLOC_ARENA_MAX");
  std::printf("GLIBC_TUNABLES: %s; malloc arenas: %s\n", tunables ? tunables : "unset",
              arenas ? arenas : "1 (cas3::use_one_malloc_arena())");
  std::ofstream csv = cas3_benchmark::open_csv(
    o.csv, argc, argv,
    "input,n,process,stage,group,wall_s,cpu_s,peak_added_mib,peak_process_mib,wall_us_per_point,"
    "cpu_us_per_point,wall_x_delaunay,cpu_x_delaunay,peak_added_x_delaunay,load_before,load_after,note");
  std::printf("wall and processor (cpu) time in s; xDT: ratio to the Delaunay build alone of the same points\n"
              "(wall to wall, cpu to cpu, peak to peak); peak+: the peak resident memory (VmHWM) of the stage\n"
              "less the child process's resident memory at its start; proc: VmHWM of the process\n");
  for(const std::string& kind : o.surfaces)
    for(std::size_t n : o.sizes)
    {
      if(kind != "noisy" && kind != "clean")
      {
        std::cerr << "unknown surface " << kind << " (noisy, clean)\n";
        return EXIT_FAILURE;
      }
      Input in;
      auto sample = cas3_analytic::ellipsoid_truth_sample<Point, Vector>(n, 1, 0.7, 0.4);
      if(kind == "noisy")
        cas3_analytic::add_normal_noise(sample, 0.1, 21);
      in.name = "ellipsoid 1:0.7:0.4 " + (kind == "noisy" ? std::string("noise 0.1 spacing") : std::string("clean"));
      in.points = std::move(sample.points);
      if(!o.write_points.empty())
      {
        in.kept = (fs::path(o.write_points) / ("ellipsoid_" + kind + "_" + std::to_string(n))).string();
        try
        {
          fs::create_directories(o.write_points);
          write_xyz(in.points, in.kept + ".xyz");
          write_truth(sample, in.kept + "_truth.txt");
        }
        catch(const std::exception& e)
        {
          std::cerr << e.what() << "\n";
          return EXIT_FAILURE;
        }
      }
      run(o, csv, in);
    }
  for(const std::string& f : o.files)
  {
    Input in;
    try
    {
      cas3::Point_cloud cloud = cas3::read_point_cloud(f);
      in.points.assign(cloud.points.begin(), cloud.points.end());
      in.normals.assign(cloud.normals.begin(), cloud.normals.end());
    }
    catch(const std::exception& e)
    {
      std::cerr << e.what() << "\n";
      return EXIT_FAILURE;
    }
    in.name = f.substr(f.find_last_of('/') + 1);
    run(o, csv, in);
  }
  return EXIT_SUCCESS;
}
