// conformal_match: matches the regions of one surface against those of
// another (region_descriptors.h, match_regions.h) from their multi-scale
// curvature, and registers the second onto the first; see the usage below
// and the manual's section "Matching Surface Regions".
#include <CGAL/Conformal_alpha_shapes_3/match_regions.h>
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>
#include <CGAL/Conformal_alpha_shapes_3/region_descriptors.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cas3_molecular_surface.h"
#include "cas3_output_transaction.h"
#include "cas3_read_point_cloud.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace {

namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef std::tuple<Point, Vector, Vector> Oriented_point;  // position, normal, the centre's normal

const char* const usage =
  "usage: conformal_match A B [--output DIR] [--radius LIST] [--rings LIST]\n"
  "                       [--centers N] [--candidates N] [--top K] [--tolerance T]\n"
  "                       [--region INDEX] [--chains-a IDS] [--chains-b IDS]\n"
  "                       [--spacing H] [--quiet]\n"
  "\n"
  "Finds, for regions of surface A, the regions of surface B that look alike\n"
  "by their curvature (histograms of shape index and curvedness at every\n"
  "radius, and of the normals' angles and heights, in rings around each\n"
  "centre), and the rigid motion placing B onto A that those matches give.\n"
  "A and B are point clouds (.xyz, .pwn, .ply, .off, .obj, .las; with\n"
  "normals when the file has them) or PDB files (.pdb, .ent), whose molecular\n"
  "surface is sampled as molecular_surface_points does (the skin, with\n"
  "normals). Lengths are in the points' units (angstroms for PDB files).\n"
  "\n"
  "  --output DIR      the output directory, default conformal_match_output:\n"
  "                    matches.csv (per centre of A and rank: A's point index\n"
  "                    and position, B's candidate index and position, the\n"
  "                    descriptors' distance, whether the registration places\n"
  "                    the candidate within the tolerance), similarity.ply (B's\n"
  "                    points with the similarity of each to the region of A\n"
  "                    at --region, 1 for identical descriptors, 0 for the most\n"
  "                    different) and summary.txt (also printed)\n"
  "  --radius LIST     the curvature's neighborhood radii, default 1.5,3,6,9,12;\n"
  "                    the centres' tangent planes come from the radius nearest 3\n"
  "  --rings LIST      the rings' outer radii, default 2,4,6,8,10,12,14\n"
  "  --centers N       farthest-point centres on A, default 300\n"
  "  --candidates N    farthest-point candidates on B, default 2000\n"
  "  --top K           candidates per centre, default 10\n"
  "  --tolerance T     the registration's inlier distance, default 3\n"
  "  --region INDEX    the point of A whose region's similarity over B is\n"
  "                    written, default 0 (the first centre)\n"
  "  --chains-a IDS, --chains-b IDS  PDB files: keep only these chains\n"
  "  --spacing H       PDB files: the sample's spacing, default 0.4\n"
  "  --quiet           no summary on the standard output\n";

struct Options
{
  std::string a, b, output = "conformal_match_output", chains_a, chains_b;
  std::vector<double> radii{1.5, 3, 6, 9, 12}, rings{2, 4, 6, 8, 10, 12, 14};
  std::size_t centers = 300, candidates = 2000, top = 10, region = 0;
  double tolerance = 3, spacing = 0.4;
  bool quiet = false, help = false;
};

double number(const std::string& option, const std::string& text)
{
  std::size_t used = 0;
  double v = 0;
  try { v = std::stod(text, &used); }
  catch(const std::exception&) { used = 0; }
  if(used == 0 || used != text.size() || !std::isfinite(v))
    throw std::invalid_argument(option + ": not a number: '" + text + "'");
  return v;
}

double positive(const std::string& option, const std::string& text)
{
  const double v = number(option, text);
  if(!(v > 0))
    throw std::invalid_argument(option + ": must be > 0: '" + text + "'");
  return v;
}

std::size_t count(const std::string& option, const std::string& text, std::size_t least)
{
  const double v = number(option, text);
  if(v != std::floor(v) || v < double(least) || v > 1e12)
    throw std::invalid_argument(option + ": must be an integer >= " + std::to_string(least) + ": '" + text + "'");
  return std::size_t(v);
}

std::vector<double> increasing_list(const std::string& option, const std::string& text)
{
  std::vector<double> values;
  std::stringstream in(text);
  for(std::string item; std::getline(in, item, ',');)
    values.push_back(positive(option, item));
  for(std::size_t k = 1; k < values.size(); ++k)
    if(!(values[k] > values[k - 1]))
      throw std::invalid_argument(option + ": the values must increase: '" + text + "'");
  if(values.empty())
    throw std::invalid_argument(option + ": no value");
  return values;
}

