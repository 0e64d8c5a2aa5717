// The real scans and meshes of the tests: CGAL's example data from Debian's
// libcgal-demo, which CMake extracts into the build tree (CAS3_TEST_DATA,
// see the top CMakeLists.txt). A test whose file is missing fails with a
// message naming the package; it is never skipped.
#ifndef CAS3_TEST_DATA_H
#define CAS3_TEST_DATA_H

#include <CGAL/IO/read_points.h>
#include <CGAL/property_map.h>

#include <boost/test/unit_test.hpp>

#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace cas3_test {

// The path of `name` in the build tree's copy of CGAL's data; fails the
// test when the file is not there.
inline std::string test_data_file(const std::string& name)
{
  const std::string path = std::string(CAS3_TEST_DATA) + "/" + name;
  BOOST_REQUIRE_MESSAGE(std::ifstream(path).good(),
                        path << " is missing: install Debian's libcgal-demo (apt-get install libcgal-demo), whose "
                                "/usr/share/doc/libcgal-dev/data.tar.gz and examples.tar.gz hold it, and run cmake "
                                "again");
  return path;
}

// The points of a file (`CGAL::IO::read_points()`: .xyz, .pwn, .ply, .off).
template <class Point>
std::vector<Point> read_points(const std::string& path)
{
  std::vector<Point> points;
  BOOST_REQUIRE_MESSAGE(CGAL::IO::read_points(path, std::back_inserter(points)), "cannot read " << path);
  return points;
}

// The points and their normals of a file of CGAL's data (.xyz and .pwn with
// six columns, .ply with nx ny nz).
template <class Point, class Vector>
void read_oriented_points(const std::string& name, std::vector<Point>& points, std::vector<Vector>& normals)
{
  typedef std::pair<Point, Vector> Point_and_normal;
  std::vector<Point_and_normal> read;
  const std::string path = test_data_file(name);
  BOOST_REQUIRE_MESSAGE(CGAL::IO::read_points(path, std::back_inserter(read),
                                              CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_and_normal>())
                                                .normal_map(CGAL::Second_of_pair_property_map<Point_and_normal>())),
                        "cannot read " << path);
  for(const Point_and_normal& pn : read)
  {
    points.push_back(pn.first);
    normals.push_back(pn.second);
  }
}

} // namespace cas3_test

#endif // CAS3_TEST_DATA_H
