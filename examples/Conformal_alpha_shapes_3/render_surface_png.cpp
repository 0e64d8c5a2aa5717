// Renders a PLY surface written by conformal_curvature (its per-vertex
// colors, or the color ramp of a per-vertex property such as H_r4s) into a
// PNG image, headless: a small software rasteriser with a z-buffer, Lambert
// shading and 3x3 supersampling.
//   render_surface_png SURFACE.ply IMAGE.png [--size N] [--view X,Y,Z] [--up X,Y,Z]
//                      [--color-by PROPERTY [--relative-to PROPERTY]]
// With --relative-to, the color is the ratio |color-by| / |relative-to| on a
// logarithmic ramp (blue 1%, white 10%, red 100%): an uncertainty such as
// H_sigma_r4s relative to its value H_r4s.
// The PNG is compressed with zlib, which libcgal-dev already depends on:
// rendering adds no package (see the manual).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include "cas3_curvature_colors.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;

namespace {

struct Image
{
  int width, height;
  std::vector<std::uint8_t> rgb;
};

void put_u32(std::string& out, std::uint32_t x)
{
  for(int shift = 24; shift >= 0; shift -= 8)
    out += char((x >> shift) & 0xff);
}

void write_chunk(std::ofstream& out, const char* type, const std::string& data)
{
  std::string chunk(type, 4);
  chunk += data;
  std::string length;
  put_u32(length, std::uint32_t(data.size()));
  std::string crc;
  put_u32(crc, std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(chunk.data()), uInt(chunk.size()))));
  out << length << chunk << crc;
}

bool write_png(const std::string& file, const Image& image)
{
  std::string raw;  // each row: filter type 0, then RGB
  for(int y = 0; y < image.height; ++y)
  {
    raw += char(0);
    raw.append(reinterpret_cast<const char*>(&image.rgb[std::size_t(y) * std::size_t(image.width) * 3]),
               std::size_t(image.width) * 3);
  }
  uLongf size = compressBound(uLong(raw.size()));
  std::string compressed(size, '\0');
  if(compress2(reinterpret_cast<Bytef*>(&compressed[0]), &size, reinterpret_cast<const Bytef*>(raw.data()),
               uLong(raw.size()), 9) != Z_OK)
    return false;
  compressed.resize(size);

  std::ofstream out(file, std::ios::binary);
  out << "\x89PNG\r\n\x1a\n";
  std::string header;
  put_u32(header, std::uint32_t(image.width));
  put_u32(header, std::uint32_t(image.height));
  header += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, no filter, no interlace
  write_chunk(out, "IHDR", header);
  write_chunk(out, "IDAT", compressed);
  write_chunk(out, "IEND", "");
  return bool(out);
}

Vector parse_vector(const std::string& text)
{
  std::stringstream in(text);
  std::array<double, 3> v{};
  char comma = 0;
  if(!(in >> v[0] >> comma >> v[1] >> comma >> v[2]))
    throw std::invalid_argument("not a vector X,Y,Z: " + text);
  return Vector(v[0], v[1], v[2]);
}

// Orthographic view along -view, `up` projected to the image's vertical.
Image render(const Mesh& mesh, int size, const Vector& view, const Vector& up)
{
  const int ss = 3;  // supersampling
  const int n = size * ss;
  const Vector w = view / std::sqrt(view.squared_length());
  Vector u = CGAL::cross_product(up, w);
  u = u / std::sqrt(u.squared_length());
  const Vector v = CGAL::cross_product(w, u);

  auto color = mesh.property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color");
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for(auto vd : mesh.vertices())
  {
    const Vector p = mesh.point(vd) - CGAL::ORIGIN;
    const double c[2] = {p * u, p * v};
    for(int i = 0; i < 2; ++i)
    {
      lo[i] = std::min(lo[i], c[i]);
      hi[i] = std::max(hi[i], c[i]);
    }
  }
  const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]) * 1.05;
  const double cx = (lo[0] + hi[0]) / 2, cy = (lo[1] + hi[1]) / 2;
  auto to_pixel = [&](const Point& p, double& x, double& y, double& depth) {
    const Vector q = p - CGAL::ORIGIN;
    x = ((q * u - cx) / extent + 0.5) * n;
    y = (0.5 - (q * v - cy) / extent) * n;
    depth = q * w;
  };

  std::vector<double> zbuffer(std::size_t(n) * std::size_t(n), -std::numeric_limits<double>::infinity());
  std::vector<std::array<double, 3> > frame(std::size_t(n) * std::size_t(n), {{1, 1, 1}});
  for(auto f : mesh.faces())
  {
    std::array<Point, 3> p;
    std::array<std::array<double, 3>, 3> c;
    int k = 0;
    for(auto vd : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      p[k] = mesh.point(vd);
      const CGAL::IO::Color col = color.second ? color.first[vd] : CGAL::IO::Color(200, 200, 200);
      c[k] = {{col.red() / 255.0, col.green() / 255.0, col.blue() / 255.0}};
      ++k;
    }
    Vector normal = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    const double len = std::sqrt(normal.squared_length());
    if(!(len > 0))
      continue;
    const double shade = 0.25 + 0.75 * std::abs(normal * w) / len;  // headlight, two-sided
    double x[3], y[3], z[3];
    for(int i = 0; i < 3; ++i)
      to_pixel(p[i], x[i], y[i], z[i]);
    const double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    if(area == 0)
      continue;
    const int x0 = std::max(0, int(std::floor(std::min({x[0], x[1], x[2]}))));
    const int x1 = std::min(n - 1, int(std::ceil(std::max({x[0], x[1], x[2]}))));
    const int y0 = std::max(0, int(std::floor(std::min({y[0], y[1], y[2]}))));
    const int y1 = std::min(n - 1, int(std::ceil(std::max({y[0], y[1], y[2]}))));
    for(int py = y0; py <= y1; ++py)
      for(int px = x0; px <= x1; ++px)
      {
        const double sx = px + 0.5, sy = py + 0.5;
        const double b0 = ((x[1] - sx) * (y[2] - sy) - (x[2] - sx) * (y[1] - sy)) / area;
        const double b1 = ((x[2] - sx) * (y[0] - sy) - (x[0] - sx) * (y[2] - sy)) / area;
        const double b2 = 1 - b0 - b1;
        if(b0 < 0 || b1 < 0 || b2 < 0)
          continue;
        const double depth = b0 * z[0] + b1 * z[1] + b2 * z[2];
        const std::size_t at = std::size_t(py) * std::size_t(n) + std::size_t(px);
        if(depth <= zbuffer[at])
          continue;
        zbuffer[at] = depth;
        for(int ch = 0; ch < 3; ++ch)
          frame[at][std::size_t(ch)] = shade * (b0 * c[0][std::size_t(ch)] + b1 * c[1][std::size_t(ch)] +
                                                b2 * c[2][std::size_t(ch)]);
      }
  }

  Image image{size, size, std::vector<std::uint8_t>(std::size_t(size) * std::size_t(size) * 3)};
  for(int y = 0; y < size; ++y)
    for(int x = 0; x < size; ++x)
      for(int ch = 0; ch < 3; ++ch)
      {
        double sum = 0;
        for(int j = 0; j < ss; ++j)
          for(int i = 0; i < ss; ++i)
            sum += frame[std::size_t(y * ss + j) * std::size_t(n) + std::size_t(x * ss + i)][std::size_t(ch)];
        image.rgb[(std::size_t(y) * std::size_t(size) + std::size_t(x)) * 3 + std::size_t(ch)] =
          std::uint8_t(std::min(255.0, 255.0 * sum / (ss * ss) + 0.5));
      }
  return image;
}