Options parse(int argc, char* argv[])
{
  Options o;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::invalid_argument(arg + ": needs a value");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h") o.help = true;
    else if(arg == "--output") o.output = value();
    else if(arg == "--radius") o.radii = increasing_list(arg, value());
    else if(arg == "--rings") o.rings = increasing_list(arg, value());
    else if(arg == "--centers") o.centers = count(arg, value(), 1);
    else if(arg == "--candidates") o.candidates = count(arg, value(), 1);
    else if(arg == "--top") o.top = count(arg, value(), 1);
    else if(arg == "--tolerance") o.tolerance = positive(arg, value());
    else if(arg == "--region") o.region = count(arg, value(), 0);
    else if(arg == "--chains-a") o.chains_a = value();
    else if(arg == "--chains-b") o.chains_b = value();
    else if(arg == "--spacing")
    {
      o.spacing = positive(arg, value());
      if(o.spacing < 0.05)
        throw std::invalid_argument("--spacing: below 0.05");
    }
    else if(arg == "--quiet") o.quiet = true;
    else if(!arg.empty() && arg[0] == '-')
      throw std::invalid_argument("unknown option " + arg + " (see --help)");
    else
      files.push_back(arg);
  }
  if(!o.help && files.size() != 2)
    throw std::invalid_argument("expected two input files, A and B (see --help)");
  if(!o.help)
  {
    o.a = files[0];
    o.b = files[1];
  }
  return o;
}

// A surface's points and normals (empty when the file has none).
cas3::Point_cloud read_surface(const std::string& path, const std::string& chains, double spacing)
{
  const std::string extension = cas3::read_detail::lower_extension(path);
  cas3::Point_cloud cloud;
  if(extension == ".pdb" || extension == ".ent")
  {
    cas3::Pdb_options pdb;
    for(char c : chains)
      if(c != ',')
        pdb.chains += c;
    cas3::Skin_surface_sample skin;
    cas3::sample_skin_surface(cas3::read_pdb(path, pdb), spacing, skin);
    cloud.points.assign(skin.sample.points.begin(), skin.sample.points.end());
    cloud.normals.assign(skin.sample.normals.begin(), skin.sample.normals.end());
  }
  else
  {
    if(!chains.empty())
      throw std::invalid_argument(path + ": --chains-a and --chains-b are for PDB files");
    cloud = cas3::read_point_cloud(path);
  }
  if(cloud.points.size() < 3)
    throw std::invalid_argument(path + ": " + std::to_string(cloud.points.size())
                                + " points, a surface needs at least 3");
  return cloud;
}

struct Described
{
  std::vector<Oriented_point> points;
  std::vector<std::vector<CAS3::Point_curvature<K> > > layers;
};

// The curvature layers of a surface at the radii, and its points with their
// normals (the file's, else the fitted ones) and the centres' normals.
Described curvature(const cas3::Point_cloud& cloud, const Options& o, const std::string& name)
{
  std::vector<CAS3::Neighborhood> neighborhoods;
  for(double r : o.radii)
    neighborhoods.push_back(CAS3::Neighborhood::radius(r));
  std::vector<CAS3::Curvature_layer<K> > layers;
  try
  {
    layers = CAS3::multiscale_curvatures(
      cloud.points, CAS3::parameters::neighborhoods(neighborhoods, CAS3::parameters::reference_normals(cloud.normals)));
  }
  catch(const std::invalid_argument& e) { throw std::runtime_error(name + ": " + e.what()); }
  std::size_t steady = 0;  // the layer whose radius is nearest 3
  for(std::size_t k = 0; k < o.radii.size(); ++k)
    if(std::abs(o.radii[k] - 3) < std::abs(o.radii[steady] - 3))
      steady = k;
  Described d;
  for(std::size_t i = 0; i < cloud.points.size(); ++i)
  {
    const Vector fitted = layers[steady].points[i].normal;
    d.points.emplace_back(cloud.points[i], cloud.normals.empty() ? fitted : cloud.normals[i], fitted);
  }
  for(auto& layer : layers)
    d.layers.push_back(std::move(layer.points));
  return d;
}

CAS3::Region_descriptors describe(const Described& d, const std::vector<std::size_t>& centers, const Options& o)
{
  return CAS3::region_descriptors<CGAL::Parallel_if_available_tag>(
    d.points, d.layers, centers,
    CAS3::parameters::ring_radii(o.rings, CAS3::parameters::center_normal_map(
      CGAL::Nth_of_tuple_property_map<2, Oriented_point>()))
      .point_map(CGAL::Nth_of_tuple_property_map<0, Oriented_point>())
      .normal_map(CGAL::Nth_of_tuple_property_map<1, Oriented_point>()));
}

std::vector<Point> positions(const Described& d)
{
  std::vector<Point> out;
  for(const Oriented_point& p : d.points)
    out.push_back(std::get<0>(p));
  return out;
}

