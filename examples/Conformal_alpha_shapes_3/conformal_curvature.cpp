// conformal_curvature: multi-scale curvature of a point cloud, end to end.
// Run with --help for the usage. Writes, into the output directory, one PLY
// surface per (scale, ring size) with per-vertex normal, curvatures and a
// colour ramp of the mean curvature, and one CSV with a row per input point
// per (scale, ring size); prints a summary table on stdout.
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
namespace fs = std::filesystem;
typedef CAS3::Multiscale_curvatures<K> Analysis;

namespace {

const char* const usage =
  "usage: conformal_curvature [INPUT] [--alpha LIST] [--rings LIST] [--estimator NAME]\n"
  "                           [--denoise MODE] [--denoise-neighbors K]\n"
  "                           [--extraction NAME] [--output DIR] [--quiet] [--help]\n"
  "\n"
  "Multi-scale curvature of a point cloud on its conformal alpha shape.\n"
  "  INPUT            .xyz, .pwn, .ply, .off or .obj (meshes: their vertices);\n"
  "                   default: the bundled Stanford bunny sample\n"
  "  --alpha LIST     comma list of scales: values (0.5), quantiles of the facet\n"
  "                   values (25%) and/or auto; default 10%,25%,35%,50%\n"
  "  --rings LIST     comma list of ring sizes >= 1; default 1,2\n"
  "  --estimator NAME quadric (default), euler-least-squares or paper\n"
  "  --denoise MODE   auto (default: smooth when the estimated noise exceeds\n"
  "                   0.02 x spacing), on or off\n"
  "  --denoise-neighbors K  neighbours of the smoothing jet fit; default: from\n"
  "                   the estimated noise (24 to 64)\n"
  "  --extraction NAME front (default: one sheet per part, open or closed)\n"
  "                   or solid (the boundary of the enclosed solid)\n"
  "  --output DIR     default ./conformal_curvature_out\n"
  "  --quiet          no progress and no summary\n"
  "Writes DIR/surface_<scale>_rings<k>.ply per scale and ring size, and\n"
  "DIR/curvatures.csv with one row per input point per (scale, ring size).\n";

// A failure with a one-line reason for the user.
struct Failure : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Options
{
  std::string input = CGAL_CAS3_DEFAULT_INPUT;
  std::vector<CAS3::Scale> scales = {CAS3::Scale::quantile(0.10), CAS3::Scale::quantile(0.25),
                                     CAS3::Scale::quantile(0.35), CAS3::Scale::quantile(0.50)};
  std::vector<int> rings = {1, 2};
  CAS3::Curvature_estimator estimator = CAS3::QUADRIC_FIT;
  CAS3::Denoising denoising = CAS3::AUTOMATIC_DENOISING;
  unsigned int denoising_neighbors = 0;  // 0: as the library's plan says
  CAS3::Surface_extraction extraction = CAS3::ADVANCING_FRONT;
  std::string output = "conformal_curvature_out";
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
      if(i + 1 >= argc)
        throw Failure("option " + arg + " needs a value");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h")
      o.help = true;
    else if(arg == "--quiet")
      o.quiet = true;
    else if(arg == "--alpha")
    {
      o.scales.clear();
      for(const std::string& item : split_list(value()))
        try { o.scales.push_back(CAS3::Scale::from_string(item)); }
        catch(const std::invalid_argument& e) { throw Failure(std::string("--alpha: ") + e.what()); }
    }
    else if(arg == "--rings")
    {
      o.rings.clear();
      for(const std::string& item : split_list(value()))
      {
        int k = 0;
        const auto r = std::from_chars(item.data(), item.data() + item.size(), k);
        if(r.ec != std::errc() || r.ptr != item.data() + item.size() || k < 1)
          throw Failure("--rings: not a ring size >= 1: '" + item + "'");
        o.rings.push_back(k);
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
        throw Failure("--denoise-neighbors: not a neighbour count >= 7: '" + item + "'");
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
      o.output = value();
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

std::vector<Point> read_input(const std::string& file)
{
  if(!fs::is_regular_file(file))
    throw Failure("cannot open " + file);
  std::string ext = fs::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if(ext != ".xyz" && ext != ".pwn" && ext != ".ply" && ext != ".off" && ext != ".obj")
    throw Failure("unknown input extension '" + ext + "' (.xyz, .pwn, .ply, .off, .obj)");
  // CGAL's readers explain a failure on std::cerr: keep it for our one line
  std::ostringstream reader_messages;
  std::streambuf* const cerr_buffer = std::cerr.rdbuf(reader_messages.rdbuf());
  std::vector<Point> points;
  bool ok = false;
  if(ext == ".obj")
  {
    std::vector<std::vector<std::size_t> > faces;
    ok = CGAL::IO::read_OBJ(file, points, faces);
  }
  else
    ok = CGAL::IO::read_points(file, std::back_inserter(points));
  std::cerr.rdbuf(cerr_buffer);
  if(!ok)
  {
    std::string why = reader_messages.str();
    why = why.substr(0, why.find('\n'));
    throw Failure("cannot read " + file + ": not a valid " + ext.substr(1) + " file" +
                  (why.empty() ? std::string() : " (" + why + ")"));
  }
  if(points.empty())
    throw Failure(file + " holds no point");
  return points;
}

// Blue (concave) - white - red (convex) by mean curvature, grey where
// undefined; saturated at the 95th percentile of |H|.
void colour_by_mean_curvature(Analysis::Surface& surface)
{
  auto mean = surface.property_map<Analysis::Surface_vertex, double>("v:mean_curvature").first;
  std::vector<double> magnitude;
  for(auto v : surface.vertices())
    if(std::isfinite(mean[v]))
      magnitude.push_back(std::abs(mean[v]));
  double saturation = 1;
  if(!magnitude.empty())
  {
    std::nth_element(magnitude.begin(), magnitude.begin() + std::ptrdiff_t(magnitude.size() * 95 / 100),
                     magnitude.end());
    saturation = magnitude[magnitude.size() * 95 / 100];
  }
  auto colour = surface.add_property_map<Analysis::Surface_vertex, CGAL::IO::Color>("v:color").first;
  for(auto v : surface.vertices())
  {
    if(!std::isfinite(mean[v]) || !(saturation > 0))
    {
      colour[v] = CGAL::IO::Color(128, 128, 128);
      continue;
    }
    const double t = std::max(-1.0, std::min(1.0, mean[v] / saturation));
    const unsigned char fade = static_cast<unsigned char>(255 * (1 - std::abs(t)) + 0.5);
    colour[v] = t >= 0 ? CGAL::IO::Color(255, fade, fade) : CGAL::IO::Color(fade, fade, 255);
  }
}

// Appends a number the shortest way that reads back exactly.
void append(std::string& out, double x)
{
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
  out.append(buffer, r.ptr);
}

void append_csv_rows(std::ostream& csv, const std::vector<Point>& points, double alpha, int rings,
                     const std::vector<CAS3::Point_curvature<K> >& curvatures)
{
  std::string line;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const CAS3::Point_curvature<K>& c = curvatures[i];
    line.clear();
    line += std::to_string(i);
    for(double x : {points[i].x(), points[i].y(), points[i].z(), alpha})
    {
      line += ',';
      append(line, x);
    }
    line += ',' + std::to_string(rings) + (c.on_surface ? ",1" : ",0");
    for(double x : {c.normal.x(), c.normal.y(), c.normal.z(), c.mean_curvature, c.gaussian_curvature,
                    c.principal.max_curvature, c.principal.min_curvature, c.principal.max_direction.x(),
                    c.principal.max_direction.y(), c.principal.max_direction.z(), c.principal.min_direction.x(),
                    c.principal.min_direction.y(), c.principal.min_direction.z()})
    {
      line += ',';
      append(line, x);
    }
    line += '\n';
    csv << line;
  }
}

std::string quantiles(std::vector<double> values)
{
  values.erase(std::remove_if(values.begin(), values.end(), [](double x) { return !std::isfinite(x); }),
               values.end());
  if(values.empty())
    return "            -            -            -";
  std::sort(values.begin(), values.end());
  char text[64];
  auto at = [&](double q) { return values[std::size_t(q * double(values.size() - 1))]; };
  std::snprintf(text, sizeof text, " %12.4g %12.4g %12.4g", at(0.05), at(0.5), at(0.95));
  return text;
}

// Files are written under temporary names and renamed when the whole run
// succeeded, so that a failed run leaves no partial results behind.
class Output
{
public:
  explicit Output(const std::string& dir) : m_dir(dir)
  {
    std::error_code error;
    fs::create_directories(m_dir, error);
    if(!fs::is_directory(m_dir))
      throw Failure("cannot create the output directory " + dir);
  }
  ~Output()
  {
    std::error_code ignored;
    for(const auto& f : m_files)
      fs::remove(temporary(f), ignored);
  }
  std::ofstream open(const std::string& name, bool binary)
  {
    m_files.push_back(name);
    std::ofstream out(temporary(name), binary ? std::ios::binary : std::ios::out);
    if(!out)
      throw Failure("cannot write into the output directory " + m_dir.string());
    return out;
  }
  void commit()
  {
    for(const auto& f : m_files)
      fs::rename(temporary(f), m_dir / f);
    m_files.clear();
  }

private:
  fs::path temporary(const std::string& name) const { return m_dir / ("." + name + ".partial"); }
  fs::path m_dir;
  std::vector<std::string> m_files;
};

std::string file_label(const CAS3::Scale& s)
{
  std::string label = s.label();
  if(!label.empty() && label.back() == '%')
    label = label.substr(0, label.size() - 1) + "pct";
  return label;
}

int run(const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  auto progress = [&](const std::string& what) {
    if(!o.quiet && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > 1.0)
      std::cerr << "conformal_curvature: " << what << std::endl;
  };

  const std::vector<Point> points = read_input(o.input);
  progress("read " + std::to_string(points.size()) + " points");
  std::unique_ptr<Analysis> analysis;
  try
  {
    const auto np = CAS3::parameters::denoising(o.denoising, CAS3::parameters::surface_extraction(o.extraction));
    analysis = o.denoising_neighbors > 0
      ? std::make_unique<Analysis>(points.begin(), points.end(), CAS3::parameters::denoising_neighbors(o.denoising_neighbors, np))
      : std::make_unique<Analysis>(points.begin(), points.end(), np);
  }
  catch(const std::invalid_argument& e) { throw Failure(o.input + ": " + e.what()); }
  progress("built the conformal alpha shape");

  Output output(o.output);
  std::ofstream csv = output.open("curvatures.csv", false);
  csv << "point_index,x,y,z,alpha_hat,rings,on_surface,nx,ny,nz,H,K,k1,k2,d1x,d1y,d1z,d2x,d2y,d2z\n";
  std::ostringstream summary;
  char noise[200];
  const CAS3::Denoising_plan& smoothing = analysis->denoising();
  std::snprintf(noise, sizeof noise, "noise: %.3g x spacing (spacing %.4g)%s; ", analysis->noise().noise,
                analysis->noise().spacing,
                analysis->noise().noise_24 > 1.3 * analysis->noise().noise ? ", mostly unresolved detail" : "");
  std::string smoothing_text = smoothing.passes == 0 ? std::string("no smoothing\n")
    : "smoothed by " + std::to_string(smoothing.passes) + " jet pass(es) over "
        + std::to_string(smoothing.neighbors) + " neighbours before building the shape\n";
  summary << o.input << ": " << points.size() << " points\n" << noise << smoothing_text
          << "surface: " << (o.extraction == CAS3::ADVANCING_FRONT ? "advancing front" : "solid boundary")
          << "; orientation: "
          << (analysis->has_reference_normals() ? "the majority of the input normals, per part"
                                                : "closed parts outward, open parts away from the centre")
          << "\n"
          << "scale      alpha_hat   rings  on surface     faces    H:  5%          50%          95%"
             "      K:  5%          50%          95%\n";
  for(const CAS3::Scale& scale : o.scales)
  {
    const double alpha = analysis->alpha(scale);
    Analysis::Surface surface;
    const CAS3::Surface_report report = analysis->extract_surface(alpha, surface);
    progress("scale " + scale.label() + ": surface of " + std::to_string(report.number_of_faces) + " faces");
    summary << "scale " << scale.label() << ": " << report.number_of_parts << " parts (" << report.number_of_closed_parts
            << " closed, " << report.number_of_open_parts() << " open), "
            << report.number_of_points_off_surface << " points off the surface\n";
    for(int k : o.rings)
    {
      const auto curvatures = analysis->estimate_curvatures(surface, k, o.estimator);
      colour_by_mean_curvature(surface);
      std::ofstream ply = output.open("surface_" + file_label(scale) + "_rings" + std::to_string(k) + ".ply", true);
      CGAL::IO::set_mode(ply, CGAL::IO::BINARY);
      if(!CGAL::IO::write_PLY(ply, surface) || !ply)
        throw Failure("cannot write into the output directory " + o.output);
      append_csv_rows(csv, points, alpha, k, curvatures);
      if(!csv)
        throw Failure("cannot write into the output directory " + o.output);

      std::vector<double> H, Kg;
      std::size_t on = 0;
      for(const auto& c : curvatures)
      {
        on += c.on_surface ? 1 : 0;
        H.push_back(c.mean_curvature);
        Kg.push_back(c.gaussian_curvature);
      }
      char row[96];
      std::snprintf(row, sizeof row, "%-8s %12.5g %5d %8zu %5.1f%% %9zu", scale.label().c_str(), alpha, k, on,
                    100.0 * double(on) / double(points.size()), report.number_of_faces);
      summary << row << "  " << quantiles(H) << "  " << quantiles(Kg) << "\n";
      progress("scale " + scale.label() + ", rings " + std::to_string(k) + ": curvature written");
    }
  }
  csv.close();
  if(!csv)
    throw Failure("cannot write into the output directory " + o.output);
  output.commit();
  if(!o.quiet)
    std::cout << summary.str() << "results in " << o.output << "\n";
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char* argv[])
{
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