// A vertex property's values by vertex index: PLY floats and doubles read
// back as float or double properties.
std::vector<double> vertex_values(const Mesh& mesh, const std::string& name, const char* file)
{
  std::vector<double> out(mesh.number_of_vertices());
  auto as_float = mesh.property_map<Mesh::Vertex_index, float>("v:" + name);
  auto as_double = mesh.property_map<Mesh::Vertex_index, double>("v:" + name);
  if(!as_float.second && !as_double.second)
    throw std::invalid_argument(std::string(file) + " has no vertex property " + name);
  for(auto v : mesh.vertices())
    out[v.idx()] = as_float.second ? double(as_float.first[v]) : as_double.first[v];
  return out;
}

} // namespace

int main(int argc, char* argv[])
{
  if(argc < 3)
  {
    std::cerr << "usage: render_surface_png SURFACE.ply IMAGE.png [--size N] [--view X,Y,Z] [--up X,Y,Z]"
                 " [--color-by PROPERTY [--relative-to PROPERTY]]\n";
    return EXIT_FAILURE;
  }
  try
  {
    int size = 480;
    Vector view(0, 0, 1), up(0, 1, 0);  // the Stanford bunny's front
    std::string color_by, relative_to;
    for(int i = 3; i + 1 < argc; i += 2)
    {
      const std::string option = argv[i];
      if(option == "--size") size = std::stoi(argv[i + 1]);
      else if(option == "--view") view = parse_vector(argv[i + 1]);
      else if(option == "--up") up = parse_vector(argv[i + 1]);
      else if(option == "--color-by") color_by = argv[i + 1];
      else if(option == "--relative-to") relative_to = argv[i + 1];
      else throw std::invalid_argument("unknown option " + option);
    }
    Mesh mesh;
    std::ifstream in(argv[1], std::ios::binary);
    if(!in || !CGAL::IO::read_PLY(in, mesh) || mesh.number_of_faces() == 0)
      throw std::invalid_argument(std::string("cannot read a surface from ") + argv[1]);
    if(!relative_to.empty() && color_by.empty())
      throw std::invalid_argument("--relative-to needs --color-by");
    if(!color_by.empty())
    {
      auto color = mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
      const std::vector<double> value = vertex_values(mesh, color_by, argv[1]);
      auto shown = mesh.add_property_map<Mesh::Vertex_index, double>("v:cas3_shown").first;
      if(relative_to.empty())
      {
        for(auto v : mesh.vertices())
          shown[v] = value[v.idx()];
        cas3::color_by_curvature(mesh, shown, color);
      }
      else
      {
        const std::vector<double> base = vertex_values(mesh, relative_to, argv[1]);
        for(auto v : mesh.vertices())
          shown[v] = std::abs(value[v.idx()]) / std::abs(base[v.idx()]);
        cas3::color_by_ratio(mesh, shown, color);
      }
    }
    if(!write_png(argv[2], render(mesh, size, view, up)))
      throw std::invalid_argument(std::string("cannot write ") + argv[2]);
  }
  catch(const std::exception& e)
  {
    std::cerr << "render_surface_png: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
