// What conformal_curvature writes per layer (a scale and a neighborhood):
// the values per input point, the binary PLY point cloud that holds them,
// the surface PLY with the same values at its vertices, and the CSV. The
// benchmark of the default job writes through the same code.
#ifndef CAS3_CURVATURE_OUTPUT_H
#define CAS3_CURVATURE_OUTPUT_H

#include "cas3_curvature_colors.h"
#include "cas3_las.h"
#include "cas3_layer_names.h"
#include "cas3_read_point_cloud.h"

#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>
#include <CGAL/Conformal_alpha_shapes_3/shape_index.h>
#include <CGAL/boost/graph/iterator.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace cas3 {

// The values of one layer per input point, in input units, as the point
// cloud file stores them.
struct Layer
{
  static constexpr int number_of_values = 19;
  // the standard uncertainties of H, K and the normal (degrees) and the
  // noise's part of H's last, so that the columns before them keep their places
  static constexpr int H_sigma_column = 15;
  // the values that the LAS file holds, those before the uncertainties:
  // its Extra Bytes VLR holds 341 fields, 21 layers of these
  static constexpr int number_of_las_values = 15;
  static const char* const* value_names()
  {
    static const char* const names[number_of_values] = {"nx", "ny", "nz", "H", "K", "k1", "k2", "d1x", "d1y",
                                                         "d1z", "d2x", "d2y", "d2z", "radius", "distance",
                                                         "H_sigma", "K_sigma", "normal_sigma", "H_noise_sigma"};
    return names;
  }
  std::string label;       // the property suffix: layer_label()
  std::string description; // for the file header: layer_description()
  std::vector<float> values;        // number_of_values per point
  std::vector<std::uint8_t> source; // Point_source per point

  Layer() = default;  // filled by the caller (the Python module, from its arrays)
  template <class Kernel>
  explicit Layer(const std::vector<CGAL::Conformal_alpha_shapes_3::Point_curvature<Kernel> >& curvatures)
    : values(curvatures.size() * number_of_values), source(curvatures.size())
  {
    for(std::size_t i = 0; i < curvatures.size(); ++i)
    {
      const auto& c = curvatures[i];
      const auto& p = c.principal;
      const double v[number_of_values] = {c.normal.x(), c.normal.y(), c.normal.z(), c.mean_curvature,
                                          c.gaussian_curvature, p.max_curvature, p.min_curvature,
                                          p.max_direction.x(), p.max_direction.y(), p.max_direction.z(),
                                          p.min_direction.x(), p.min_direction.y(), p.min_direction.z(),
                                          c.radius, c.distance, c.uncertainty.mean_curvature,
                                          c.uncertainty.gaussian_curvature, c.uncertainty.normal_degrees,
                                          c.uncertainty.mean_curvature_noise};
      for(int j = 0; j < number_of_values; ++j)
        values[i * number_of_values + std::size_t(j)] = float(v[j]);
      source[i] = std::uint8_t(c.source);
    }
  }
};

// What a layer is, for the comment lines of the files' headers: its scale
// `a` (as requested), its neighborhood and, for a radius, its length in
// input units.
template <class Analysis>
std::string layer_description(const Analysis& analysis, double a, const CGAL::Conformal_alpha_shapes_3::Scale& scale,
                              const CGAL::Conformal_alpha_shapes_3::Neighborhood& neighborhood,
                              const std::string& label)
{
  typedef CGAL::Conformal_alpha_shapes_3::Neighborhood Neighborhood;
  std::ostringstream description;
  description << "a = " << a << " (" << scale_text(scale) << "), ";
  if(neighborhood.kind() == Neighborhood::RINGS)
    description << int(neighborhood.value()) << "-ring";
  else if(neighborhood.kind() == Neighborhood::AUTOMATIC)
    description << "radius chosen per point (radius_" << label << ")";
  else
    description << "radius " << analysis.radius(neighborhood);
  return description.str();
}

