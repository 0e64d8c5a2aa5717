// molecular_surface_points: a point sample of the surface of a molecule from
// a PDB file, written as .xyz for conformal_curvature. Run with --help for
// the usage; the sampling is described in include/cas3_molecular_surface.h
// and in the manual's section "Molecular surfaces".
#include "cas3_molecular_surface.h"

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/IO/Polyhedron_iostream.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

typedef cas3::Molecule_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;

namespace {

const char* const usage =
  "usage: molecular_surface_points INPUT.pdb [OUTPUT.xyz] [--method NAME]\n"
  "                                [--spacing H] [--shrink S] [--probe P] [--normals]\n"
  "                                [--hydrogens] [--water] [--default-radius R]\n"
  "                                [--model N] [--chains IDS] [--no-hetatm]\n"
  "                                [--cavities] [--mesh FILE.off] [--check] [--expect-points MIN,MAX]\n"
  "                                [--stats] [--quiet] [--help]\n"
  "\n"
  "Samples the surface of the molecule of a PDB file (ATOM and HETATM records,\n"
  "one model; Bondi van der Waals radii by element) and writes the points,\n"
  "one 'x y z' line each (angstroms), for conformal_curvature.\n"
  "  OUTPUT.xyz        default: INPUT with the extension .xyz\n"
  "  --method NAME     skin (default): the skin surface of the van der Waals balls,\n"
  "                    a smooth molecular surface;\n"
  "                    vdw: the van der Waals spheres' exposed parts;\n"
  "                    sas: the exposed parts of the spheres of radius r + probe\n"
  "  --shrink S        shrink factor of the skin in (0, 1), default 0.35: smaller\n"
  "                    fills the crevices between atoms more\n"
  "  --spacing H       minimum distance between points, default 0.4\n"
  "  --probe P         probe radius of sas (and of the --stats comparison), 1.4\n"
  "  --normals         write 'x y z nx ny nz' with outward unit normals\n"
  "  --hydrogens       keep hydrogen atoms (left out by default)\n"
  "  --water           keep waters (HOH, WAT, H2O, DOD, SOL; left out by default)\n"
  "  --default-radius R  radius of elements without a Bondi radius (Fe, Ca, ...),\n"
  "                    default 2.0; 0: such an element is an error\n"
  "  --model N         the model of MODEL serial number N (default: the first)\n"
  "  --chains IDS      keep only these chains: A, AB or A,B (default: all)\n"
  "  --no-hetatm       leave out HETATM records (ligands, ions, waters)\n"
  "  --cavities        skin only: keep the surfaces of cavities inside the molecule\n"
  "                    (closed sheets facing inward; left out by default)\n"
  "  --mesh FILE.off   skin only: write the subdivided skin mesh (the reference)\n"
  "  --check           verify the sample (spacing, unit outward normals, points\n"
  "                    on their sphere and outside all others; for the skin:\n"
  "                    outside every van der Waals ball, near the atoms);\n"
  "                    exit status 1 on a failure\n"
  "  --expect-points MIN,MAX  with --check: the number of points in [MIN, MAX]\n"
  "  --stats           print the spacing, the normals' smoothness and the distance\n"
  "                    to the solvent-excluded surface of the probe\n"
  "  --quiet           print nothing but errors\n";

struct Failure : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Options
{
  std::string input, output, method = "skin", mesh;
  double spacing = 0.4, probe = 1.4, shrink = 0.35;
  bool normals = false, cavities = false, check = false, stats = false, quiet = false, help = false;
  std::size_t min_points = 0, max_points = std::size_t(-1);
  cas3::Pdb_options pdb;
};

double positive(const std::string& option, const std::string& text)
{
  double x = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), x);
  if(r.ec != std::errc() || r.ptr != text.data() + text.size() || !(x >= 0) || !std::isfinite(x))
    throw Failure(option + ": not a number >= 0: '" + text + "'");
  return x;
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
        throw Failure("option " + arg + " needs a value");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h") o.help = true;
    else if(arg == "--method")
    {
      o.method = value();
      if(o.method != "skin" && o.method != "vdw" && o.method != "sas")
        throw Failure("--method: unknown method '" + o.method + "' (skin, vdw, sas)");
    }
    else if(arg == "--spacing")
    {
      o.spacing = positive(arg, value());
      if(!(o.spacing >= 0.05))
        throw Failure("--spacing: below 0.05 angstrom");
    }
    else if(arg == "--probe") o.probe = positive(arg, value());
    else if(arg == "--shrink")
    {
      o.shrink = positive(arg, value());
      if(!(o.shrink > 0 && o.shrink < 1))
        throw Failure("--shrink: not in (0, 1)");
    }
    else if(arg == "--normals") o.normals = true;
    else if(arg == "--hydrogens") o.pdb.keep_hydrogens = true;
    else if(arg == "--water") o.pdb.keep_water = true;
    else if(arg == "--default-radius")
      o.pdb.default_radius = positive(arg, value());
    else if(arg == "--model")
    {
      const double m = positive(arg, value());
      if(!(m >= 1 && m == std::floor(m) && m < 1e9))
        throw Failure("--model: not a model serial number (an integer from 1)");
      o.pdb.model = int(m);
    }
    else if(arg == "--chains")
    {
      o.pdb.chains.clear();
      for(char c : value())
        if(c != ',')
          o.pdb.chains += c;
      if(o.pdb.chains.empty())
        throw Failure("--chains: no chain identifier");
    }
    else if(arg == "--no-hetatm") o.pdb.keep_hetatm = false;
    else if(arg == "--mesh") o.mesh = value();
    else if(arg == "--check") o.check = true;
    else if(arg == "--cavities") o.cavities = true;
    else if(arg == "--stats") o.stats = true;
    else if(arg == "--quiet") o.quiet = true;
    else if(arg == "--expect-points")
    {
      const std::string v = value();
      const std::size_t comma = v.find(',');
      if(comma == std::string::npos)
        throw Failure("--expect-points: expected MIN,MAX: '" + v + "'");
      o.min_points = std::size_t(positive(arg, v.substr(0, comma)));
      o.max_points = std::size_t(positive(arg, v.substr(comma + 1)));
    }
    else if(!arg.empty() && arg[0] == '-')
      throw Failure("unknown option " + arg);
    else
      files.push_back(arg);
  }
  if(o.help)
    return o;
  if(files.empty() || files.size() > 2)
    throw Failure(files.empty() ? "no input file (see --help)" : "more than two file names (see --help)");
  o.input = files[0];
  o.output = files.size() == 2 ? files[1] : o.input.substr(0, o.input.rfind('.')) + ".xyz";
  if(!o.mesh.empty() && o.method != "skin")
    throw Failure("--mesh: only with --method skin");
  if(o.cavities && o.method != "skin")
    throw Failure("--cavities: only with --method skin");
  return o;
}

