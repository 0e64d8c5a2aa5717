// End-to-end tests of the conformal_curvature program: its CSV and PLY
// output on the bundled bunny and on a generated noisy ellipsoid (against
// the analytic mean curvature), and its answer to bad input.
#define BOOST_TEST_MODULE test_conformal_curvature_program
#include <boost/test/unit_test.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include "cas3_test_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace fs = std::filesystem;

namespace {

const fs::path work = fs::temp_directory_path() / "cas3_test_conformal_curvature_program";

struct Run
{
  int exit_code;
  std::string err;
};

// Runs the program with `args` (a shell fragment) from the work directory.
Run run(const std::string& args)
{
  fs::create_directories(work);
  const fs::path err = work / "stderr.txt";
  const std::string command = "cd '" + work.string() + "' && '" + std::string(CAS3_PROGRAM) + "' " + args + " 2> '" +
                              err.string() + "' > /dev/null";
  const int status = std::system(command.c_str());
  std::ifstream in(err);
  std::stringstream text;
  text << in.rdbuf();
  return Run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

struct Csv
{
  std::vector<std::string> header;
  std::vector<std::vector<double> > rows;
};

Csv read_csv(const fs::path& file)
{
  Csv csv;
  std::ifstream in(file);
  BOOST_REQUIRE(in);
  std::string line, cell;
  std::getline(in, line);
  std::stringstream head(line);
  while(std::getline(head, cell, ','))
    csv.header.push_back(cell);
  while(std::getline(in, line))
  {
    std::vector<double> row;
    std::stringstream cells(line);
    while(std::getline(cells, cell, ','))
      row.push_back(std::strtod(cell.c_str(), nullptr));
    csv.rows.push_back(row);
  }
  return csv;
}

void write_xyz(const fs::path& file, const std::vector<Point>& pts)
{
  std::ofstream out(file);
  out << std::setprecision(17);
  for(const Point& p : pts)
    out << p << "\n";
}

} // namespace

BOOST_AUTO_TEST_CASE(bunny_default_run)
{
  fs::remove_all(work / "bunny");
  const Run r = run("--output bunny --quiet");
  BOOST_REQUIRE_EQUAL(r.exit_code, 0);
  BOOST_TEST(r.err.empty());

  const Csv csv = read_csv(work / "bunny" / "curvatures.csv");
  const std::vector<std::string> expected = {"point_index", "x", "y", "z", "alpha_hat", "rings", "on_surface",
                                             "nx", "ny", "nz", "H", "K", "k1", "k2", "d1x", "d1y", "d1z",
                                             "d2x", "d2y", "d2z"};
  BOOST_TEST(csv.header == expected, boost::test_tools::per_element());
  BOOST_REQUIRE_EQUAL(csv.rows.size(), 5000u * 4 * 2);  // points x scales x rings
  std::size_t on = 0;
  for(const auto& row : csv.rows)
  {
    BOOST_REQUIRE_EQUAL(row.size(), expected.size());
    BOOST_TEST((row[5] == 1 || row[5] == 2));
    if(row[6] != 1)
    {
      BOOST_TEST(std::isnan(row[10]));
      continue;
    }
    ++on;
    for(std::size_t k = 7; k < row.size(); ++k)
      BOOST_TEST(std::isfinite(row[k]));
    BOOST_TEST(row[12] >= row[13]);                                                   // k1 >= k2
    BOOST_TEST(std::abs(row[7] * row[7] + row[8] * row[8] + row[9] * row[9] - 1) < 1e-6);  // unit normal
    BOOST_TEST(row[10] == (row[12] + row[13]) / 2, boost::test_tools::tolerance(1e-9));
  }
  BOOST_TEST(on > csv.rows.size() * 4 / 10);  // few at 10%, most from 35% on

  // the PLY surfaces read back with their properties
  for(const char* scale : {"10pct", "25pct", "35pct", "50pct"})
    for(int rings : {1, 2})
    {
      const fs::path file = work / "bunny" / ("surface_" + std::string(scale) + "_rings" + std::to_string(rings) + ".ply");
      Mesh mesh;
      std::ifstream in(file, std::ios::binary);
      BOOST_TEST_INFO(file);
      BOOST_REQUIRE(CGAL::IO::read_PLY(in, mesh));
      BOOST_TEST(mesh.number_of_faces() > 0u);
      for(const char* property : {"v:mean_curvature", "v:gaussian_curvature", "v:k1", "v:k2"})
        BOOST_TEST((mesh.property_map<Mesh::Vertex_index, double>(property).second));
      BOOST_TEST((mesh.property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").second));
      BOOST_TEST((mesh.property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").second));
    }
}

BOOST_AUTO_TEST_CASE(noisy_ellipsoid_at_the_automatic_scale)
{
  const double a = 1.0, b = 0.8, c = 0.6;
  write_xyz(work / "ellipsoid.xyz", cas3_test::ellipsoid_sample<Point>(20000, a, b, c, 1e-4));
  fs::remove_all(work / "ellipsoid");
  const Run r = run("ellipsoid.xyz --alpha auto,0.5 --rings 3 --output ellipsoid --quiet");
  BOOST_REQUIRE_EQUAL(r.exit_code, 0);
  const Csv csv = read_csv(work / "ellipsoid" / "curvatures.csv");
  BOOST_REQUIRE_EQUAL(csv.rows.size(), 20000u * 2);
  std::vector<double> error;
  for(std::size_t i = 0; i < 20000; ++i)
  {
    const auto& row = csv.rows[i];  // the automatic scale comes first
    if(row[6] != 1)
      continue;  // left off the surface, reported with no values
    const double x = row[1], y = row[2], z = row[3];
    const double h = std::sqrt(x * x / std::pow(a, 4) + y * y / std::pow(b, 4) + z * z / std::pow(c, 4));
    const double H = std::abs(x * x + y * y + z * z - a * a - b * b - c * c) / (2 * a * a * b * b * c * c * std::pow(h, 3));
    error.push_back(std::abs(row[10] / H - 1));
  }
  BOOST_TEST(error.size() >= 19800u);  // at least 99% on the surface
  std::sort(error.begin(), error.end());
  BOOST_TEST_MESSAGE("relative H error: median " << error[error.size() / 2] << ", 90th percentile "
                     << error[error.size() * 9 / 10]);
  BOOST_TEST(error[error.size() / 2] < 0.02);
  BOOST_TEST(error[error.size() * 9 / 10] < 0.06);
  BOOST_TEST(csv.rows[20000][4] == 0.5);  // the absolute scale, as given
}

BOOST_AUTO_TEST_CASE(bad_input_fails_with_one_line_and_no_output)
{
  fs::create_directories(work);
  std::ofstream(work / "empty.xyz").close();
  std::ofstream(work / "garbage.xyz") << "hello world\nthis is not a point cloud\n";
  std::ofstream(work / "three.xyz") << "0 0 0\n1 0 0\n0 1 0\n";
  std::ofstream(work / "nan.xyz") << "0 0 0\n1 0 0\nnan 1 0\n0 0 1\n1 1 1\n";
  std::ofstream(work / "points.abc") << "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  std::ofstream(work / "a_file") << "not a directory\n";
  struct Case { std::string args, reason; };
  const std::vector<Case> cases = {
    {"missing.xyz", "cannot open"},
    {"empty.xyz", "no point"},
    {"garbage.xyz", "not a valid xyz file"},
    {"three.xyz", "span dimension 2"},
    {"nan.xyz", "not a valid xyz file"},
    {"points.abc", "unknown input extension"},
    {"--output a_file/out", "cannot create the output directory"},
    {"--bogus", "unknown option"},
    {"--alpha 10%,,20%", "empty item"},
    {"--alpha 10%,big", "not a scale"},
    {"--alpha 150%", "not a scale"},
    {"--rings 1,0", "ring size"},
    {"--estimator magic", "unknown estimator"},
    {"--output", "needs a value"},
  };
  for(const Case& k : cases)
  {
    fs::remove_all(work / "out");
    const Run r = run(k.args + (k.args.find("--output") == std::string::npos ? " --output out" : ""));
    BOOST_TEST_INFO(k.args << ": " << r.err);
    BOOST_TEST(r.exit_code != 0);
    BOOST_TEST(r.err.find(k.reason) != std::string::npos);
    BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);  // one line
    BOOST_TEST((!fs::exists(work / "out") || fs::is_empty(work / "out")));
  }
}

// The pictures of the manual are rendered headless from the program's PLY.
BOOST_AUTO_TEST_CASE(renders_a_png_headless)
{
  BOOST_REQUIRE_EQUAL(run("--alpha 50% --rings 2 --output picture --quiet").exit_code, 0);
  const fs::path png = work / "picture.png";
  fs::remove(png);
  const std::string command = "'" + std::string(CAS3_RENDERER) + "' '" +
                              (work / "picture" / "surface_50pct_rings2.ply").string() + "' '" + png.string() +
                              "' --size 64";
  BOOST_REQUIRE_EQUAL(std::system(command.c_str()), 0);
  std::ifstream in(png, std::ios::binary);
  std::string signature(8, '\0');
  in.read(&signature[0], 8);
  BOOST_TEST(signature == std::string("\x89PNG\r\n\x1a\n"));
  BOOST_TEST(fs::file_size(png) > 200u);
}