namespace output_detail {

// What the two binary little-endian PLY files share: the header's start
// with its comments and a comment line per layer, the float properties of
// a layer's values, and the rows, of a fixed size each, made side by side.
inline void put_header_start(std::ostream& header, std::initializer_list<const char*> comments,
                             const Layer* first, const Layer* last)
{
  header << "ply\nformat binary_little_endian 1.0\n";
  for(const char* comment : comments)
    header << "comment " << comment << "\n";
  for(const Layer* layer = first; layer != last; ++layer)
    header << "comment layer " << layer->label << ": " << layer->description << "\n";
}

inline void put_value_properties(std::ostream& header, const Layer& layer)
{
  for(int j = 0; j < Layer::number_of_values; ++j)
    header << "property float " << Layer::value_names()[j] << "_" << layer.label << "\n";
}

// Asks the processor to bring the memory at `p` into its caches.
inline void prefetch(const void* p)
{
#if defined(__GNUC__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

// The same for the values of point i in `layer` (72 bytes: up to three lines).
inline void prefetch_values(const Layer& layer, std::size_t i)
{
  const float* row = layer.values.data() + i * Layer::number_of_values;
  prefetch(row);
  prefetch(row + Layer::number_of_values / 2);
  prefetch(row + Layer::number_of_values - 1);
}

// Appends a number the shortest way that reads back exactly.
inline void append(std::string& out, double x)
{
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
  out.append(buffer, r.ptr);
}

class Row_cursor
{
public:
  explicit Row_cursor(char* p) : m_p(p) {}

  template <class T>
  void put(T x)
  {
    static_assert(std::is_arithmetic<T>::value, "a number");
    // the platforms of these programs are little-endian; the header says so
    std::memcpy(m_p, &x, sizeof(T));
    m_p += sizeof(T);
  }
  template <class Point>
  void put_position(const Point& p)
  {
    put(double(p.x()));
    put(double(p.y()));
    put(double(p.z()));
  }
  void put_bytes(const char* bytes, std::size_t n)
  {
    std::memcpy(m_p, bytes, n);
    m_p += n;
  }
  void put_values(const Layer& layer, std::size_t i, int count = Layer::number_of_values)
  {
    for(int j = 0; j < count; ++j)
      put(layer.values[i * Layer::number_of_values + std::size_t(j)]);
  }
  const char* position() const { return m_p; }

private:
  char* m_p;
};

// Writes rows 0 to n - 1 of `row_size` bytes each, in order, `put_row(i,
// row)` putting row i at a cursor: in batches of about 16 MB whose rows are
// made on TBB's threads (with CGAL_LINKED_WITH_TBB), each at its place, so
// that the bytes are those of one thread.
template <class PutRow>
void write_rows(std::ostream& out, std::size_t n, std::size_t row_size, PutRow put_row)
{
  const std::size_t batch = (std::max)(std::size_t(1), (std::size_t(16) << 20) / row_size);
  std::vector<char> bytes;
  for(std::size_t first = 0; first < n; first += batch)
  {
    const std::size_t count = (std::min)(batch, n - first);
    bytes.resize(count * row_size);
    auto make = [&](std::size_t k) {
      Row_cursor row(bytes.data() + k * row_size);
      put_row(first + k, row);
      CGAL_assertion(row.position() == bytes.data() + (k + 1) * row_size);
    };
#ifdef CGAL_LINKED_WITH_TBB
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
      for(std::size_t k = r.begin(); k != r.end(); ++k)
        make(k);
    });
#else
    for(std::size_t k = 0; k < count; ++k)
      make(k);
#endif
    out.write(bytes.data(), std::streamsize(bytes.size()));
  }
}

} // namespace output_detail

