// conformal_curvature: multi-scale curvature of a point cloud, end to end.
// Run with --help for the usage. Writes, into the output directory, a binary
// PLY point cloud with every input point's values at every scale and
// neighborhood, one binary PLY surface per scale with the same values per
// vertex, and on request a CSV with a row per input point per layer; prints
// a summary table on stdout.
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cas3_curvature_output.h"
#include "cas3_layer_names.h"
#include "cas3_malloc_policy.h"
#include "cas3_read_point_cloud.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <unistd.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
namespace fs = std::filesystem;
typedef CAS3::Multiscale_curvatures<K> Analysis;

namespace {

const char* const usage =
  "usage: conformal_curvature [INPUT] [--alpha LIST] [--radius LIST] [--rings LIST]\n"
  "                           [--estimator NAME] [--denoise MODE] [--denoise-neighbors K]\n"
  "                           [--extraction NAME] [--output DIR] [--csv] [--quiet] [--help]\n"
  "\n"
  "Multi-scale curvature of a point cloud on its conformal alpha shape.\n"
  "  INPUT            .xyz, .pwn, .ply, .off or .obj (meshes: their vertices);\n"
  "                   default: the bundled Stanford bunny sample\n"
  "  --alpha LIST     comma list of conformal scales a: values > 0 (0.5),\n"
  "                   quantiles of the facet values in (0%, 100%] (25%; the\n"
  "                   paper's figures use 10%,25%,35%,50%) and/or auto; default auto\n"
  "  --radius LIST    comma list of neighborhood radii of the curvature fit:\n"
  "                   model units (0.01), multiples of the measured sample\n"
  "                   spacing (4s) and/or auto (chosen per point from the data);\n"
  "                   default auto,2s,4s,8s,16s unless --rings is given\n"
  "  --rings LIST     comma list of ring sizes from 1 to 100, instead of or\n"
  "                   besides radii\n"
  "  --estimator NAME quadric (default), euler-least-squares or paper\n"
  "  --denoise MODE   auto (default: smooth when the estimated noise exceeds\n"
  "                   0.02 x spacing), on or off\n"
  "  --denoise-neighbors K  neighbors of the smoothing jet fit; default: from\n"
  "                   the estimated noise (24 to 64)\n"
  "  --extraction NAME front (default: one sheet per part, open or closed)\n"
  "                   or solid (the boundary of the enclosed solid)\n"
  "  --output DIR     default ./conformal_curvature_out\n"
  "  --csv            also write DIR/curvatures.csv, a row per point per layer\n"
  "  --quiet          no progress and no summary\n"
  "Writes DIR/curvatures.ply (binary point cloud: per point x y z, outlier,\n"
  "and per layer L = [scale_]neighborhood, e.g. r4s or 25pct_k2: nx_L ny_L\n"
  "nz_L H_L K_L k1_L k2_L d1x_L .. d2z_L radius_L distance_L source_L, where\n"
  "source 0 = the point's own surface vertex, 1 = the nearest surface point,\n"
  "2 = no value) and DIR/surface_<scale>.ply per scale.\n"
  "The points are recentered and rescaled before the work (results are in the\n"
  "input's units); isolated far outliers are left out and get outlier = 1.\n"
  "A failed run exits with status 1 and one line on stderr, and leaves DIR\n"
  "as it was.\n"
  "Where the kernel gives transparent huge pages only on request, the program\n"
  "starts itself again with glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES\n"
  "(faster on large inputs), unless GLIBC_TUNABLES names that tunable already\n"
  "(glibc.malloc.hugetlb=0 keeps malloc's default).\n";

// A failure with a one-line reason for the user.
struct Failure : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Options
{
  std::string input = CGAL_CAS3_DEFAULT_INPUT;
  std::vector<CAS3::Scale> scales = CAS3::default_scales();
  std::vector<CAS3::Neighborhood> neighborhoods = CAS3::default_neighborhoods();
  bool neighborhoods_given = false;
  CAS3::Curvature_estimator estimator = CAS3::QUADRIC_FIT;
  CAS3::Denoising denoising = CAS3::AUTOMATIC_DENOISING;
  unsigned int denoising_neighbors = 0;  // 0: as the library's plan says
  CAS3::Surface_extraction extraction = CAS3::ADVANCING_FRONT;
  std::string output = "conformal_curvature_out";
  bool csv = false;
  bool quiet = false;
  bool help = false;
};

std::vector<std::string> split_list(const std::string& list)
{
  std::vector<std::string> items;
  std::stringstream in(list);
  std::string item;
  while(std::getline(in, item, ','))
    items.push_back(item);
  if(items.empty() || list.back() == ',' || std::find(items.begin(), items.end(), "") != items.end())
    throw Failure("empty item in the list '" + list + "'");
  return items;
}

Options parse(int argc, char* argv[])
{
  Options o;
  bool input_given = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc || (std::string(argv[i + 1]).rfind("--", 0) == 0))
        throw Failure("option " + arg + " needs a value");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h")
      o.help = true;
    else if(arg == "--quiet")
      o.quiet = true;
    else if(arg == "--csv")
      o.csv = true;
    else if(arg == "--alpha")
    {
      o.scales.clear();
      for(const std::string& item : split_list(value()))
      {
        try { o.scales.push_back(cas3::parse_scale(item)); }
        catch(const std::invalid_argument& e) { throw Failure(std::string("--alpha: ") + e.what()); }
        if(o.scales.back().kind() != CAS3::Scale::AUTOMATIC && !(o.scales.back().value() > 0))
          throw Failure("--alpha: a scale must be above 0 (a value > 0 or a quantile in (0%, 100%]): '" + item + "'");
      }
    }
    else if(arg == "--rings" || arg == "--radius")
    {
      if(!o.neighborhoods_given)
        o.neighborhoods.clear();
      o.neighborhoods_given = true;
      for(const std::string& item : split_list(value()))
      {
        if(arg == "--radius")
        {
          try { o.neighborhoods.push_back(cas3::parse_radius(item)); }
          catch(const std::invalid_argument& e) { throw Failure(std::string("--radius: ") + e.what()); }
          continue;
        }
        int k = 0;
        const auto r = std::from_chars(item.data(), item.data() + item.size(), k);
        if(r.ec != std::errc() || r.ptr != item.data() + item.size() || k < 1 || k > 100)
          throw Failure("--rings: not a ring size from 1 to 100: '" + item + "'");
        o.neighborhoods.push_back(CAS3::Neighborhood::rings(k));
      }
    }
    else if(arg == "--estimator")
    {
      const std::string name = value();
      if(name == "quadric") o.estimator = CAS3::QUADRIC_FIT;
      else if(name == "euler-least-squares") o.estimator = CAS3::EULER_LEAST_SQUARES_FIT;
      else if(name == "paper") o.estimator = CAS3::PAPER_EULER_FIT;
      else throw Failure("--estimator: unknown estimator '" + name + "' (quadric, euler-least-squares, paper)");
    }
    else if(arg == "--denoise")
    {
      const std::string mode = value();
      if(mode == "auto") o.denoising = CAS3::AUTOMATIC_DENOISING;
      else if(mode == "on") o.denoising = CAS3::ALWAYS_DENOISE;
      else if(mode == "off") o.denoising = CAS3::NEVER_DENOISE;
      else throw Failure("--denoise: unknown mode '" + mode + "' (auto, on, off)");
    }
    else if(arg == "--denoise-neighbors")
    {
      const std::string item = value();
      unsigned int k = 0;
      const auto r = std::from_chars(item.data(), item.data() + item.size(), k);
      if(r.ec != std::errc() || r.ptr != item.data() + item.size() || k < 7)
        throw Failure("--denoise-neighbors: not a neighbor count >= 7: '" + item + "'");
      o.denoising_neighbors = k;
    }
    else if(arg == "--extraction")
    {
      const std::string name = value();
      if(name == "front") o.extraction = CAS3::ADVANCING_FRONT;
      else if(name == "solid") o.extraction = CAS3::SOLID_BOUNDARY;
      else throw Failure("--extraction: unknown extraction '" + name + "' (front, solid)");
    }
    else if(arg == "--output")
    {
      o.output = value();
      if(o.output.empty())
        throw Failure("--output: empty directory name");
    }
    else if(!arg.empty() && arg[0] == '-')
      throw Failure("unknown option " + arg);
    else if(input_given)
      throw Failure("more than one input file: " + o.input + ", " + arg);
    else
    {
      o.input = arg;
      input_given = true;
    }
  }
  return o;
}