typedef CGAL::Search_traits_3<K> Search_traits;
typedef CGAL::Orthogonal_k_neighbor_search<Search_traits> Neighbor_search;
typedef Neighbor_search::Tree Tree;

double quantile(std::vector<double> v, double q)
{
  if(v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  return v[std::size_t(q * double(v.size() - 1))];
}

// Spacing, smoothness of the normals, and distance to the solvent-excluded
// surface (SES) of the probe: the SES is the set of points inside the
// solvent-accessible body at distance `probe` from its boundary, so the
// distance of x to the SES is about | dist(x, SAS) - probe |, measured on a
// dense SAS sample (spacing 0.15).
void print_stats(const cas3::Surface_sample& s, const std::vector<cas3::Atom>& atoms, double probe)
{
  Tree tree(s.points.begin(), s.points.end());
  std::vector<double> nearest, angle;
  // the index of a point, through a sorted copy
  std::vector<std::size_t> order(s.points.size());
  for(std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.points[a] < s.points[b]; });
  auto index_of = [&](const Point& p) {
    const auto it = std::lower_bound(order.begin(), order.end(), p,
                                     [&](std::size_t a, const Point& q) { return s.points[a] < q; });
    return *it;
  };
  for(std::size_t i = 0; i < s.points.size(); ++i)
  {
    Neighbor_search search(tree, s.points[i], 7);
    double worst = 0, closest = std::numeric_limits<double>::infinity();
    for(const auto& n : search)
    {
      const std::size_t j = index_of(n.first);
      if(j == i)
        continue;
      closest = std::min(closest, std::sqrt(n.second));
      const double c = std::max(-1.0, std::min(1.0, s.normals[i] * s.normals[j]));
      worst = std::max(worst, std::acos(c) * 180 / CGAL_PI);
    }
    angle.push_back(worst);
    nearest.push_back(closest);
  }
  std::printf("spacing: nearest neighbor %.3f (5%%) %.3f (median) %.3f (95%%) %.3f (max)\n", quantile(nearest, 0.05),
              quantile(nearest, 0.5), quantile(nearest, 0.95), quantile(nearest, 1.0));
  std::printf("smoothness: largest angle between a point's normal and its 6 neighbors' %.1f (median) %.1f (95%%)"
              " %.1f (99%%) degrees\n",
              quantile(angle, 0.5), quantile(angle, 0.95), quantile(angle, 0.99));
  const cas3::Surface_sample sas = cas3::sample_atom_spheres(atoms, probe, 0.15);
  Tree sas_tree(sas.points.begin(), sas.points.end());
  std::vector<double> deviation;
  for(const Point& p : s.points)
  {
    Neighbor_search search(sas_tree, p, 1);
    deviation.push_back(std::abs(std::sqrt(search.begin()->second) - probe));
  }
  std::printf("distance to the solvent-excluded surface (probe %.2f): %.3f (median) %.3f (95%%) %.3f (max)\n", probe,
              quantile(deviation, 0.5), quantile(deviation, 0.95), quantile(deviation, 1.0));
}