// The point cloud: binary little-endian PLY, double positions, float
// values, uchar flags; a comment line per layer says what it is.
template <class Point>
void write_point_cloud(std::ostream& out, const std::vector<Point>& points, const std::vector<bool>& outlier,
                       const std::vector<Layer>& layers)
{
  std::ostringstream header;
  output_detail::put_header_start(header,
                                  {"conformal_curvature: values per input point, in input units",
                                   "source_L: 0 own surface vertex, 1 nearest surface point, 2 no value"},
                                  layers.data(), layers.data() + layers.size());
  header << "element vertex " << points.size() << "\n"
         << "property double x\nproperty double y\nproperty double z\nproperty uchar outlier\n";
  for(const Layer& layer : layers)
  {
    output_detail::put_value_properties(header, layer);
    header << "property uchar source_" << layer.label << "\n";
  }
  // appended after the layers: Koenderink's shape index and curvedness of
  // each layer, from its k1 and k2 (shape_index.h)
  for(const Layer& layer : layers)
    header << "property float shape_index_" << layer.label << "\nproperty float curvedness_" << layer.label << "\n";
  header << "end_header\n";
  out << header.str();
  const std::size_t row_size = 3 * sizeof(double) + 1 + layers.size() * (Layer::number_of_values * sizeof(float) + 1)
                               + layers.size() * 2 * sizeof(float);
  output_detail::write_rows(out, points.size(), row_size, [&](std::size_t i, output_detail::Row_cursor& row) {
    row.put_position(points[i]);
    row.put(std::uint8_t(outlier[i] ? 1 : 0));
    for(const Layer& layer : layers)
    {
      row.put_values(layer, i);
      row.put(layer.source[i]);
    }
    for(const Layer& layer : layers)
    {
      const float* v = layer.values.data() + i * Layer::number_of_values;
      // from k1 and k2 in double, as Python's functions compute them
      row.put(float(CGAL::Conformal_alpha_shapes_3::shape_index(double(v[5]), double(v[6]))));
      row.put(float(CGAL::Conformal_alpha_shapes_3::curvedness(double(v[5]), double(v[6]))));
    }
  });
}

// The surface of one scale: binary little-endian PLY, each vertex at its
// input point (the library's surface lies at the smoothed positions) with
// its input index, the float values of the scale's layers [first, last) and
// the color of the first layer's H, then the triangles. Written straight
// from the layers: a copy of the surface with a property map per value
// would hold every value twice.
template <class Surface, class Point>
void write_surface(std::ostream& out, const Surface& surface, const std::vector<Point>& points,
                   const Layer* first, const Layer* last)
{
  typedef typename Surface::Vertex_index Vertex;
  const auto input_index = surface.template property_map<Vertex, std::size_t>("v:input_index").first;
  const std::vector<Vertex> written(surface.vertices().begin(), surface.vertices().end());
  std::vector<std::uint32_t> number(surface.num_vertices());  // by vertex, in the order written
  for(std::size_t k = 0; k < written.size(); ++k)
    number[written[k]] = std::uint32_t(k);

  struct First_layer_H
  {
    const Layer* layer;
    const decltype(input_index)* index;
    float operator[](Vertex v) const { return layer->values[(*index)[v] * Layer::number_of_values + 3]; }
  };
  std::vector<CGAL::IO::Color> color(surface.num_vertices());
  if(first != last)
    color_by_curvature(surface, First_layer_H{first, &input_index}, color);

  std::ostringstream header;
  output_detail::put_header_start(
    header, {"conformal_curvature: a surface, its vertices at their input points, values in input units"}, first,
    last);
  header << "element vertex " << surface.number_of_vertices() << "\n"
         << "property double x\nproperty double y\nproperty double z\nproperty uint input_index\n";
  for(const Layer* layer = first; layer != last; ++layer)
    output_detail::put_value_properties(header, *layer);
  header << "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
         << "element face " << surface.number_of_faces() << "\n"
         << "property list uchar int vertex_indices\nend_header\n";
  out << header.str();
  // the rows are read by input index, out of memory order: each vertex asks
  // for the rows of the one 16 places later, so that they are in the
  // caches when their turn comes
  const std::size_t vertex_row = 3 * sizeof(double) + sizeof(std::uint32_t)
                                 + std::size_t(last - first) * Layer::number_of_values * sizeof(float) + 4;
  output_detail::write_rows(out, written.size(), vertex_row, [&](std::size_t k, output_detail::Row_cursor& row) {
    if(k + 16 < written.size())
    {
      const std::size_t later = input_index[written[k + 16]];
      output_detail::prefetch(&points[later]);
      for(const Layer* layer = first; layer != last; ++layer)
        output_detail::prefetch_values(*layer, later);
    }
    const std::size_t i = input_index[written[k]];
    row.put_position(points[i]);
    row.put(std::uint32_t(i));
    for(const Layer* layer = first; layer != last; ++layer)
      row.put_values(*layer, i);
    const CGAL::IO::Color& c = color[written[k]];
    for(unsigned char channel : {c.red(), c.green(), c.blue(), c.alpha()})
      row.put(std::uint8_t(channel));
  });
  const std::vector<typename Surface::Face_index> faces(surface.faces().begin(), surface.faces().end());
  const std::size_t face_row = 1 + 3 * sizeof(std::int32_t);
  output_detail::write_rows(out, faces.size(), face_row, [&](std::size_t k, output_detail::Row_cursor& row) {
    row.put(std::uint8_t(3));
    for(Vertex v : CGAL::vertices_around_face(surface.halfedge(faces[k]), surface))
      row.put(std::int32_t(number[v]));
  });
}

