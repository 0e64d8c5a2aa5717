// Reading point clouds for the conformal_curvature program, the benchmarks
// and the fuzz harness (not part of the library).
//
// read_point_cloud(path) reads .xyz (3 or 6 numbers a line: x y z [nx ny nz],
// optionally after a first line with the number of points, which must match),
// .pwn (6 numbers a line), .ply (ASCII or binary, element "vertex" with
// properties x y z and optionally nx ny nz), .off (the vertices; NOFF gives
// normals), .obj (the "v" lines) and .las (LAS 1.0 to 1.4, cas3_las.h: the
// points a Las_filter keeps, with their records on request; a .laz file is
// refused with how to decompress it). Normals are returned when the file has
// them, else the vector is empty. Anything else throws cas3::Read_error with
// one line naming the file, the line (or vertex) and what is wrong:
// malformed numbers, wrong column counts, truncated files, headers that
// promise more vertices than the file holds, NaN or infinite coordinates,
// unknown extensions, missing or unreadable paths, directories, files
// without any point.
//
// CGAL::IO::read_points() is not used for any format: it reads ASCII PLY
// float properties as floats (every coordinate of CGAL's ball.ply and
// building.ply would change), accepts files this reader rejects (a lying
// point count, extra columns, NaN in a binary PLY, a PLY vertex without z),
// reports errors on std::cerr without the file's name, and reads no .obj.
#ifndef CAS3_READ_POINT_CLOUD_H
#define CAS3_READ_POINT_CLOUD_H

#include "cas3_las.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace cas3 {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Read_kernel;

// What a LAS input adds: its header, the filters and what they kept, and
// the records of the points kept (when asked for), in file order, with
// their extra bytes.
struct Las_input
{
  bool present = false;
  Las_header header;
  Las_filter filter;
  Las_filter_counts counts;
  std::vector<Las_record> records;  // one per point, or empty
  std::vector<char> extra_bytes;    // header.extra_bytes per record
};

struct Point_cloud
{
  std::vector<Read_kernel::Point_3> points;
  std::vector<Read_kernel::Vector_3> normals;  // empty when the file has none
  Las_input las;                               // for a .las file
};

namespace read_detail {

// The whole content of the file `path`.
inline std::string file_bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw Read_error(path + ": cannot be opened for reading");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if(in.bad())
    throw Read_error(path + ": read error");
  return bytes.str();
}

// A token for a message: printable, at most 24 characters.
inline std::string shown(const std::string& token)
{
  std::string s;
  for(unsigned char c : token.substr(0, 24))
  {
    if(std::isprint(c))
      s += char(c);
    else
    {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      s += hex;
    }
  }
  return token.size() > 24 ? s + "..." : s;
}

// Lines of a text buffer, with their 1-based numbers; CR before LF dropped.
class Lines
{
public:
  explicit Lines(const std::string& text, std::size_t start = 0) : m_text(text), m_pos(start) {}
  bool next(std::string& line)
  {
    if(m_pos >= m_text.size())
      return false;
    std::size_t end = m_text.find('\n', m_pos);
    if(end == std::string::npos)
      end = m_text.size();
    line.assign(m_text, m_pos, end - m_pos);
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    m_pos = end + 1;
    ++m_number;
    return true;
  }
  std::size_t number() const { return m_number; }
  std::size_t position() const { return m_pos; }
  void set_number(std::size_t n) { m_number = n; }

private:
  const std::string& m_text;
  std::size_t m_pos;
  std::size_t m_number = 0;
};

