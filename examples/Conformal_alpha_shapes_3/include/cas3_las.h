// LAS files (ASPRS LAS 1.0 to 1.4, point data record formats 0 to 10,
// uncompressed), read and written from the specification, for the
// conformal_curvature program, the Python module and its tiles (Debian 12
// has no LAS library). Not part of the library.
//
// Las_file opens a file (or bytes, for the fuzz harness), reads and checks
// its header, and reads any range of its point records (read()) without
// loading the file: the tiles read a cloud in chunks. Each record is given
// as a Las_record, the fields of point formats 6 to 10 (the older formats'
// fields are converted: the 5-bit class and its 3 flags, the scan angle
// rank in degrees). Coordinates are the record's scaled integers times the
// header's scale plus its offset, in double. Bytes beyond a format's base
// size (extra bytes) are given raw, on request, with their fields as the
// Extra Bytes VLR describes them; of the VLRs and EVLRs, the coordinate
// reference system's records are kept (GeoTIFF keys and OGC WKT); the
// others, and waveform data, are skipped.
//
// A bad file throws Las_error (a Read_error of cas3_read_point_cloud.h)
// with one line naming the file and what is wrong: not a LAS file, an
// unknown version or point format, a compressed (LAZ) file, a header
// smaller than its version's, an offset to the point data inside the
// header or beyond the file, a record length below the format's base size,
// a scale that is not finite and nonzero, an offset that is not finite, a
// point count beyond the file, a VLR that runs into the point data, an
// EVLR beyond the file, an Extra Bytes VLR that does not fit the records.
// Nothing is read past the end of the file.
//
// Las_filter is what LiDAR users filter on: classes, withheld points,
// first or last returns. las_header_bytes() and encode_las_record() write
// LAS 1.4 with point format 6, 7 or 8 and named extra bytes (the Extra
// Bytes VLR, record id 4 of LASF_Spec), which lidR, PDAL and CloudCompare
// load as attributes; a LAS input's own extra bytes and CRS records are
// carried into it.
#ifndef CAS3_LAS_H
#define CAS3_LAS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <limits>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cas3 {

// The one exception type of the point readers: what() is one line.
struct Read_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// A bad LAS file.
struct Las_error : Read_error
{
  using Read_error::Read_error;
};

// A variable length record (VLR, or EVLR of LAS 1.4) kept from a file.
struct Las_vlr
{
  std::string user_id;      // at most 16 characters
  std::uint16_t record_id = 0;
  std::string description;  // at most 32 characters
  std::string data;
};

// An extra-bytes field of a file's records: its descriptor (the 192 bytes
// of the Extra Bytes VLR) and the place of its bytes among the record's
// extra bytes.
struct Las_extra_bytes_field
{
  std::string name;
  std::string descriptor;
  std::size_t offset = 0, size = 0;
};

// What the header says, checked.
struct Las_header
{
  int version_major = 1, version_minor = 4;
  std::uint16_t file_source_id = 0;
  std::uint16_t global_encoding = 0;
  std::uint16_t creation_day = 0, creation_year = 0;
  std::uint16_t header_size = 0;
  std::uint32_t offset_to_points = 0;
  std::uint32_t number_of_vlrs = 0;
  int point_format = 0;
  std::uint16_t record_length = 0;
  std::uint64_t number_of_points = 0;
  double scale[3] = {0.001, 0.001, 0.001};
  double offset[3] = {0, 0, 0};
  double min[3] = {0, 0, 0}, max[3] = {0, 0, 0};
  std::uint64_t file_size = 0;
  std::uint64_t start_of_first_evlr = 0;  // LAS 1.4
  std::uint32_t number_of_evlrs = 0;
  // filled by Las_file: the bytes of a record beyond its format's base size,
  // their fields (an undescribed rest as fields of data type 0), and the
  // CRS records, VLRs then EVLRs, in file order
  std::size_t extra_bytes = 0;
  std::vector<Las_extra_bytes_field> extra_fields;
  std::vector<Las_vlr> crs;
};

// A point's fields, in the terms of point formats 6 to 10.
struct Las_record
{
  std::int32_t X = 0, Y = 0, Z = 0;  // the scaled integers
  std::uint16_t intensity = 0;
  std::uint8_t return_number = 0, number_of_returns = 0;  // 4 bits each (3 in formats 0 to 5)
  std::uint8_t flags = 0;  // bit 0 synthetic, 1 key-point, 2 withheld, 3 overlap
  std::uint8_t scanner_channel = 0, scan_direction = 0, edge_of_flight_line = 0;
  std::uint8_t classification = 0;  // 0 to 255 (0 to 31 in formats 0 to 5)
  std::uint8_t user_data = 0;
  std::int16_t scan_angle = 0;  // in 0.006 degrees
  std::uint16_t point_source_id = 0;
  double gps_time = 0;
  std::uint16_t red = 0, green = 0, blue = 0, nir = 0;