// The extra-bytes fields of the LAS point cloud, the PLY's properties by
// the same names: outlier, then per layer L nx_L .. distance_L (float) and
// source_L. Throws std::invalid_argument when a name is too long for LAS
// (32 characters) or there are more than 21 layers.
inline std::vector<Las_extra_field> las_extra_fields(const std::vector<std::string>& labels)
{
  static const char* const meaning[Layer::number_of_las_values] = {
    "unit normal, x", "unit normal, y", "unit normal, z", "mean curvature H", "Gaussian curvature K",
    "principal curvature k1 (max)", "principal curvature k2 (min)", "direction of k1, x", "direction of k1, y",
    "direction of k1, z", "direction of k2, x", "direction of k2, y", "direction of k2, z",
    "radius of the fit", "distance to the surface value"};
  std::vector<Las_extra_field> fields = {{"outlier", "1: isolated far outlier", false}};
  for(const std::string& label : labels)
  {
    for(int j = 0; j < Layer::number_of_las_values; ++j)
      fields.push_back({std::string(Layer::value_names()[j]) + "_" + label, meaning[j], true});
    fields.push_back({"source_" + label, "0 own vertex, 1 nearest, 2 none", false});
  }
  check_las_extra_fields(fields);
  return fields;
}

// The point records of a LAS 1.4 file of `header` (las_header_bytes()):
// per point i, `record(i)` (a Las_record) in the header's point format, the
// input's extra-bytes fields that the header carries, from `extra(i)` (the
// input record's extra bytes, or nullptr when it carries none), its outlier
// flag and the values of the layers, as las_extra_fields() names them.
template <class Record, class Extra>
void write_las_point_records(std::ostream& out, std::size_t n, const Las_output_header& header, Record record,
                             Extra extra, const std::vector<bool>& outlier, const std::vector<Layer>& layers)
{
  const int format = las_output_point_format(header);
  const std::size_t base = std::size_t(las_detail::base_record_length(format));
  const std::size_t row_size = las_output_record_length(header);
  output_detail::write_rows(out, n, row_size, [&](std::size_t i, output_detail::Row_cursor& row) {
    char bytes[38];
    encode_las_record(record(i), format, bytes);
    row.put_bytes(bytes, base);
    if(!header.carried.empty())
    {
      const char* in = extra(i);
      for(const Las_extra_bytes_field& f : header.carried)
        row.put_bytes(in + f.offset, f.size);
    }
    row.put(std::uint8_t(outlier[i] ? 1 : 0));
    for(const Layer& layer : layers)
    {
      row.put_values(layer, i, Layer::number_of_las_values);
      row.put(layer.source[i]);
    }
  });
}