// Appends a number the shortest way that reads back exactly.
void append(std::string& out, double x)
{
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
  out.append(buffer, r.ptr);
}

const char* const csv_header =
  "point_index,x,y,z,a,rings,on_surface,nx,ny,nz,H,K,k1,k2,d1x,d1y,d1z,d2x,d2y,d2z,outlier,"
  "neighborhood,radius,source,distance\n";

void append_csv_rows(std::ostream& csv, const std::vector<Point>& points, double a,
                     const CAS3::Neighborhood& neighborhood, const std::vector<CAS3::Point_curvature<K> >& curvatures,
                     const std::vector<bool>& outlier)
{
  const std::string rings =
    neighborhood.kind() == CAS3::Neighborhood::RINGS ? std::to_string(int(neighborhood.value())) : "0";
  const std::string label = cas3::neighborhood_label(neighborhood);
  std::string line;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const CAS3::Point_curvature<K>& c = curvatures[i];
    line.clear();
    line += std::to_string(i);
    for(double x : {points[i].x(), points[i].y(), points[i].z(), a})
    {
      line += ',';
      append(line, x);
    }
    line += ',' + rings + (c.on_surface() ? ",1" : ",0");
    for(double x : {c.normal.x(), c.normal.y(), c.normal.z(), c.mean_curvature, c.gaussian_curvature,
                    c.principal.max_curvature, c.principal.min_curvature, c.principal.max_direction.x(),
                    c.principal.max_direction.y(), c.principal.max_direction.z(), c.principal.min_direction.x(),
                    c.principal.min_direction.y(), c.principal.min_direction.z()})
    {
      line += ',';
      append(line, x);
    }
    line += outlier[i] ? ",1," : ",0,";
    line += label + ',';
    append(line, c.radius);
    line += ',' + std::to_string(int(c.source)) + ',';
    append(line, c.distance);
    line += '\n';
    csv << line;
  }
}