  enum Flag { SYNTHETIC = 1, KEY_POINT = 2, WITHHELD = 4, OVERLAP = 8 };
  bool withheld() const { return (flags & WITHHELD) != 0; }
  bool synthetic() const { return (flags & SYNTHETIC) != 0; }
  // A return number of 0 (not set) counts as a single return: first and last.
  bool first_return() const { return return_number <= 1; }
  bool last_return() const { return return_number >= number_of_returns; }
};

namespace las_detail {

template <class T>
T get(const char* p)
{
  T x;
  std::memcpy(&x, p, sizeof(T));  // LAS is little-endian, as the platforms of these programs
  return x;
}

template <class T>
void put(char* p, T x)
{
  std::memcpy(p, &x, sizeof(T));
}

// The size of a record of point format f (0 to 10) without extra bytes.
inline int base_record_length(int f)
{
  static const int sizes[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
  return sizes[f];
}

inline bool has_gps_time(int f) { return f != 0 && f != 2; }
inline bool has_rgb(int f) { return f == 2 || f == 3 || f == 5 || f == 7 || f == 8 || f == 10; }
inline bool has_nir(int f) { return f == 8 || f == 10; }

// The header size of LAS 1.minor.
inline int header_size_of_version(int minor) { return minor <= 2 ? 227 : (minor == 3 ? 235 : 375); }

// The text of a fixed-size, zero-padded field.
inline std::string field_text(const char* p, std::size_t size)
{
  std::size_t n = 0;
  while(n < size && p[n] != '\0')
    ++n;
  return std::string(p, n);
}

// The records of a coordinate reference system: GeoKeyDirectoryTag,
// GeoDoubleParamsTag, GeoAsciiParamsTag and OGC coordinate system WKT.
inline bool is_crs_record(const std::string& user_id, std::uint16_t record_id)
{
  return user_id == "LASF_Projection"
         && (record_id == 34735 || record_id == 34736 || record_id == 34737 || record_id == 2112);
}

inline bool is_extra_bytes_record(const std::string& user_id, std::uint16_t record_id)
{
  return user_id == "LASF_Spec" && record_id == 4;
}

// The bytes of an extra-bytes field of data type `type` (1 to 10 scalars,
// 11 to 30 the deprecated arrays of 2 and 3), -1 for an unknown type; type
// 0 (undocumented bytes) has the size of its options byte.
inline int extra_bytes_type_size(int type, int options)
{
  static const int scalar[11] = {0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8};
  if(type == 0)
    return options;
  if(type < 1 || type > 30)
    return -1;
  return ((type - 1) / 10 + 1) * scalar[(type - 1) % 10 + 1];
}

// The fields an Extra Bytes VLR's `payload` describes in records of
// `extra_bytes` bytes beyond their base size, and a field of data type 0
// for any undescribed rest. Throws Las_error.
inline std::vector<Las_extra_bytes_field> extra_bytes_fields(const std::string& payload, std::size_t extra_bytes,
                                                            const std::string& name)
{
  std::vector<Las_extra_bytes_field> fields;
  if(payload.size() % 192 != 0)
    throw Las_error(name + ": the Extra Bytes VLR has " + std::to_string(payload.size())
                    + " bytes, not a multiple of its 192-byte descriptors");
  std::size_t at = 0;
  for(std::size_t k = 0; k < payload.size() / 192; ++k)
  {
    Las_extra_bytes_field f;
    f.descriptor = payload.substr(192 * k, 192);
    f.name = field_text(f.descriptor.data() + 4, 32);
    const int type = std::uint8_t(f.descriptor[2]), options = std::uint8_t(f.descriptor[3]);
    const int size = extra_bytes_type_size(type, options);
    if(size < 0)
      throw Las_error(name + ": extra-bytes field " + std::to_string(k + 1)
                      + " of the Extra Bytes VLR has the unknown data type " + std::to_string(type)
                      + " (0 to 30 are defined)");
    f.offset = at;
    f.size = std::size_t(size);
    at += f.size;
    if(at > extra_bytes)
      throw Las_error(name + ": the Extra Bytes VLR describes " + std::to_string(at) + " bytes per point or more, "
                      "the records have " + std::to_string(extra_bytes) + " beyond their point format's");
    fields.push_back(f);
  }
  // data type 0 (undocumented bytes) holds up to 255 bytes: a longer rest
  // is cut in such fields
  for(std::size_t done = at; done < extra_bytes; done += 255)
  {
    Las_extra_bytes_field rest;
    rest.name = "undescribed_extra_bytes";
    rest.offset = done;
    rest.size = (std::min)(extra_bytes - done, std::size_t(255));
    rest.descriptor.assign(192, '\0');
    rest.descriptor[3] = char(std::uint8_t(rest.size));
    std::memcpy(&rest.descriptor[4], rest.name.data(), rest.name.size());
    fields.push_back(rest);
  }
  return fields;
}

inline std::string text(double x)
{
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

} // namespace las_detail

// The message for a compressed file: how to get an uncompressed one.
inline std::string laz_message(const std::string& name)
{
  return name + ": compressed LAS (LAZ) cannot be read without LASzip; decompress it first, e.g. "
         "'laszip -i x.laz -o x.las' or 'pdal translate x.laz x.las'";
}

// Checks the header in `bytes` (at least its first 227 bytes, all of them
// for a 1.3 or 1.4 header) of a file of `file_size` bytes. Throws Las_error.
inline Las_header parse_las_header(const std::string& bytes, std::uint64_t file_size, const std::string& name)
{
  using las_detail::get;
  Las_header h;
  h.file_size = file_size;
  if(bytes.size() < 4 || bytes.compare(0, 4, "LASF") != 0)
    throw Las_error(name + ": not a LAS file (no LASF signature)");
  if(bytes.size() < 227)
    throw Las_error(name + ": truncated LAS header: the file has " + std::to_string(file_size)
                    + " bytes, a header at least 227");
  const char* p = bytes.data();
  h.file_source_id = get<std::uint16_t>(p + 4);
  h.global_encoding = get<std::uint16_t>(p + 6);
  h.version_major = std::uint8_t(p[24]);
  h.version_minor = std::uint8_t(p[25]);
  if(h.version_major != 1 || h.version_minor > 4)
    throw Las_error(name + ": unknown LAS version " + std::to_string(h.version_major) + "."
                    + std::to_string(h.version_minor) + " (1.0 to 1.4 are read)");
  h.creation_day = get<std::uint16_t>(p + 90);
  h.creation_year = get<std::uint16_t>(p + 92);
  h.header_size = get<std::uint16_t>(p + 94);
  h.offset_to_points = get<std::uint32_t>(p + 96);
  h.number_of_vlrs = get<std::uint32_t>(p + 100);
  const std::uint8_t format_byte = std::uint8_t(p[104]);
  h.record_length = get<std::uint16_t>(p + 105);
  const std::uint32_t legacy_count = get<std::uint32_t>(p + 107);
  for(int k = 0; k < 3; ++k)
  {
    h.scale[k] = get<double>(p + 131 + 8 * k);
    h.offset[k] = get<double>(p + 155 + 8 * k);
    h.max[k] = get<double>(p + 179 + 16 * k);
    h.min[k] = get<double>(p + 187 + 16 * k);
  }
  if(format_byte & 0xC0)
    throw Las_error(laz_message(name));
  h.point_format = format_byte;
  if(h.point_format > 10)
    throw Las_error(name + ": unknown LAS point data record format " + std::to_string(h.point_format)
                    + " (0 to 10 are read)");
  const int needed = las_detail::header_size_of_version(h.version_minor);
  if(h.header_size < needed)
    throw Las_error(name + ": the header size " + std::to_string(h.header_size) + " is smaller than LAS 1."
                    + std::to_string(h.version_minor) + "'s " + std::to_string(needed) + " bytes");
  if(std::uint64_t(h.header_size) > file_size || bytes.size() < std::size_t(needed))
    throw Las_error(name + ": truncated LAS header: the file has " + std::to_string(file_size)
                    + " bytes, the header " + std::to_string(h.header_size));
  if(h.offset_to_points < h.header_size)
    throw Las_error(name + ": the offset to the point data (" + std::to_string(h.offset_to_points)
                    + ") is inside the header (" + std::to_string(h.header_size) + " bytes)");
  if(h.offset_to_points > file_size)
    throw Las_error(name + ": the offset to the point data (" + std::to_string(h.offset_to_points)
                    + ") is beyond the end of the file (" + std::to_string(file_size) + " bytes)");
  const int base = las_detail::base_record_length(h.point_format);
  if(h.record_length < base)
    throw Las_error(name + ": the point record length " + std::to_string(h.record_length)
                    + " is smaller than point format " + std::to_string(h.point_format) + "'s "
                    + std::to_string(base) + " bytes");
  const char* axis = "XYZ";
  for(int k = 0; k < 3; ++k)
  {
    if(!std::isfinite(h.scale[k]) || h.scale[k] == 0)
      throw Las_error(name + ": the " + axis[k] + " scale factor is not finite and nonzero: "
                      + las_detail::text(h.scale[k]));
    if(!std::isfinite(h.offset[k]))
      throw Las_error(name + ": the " + axis[k] + " offset is not finite: " + las_detail::text(h.offset[k]));
  }
  // the count: the 64-bit one of LAS 1.4, unless a writer left it 0 and
  // filled the legacy one; the legacy one before
  h.number_of_points = legacy_count;
  if(h.version_minor >= 4)
  {
    const std::uint64_t count = get<std::uint64_t>(p + 247);
    if(count != 0)
      h.number_of_points = count;
  }
  h.extra_bytes = std::size_t(h.record_length - base);
  if(h.version_minor >= 4)
  {
    h.start_of_first_evlr = get<std::uint64_t>(p + 235);
    h.number_of_evlrs = get<std::uint32_t>(p + 243);
  }
  const std::uint64_t room = (file_size - h.offset_to_points) / h.record_length;
  if(h.number_of_points > room)
    throw Las_error(name + ": the header announces " + std::to_string(h.number_of_points) + " points of "
                    + std::to_string(h.record_length) + " bytes, the file holds " + std::to_string(room)
                    + " (truncated, or a wrong point count)");
  return h;
}

// Decodes a record of point format `format` at `p` (the format's base size
// at least).
inline Las_record decode_las_record(const char* p, int format)
{
  using las_detail::get;
  Las_record r;
  r.X = get<std::int32_t>(p);
  r.Y = get<std::int32_t>(p + 4);
  r.Z = get<std::int32_t>(p + 8);
  r.intensity = get<std::uint16_t>(p + 12);
  const std::uint8_t b14 = std::uint8_t(p[14]), b15 = std::uint8_t(p[15]);
  if(format <= 5)
  {
    r.return_number = b14 & 7;
    r.number_of_returns = (b14 >> 3) & 7;
    r.scan_direction = (b14 >> 6) & 1;
    r.edge_of_flight_line = (b14 >> 7) & 1;
    r.classification = b15 & 31;
    r.flags = std::uint8_t(b15 >> 5);  // synthetic, key-point, withheld
    r.scan_angle = std::int16_t(std::lround(double(std::int8_t(p[16])) / 0.006));
    r.user_data = std::uint8_t(p[17]);
    r.point_source_id = get<std::uint16_t>(p + 18);
    int at = 20;
    if(las_detail::has_gps_time(format))
    {
      r.gps_time = get<double>(p + at);
      at += 8;
    }
    if(las_detail::has_rgb(format))
    {
      r.red = get<std::uint16_t>(p + at);
      r.green = get<std::uint16_t>(p + at + 2);
      r.blue = get<std::uint16_t>(p + at + 4);
    }
  }
  else
  {
    r.return_number = b14 & 15;
    r.number_of_returns = b14 >> 4;
    r.flags = b15 & 15;
    r.scanner_channel = (b15 >> 4) & 3;
    r.scan_direction = (b15 >> 6) & 1;
    r.edge_of_flight_line = (b15 >> 7) & 1;
    r.classification = std::uint8_t(p[16]);
    r.user_data = std::uint8_t(p[17]);
    r.scan_angle = get<std::int16_t>(p + 18);
    r.point_source_id = get<std::uint16_t>(p + 20);
    r.gps_time = get<double>(p + 22);
    if(las_detail::has_rgb(format))
    {
      r.red = get<std::uint16_t>(p + 30);
      r.green = get<std::uint16_t>(p + 32);
      r.blue = get<std::uint16_t>(p + 34);
    }
    if(las_detail::has_nir(format))
      r.nir = get<std::uint16_t>(p + 36);
  }
  return r;
}

// Writes `r` as a record of point format 6 (30 bytes), 7 (36 bytes, with
// RGB) or 8 (38 bytes, with RGB and NIR) at `p`.
inline void encode_las_record(const Las_record& r, int format, char* p)
{
  using las_detail::put;
  put(p, r.X);
  put(p + 4, r.Y);
  put(p + 8, r.Z);
  put(p + 12, r.intensity);
  p[14] = char(std::uint8_t((r.return_number & 15) | (r.number_of_returns << 4)));
  p[15] = char(std::uint8_t((r.flags & 15) | ((r.scanner_channel & 3) << 4) | ((r.scan_direction & 1) << 6)
                            | ((r.edge_of_flight_line & 1) << 7)));
  p[16] = char(r.classification);
  p[17] = char(r.user_data);
  put(p + 18, r.scan_angle);
  put(p + 20, r.point_source_id);
  put(p + 22, r.gps_time);
  if(format >= 7)
  {
    put(p + 30, r.red);
    put(p + 32, r.green);
    put(p + 34, r.blue);
  }
  if(format == 8)
    put(p + 36, r.nir);
}

// A LAS file, its header checked, its records read by range.
class Las_file
{
public:
  // Opens the file `path`. Throws Las_error (or Read_error when it cannot
  // be opened).
  explicit Las_file(const std::string& path) : m_name(path)
  {
    auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
    if(!*file)
      throw Read_error(path + ": cannot be opened for reading");
    m_in = std::move(file);
    open();
  }
  // The file whose bytes are `bytes`; `name` starts the messages.
  Las_file(const std::string& bytes, const std::string& name)
    : m_name(name), m_in(std::make_unique<std::istringstream>(bytes))
  {
    open();
  }

  const Las_header& header() const { return m_header; }
  const std::string& name() const { return m_name; }
  std::uint64_t number_of_points() const { return m_header.number_of_points; }
  bool has_rgb() const { return las_detail::has_rgb(m_header.point_format); }

  // Replaces `out` by the records first to first + count - 1 (clamped to
  // the file's), and `extra` (when given) by their extra bytes, the
  // header's extra_bytes per record. Throws Read_error when the file cannot
  // be read (it shrank).
  void read(std::uint64_t first, std::uint64_t count, std::vector<Las_record>& out, std::vector<char>* extra = nullptr)
  {
    out.clear();
    if(extra)
      extra->clear();
    if(first >= m_header.number_of_points)
      return;
    count = (std::min)(count, m_header.number_of_points - first);
    const std::size_t length = m_header.record_length;
    const std::uint64_t batch = (std::uint64_t(1) << 22) / length + 1;
    out.reserve(std::size_t(count));
    m_in->clear();
    m_in->seekg(std::streamoff(m_header.offset_to_points + first * length));
    for(std::uint64_t done = 0; done < count;)
    {
      const std::size_t n = std::size_t((std::min)(batch, count - done));
      m_buffer.resize(n * length);
      m_in->read(m_buffer.data(), std::streamsize(m_buffer.size()));
      if(!*m_in)
        throw Read_error(m_name + ": read error in point record " + std::to_string(first + done));
      const std::size_t base = length - m_header.extra_bytes;
      for(std::size_t i = 0; i < n; ++i)
      {
        const char* record = m_buffer.data() + i * length;
        out.push_back(decode_las_record(record, m_header.point_format));
        if(extra)
          extra->insert(extra->end(), record + base, record + length);
      }
      done += n;
    }
  }

  // The coordinates of `r`: its scaled integers times the scale plus the offset.
  std::array<double, 3> position(const Las_record& r) const
  {
    return {double(r.X) * m_header.scale[0] + m_header.offset[0], double(r.Y) * m_header.scale[1] + m_header.offset[1],
            double(r.Z) * m_header.scale[2] + m_header.offset[2]};
  }

private:
  void open()
  {
    m_in->seekg(0, std::ios::end);
    const std::streamoff end = m_in->tellg();
    if(!*m_in || end < 0)
      throw Read_error(m_name + ": read error");
    m_in->seekg(0);
    std::string head(std::size_t((std::min)(std::streamoff(375), end)), '\0');
    m_in->read(&head[0], std::streamsize(head.size()));
    if(!*m_in)
      throw Read_error(m_name + ": read error");
    m_header = parse_las_header(head, std::uint64_t(end), m_name);
    read_records();
  }

  // The `size` bytes at `at`, within the file (checked by the caller).
  std::string bytes_at(std::uint64_t at, std::uint64_t size)
  {
    std::string b(std::size_t(size), '\0');
    m_in->clear();
    m_in->seekg(std::streamoff(at));
    m_in->read(&b[0], std::streamsize(size));
    if(!*m_in)
      throw Read_error(m_name + ": read error");
    return b;
  }

  // Keeps the record of `head` (a VLR's 54 bytes or an EVLR's 60) whose
  // payload of `length` bytes is at `at` when it is a CRS record or the
  // Extra Bytes VLR.
  void keep_record(const std::string& head, std::uint64_t at, std::uint64_t length, std::string& extra_bytes_payload,
                   bool& has_extra_bytes)
  {
    using las_detail::get;
    Las_vlr v;
    v.user_id = las_detail::field_text(head.data() + 2, 16);
    v.record_id = get<std::uint16_t>(head.data() + 18);
    v.description = las_detail::field_text(head.data() + head.size() - 32, 32);
    if(las_detail::is_crs_record(v.user_id, v.record_id))
    {
      v.data = bytes_at(at, length);
      m_header.crs.push_back(v);
    }
    else if(las_detail::is_extra_bytes_record(v.user_id, v.record_id) && !has_extra_bytes)
    {
      extra_bytes_payload = bytes_at(at, length);
      has_extra_bytes = true;
    }
  }

  // The VLRs between the header and the point data, and the EVLRs after
  // the points: the CRS records and the extra-bytes fields.
  void read_records()
  {
    using las_detail::get;
    Las_header& h = m_header;
    std::string extra_bytes_payload;
    bool has_extra_bytes = false;
    std::uint64_t at = h.header_size;
    for(std::uint32_t k = 0; k < h.number_of_vlrs; ++k)
    {
      const std::string where = m_name + ": VLR " + std::to_string(k + 1) + " of " + std::to_string(h.number_of_vlrs);
      if(at + 54 > h.offset_to_points)
        throw Las_error(where + " runs into the point data (at " + std::to_string(h.offset_to_points) + ")");
      const std::string head = bytes_at(at, 54);
      const std::uint16_t length = get<std::uint16_t>(head.data() + 20);
      if(at + 54 + length > h.offset_to_points)
        throw Las_error(where + " runs into the point data (at " + std::to_string(h.offset_to_points) + ")");
      keep_record(head, at + 54, length, extra_bytes_payload, has_extra_bytes);
      at += 54 + length;
    }
    if(h.number_of_evlrs > 0)
    {
      const std::uint64_t points_end = h.offset_to_points + h.number_of_points * h.record_length;
      at = h.start_of_first_evlr;
      if(at < points_end)
        throw Las_error(m_name + ": the first EVLR (at " + std::to_string(at) + ") is not after the point data (which "
                        "ends at " + std::to_string(points_end) + ")");
      for(std::uint32_t k = 0; k < h.number_of_evlrs; ++k)
      {
        const std::string where
          = m_name + ": EVLR " + std::to_string(k + 1) + " of " + std::to_string(h.number_of_evlrs);
        if(at > h.file_size || h.file_size - at < 60)
          throw Las_error(where + " is beyond the end of the file (" + std::to_string(h.file_size) + " bytes)");
        const std::string head = bytes_at(at, 60);
        const std::uint64_t length = get<std::uint64_t>(head.data() + 20);
        if(length > h.file_size - at - 60)
          throw Las_error(where + " is beyond the end of the file (" + std::to_string(h.file_size) + " bytes)");
        keep_record(head, at + 60, length, extra_bytes_payload, has_extra_bytes);
        at += 60 + length;
      }
    }
    h.extra_fields = las_detail::extra_bytes_fields(extra_bytes_payload, h.extra_bytes, m_name);
  }

  std::string m_name;
  std::unique_ptr<std::istream> m_in;
  Las_header m_header;
  std::vector<char> m_buffer;
};

// Which points of a LAS file are kept: by class, not withheld, first or
// last returns. Empty classes: all.
struct Las_filter
{
  enum Returns { ALL_RETURNS, FIRST_RETURNS, LAST_RETURNS };
  std::vector<int> classes;
  bool drop_withheld = false;
  Returns returns = ALL_RETURNS;

  bool active() const { return !classes.empty() || drop_withheld || returns != ALL_RETURNS; }
};

// How many points were read, and how many each filter kept, in order:
// classes, withheld, returns.
struct Las_filter_counts
{
  std::uint64_t read = 0, classes = 0, withheld = 0, returns = 0;
};

// Whether `r` passes the filters, counted in `counts` as far as it passes.
inline bool keep_las_record(const Las_record& r, const Las_filter& filter, const std::vector<bool>& class_kept,
                            Las_filter_counts& counts)
{
  ++counts.read;
  if(!filter.classes.empty() && !class_kept[r.classification])
    return false;
  ++counts.classes;
  if(filter.drop_withheld && r.withheld())
    return false;
  ++counts.withheld;
  if((filter.returns == Las_filter::FIRST_RETURNS && !r.first_return()) ||
     (filter.returns == Las_filter::LAST_RETURNS && !r.last_return()))
    return false;
  ++counts.returns;
  return true;
}

// keep_las_record()'s table of the classes kept.
inline std::vector<bool> las_classes_kept(const Las_filter& filter)
{
  std::vector<bool> kept(256, filter.classes.empty());
  for(int c : filter.classes)
    if(c >= 0 && c < 256)
      kept[std::size_t(c)] = true;
  return kept;
}

// The line of the summary on a LAS input `name`: its version, point format
// and points, then what each filter kept, e.g. "x.las: LAS 1.4, point
// format 6, 1000 points; classes 2,6 kept 812, without withheld points
// kept 800, first returns kept 640".
inline std::string las_input_summary(const std::string& name, const Las_header& header, const Las_filter& filter,
                                     const Las_filter_counts& counts)
{
  std::string s = name + ": LAS " + std::to_string(header.version_major) + "." + std::to_string(header.version_minor)
                  + ", point format " + std::to_string(header.point_format) + ", " + std::to_string(counts.read)
                  + " points";
  if(!filter.classes.empty())
  {
    std::string list;
    for(int c : filter.classes)
      list += (list.empty() ? "" : ",") + std::to_string(c);
    s += "; classes " + list + " kept " + std::to_string(counts.classes);
  }
  if(filter.drop_withheld)
    s += "; without withheld points kept " + std::to_string(counts.withheld);
  if(filter.returns != Las_filter::ALL_RETURNS)
    s += std::string("; ") + (filter.returns == Las_filter::FIRST_RETURNS ? "first" : "last") + " returns kept "
         + std::to_string(counts.returns);
  return s;
}

// ---------------------------------------------------------------- writing

// A named extra-bytes field of the records written: a float or a uchar.
struct Las_extra_field
{
  std::string name;         // at most 32 characters
  std::string description;  // at most 32 characters
  bool is_float = true;     // else unsigned char
};

// What las_header_bytes() writes: LAS 1.4, point format 6, 7 (with RGB)
// or 8 (with RGB and NIR).
struct Las_output_header
{
  bool rgb = false;  // point format 7 (else 6)
  bool nir = false;  // point format 8 (with rgb)
  double scale[3] = {0.001, 0.001, 0.001};
  double offset[3] = {0, 0, 0};
  double min[3] = {0, 0, 0}, max[3] = {0, 0, 0};
  std::uint64_t number_of_points = 0;
  std::uint64_t points_by_return[15] = {};
  std::uint16_t file_source_id = 0;
  std::uint16_t global_encoding = 0;  // bits 0 (GPS time type) and 3 (synthetic return numbers) are written
  bool wkt = true;                    // bit 4: the CRS is WKT (or there is none)
  std::uint16_t creation_day = 0, creation_year = 0;
  // the input's extra-bytes fields carried, before `extra` in the records
  std::vector<Las_extra_bytes_field> carried;
  std::vector<Las_extra_field> extra;
  // the input's CRS records: VLRs, or EVLRs when longer than a VLR holds
  std::vector<Las_vlr> crs;
};

inline int las_output_point_format(const Las_output_header& h) { return h.nir ? 8 : (h.rgb ? 7 : 6); }

inline std::size_t las_extra_bytes_per_point(const Las_output_header& h)
{
  std::size_t n = 0;
  for(const Las_extra_bytes_field& f : h.carried)
    n += f.size;
  for(const Las_extra_field& f : h.extra)
    n += f.is_float ? 4 : 1;
  return n;
}

inline std::size_t las_output_record_length(const Las_output_header& h)
{
  return std::size_t(las_detail::base_record_length(las_output_point_format(h))) + las_extra_bytes_per_point(h);
}

// Throws std::invalid_argument when the fields do not fit the Extra Bytes
// VLR: a name of more than 32 characters, more than 341 fields (with
// `carried` of the input's).
inline void check_las_extra_fields(const std::vector<Las_extra_field>& extra, std::size_t carried = 0)
{
  if(extra.size() + carried > 341)
    throw std::invalid_argument("LAS output: " + std::to_string(extra.size()) + " extra-bytes fields"
                                + (carried ? " and " + std::to_string(carried) + " of the input" : std::string())
                                + ", the Extra Bytes VLR holds at most 341 (21 layers)");
  for(const Las_extra_field& f : extra)
    if(f.name.empty() || f.name.size() > 32)
      throw std::invalid_argument("LAS output: the field name '" + f.name
                                  + "' does not fit the Extra Bytes VLR (1 to 32 characters)");
}

// What the output keeps of a LAS input `in`: its point format's colors
// (RGB, NIR), scale, offset, file source id, GPS time type, creation date,
// CRS records (the WKT bit as the input's, set when it has no GeoTIFF
// keys) and extra-bytes fields, but those named as a field of `out.extra`,
// whose new values replace them. Throws std::invalid_argument when the
// fields do not fit a record or the Extra Bytes VLR.
inline void carry_las_input(const Las_header& in, Las_output_header& out)
{
  out.rgb = las_detail::has_rgb(in.point_format);
  out.nir = las_detail::has_nir(in.point_format);
  std::copy(in.scale, in.scale + 3, out.scale);
  std::copy(in.offset, in.offset + 3, out.offset);
  out.file_source_id = in.file_source_id;
  out.global_encoding = in.global_encoding;
  out.creation_day = in.creation_day;
  out.creation_year = in.creation_year;
  out.crs = in.crs;
  const bool geotiff = std::any_of(in.crs.begin(), in.crs.end(), [](const Las_vlr& v) { return v.record_id == 34735; });
  out.wkt = (in.global_encoding & 16) != 0 || !geotiff;
  out.carried.clear();
  for(const Las_extra_bytes_field& f : in.extra_fields)
    if(std::none_of(out.extra.begin(), out.extra.end(), [&](const Las_extra_field& e) { return e.name == f.name; }))
      out.carried.push_back(f);
  check_las_extra_fields(out.extra, out.carried.size());
  if(las_output_record_length(out) > 65535)
    throw std::invalid_argument("LAS output: records of " + std::to_string(las_output_record_length(out))
                                + " bytes with the input's extra bytes, a LAS record holds at most 65535");
}

namespace las_detail {

inline void put_text(char* at, const std::string& s, std::size_t size)
{
  std::memcpy(at, s.data(), (std::min)(s.size(), size));
}

inline bool is_evlr(const Las_vlr& v) { return v.data.size() > 65535; }

// A VLR's 54-byte header and payload, or an EVLR's 60.
inline std::string record_bytes(const Las_vlr& v, bool extended)
{
  const std::size_t head = extended ? 60 : 54;
  std::string b(head, '\0');
  put_text(&b[2], v.user_id, 16);
  put(&b[18], v.record_id);
  if(extended)
    put(&b[20], std::uint64_t(v.data.size()));
  else
    put(&b[20], std::uint16_t(v.data.size()));
  put_text(&b[head - 32], v.description, 32);
  return b + v.data;
}

} // namespace las_detail

// The header and the VLRs (the Extra Bytes VLR, the CRS records): the
// bytes before the point records.
inline std::string las_header_bytes(const Las_output_header& h)
{
  using las_detail::put;
  using las_detail::put_text;
  check_las_extra_fields(h.extra, h.carried.size());
  std::string vlrs;
  std::uint32_t number_of_vlrs = 0, number_of_evlrs = 0;
  if(!h.carried.empty() || !h.extra.empty())
  {
    Las_vlr v;
    v.user_id = "LASF_Spec";
    v.record_id = 4;
    v.description = h.carried.empty() ? "curvature values per point" : "input's and curvature values per point";
    for(const Las_extra_bytes_field& f : h.carried)
      v.data += f.descriptor;
    for(const Las_extra_field& f : h.extra)
    {
      std::string d(192, '\0');
      d[2] = char(f.is_float ? 9 : 1);  // data type: float, unsigned char
      put_text(&d[4], f.name, 32);
      put_text(&d[160], f.description, 32);
      v.data += d;
    }
    vlrs += las_detail::record_bytes(v, false);
    ++number_of_vlrs;
  }
  for(const Las_vlr& v : h.crs)
  {
    if(las_detail::is_evlr(v))
      ++number_of_evlrs;
    else
    {
      vlrs += las_detail::record_bytes(v, false);
      ++number_of_vlrs;
    }
  }
  const std::size_t offset_to_points = 375 + vlrs.size();
  const std::size_t record_length = las_output_record_length(h);
  std::string bytes(375, '\0');
  char* p = &bytes[0];
  std::memcpy(p, "LASF", 4);
  put(p + 4, h.file_source_id);
  put(p + 6, std::uint16_t((h.global_encoding & 9) | (h.wkt ? 16 : 0)));
  p[24] = 1;
  p[25] = 4;
  put_text(p + 26, "conformal_curvature", 32);
  put_text(p + 58, "Conformal_alpha_shapes_3", 32);
  put(p + 90, h.creation_day);
  put(p + 92, h.creation_year);
  put(p + 94, std::uint16_t(375));
  put(p + 96, std::uint32_t(offset_to_points));
  put(p + 100, number_of_vlrs);
  p[104] = char(las_output_point_format(h));
  put(p + 105, std::uint16_t(record_length));
  // the legacy counts stay 0: point formats 6 to 10 have none
  for(int k = 0; k < 3; ++k)
  {
    put(p + 131 + 8 * k, h.scale[k]);
    put(p + 155 + 8 * k, h.offset[k]);
    put(p + 179 + 16 * k, h.max[k]);
    put(p + 187 + 16 * k, h.min[k]);
  }
  if(number_of_evlrs > 0)
  {
    put(p + 235, std::uint64_t(offset_to_points + h.number_of_points * record_length));
    put(p + 243, number_of_evlrs);
  }
  put(p + 247, h.number_of_points);
  for(int k = 0; k < 15; ++k)
    put(p + 255 + 8 * k, h.points_by_return[k]);
  return bytes + vlrs;
}

// The EVLRs after the point records: the CRS records longer than a VLR holds.
inline std::string las_evlr_bytes(const Las_output_header& h)
{
  std::string bytes;
  for(const Las_vlr& v : h.crs)
    if(las_detail::is_evlr(v))
      bytes += las_detail::record_bytes(v, true);
  return bytes;
}

// Sets the bounds and the counts by return of `h` from the records.
class Las_bounds
{
public:
  void add(const Las_record& r)
  {
    const std::int32_t xyz[3] = {r.X, r.Y, r.Z};
    for(int k = 0; k < 3; ++k)
    {
      m_min[k] = (std::min)(m_min[k], xyz[k]);
      m_max[k] = (std::max)(m_max[k], xyz[k]);
    }
    if(r.return_number >= 1 && r.return_number <= 15)
      ++m_by_return[r.return_number - 1];
    ++m_count;
  }
  void set(Las_output_header& h) const
  {
    for(int k = 0; k < 3; ++k)
    {
      h.min[k] = m_count == 0 ? 0 : double(m_min[k]) * h.scale[k] + h.offset[k];
      h.max[k] = m_count == 0 ? 0 : double(m_max[k]) * h.scale[k] + h.offset[k];
      if(h.scale[k] < 0)
        std::swap(h.min[k], h.max[k]);
    }
    h.number_of_points = m_count;
    std::copy(m_by_return, m_by_return + 15, h.points_by_return);
  }

private:
  std::int32_t m_min[3] = {INT32_MAX, INT32_MAX, INT32_MAX}, m_max[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
  std::uint64_t m_by_return[15] = {};
  std::uint64_t m_count = 0;
};

// A scale and offset for points that do not come from a LAS file: per
// axis, the offset the middle of the range rounded, the scale the smallest
// power of ten (at least 1e-9) whose integers hold the range. Throws
// std::invalid_argument when no finite scale does.
inline void choose_las_scale(const double low[3], const double high[3], Las_output_header& h)
{
  for(int k = 0; k < 3; ++k)
  {
    h.offset[k] = std::round(low[k] / 2 + high[k] / 2);
    const double reach = (std::max)(std::abs(high[k] - h.offset[k]), std::abs(low[k] - h.offset[k]));
    double scale = 1e-9;
    while(std::isfinite(scale) && !(reach / scale <= 2.0e9))
      scale *= 10;
    if(!std::isfinite(scale) || !std::isfinite(h.offset[k]))
      throw std::invalid_argument("LAS output: the points' range does not fit LAS's scaled 32-bit integers");
    h.scale[k] = scale;
  }
}

// The record of a point at `x` (y, z) written with the scale and offset of `h`.
inline void quantize_las(const Las_output_header& h, const double xyz[3], Las_record& r)
{
  std::int32_t* q[3] = {&r.X, &r.Y, &r.Z};
  for(int k = 0; k < 3; ++k)
    *q[k] = std::int32_t(std::llround((xyz[k] - h.offset[k]) / h.scale[k]));
}

} // namespace cas3

#endif // CAS3_LAS_H