// The header of the LAS output of points read from `las` (when present)
// with layers labelled `labels`: las_extra_fields() after what
// carry_las_input() keeps of the input. Throws std::invalid_argument when
// the fields do not fit.
inline Las_output_header las_output_header(const Las_input& las, const std::vector<std::string>& labels)
{
  Las_output_header header;
  header.extra = las_extra_fields(labels);
  if(!las.present)
    return header;
  if(las.extra_bytes.size() != las.records.size() * las.header.extra_bytes)
    throw std::invalid_argument("LAS output: the input's extra bytes are not " + std::to_string(las.header.extra_bytes)
                                + " per record");
  carry_las_input(las.header, header);
  return header;
}

// The point cloud as LAS 1.4: point format 6, or 7 (8) when the LAS input
// had colors (and NIR); the input's records (scaled integers, scale and
// offset, fields, extra bytes, CRS) when `las` holds one per point, else
// the points written with choose_las_scale(); then the fields of
// las_extra_fields(), described in the Extra Bytes VLR.
template <class Point>
void write_point_cloud_las(std::ostream& out, const std::vector<Point>& points, const Las_input& las,
                           const std::vector<bool>& outlier, const std::vector<Layer>& layers)
{
  std::vector<std::string> labels;
  for(const Layer& layer : layers)
    labels.push_back(layer.label);
  const bool from_las = las.present && las.records.size() == points.size();
  Las_output_header header = las_output_header(from_las ? las : Las_input(), labels);
  auto record = [&](std::size_t i) {
    if(from_las)
      return las.records[i];
    Las_record r;
    const double xyz[3] = {double(points[i].x()), double(points[i].y()), double(points[i].z())};
    quantize_las(header, xyz, r);
    r.return_number = r.number_of_returns = 1;
    return r;
  };
  auto extra = [&](std::size_t i) { return las.extra_bytes.data() + i * las.header.extra_bytes; };
  if(!from_las && !points.empty())
  {
    double low[3], high[3];
    for(int k = 0; k < 3; ++k)
      low[k] = high[k] = double(points[0][k]);
    for(const Point& p : points)
      for(int k = 0; k < 3; ++k)
      {
        low[k] = (std::min)(low[k], double(p[k]));
        high[k] = (std::max)(high[k], double(p[k]));
      }
    choose_las_scale(low, high, header);
  }
  Las_bounds bounds;
  for(std::size_t i = 0; i < points.size(); ++i)
    bounds.add(record(i));
  bounds.set(header);
  out << las_header_bytes(header);
  write_las_point_records(out, points.size(), header, record, extra, outlier, layers);
  out << las_evlr_bytes(header);
}

// The CSV: its header line, then append_csv_rows() for each layer.
inline const char* csv_header()
{
  return "point_index,x,y,z,a,rings,on_surface,nx,ny,nz,H,K,k1,k2,d1x,d1y,d1z,d2x,d2y,d2z,outlier,"
         "neighborhood,radius,source,distance,H_sigma,K_sigma,normal_sigma,H_noise_sigma\n";
}

// The CSV rows of one layer, a row per input point: the layer's scale `a`,
// its neighborhood (labelled as cas3_layer_names.h says) and values.
template <class Point, class Kernel>
void append_csv_rows(std::ostream& csv, const std::vector<Point>& points, double a,
                     const CGAL::Conformal_alpha_shapes_3::Neighborhood& neighborhood,
                     const std::vector<CGAL::Conformal_alpha_shapes_3::Point_curvature<Kernel> >& curvatures,
                     const std::vector<bool>& outlier)
{
  using output_detail::append;
  const std::string rings = neighborhood.kind() == CGAL::Conformal_alpha_shapes_3::Neighborhood::RINGS
                              ? std::to_string(int(neighborhood.value())) : "0";
  const std::string label = neighborhood_label(neighborhood);
  std::string line;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const CGAL::Conformal_alpha_shapes_3::Point_curvature<Kernel>& c = curvatures[i];
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
    for(double x : {double(c.uncertainty.mean_curvature), double(c.uncertainty.gaussian_curvature),
                    double(c.uncertainty.normal_degrees), double(c.uncertainty.mean_curvature_noise)})
    {
      line += ',';
      append(line, x);
    }
    line += '\n';
    csv << line;
  }
}

} // namespace cas3

#endif // CAS3_CURVATURE_OUTPUT_H