// Files are written into a private temporary directory and moved into the
// output directory only when the whole run succeeded, so that a failed run
// leaves the output directory as it was: no partial or hidden files, and no
// directory when the run created it. A fatal signal (a crash) removes the
// temporary files too. The output directory is created and probed for
// writing before any work starts.
namespace cleanup {
// async-signal-safe state for the fatal-signal handler
char temporary_dir[4096] = "";
char files[64][4096];
volatile std::sig_atomic_t number_of_files = 0;
char created_dirs[16][4096];  // the directories this run created, deepest first
volatile std::sig_atomic_t number_of_created_dirs = 0;

extern "C" void on_fatal_signal(int sig)
{
  for(int i = 0; i < number_of_files; ++i)
    ::unlink(files[i]);
  if(temporary_dir[0])
    ::rmdir(temporary_dir);
  for(int i = 0; i < number_of_created_dirs; ++i)
    ::rmdir(created_dirs[i]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void copy(char* to, const std::string& from)
{
  std::strncpy(to, from.c_str(), 4095);
  to[4095] = 0;
}
} // namespace cleanup

class Output
{
public:
  explicit Output(const std::string& dir) : m_dir(dir)
  {
    std::error_code error;
    const bool existed = fs::exists(m_dir, error);
    if(existed && !fs::is_directory(m_dir, error))
      throw Failure("cannot create the output directory " + dir + ": a file of that name exists");
    if(!existed)
    {
      // remember the levels we create, to remove them on failure
      std::vector<fs::path> created;
      for(fs::path p = fs::absolute(m_dir, error); !p.empty() && !fs::exists(p, error); p = p.parent_path())
      {
        created.push_back(p);
        if(p == p.parent_path())
          break;
      }
      fs::create_directories(m_dir, error);
      if(!fs::is_directory(m_dir, error))
        throw Failure("cannot create the output directory " + dir);
      m_created = created.empty() ? fs::path() : created.back();
      for(std::size_t i = 0; i < created.size() && i < 16; ++i)
        cleanup::copy(cleanup::created_dirs[i], created[i].string());
      cleanup::number_of_created_dirs = int((std::min)(created.size(), std::size_t(16)));
    }
    // probe: can we create and rename files there?
    const fs::path probe = m_dir / (".conformal_curvature_probe_" + std::to_string(::getpid()));
    {
      std::ofstream out(probe);
      out << "probe";
      out.close();
      if(!out)
      {
        fs::remove(probe, error);
        remove_created();
        throw Failure("cannot write into the output directory " + dir);
      }
    }
    fs::remove(probe, error);

    std::string templ = (fs::temp_directory_path(error) / "conformal_curvature_XXXXXX").string();
    if(::mkdtemp(&templ[0]) == nullptr)
    {
      remove_created();
      throw Failure("cannot create a temporary directory in " + fs::temp_directory_path(error).string());
    }
    m_temporary = templ;
    cleanup::copy(cleanup::temporary_dir, templ);
    for(int sig : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL, SIGINT, SIGTERM})
      std::signal(sig, cleanup::on_fatal_signal);
  }
  ~Output()
  {
    std::error_code ignored;
    cleanup::number_of_files = 0;
    cleanup::temporary_dir[0] = 0;
    fs::remove_all(m_temporary, ignored);
    if(!m_committed)
      remove_created();
    cleanup::number_of_created_dirs = 0;
  }
  std::ofstream open(const std::string& name, bool binary)
  {
    m_files.push_back(name);
    if(cleanup::number_of_files < 64)
    {
      cleanup::copy(cleanup::files[cleanup::number_of_files], (m_temporary / name).string());
      cleanup::number_of_files = cleanup::number_of_files + 1;
    }
    std::ofstream out(m_temporary / name, binary ? std::ios::binary : std::ios::out);
    if(!out)
      throw Failure("cannot write a temporary file into " + m_temporary.string());
    return out;
  }
  void commit()
  {
    for(const auto& f : m_files)
    {
      std::error_code error;
      fs::rename(m_temporary / f, m_dir / f, error);
      if(error)  // another file system: copy
      {
        fs::copy_file(m_temporary / f, m_dir / f, fs::copy_options::overwrite_existing, error);
        if(error)
          throw Failure("cannot write into the output directory " + m_dir.string());
      }
    }
    m_committed = true;
  }

private:
  void remove_created()
  {
    std::error_code ignored;
    if(!m_created.empty())
      fs::remove_all(m_created, ignored);
    m_created.clear();
  }
  fs::path m_dir, m_temporary, m_created;
  std::vector<std::string> m_files;
  bool m_committed = false;
};

int run(const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  auto progress = [&](const std::string& what) {
    if(!o.quiet && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > 1.0)
      std::cerr << "conformal_curvature: " << what << std::endl;
  };

  Output output(o.output);  // before any work: an unwritable folder fails first
  const cas3::Point_cloud cloud = cas3::read_point_cloud(o.input);
  const std::vector<Point>& points = cloud.points;
  progress("read " + std::to_string(points.size()) + " points");
  // the library recenters, rescales and leaves isolated far outliers out
  // (see the manual, section "Input Rules")
  std::unique_ptr<Analysis> analysis;
  try
  {
    const auto np = CAS3::parameters::reference_normals(std::cref(cloud.normals),
      CAS3::parameters::denoising(o.denoising, CAS3::parameters::surface_extraction(o.extraction)));
    analysis = o.denoising_neighbors > 0
      ? std::make_unique<Analysis>(points.begin(), points.end(),
                                   CAS3::parameters::denoising_neighbors(o.denoising_neighbors, np))
      : std::make_unique<Analysis>(points.begin(), points.end(), np);
  }
  catch(const std::invalid_argument& e) { throw Failure(o.input + ": " + e.what()); }
  const std::vector<std::size_t>& outliers = analysis->outliers();
  std::vector<bool> is_outlier(points.size(), false);
  for(std::size_t i : outliers)
    is_outlier[i] = true;
  if(!outliers.empty())
    progress(std::to_string(outliers.size()) + " isolated far outliers left out");
  progress("built the conformal alpha shape");

  std::ofstream csv;
  if(o.csv)
  {
    csv = output.open("curvatures.csv", false);
    csv << csv_header;
  }
  std::ostringstream summary;
  char noise[200];
  const CAS3::Denoising_plan& smoothing = analysis->denoising();
  std::snprintf(noise, sizeof noise, "noise: %.3g x spacing (spacing %.4g)%s; ", analysis->noise().noise,
                analysis->noise().spacing,
                analysis->noise().shows_unresolved_detail() ? ", mostly unresolved detail" : "");
  const std::string smoothing_text = smoothing.passes == 0 ? std::string("no smoothing\n")
    : "smoothed by " + std::to_string(smoothing.passes) + " jet pass(es) over "
        + std::to_string(smoothing.neighbors) + " neighbors before building the shape\n";
  summary << o.input << ": " << points.size() << " points";
  if(!outliers.empty())
    summary << ", " << outliers.size() << " isolated far outliers left out (outlier column)";
  summary << "\n" << noise << smoothing_text
          << "surface: " << (o.extraction == CAS3::ADVANCING_FRONT ? "advancing front" : "solid boundary")
          << "; orientation: "
          << (analysis->has_reference_normals()
                ? "the majority of the input normals, per sheet; values per point"
                : "closed sheets outward, open sheets away from the center, with those they continue across gaps")
          << "\n"
          << "layer               a  own vertex  nearest  no value  radius(median)"
             "    H:  5%          50%          95%      K:  5%          50%          95%\n";
  std::vector<cas3::Layer> layers;
  for(const CAS3::Scale& scale : o.scales)
  {
    const double a = analysis->scale_value(scale);
    Analysis::Surface surface;
    const CAS3::Surface_report report = analysis->extract_surface(a, surface);
    progress("scale " + cas3::scale_text(scale) + ": surface of " + std::to_string(report.number_of_faces) + " faces");
    summary << "scale " << cas3::scale_text(scale) << ": " << report.number_of_parts << " parts (" << report.number_of_closed_parts
            << " closed, " << report.number_of_open_parts() << " open), "
            << report.number_of_points_off_surface << " points off the surface\n";
    cas3::return_freed_memory();
    std::vector<std::vector<CAS3::Point_curvature<K> > > by_neighborhood =
      analysis->estimate_curvatures(surface, o.neighborhoods, o.estimator);
    for(std::size_t r = 0; r < o.neighborhoods.size(); ++r)
    {
      const CAS3::Neighborhood& neighborhood = o.neighborhoods[r];
      const std::vector<CAS3::Point_curvature<K> >& curvatures = by_neighborhood[r];
      cas3::Layer layer(curvatures);
      layer.label = cas3::layer_label(scale, neighborhood, o.scales.size() > 1);
      std::ostringstream description;
      description << "a = " << a << " (" << cas3::scale_text(scale) << "), ";
      if(neighborhood.kind() == CAS3::Neighborhood::RINGS)
        description << int(neighborhood.value()) << "-ring";
      else if(neighborhood.kind() == CAS3::Neighborhood::AUTOMATIC)
        description << "radius chosen per point (radius_" << layer.label << ")";
      else
        description << "radius " << analysis->radius(neighborhood);
      layer.description = description.str();
      if(o.csv)
      {
        append_csv_rows(csv, points, a, neighborhood, curvatures, is_outlier);
        if(!csv)
          throw Failure("cannot write into the output directory " + o.output);
      }
      summary << cas3::summary_row(layer.label, a, curvatures) << "\n";
      progress("layer " + layer.label + ": curvature estimated");
      layers.push_back(std::move(layer));
      // the layer keeps its values as floats: the doubles go now rather
      // than after the last layer
      std::vector<CAS3::Point_curvature<K> >().swap(by_neighborhood[r]);
    }
    if(!cloud.normals.empty())
    {
      // how far the oriented sheets follow the input normals, before each
      // point's values are turned to its own normal's side
      auto index = surface.property_map<Analysis::Surface_vertex, std::size_t>("v:input_index").first;
      auto normal = surface.property_map<Analysis::Surface_vertex, K::Vector_3>("v:normal").first;
      std::size_t agree = 0, compared = 0;
      for(auto v : surface.vertices())
        if(normal[v] != K::Vector_3(CGAL::NULL_VECTOR) && std::isfinite(normal[v].x()))
        {
          ++compared;
          agree += normal[v] * cloud.normals[index[v]] > 0 ? 1 : 0;
        }
      char line[160];
      std::snprintf(line, sizeof line,
                    "scale %s: the sheets agree with the input normals at %.1f%% of their vertices; "
                    "each point's values are on its own normal's side\n",
                    cas3::scale_text(scale).c_str(), compared == 0 ? 0.0 : 100.0 * double(agree) / double(compared));
      summary << line;
    }
    std::ofstream ply = output.open("surface_" + cas3::scale_label(scale) + ".ply", true);
    cas3::write_surface(ply, surface, points, layers.data() + (layers.size() - o.neighborhoods.size()),
                        layers.data() + layers.size());
    ply.close();
    if(!ply)
      throw Failure("cannot write into the output directory " + o.output);
  }
  std::ofstream cloud_ply = output.open("curvatures.ply", true);
  cas3::write_point_cloud(cloud_ply, points, is_outlier, layers);
  cloud_ply.close();
  if(!cloud_ply)
    throw Failure("cannot write into the output directory " + o.output);
  if(o.csv)
  {
    csv.close();
    if(!csv)
      throw Failure("cannot write into the output directory " + o.output);
  }
  output.commit();
  if(!o.quiet)
    std::cout << summary.str() << "results in " << o.output << "\n";
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char* argv[])
{
  cas3::use_transparent_huge_pages(argv);
  cas3::use_one_malloc_arena();
  try
  {
    const Options options = parse(argc, argv);
    if(options.help)
    {
      std::cout << usage;
      return EXIT_SUCCESS;
    }
    return run(options);
  }
  catch(const std::exception& e)  // a Failure, or a library error
  {
    std::cerr << "conformal_curvature: " << e.what() << "\n";
  }
  return EXIT_FAILURE;
}