// Checks of --check; returns the failures.
std::vector<std::string> check(const cas3::Surface_sample& s, const std::vector<cas3::Atom>& atoms,
                               const Options& o)
{
  std::vector<std::string> failures;
  auto fail = [&](const std::string& what) {
    if(failures.size() < 10)
      failures.push_back(what);
  };
  const std::size_t n = s.points.size();
  if(n < o.min_points || n > o.max_points)
    fail(std::to_string(n) + " points, expected from " + std::to_string(o.min_points) + " to "
         + std::to_string(o.max_points));
  if(s.normals.size() != n || s.atom.size() != n)
    fail("not one normal and one atom per point");
  // spacing: no two points closer than the spacing
  Tree tree(s.points.begin(), s.points.end());
  for(std::size_t i = 0; i < n; ++i)
  {
    // the two nearest: the point itself, then its nearest neighbor (or a
    // duplicate at distance 0)
    Neighbor_search search(tree, s.points[i], 2);
    int at_zero = 0;
    for(const auto& m : search)
    {
      at_zero += m.second == 0 ? 1 : 0;
      if(m.second > 0 && std::sqrt(m.second) < o.spacing * (1 - 1e-12))
        fail("points " + std::to_string(i) + " and another are " + std::to_string(std::sqrt(m.second))
             + " apart, below the spacing");
    }
    if(at_zero > 1)
      fail("point " + std::to_string(i) + " is duplicated");
  }
  const double probe = o.method == "sas" ? o.probe : 0;
  std::size_t on_sphere = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const Point& p = s.points[i];
    const cas3::Atom& own = atoms[s.atom[i]];
    const double R = own.radius + probe;
    const double d = std::sqrt(CGAL::squared_distance(p, own.center));
    if(std::abs(std::sqrt(s.normals[i].squared_length()) - 1) > 1e-9)
      fail("the normal of point " + std::to_string(i) + " is not a unit vector");
    const Vector radial = (p - own.center) / d;
    // on its atom's sphere (the skin's vertices are placed by bisection)
    const bool patch = std::abs(d - R) <= (o.method == "skin" ? 1e-4 : 1e-9 * R);
    on_sphere += patch ? 1 : 0;
    if(o.method != "skin" && !patch)
      fail("point " + std::to_string(i) + " is " + std::to_string(d) + " from the center of its atom (line "
           + std::to_string(own.line) + "), not on its sphere of radius " + std::to_string(R));
    // on a sphere patch the outward normal is radial
    if(patch && s.normals[i] * radial < (o.method == "skin" ? 0.999 : 1 - 1e-9))
      fail("the normal of point " + std::to_string(i) + " is not the outward radius of its sphere (cos "
           + std::to_string(s.normals[i] * radial) + ")");
    double gap = std::numeric_limits<double>::infinity();  // to the nearest sphere, outside
    for(std::size_t j = 0; j < atoms.size(); ++j)
    {
      const double Rj = atoms[j].radius + probe;
      const double dj = std::sqrt(CGAL::squared_distance(p, atoms[j].center)) - Rj;
      gap = std::min(gap, dj);
      // the skin's vertices are placed by bisection: a tolerance of 1e-3
      if(dj < (o.method == "skin" ? -1e-3 : -1e-9 * Rj))
        fail("point " + std::to_string(i) + " is inside the sphere of the atom on line "
             + std::to_string(atoms[j].line) + " by " + std::to_string(-dj));
    }
    // the skin fills crevices: no point farther from every atom than a probe
    if(o.method == "skin" && gap > 1.4)
      fail("skin point " + std::to_string(i) + " is " + std::to_string(gap) + " away from every atom");
  }
  // the skin is made of exposed van der Waals sphere patches for a good part
  // (measured: 22% of the points on crambin, 19% on ubiquitin)
  if(o.method == "skin" && !(on_sphere > n / 10))
    fail("only " + std::to_string(on_sphere) + " skin points on a van der Waals sphere");
  return failures;
}