int run(const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  const cas3::Point_cloud cloud_a = read_surface(o.a, o.chains_a, o.spacing);
  const cas3::Point_cloud cloud_b = read_surface(o.b, o.chains_b, o.spacing);
  if(o.region >= cloud_a.points.size())
    throw std::invalid_argument("--region: " + std::to_string(o.region) + " is not a point of " + o.a + " ("
                                + std::to_string(cloud_a.points.size()) + " points)");
  cas3::Output_transaction output(o.output);

  const Described a = curvature(cloud_a, o, o.a), b = curvature(cloud_b, o, o.b);
  const double curvature_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<std::size_t> centers = CAS3::farthest_point_sample(positions(a), o.centers);
  const std::vector<std::size_t> candidates = CAS3::farthest_point_sample(positions(b), o.candidates);
  const CAS3::Region_descriptors ra = describe(a, centers, o), rb = describe(b, candidates, o);
  const CAS3::Region_matches m = CAS3::match_regions<CGAL::Parallel_if_available_tag>(
    ra, rb, CAS3::parameters::number_of_candidates(o.top, CAS3::parameters::inlier_tolerance(o.tolerance)));
  // the region at --region against every point of B
  std::vector<std::size_t> all_b(b.points.size());
  for(std::size_t i = 0; i < all_b.size(); ++i)
    all_b[i] = i;
  const std::vector<double> distance = CAS3::histogram_distances<CGAL::Parallel_if_available_tag>(
    describe(a, {o.region}, o), describe(b, all_b, o), false);
  const double match_seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - curvature_seconds;

  std::ofstream csv = output.open("matches.csv", false);
  csv << "a_index,a_x,a_y,a_z,rank,b_index,b_x,b_y,b_z,score,inlier\n";
  char line[512];
  for(std::size_t i = 0; i < m.centers.size(); ++i)
    for(std::size_t k = 0; k < m.top; ++k)
    {
      const Point& p = std::get<0>(a.points[m.centers[i]]);
      const std::size_t j = m.candidates[i * m.top + k];
      const Point& q = std::get<0>(b.points[j]);
      const std::array<double, 3> placed = m.motion({q.x(), q.y(), q.z()});
      const double gap2 = CAS3::internal::squared_gap(placed, {p.x(), p.y(), p.z()});
      std::snprintf(line, sizeof(line), "%zu,%.6f,%.6f,%.6f,%zu,%zu,%.6f,%.6f,%.6f,%.6g,%d\n", m.centers[i], p.x(),
                    p.y(), p.z(), k + 1, j, q.x(), q.y(), q.z(), m.scores[i * m.top + k],
                    gap2 < o.tolerance * o.tolerance ? 1 : 0);
      csv << line;
    }
  output.close(csv);

  std::ofstream ply = output.open("similarity.ply", true);
  ply << "ply\nformat binary_little_endian 1.0\ncomment similarity to the region of " << o.a << " point "
      << o.region << "\nelement vertex " << b.points.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty float similarity\nend_header\n";
  for(std::size_t i = 0; i < b.points.size(); ++i)
  {
    const Point& q = std::get<0>(b.points[i]);
    const double xyz[3] = {q.x(), q.y(), q.z()};
    const float similarity = float(1 - distance[i]);
    ply.write(reinterpret_cast<const char*>(xyz), sizeof(xyz));
    ply.write(reinterpret_cast<const char*>(&similarity), sizeof(similarity));
  }
  output.close(ply);

  std::ostringstream summary;
  const CAS3::Rigid_motion& r = m.motion;
  std::snprintf(line, sizeof(line),
                "A: %s, %zu points, %zu centres\nB: %s, %zu points, %zu candidates\n"
                "registration of B onto A (x -> R x + t):\n  R = [[%.6f, %.6f, %.6f], [%.6f, %.6f, %.6f], "
                "[%.6f, %.6f, %.6f]]\n  t = [%.4f, %.4f, %.4f]\n  consistent: %.3f of the centres' best matches\n"
                "time: reading (and sampling) and curvature %.1f s, descriptors and matching %.1f s\n",
                o.a.c_str(), a.points.size(), centers.size(), o.b.c_str(), b.points.size(), candidates.size(),
                r.rotation[0][0], r.rotation[0][1], r.rotation[0][2], r.rotation[1][0], r.rotation[1][1],
                r.rotation[1][2], r.rotation[2][0], r.rotation[2][1], r.rotation[2][2], r.translation[0],
                r.translation[1], r.translation[2], m.consistent, curvature_seconds, match_seconds);
  summary << line;
  std::ofstream text = output.open("summary.txt", false);
  text << summary.str();
  output.close(text);
  output.commit();
  if(!o.quiet)
    std::cout << summary.str();
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
  catch(const std::exception& e)  // one line: a bad option, input or output, or a library error
  {
    std::cerr << "conformal_match: " << e.what() << "\n";
  }
  return EXIT_FAILURE;
}