inline std::vector<std::string> tokens(const std::string& line)
{
  std::vector<std::string> t;
  std::size_t i = 0;
  while(i < line.size())
  {
    while(i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\v' || line[i] == '\f'))
      ++i;
    const std::size_t start = i;
    while(i < line.size() && !(line[i] == ' ' || line[i] == '\t' || line[i] == '\v' || line[i] == '\f'))
      ++i;
    if(i > start)
      t.push_back(line.substr(start, i - start));
  }
  return t;
}

// Throws "where: ..." on anything but a finite double.
inline double number(const std::string& token, const std::string& where)
{
  const char* first = token.data();
  const char* last = first + token.size();
  if(first != last && *first == '+')
    ++first;
  double x = 0;
  const auto r = std::from_chars(first, last, x);
  if(r.ec == std::errc::result_out_of_range)
    throw Read_error(where + ": number out of the range of double: '" + shown(token) + "'");
  if(r.ec != std::errc() || r.ptr != last || first == last)
    throw Read_error(where + ": not a number: '" + shown(token) + "'");
  if(!std::isfinite(x))
    throw Read_error(where + ": coordinate is NaN or infinite: '" + shown(token) + "'");
  return x;
}

inline bool blank_or_comment(const std::vector<std::string>& t) { return t.empty() || t[0][0] == '#'; }

// .xyz and .pwn: 3 or 6 numbers a line, the same on every line.
inline Point_cloud read_xyz(const std::string& text, const std::string& name, bool pwn)
{
  Point_cloud cloud;
  Lines lines(text);
  std::string line;
  std::size_t columns = 0, first_line = 0, count = 0, count_line = 0;
  while(lines.next(line))
  {
    const std::vector<std::string> t = tokens(line);
    if(blank_or_comment(t))
      continue;
    const std::string where = name + ":" + std::to_string(lines.number());
    if(columns == 0 && count_line == 0 && cloud.points.empty() && t.size() == 1 &&
       t[0].find_first_not_of("0123456789") == std::string::npos && t[0].size() < 13)
    {
      // a first line with the number of points, as CGAL's XYZ files have
      count = std::stoull(t[0]);
      count_line = lines.number();
      continue;
    }
    if(columns == 0)
    {
      if(pwn ? t.size() != 6 : (t.size() != 3 && t.size() != 6))
        throw Read_error(where + ": expected " + std::string(pwn ? "6 numbers (x y z nx ny nz)"
                                                                 : "3 or 6 numbers (x y z [nx ny nz])")
                         + ", found " + std::to_string(t.size()) + " fields");
      columns = t.size();
      first_line = lines.number();
    }
    else if(t.size() != columns)
      throw Read_error(where + ": expected " + std::to_string(columns) + " numbers as on line "
                       + std::to_string(first_line) + ", found " + std::to_string(t.size()) + " fields");
    double v[6];
    for(std::size_t i = 0; i < columns; ++i)
      v[i] = number(t[i], where);
    cloud.points.emplace_back(v[0], v[1], v[2]);
    if(columns == 6)
      cloud.normals.emplace_back(v[3], v[4], v[5]);
  }
  if(count_line != 0 && count != cloud.points.size())
    throw Read_error(name + ":" + std::to_string(count_line) + ": the first line announces " + std::to_string(count)
                     + " points, the file holds " + std::to_string(cloud.points.size()));
  return cloud;
}

// .off: the vertices (and their normals for NOFF).
inline Point_cloud read_off(const std::string& text, const std::string& name)
{
  Point_cloud cloud;
  Lines lines(text);
  std::string line;
  std::vector<std::string> t;
  auto next_tokens = [&]() {
    while(lines.next(line))
    {
      t = tokens(line);
      if(!blank_or_comment(t))
        return true;
    }
    return false;
  };
  if(!next_tokens())
    throw Read_error(name + ": empty OFF file");
  const std::string keyword = t[0];
  if(keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0 ||
     keyword.find_first_not_of("STCN4nOF") != std::string::npos || keyword.find('4') != std::string::npos ||
     keyword.find('n') != std::string::npos)
    throw Read_error(name + ":" + std::to_string(lines.number()) + ": not an OFF header: '" + shown(keyword) + "'");
  const bool with_normals = keyword.find('N') != std::string::npos;
  const bool with_texture = keyword.find("ST") != std::string::npos;
  t.erase(t.begin());
  if(t.empty() && !next_tokens())
    throw Read_error(name + ": the OFF header has no vertex count");
  const std::string where = name + ":" + std::to_string(lines.number());
  if(t.size() < 2)
    throw Read_error(where + ": expected the vertex and face counts");
  const double count = number(t[0], where);
  if(count < 0 || count != std::floor(count) || count > 1e12)
    throw Read_error(where + ": not a vertex count: '" + shown(t[0]) + "'");
  const std::size_t n = std::size_t(count);
  const std::size_t needed = 3 + (with_normals ? 3 : 0) + (with_texture ? 2 : 0);
  for(std::size_t i = 0; i < n; ++i)
  {
    if(!next_tokens())
      throw Read_error(name + ": the header promises " + std::to_string(n) + " vertices, the file ends after "
                       + std::to_string(i));
    const std::string at = name + ":" + std::to_string(lines.number());
    if(t.size() < needed)
      throw Read_error(at + ": expected at least " + std::to_string(needed) + " numbers for a vertex, found "
                       + std::to_string(t.size()) + " fields");
    double v[6];
    for(std::size_t k = 0; k < (with_normals ? 6u : 3u); ++k)
      v[k] = number(t[k], at);
    cloud.points.emplace_back(v[0], v[1], v[2]);
    if(with_normals)
      cloud.normals.emplace_back(v[3], v[4], v[5]);
  }
  return cloud;
}

// .obj: the "v x y z [w]" lines.
inline Point_cloud read_obj(const std::string& text, const std::string& name)
{
  Point_cloud cloud;
  Lines lines(text);
  std::string line;
  while(lines.next(line))
  {
    const std::vector<std::string> t = tokens(line);
    if(t.empty() || t[0] != "v")
      continue;
    const std::string where = name + ":" + std::to_string(lines.number());
    if(t.size() != 4 && t.size() != 5 && t.size() != 7)  // x y z, x y z w, x y z r g b
      throw Read_error(where + ": expected 3 coordinates after 'v', found " + std::to_string(t.size() - 1)
                       + " fields");
    cloud.points.emplace_back(number(t[1], where), number(t[2], where), number(t[3], where));
  }
  return cloud;
}

// .ply, ASCII or binary.
struct Ply_property
{
  std::string name, type, count_type;  // count_type non-empty for lists
};
struct Ply_element
{
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property> properties;
};

inline int ply_type_size(const std::string& type)
{
  if(type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if(type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if(type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32") return 4;
  if(type == "double" || type == "float64") return 8;
  return 0;
}

inline Point_cloud read_ply(const std::string& text, const std::string& name)
{
  Lines lines(text);
  std::string line;
  if(!lines.next(line) || line != "ply")
    throw Read_error(name + ":1: not a PLY file (the first line is not 'ply')");
  int format = -1;  // 0 ascii, 1 little endian, 2 big endian
  std::vector<Ply_element> elements;
  bool ended = false;
  while(!ended && lines.next(line))
  {
    const std::vector<std::string> t = tokens(line);
    const std::string where = name + ":" + std::to_string(lines.number());
    if(t.empty() || t[0] == "comment" || t[0] == "obj_info")
      continue;
    if(t[0] == "format" && t.size() == 3)
    {
      if(t[1] == "ascii") format = 0;
      else if(t[1] == "binary_little_endian") format = 1;
      else if(t[1] == "binary_big_endian") format = 2;
      else throw Read_error(where + ": unknown PLY format '" + shown(t[1]) + "'");
    }
    else if(t[0] == "element" && t.size() == 3)
    {
      Ply_element e;
      e.name = t[1];
      const double count = number(t[2], where);
      if(count < 0 || count != std::floor(count) || count > 1e12)
        throw Read_error(where + ": not an element count: '" + shown(t[2]) + "'");
      e.count = std::size_t(count);
      elements.push_back(e);
    }
    else if(t[0] == "property" && !elements.empty() && t.size() == 3 && ply_type_size(t[1]) > 0)
      elements.back().properties.push_back(Ply_property{t[2], t[1], ""});
    else if(t[0] == "property" && !elements.empty() && t.size() == 5 && t[1] == "list" &&
            ply_type_size(t[2]) > 0 && ply_type_size(t[2]) <= 4 && t[2].find("float") == std::string::npos &&
            ply_type_size(t[3]) > 0)
      elements.back().properties.push_back(Ply_property{t[4], t[3], t[2]});
    else if(t[0] == "end_header" && t.size() == 1)
      ended = true;
    else
      throw Read_error(where + ": not a PLY header line: '" + shown(line) + "'");
  }
  if(!ended)
    throw Read_error(name + ": the PLY header has no end_header line");
  if(format < 0)
    throw Read_error(name + ": the PLY header has no format line");
  std::size_t vertex_element = elements.size();
  for(std::size_t i = 0; i < elements.size(); ++i)
    if(elements[i].name == "vertex")
      vertex_element = i;
  if(vertex_element == elements.size())
    throw Read_error(name + ": the PLY header declares no vertex element");
  for(std::size_t e = 0; e <= vertex_element; ++e)
    if(elements[e].properties.empty() && elements[e].count > 0)
      throw Read_error(name + ": the PLY element '" + shown(elements[e].name) + "' has no property");
  const Ply_element& vertex = elements[vertex_element];
  int slot[6] = {-1, -1, -1, -1, -1, -1};
  const char* wanted[6] = {"x", "y", "z", "nx", "ny", "nz"};
  for(std::size_t p = 0; p < vertex.properties.size(); ++p)
    for(int k = 0; k < 6; ++k)
      if(vertex.properties[p].name == wanted[k] && vertex.properties[p].count_type.empty())
        slot[k] = int(p);
  if(slot[0] < 0 || slot[1] < 0 || slot[2] < 0)
    throw Read_error(name + ": the PLY vertex element lacks an x, y or z property");
  const bool with_normals = slot[3] >= 0 && slot[4] >= 0 && slot[5] >= 0;

  Point_cloud cloud;
  double v[6] = {0, 0, 0, 0, 0, 0};
  auto store = [&](std::size_t p, double x) {
    for(int k = 0; k < 6; ++k)
      if(slot[k] == int(p))
        v[k] = x;
  };
  auto emit = [&](const std::string& where) {
    for(int k = 0; k < (with_normals ? 6 : 3); ++k)
      if(!std::isfinite(v[k]))
        throw Read_error(where + ": coordinate is NaN or infinite");
    cloud.points.emplace_back(v[0], v[1], v[2]);
    if(with_normals)
      cloud.normals.emplace_back(v[3], v[4], v[5]);
  };

  if(format == 0)
  {
    std::vector<std::string> t;
    for(std::size_t e = 0; e <= vertex_element; ++e)
      for(std::size_t i = 0; i < elements[e].count; ++i)
      {
        do
        {
          if(!lines.next(line))
            throw Read_error(name + ": the header promises " + std::to_string(elements[e].count) + " " +
                             elements[e].name + " elements, the file ends after " + std::to_string(i));
          t = tokens(line);
        } while(t.empty());
        const std::string where = name + ":" + std::to_string(lines.number());
        std::size_t at = 0;
        for(std::size_t p = 0; p < elements[e].properties.size(); ++p)
        {
          std::size_t values = 1;
          if(!elements[e].properties[p].count_type.empty())
          {
            if(at >= t.size())
              throw Read_error(where + ": too few values for element " + elements[e].name);
            const double c = number(t[at++], where);
            if(c < 0 || c != std::floor(c) || c > double(t.size()))
              throw Read_error(where + ": not a list length: '" + shown(t[at - 1]) + "'");
            values = std::size_t(c);
          }
          if(at + values > t.size())
            throw Read_error(where + ": too few values for element " + elements[e].name + ": found "
                             + std::to_string(t.size()));
          if(e == vertex_element)
          {
            // non-finite values are only an error for the coordinates we keep
            const std::string& token = t[at];
            const bool kept = std::count(slot, slot + (with_normals ? 6 : 3), int(p)) > 0;
            if(kept)
              store(p, number(token, where));
            else if(values == 1)
            {
              double ignored = 0;
              const char* f = token.data() + (token[0] == '+' ? 1 : 0);
              const auto r = std::from_chars(f, token.data() + token.size(), ignored);
              if(r.ec != std::errc() && r.ec != std::errc::result_out_of_range)
                throw Read_error(where + ": not a number: '" + shown(token) + "'");
            }
          }
          at += values;
        }
        if(at != t.size())
          throw Read_error(where + ": expected " + std::to_string(at) + " values for element " + elements[e].name
                           + ", found " + std::to_string(t.size()));
        if(e == vertex_element)
          emit(where);
      }
    return cloud;
  }

  // binary
  std::size_t pos = lines.position();
  const bool swap = (format == 2);  // this reader assumes a little-endian host
  auto read_value = [&](const std::string& type, const std::string& where) -> double {
    const int size = ply_type_size(type);
    if(pos + std::size_t(size) > text.size())
      throw Read_error(where);
    unsigned char b[8];
    std::memcpy(b, text.data() + pos, std::size_t(size));
    pos += std::size_t(size);
    if(swap)
      std::reverse(b, b + size);
    if(type == "char" || type == "int8") return double(static_cast<std::int8_t>(b[0]));
    if(type == "uchar" || type == "uint8") return double(b[0]);
    if(type == "short" || type == "int16") { std::int16_t x; std::memcpy(&x, b, 2); return x; }
    if(type == "ushort" || type == "uint16") { std::uint16_t x; std::memcpy(&x, b, 2); return x; }
    if(type == "int" || type == "int32") { std::int32_t x; std::memcpy(&x, b, 4); return x; }
    if(type == "uint" || type == "uint32") { std::uint32_t x; std::memcpy(&x, b, 4); return x; }
    if(type == "float" || type == "float32") { float x; std::memcpy(&x, b, 4); return x; }
    double x; std::memcpy(&x, b, 8); return x;
  };
  for(std::size_t e = 0; e <= vertex_element; ++e)
  {
    const std::string truncated = name + ": truncated binary PLY: the header promises "
                                  + std::to_string(elements[e].count) + " " + elements[e].name + " elements";
    for(std::size_t i = 0; i < elements[e].count; ++i)
    {
      const std::string where = truncated + ", the file ends in element " + std::to_string(i);
      for(std::size_t p = 0; p < elements[e].properties.size(); ++p)
      {
        const Ply_property& prop = elements[e].properties[p];
        if(!prop.count_type.empty())
        {
          const double c = read_value(prop.count_type, where);
          if(!(c >= 0) || c != std::floor(c) || c > double(text.size()))
            throw Read_error(name + ": not a list length in element " + std::to_string(i) + " of " + elements[e].name);
          const std::size_t skip = std::size_t(c) * std::size_t(ply_type_size(prop.type));
          if(pos + skip > text.size())
            throw Read_error(where);
          pos += skip;
        }
        else
        {
          const double x = read_value(prop.type, where);
          if(e == vertex_element)
            store(p, x);
        }
      }
      if(e == vertex_element)
        emit(name + ": vertex " + std::to_string(i));
    }
  }
  return cloud;
}

// The points of `file` that `filter` keeps (and their records, with
// `keep_records`), read a chunk at a time.
inline Point_cloud read_las(Las_file& file, const Las_filter& filter, bool keep_records)
{
  Point_cloud cloud;
  cloud.las.present = true;
  cloud.las.header = file.header();
  cloud.las.filter = filter;
  const std::vector<bool> class_kept = las_classes_kept(filter);
  std::vector<Las_record> chunk;
  std::vector<char> extra;
  const std::size_t extra_size = file.header().extra_bytes;
  const std::uint64_t n = file.number_of_points();
  if(!filter.active())
  {
    cloud.points.reserve(std::size_t(n));
    if(keep_records)
    {
      cloud.las.records.reserve(std::size_t(n));
      cloud.las.extra_bytes.reserve(std::size_t(n) * extra_size);
    }
  }
  for(std::uint64_t first = 0; first < n; first += chunk.size())
  {
    file.read(first, std::uint64_t(1) << 16, chunk, keep_records ? &extra : nullptr);
    for(std::size_t i = 0; i < chunk.size(); ++i)
    {
      if(!keep_las_record(chunk[i], filter, class_kept, cloud.las.counts))
        continue;
      const std::array<double, 3> p = file.position(chunk[i]);
      if(!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
        throw Read_error(file.name() + ": point " + std::to_string(first + i)
                         + ": coordinate is NaN or infinite (scale and offset beyond double's range)");
      cloud.points.emplace_back(p[0], p[1], p[2]);
      if(keep_records)
      {
        cloud.las.records.push_back(chunk[i]);
        cloud.las.extra_bytes.insert(cloud.las.extra_bytes.end(), extra.begin() + std::ptrdiff_t(i * extra_size),
                                     extra.begin() + std::ptrdiff_t((i + 1) * extra_size));
      }
    }
  }
  if(cloud.points.empty() && n > 0)
    throw Read_error(las_input_summary(file.name(), file.header(), filter, cloud.las.counts)
                     + ": the filters keep no point");
  return cloud;
}

inline std::string lower_extension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

} // namespace read_detail

// The input extensions, for messages.
inline const char* known_extensions() { return "(.xyz, .pwn, .ply, .off, .obj, .las)"; }

// Parses the bytes of a file of format `extension` (".xyz", ".pwn", ".ply",
// ".off", ".obj" or ".las"); `name` prefixes the messages. Throws Read_error.
inline Point_cloud parse_point_cloud(const std::string& bytes, const std::string& extension, const std::string& name,
                                     const Las_filter& filter = Las_filter(), bool keep_las_records = true)
{
  using namespace read_detail;
  Point_cloud cloud;
  if(extension == ".las")
  {
    Las_file file(bytes, name);
    cloud = read_las(file, filter, keep_las_records);
  }
  else if(extension == ".laz")
    throw Las_error(laz_message(name));
  else if(extension == ".xyz" || extension == ".pwn")
    cloud = read_xyz(bytes, name, extension == ".pwn");
  else if(extension == ".ply")
    cloud = read_ply(bytes, name);
  else if(extension == ".off")
    cloud = read_off(bytes, name);
  else if(extension == ".obj")
    cloud = read_obj(bytes, name);
  else
    throw Read_error(name + ": unknown input extension '" + shown(extension) + "' " + known_extensions());
  if(cloud.points.empty())
    throw Read_error(name + ": the file holds no point");
  return cloud;
}

// Reads the point cloud in the file `path`; for a LAS file, the points
// that `filter` keeps, and their records with `keep_las_records`. Throws
// Read_error.
inline Point_cloud read_point_cloud(const std::string& path, const Las_filter& filter = Las_filter(),
                                    bool keep_las_records = true)
{
  namespace fs = std::filesystem;
  const std::string extension = read_detail::lower_extension(path);
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if(!fs::exists(status))
    throw Read_error(path + ": no such file");
  if(fs::is_directory(status))
    throw Read_error(path + ": is a directory, not a point file");
  if(!fs::is_regular_file(status))
    throw Read_error(path + ": is not a regular file");
  if(extension == ".laz")
    throw Las_error(laz_message(path));
  if(extension == ".las")
  {
    // read a chunk at a time: the file is never held whole
    Las_file file(path);
    Point_cloud cloud = read_detail::read_las(file, filter, keep_las_records);
    if(cloud.points.empty())
      throw Read_error(path + ": the file holds no point");
    return cloud;
  }
  if(extension != ".xyz" && extension != ".pwn" && extension != ".ply" && extension != ".off" && extension != ".obj")
    throw Read_error(path + ": unknown input extension '" + read_detail::shown(extension) + "' "
                     + known_extensions());
  return parse_point_cloud(read_detail::file_bytes(path), extension, path);
}

} // namespace cas3

#endif // CAS3_READ_POINT_CLOUD_H