int run(const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  const std::vector<cas3::Atom> atoms = cas3::read_pdb(o.input, o.pdb);
  cas3::Surface_sample sample;
  cas3::Skin_surface_sample skin;
  if(o.method == "skin")
  {
    cas3::sample_skin_surface(atoms, o.spacing, skin, o.cavities, o.shrink);
    sample = skin.sample;
  }
  else
    sample = cas3::sample_atom_spheres(atoms, o.method == "sas" ? o.probe : 0.0, o.spacing);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  {
    std::ofstream out(o.output);
    if(!out)
      throw Failure("cannot write " + o.output);
    char line[160];
    for(std::size_t i = 0; i < sample.points.size(); ++i)
    {
      const Point& p = sample.points[i];
      const Vector& n = sample.normals[i];
      if(o.normals)
        std::snprintf(line, sizeof line, "%.5f %.5f %.5f %.5f %.5f %.5f\n", p.x(), p.y(), p.z(), n.x(), n.y(), n.z());
      else
        std::snprintf(line, sizeof line, "%.5f %.5f %.5f\n", p.x(), p.y(), p.z());
      out << line;
    }
    out.close();
    if(!out)
      throw Failure("cannot write " + o.output);
  }
  if(!o.mesh.empty())
  {
    std::ofstream out(o.mesh);
    out.precision(17);
    if(!out || !(out << skin.mesh) || !(out << std::flush))
      throw Failure("cannot write " + o.mesh);
  }
  if(!o.quiet)
  {
    const std::size_t defaulted = std::size_t(std::count_if(
      atoms.begin(), atoms.end(), [](const cas3::Atom& a) { return a.default_radius; }));
    if(defaulted > 0)
      std::printf("%s: %zu atom(s) without a Bondi radius given %.3g A\n", o.input.c_str(), defaulted,
                  o.pdb.default_radius);
    std::printf("%s: %zu atoms; %s surface, spacing %.3g: %zu points in %.2f s", o.input.c_str(), atoms.size(),
                o.method.c_str(), o.spacing, sample.points.size(), seconds);
    if(o.method == "skin")
      std::printf(" (skin mesh: %zu vertices, %zu faces, %d subdivisions; %zu part(s); %zu cavities %s)",
                  skin.mesh.size_of_vertices(), skin.mesh.size_of_facets(), skin.subdivisions,
                  skin.number_of_parts, skin.number_of_cavities, o.cavities ? "kept" : "left out");
    std::printf("\nwritten to %s%s\n", o.output.c_str(), o.normals ? " with normals" : "");
  }
  if(o.stats)
    print_stats(sample, atoms, o.probe);
  if(o.check)
  {
    const std::vector<std::string> failures = check(sample, atoms, o);
    for(const std::string& f : failures)
      std::cerr << "molecular_surface_points: check failed: " << f << "\n";
    if(!failures.empty())
      return EXIT_FAILURE;
    if(!o.quiet)
      std::printf("check passed: %zu points\n", sample.points.size());
  }
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
  catch(const std::exception& e)
  {
    std::cerr << "molecular_surface_points: " << e.what() << "\n";
  }
  return EXIT_FAILURE;
}
