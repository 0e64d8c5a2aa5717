// Tests of the LAS reader and writer of the conformal_curvature program
// (cas3_las.h, and .las through cas3_read_point_cloud.h): files written
// here byte by byte from the specification, one per version and point
// format, read back to the last bit; chunked reads; the filters; the bad
// files and their messages; the LAS 1.4 output with its Extra Bytes VLR.
#include <boost/test/unit_test.hpp>

#include "cas3_curvature_output.h"
#include "cas3_las.h"
#include "cas3_read_point_cloud.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

// ---- a LAS writer of the tests' own, from the specification's tables

template <class T>
void set(std::string& bytes, std::size_t at, T x)
{
  if(bytes.size() < at + sizeof(T))
    bytes.resize(at + sizeof(T), '\0');
  std::memcpy(&bytes[at], &x, sizeof(T));
}

const int record_sizes[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

struct Spec
{
  int minor = 2;
  int format = 0;
  int extra_bytes = 0;       // beyond the format's base size
  std::size_t n = 50;        // points
  std::size_t vlr_bytes = 0; // a VLR of this payload before the points
  bool evlr = false;         // a 1.4 EVLR after the points
  bool describe_extra = false; // an Extra Bytes VLR: the first 4 extra bytes a float "reflectance"
  bool crs = false;          // GeoTIFF keys in a VLR, and in LAS 1.4 a WKT EVLR and the WKT bit
  double scale[3] = {0.01, 0.001, 0.0025};
  double offset[3] = {1000.5, -20, 3};
};

// The fields of point i of the tests' files.
struct Expected
{
  std::int32_t X, Y, Z;
  std::uint16_t intensity;
  int return_number, number_of_returns, classification;
  bool synthetic, key_point, withheld;
  double gps_time;
  std::uint16_t red, green, blue;
};

Expected expected(std::size_t i, int format)
{
  Expected e;
  const int k = int(i);
  e.X = k * 37 - 1000;
  e.Y = (k * k) % 1001 - 7;
  e.Z = -3 * k + (k % 2 == 0 ? 2000000000 : -2000000000);
  e.intensity = std::uint16_t(13 * k);
  e.number_of_returns = 1 + k % 3;
  e.return_number = 1 + (k / 3) % e.number_of_returns;
  e.classification = format <= 5 ? k % 20 : (k * 11) % 256;
  e.synthetic = k % 4 == 0;
  e.key_point = k % 6 == 0;
  e.withheld = k % 5 == 0;
  e.gps_time = 1e5 + 0.25 * k;
  e.red = std::uint16_t(k);
  e.green = std::uint16_t(2 * k);
  e.blue = std::uint16_t(65535 - k);
  return e;
}

bool format_has_gps(int f) { return f != 0 && f != 2; }
bool format_has_rgb(int f) { return f == 2 || f == 3 || f == 5 || f == 7 || f == 8 || f == 10; }

// A VLR (or, `extended`, an EVLR) of `user`, `id` and `payload`.
std::string record_of(const std::string& user, std::uint16_t id, const std::string& payload, bool extended)
{
  std::string r(extended ? 60 : 54, '\0');
  std::memcpy(&r[2], user.data(), user.size());
  set(r, 18, id);
  if(extended)
    set(r, 20, std::uint64_t(payload.size()));
  else
    set(r, 20, std::uint16_t(payload.size()));
  return r + payload;
}

const std::string geokeys("\1\0\1\0\0\0\1\0\0\x0c\0\0\1\0\x79\x7f", 16);  // ProjectedCSTypeGeoKey 32633
const std::string wkt = "PROJCS[\"WGS 84 / UTM zone 33N\",AUTHORITY[\"EPSG\",\"32633\"]]";

std::string las_bytes(const Spec& s)
{
  const int header_size = s.minor <= 2 ? 227 : (s.minor == 3 ? 235 : 375);
  const int record = record_sizes[s.format] + s.extra_bytes;
  std::string b(std::size_t(header_size), '\0');
  std::memcpy(&b[0], "LASF", 4);
  if(s.crs && s.minor == 4)
    set(b, 6, std::uint16_t(16));
  b[24] = 1;
  b[25] = char(s.minor);
  std::memcpy(&b[26], "test_las", 8);
  set(b, 94, std::uint16_t(header_size));
  std::string vlrs;
  std::uint32_t number_of_vlrs = 0;
  if(s.describe_extra)
  {
    std::string descriptor(192, '\0');
    descriptor[2] = 9;  // float
    std::memcpy(&descriptor[4], "reflectance", 11);
    vlrs += record_of("LASF_Spec", 4, descriptor, false);
    ++number_of_vlrs;
  }
  if(s.crs)
  {
    vlrs += record_of("LASF_Projection", 34735, geokeys, false);
    ++number_of_vlrs;
  }
  if(s.vlr_bytes > 0)
  {
    vlrs += record_of("someone", 7, std::string(s.vlr_bytes, 'v'), false);
    ++number_of_vlrs;
  }
  set(b, 96, std::uint32_t(std::size_t(header_size) + vlrs.size()));
  set(b, 100, number_of_vlrs);
  b[104] = char(s.format);
  set(b, 105, std::uint16_t(record));
  set(b, 107, std::uint32_t(s.format <= 5 ? s.n : 0));
  for(int k = 0; k < 3; ++k)
  {
    set(b, 131 + 8 * k, s.scale[k]);
    set(b, 155 + 8 * k, s.offset[k]);
  }
  if(s.minor >= 4)
    set(b, 247, std::uint64_t(s.n));
  b += vlrs;
  for(std::size_t i = 0; i < s.n; ++i)
  {
    const Expected e = expected(i, s.format);
    std::string r(std::size_t(record), char(0xAB));  // the extra bytes: 0xAB
    set(r, 0, e.X);
    set(r, 4, e.Y);
    set(r, 8, e.Z);
    set(r, 12, e.intensity);
    if(s.format <= 5)
    {
      r[14] = char(e.return_number | (e.number_of_returns << 3) | (i % 2 ? 64 : 0));
      r[15] = char(e.classification | (e.synthetic ? 32 : 0) | (e.key_point ? 64 : 0) | (e.withheld ? 128 : 0));
      r[16] = char(std::int8_t(int(i % 181) - 90));  // scan angle rank
      r[17] = char(i % 200);
      set(r, 18, std::uint16_t(i + 1));
      std::size_t at = 20;
      if(format_has_gps(s.format))
      {
        set(r, at, e.gps_time);
        at += 8;
      }
      if(format_has_rgb(s.format))
      {
        set(r, at, e.red);
        set(r, at + 2, e.green);
        set(r, at + 4, e.blue);
      }
      if(s.format == 4 || s.format == 5)  // a wave packet descriptor: 29 bytes of its own
        for(std::size_t k = std::size_t(s.format == 4 ? 28 : 34); k < std::size_t(record_sizes[s.format]); ++k)
          r[k] = char(0x5A);
    }
    else
    {
      r[14] = char(e.return_number | (e.number_of_returns << 4));
      r[15] = char((e.synthetic ? 1 : 0) | (e.key_point ? 2 : 0) | (e.withheld ? 4 : 0) | (i % 3 == 0 ? 8 : 0)
                   | (int(i % 4) << 4));
      r[16] = char(e.classification);
      r[17] = char(i % 200);
      set(r, 18, std::int16_t(int(i) * 100 - 2000));
      set(r, 20, std::uint16_t(i + 1));
      set(r, 22, e.gps_time);
      if(format_has_rgb(s.format))
      {
        set(r, 30, e.red);
        set(r, 32, e.green);
        set(r, 34, e.blue);
      }
      if(s.format == 8 || s.format == 10)
        set(r, 36, std::uint16_t(4 * i));
    }
    b += r;
  }
  const bool wkt_evlr = s.crs && s.minor == 4;
  if(s.evlr || wkt_evlr)
  {
    set(b, 235, std::uint64_t(b.size()));
    set(b, 243, std::uint32_t((s.evlr ? 1 : 0) + (wkt_evlr ? 1 : 0)));
  }
  if(s.evlr)
    b += record_of("someone", 8, std::string(100, 'e'), true);
  if(wkt_evlr)
    b += record_of("LASF_Projection", 2112, wkt + '\0', true);
  return b;
}

const std::filesystem::path work = std::filesystem::temp_directory_path() / "cas3_test_las";

std::string write_file(const std::string& name, const std::string& bytes)
{
  std::filesystem::create_directories(work);
  const std::string path = (work / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// The message of what `read` throws, or "" when it does not.
template <class Read>
std::string message_of(Read read)
{
  try { read(); }
  catch(const cas3::Read_error& e) { return e.what(); }
  return "";
}

// The formats each version allows.
std::vector<int> formats_of(int minor)
{
  std::vector<int> f = {0, 1};
  if(minor >= 2) f.insert(f.end(), {2, 3});
  if(minor >= 3) f.insert(f.end(), {4, 5});
  if(minor >= 4) f.insert(f.end(), {6, 7, 8, 9, 10});
  return f;
}

} // namespace

BOOST_AUTO_TEST_SUITE(las)

// One file per version and point format, with and without extra bytes and
// VLRs: every coordinate is the scaled integer times the scale plus the
// offset, to the last bit, and every field as written.
BOOST_AUTO_TEST_CASE(every_version_and_point_format_reads_to_the_last_bit)
{
  for(int minor = 0; minor <= 4; ++minor)
    for(int format : formats_of(minor))
      for(int extra : {0, 7})
      {
        BOOST_TEST_CONTEXT("LAS 1." << minor << " format " << format << " extra bytes " << extra)
        {
          Spec s;
          s.minor = minor;
          s.format = format;
          s.extra_bytes = extra;
          s.vlr_bytes = extra ? 33 : 0;
          s.evlr = minor == 4 && extra;
          const std::string path = write_file("v" + std::to_string(minor) + "_f" + std::to_string(format) + ".las",
                                              las_bytes(s));
          const cas3::Point_cloud cloud = cas3::read_point_cloud(path);
          BOOST_REQUIRE_EQUAL(cloud.points.size(), s.n);
          BOOST_TEST(cloud.normals.empty());
          BOOST_REQUIRE(cloud.las.present);
          BOOST_TEST(cloud.las.header.version_minor == minor);
          BOOST_TEST(cloud.las.header.point_format == format);
          BOOST_REQUIRE_EQUAL(cloud.las.records.size(), s.n);
          for(std::size_t i = 0; i < s.n; ++i)
          {
            const Expected e = expected(i, format);
            const cas3::Las_record& r = cloud.las.records[i];
            BOOST_TEST_INFO("point " << i);
            BOOST_REQUIRE((r.X == e.X && r.Y == e.Y && r.Z == e.Z));
            BOOST_REQUIRE(cloud.points[i].x() == double(e.X) * s.scale[0] + s.offset[0]);
            BOOST_REQUIRE(cloud.points[i].y() == double(e.Y) * s.scale[1] + s.offset[1]);
            BOOST_REQUIRE(cloud.points[i].z() == double(e.Z) * s.scale[2] + s.offset[2]);
            BOOST_REQUIRE(r.intensity == e.intensity);
            BOOST_REQUIRE(int(r.return_number) == e.return_number);
            BOOST_REQUIRE(int(r.number_of_returns) == e.number_of_returns);
            BOOST_REQUIRE(int(r.classification) == e.classification);
            BOOST_REQUIRE(r.synthetic() == e.synthetic);
            BOOST_REQUIRE(bool(r.flags & cas3::Las_record::KEY_POINT) == e.key_point);
            BOOST_REQUIRE(r.withheld() == e.withheld);
            BOOST_REQUIRE(r.point_source_id == i + 1);
            BOOST_REQUIRE(r.gps_time == (format_has_gps(format) ? e.gps_time : 0.0));
            BOOST_REQUIRE(r.red == (format_has_rgb(format) ? e.red : 0));
            BOOST_REQUIRE(r.blue == (format_has_rgb(format) ? e.blue : 0));
            if(format <= 5)
              BOOST_REQUIRE(r.scan_angle == std::int16_t(std::lround((int(i % 181) - 90) / 0.006)));
            else
            {
              BOOST_REQUIRE(r.scan_angle == int(i) * 100 - 2000);
              BOOST_REQUIRE(bool(r.flags & cas3::Las_record::OVERLAP) == (i % 3 == 0));
              BOOST_REQUIRE(r.scanner_channel == i % 4);
            }
            BOOST_REQUIRE(r.nir == ((format == 8 || format == 10) ? 4 * i : 0));
          }
          // the bytes in memory (the fuzz harness's way) give the same
          const cas3::Point_cloud again = cas3::parse_point_cloud(las_bytes(s), ".las", "bytes.las");
          BOOST_TEST((again.points == cloud.points));
        }
      }
}

// LAS 1.4 counts with the 64-bit field; a legacy format in 1.4 whose writer
// left it 0 falls back to the legacy one; before 1.4 only the legacy one.
BOOST_AUTO_TEST_CASE(point_count_from_the_field_of_the_version)
{
  Spec s;
  s.minor = 4;
  s.format = 6;
  s.n = 20;
  std::string b = las_bytes(s);
  set(b, 107, std::uint32_t(999));  // a legacy count, wrong, that 1.4 ignores
  BOOST_TEST(cas3::parse_point_cloud(b, ".las", "a.las").points.size() == 20u);
  s.format = 1;
  b = las_bytes(s);
  set(b, 247, std::uint64_t(0));
  BOOST_TEST(cas3::parse_point_cloud(b, ".las", "b.las").points.size() == 20u);
  s.minor = 2;
  b = las_bytes(s);
  b.resize(227 + 28 * 20 + 10, 'x');
  set(b, 107, std::uint32_t(15));  // fewer than the file holds: those are read
  BOOST_TEST(cas3::parse_point_cloud(b, ".las", "c.las").points.size() == 15u);
}

BOOST_AUTO_TEST_CASE(chunks_read_any_range_without_the_rest)
{
  Spec s;
  s.minor = 4;
  s.format = 7;
  s.extra_bytes = 5;
  s.n = 1000;
  const std::string path = write_file("chunks.las", las_bytes(s));
  cas3::Las_file file(path);
  BOOST_TEST(file.number_of_points() == 1000u);
  BOOST_TEST(file.has_rgb());
  std::vector<cas3::Las_record> chunk;
  for(std::uint64_t first : {0, 1, 333, 999, 1000, 5000})
    for(std::uint64_t count : {0, 1, 7, 400, 2000})
    {
      file.read(first, count, chunk);
      const std::size_t expected_size = std::size_t(first >= 1000 ? 0 : std::min<std::uint64_t>(count, 1000 - first));
      BOOST_TEST_INFO(first << " " << count);
      BOOST_REQUIRE_EQUAL(chunk.size(), expected_size);
      for(std::size_t k = 0; k < chunk.size(); ++k)
      {
        const Expected e = expected(std::size_t(first) + k, 7);
        BOOST_REQUIRE((chunk[k].X == e.X && chunk[k].Z == e.Z && chunk[k].green == e.green));
        const std::array<double, 3> p = file.position(chunk[k]);
        BOOST_REQUIRE(p[1] == double(e.Y) * s.scale[1] + s.offset[1]);
      }
    }
}

BOOST_AUTO_TEST_CASE(filters_keep_classes_drop_withheld_and_pick_returns)
{
  Spec s;
  s.minor = 4;
  s.format = 6;
  s.n = 600;
  const std::string path = write_file("filters.las", las_bytes(s));
  cas3::Las_filter filter;
  filter.classes = {0, 11, 22};
  std::size_t by_class = 0, then_withheld = 0, then_first = 0, last = 0;
  for(std::size_t i = 0; i < s.n; ++i)
  {
    const Expected e = expected(i, 6);
    last += e.return_number == e.number_of_returns ? 1 : 0;
    if(e.classification != 0 && e.classification != 11 && e.classification != 22)
      continue;
    ++by_class;
    if(e.withheld)
      continue;
    ++then_withheld;
    then_first += e.return_number == 1 ? 1 : 0;
  }
  BOOST_TEST_MESSAGE("classes kept " << by_class << ", then not withheld " << then_withheld << ", then first "
                                     << then_first);
  BOOST_REQUIRE(then_first > 0u);
  filter.drop_withheld = true;
  filter.returns = cas3::Las_filter::FIRST_RETURNS;
  const cas3::Point_cloud cloud = cas3::read_point_cloud(path, filter);
  BOOST_TEST(cloud.las.counts.read == 600u);
  BOOST_TEST(cloud.las.counts.classes == by_class);
  BOOST_TEST(cloud.las.counts.withheld == then_withheld);
  BOOST_TEST(cloud.las.counts.returns == then_first);
  BOOST_TEST(cloud.points.size() == then_first);
  for(const cas3::Las_record& r : cloud.las.records)
    BOOST_REQUIRE((!r.withheld() && r.return_number == 1 && r.classification % 11 == 0));
  const std::string line = cas3::las_input_summary("filters.las", cloud.las.header, filter, cloud.las.counts);
  BOOST_TEST(line == "filters.las: LAS 1.4, point format 6, 600 points; classes 0,11,22 kept "
                     + std::to_string(by_class) + "; without withheld points kept " + std::to_string(then_withheld)
                     + "; first returns kept " + std::to_string(then_first));

  cas3::Las_filter last_only;
  last_only.returns = cas3::Las_filter::LAST_RETURNS;
  BOOST_TEST(cas3::read_point_cloud(path, last_only).points.size() == last);
  // without the records: the same points
  BOOST_TEST(cas3::read_point_cloud(path, last_only, false).las.records.empty());

  cas3::Las_filter none;
  none.classes = {255};  // point 93 is the first of class 255
  s.n = 93;
  const std::string few = write_file("few.las", las_bytes(s));
  const std::string message = message_of([&] { cas3::read_point_cloud(few, none); });
  BOOST_TEST(message.find("classes 255 kept 0: the filters keep no point") != std::string::npos, message);
}

// Bad files: a clear message naming the file and what is wrong, never a
// read past the end.
BOOST_AUTO_TEST_CASE(bad_files_get_their_message)
{
  Spec s;
  s.minor = 4;
  s.format = 6;
  s.n = 10;
  const std::string good = las_bytes(s);
  struct Case { std::string name, bytes, reason; };
  std::vector<Case> cases;
  auto with = [&](auto change) { std::string b = good; change(b); return b; };
  cases.push_back({"not_las.las", "LASX" + good.substr(4), "not_las.las: not a LAS file (no LASF signature)"});
  cases.push_back({"short.las", good.substr(0, 100), "short.las: truncated LAS header: the file has 100 bytes"});
  cases.push_back({"version.las", with([](std::string& b) { b[25] = 5; }), "unknown LAS version 1.5"});
  cases.push_back({"major.las", with([](std::string& b) { b[24] = 2; }), "unknown LAS version 2.4"});
  cases.push_back({"format.las", with([](std::string& b) { b[104] = 11; }),
                   "format.las: unknown LAS point data record format 11"});
  cases.push_back({"laz_bit7.las", with([](std::string& b) { b[104] = char(0x86); }),
                   "laz_bit7.las: compressed LAS (LAZ) cannot be read without LASzip; decompress it first, e.g. "
                   "'laszip -i x.laz -o x.las' or 'pdal translate x.laz x.las'"});
  cases.push_back({"laz_bit6.las", with([](std::string& b) { b[104] = char(0x43); }), "compressed LAS (LAZ)"});
  cases.push_back({"header_size.las", with([](std::string& b) { set(b, 94, std::uint16_t(227)); }),
                   "the header size 227 is smaller than LAS 1.4's 375 bytes"});
  cases.push_back({"inside.las", with([](std::string& b) { set(b, 96, std::uint32_t(300)); }),
                   "inside.las: the offset to the point data (300) is inside the header (375 bytes)"});
  cases.push_back({"beyond.las", with([](std::string& b) { set(b, 96, std::uint32_t(1u << 30)); }),
                   "the offset to the point data (1073741824) is beyond the end of the file"});
  cases.push_back({"record.las", with([](std::string& b) { set(b, 105, std::uint16_t(29)); }),
                   "the point record length 29 is smaller than point format 6's 30 bytes"});
  cases.push_back({"count.las", with([](std::string& b) { set(b, 247, std::uint64_t(11)); }),
                   "count.las: the header announces 11 points of 30 bytes, the file holds 10"});
  cases.push_back({"huge_count.las", with([](std::string& b) { set(b, 247, ~std::uint64_t(0)); }),
                   "the header announces 18446744073709551615 points"});
  cases.push_back({"truncated.las", good.substr(0, good.size() - 1), "the file holds 9 (truncated"});
  cases.push_back({"nan_scale.las", with([](std::string& b) { set(b, 139, std::nan("")); }),
                   "nan_scale.las: the Y scale factor is not finite and nonzero: nan"});
  cases.push_back({"inf_scale.las", with([](std::string& b) { set(b, 147, -HUGE_VAL); }),
                   "the Z scale factor is not finite and nonzero: -inf"});
  cases.push_back({"zero_scale.las", with([](std::string& b) { set(b, 131, 0.0); }),
                   "the X scale factor is not finite and nonzero: 0"});
  cases.push_back({"inf_offset.las", with([](std::string& b) { set(b, 155, HUGE_VAL); }),
                   "the X offset is not finite: inf"});
  cases.push_back({"overflow.las", with([](std::string& b) { set(b, 131, 1e307); }),
                   "overflow.las: point 0: coordinate is NaN or infinite"});
  cases.push_back({"empty.las", with([](std::string& b) { set(b, 247, std::uint64_t(0)); }),
                   "empty.las: the file holds no point"});
  cases.push_back({"x.laz", good, "x.laz: compressed LAS (LAZ) cannot be read without LASzip"});
  {
    Spec records = s;
    records.extra_bytes = 4;
    records.describe_extra = true;
    records.crs = true;
    const std::string with_records = las_bytes(records);
    auto with_r = [&](auto change) { std::string b = with_records; change(b); return b; };
    std::uint32_t offset = 0;
    std::memcpy(&offset, &with_records[96], 4);
    const std::size_t evlr = offset + 10 * 34;
    cases.push_back({"vlr.las", with_r([](std::string& b) { set(b, 100, std::uint32_t(3)); }),
                     "vlr.las: VLR 3 of 3 runs into the point data"});
    cases.push_back({"evlr.las", with_r([&](std::string& b) { set(b, evlr + 20, std::uint64_t(1000)); }),
                     "evlr.las: EVLR 1 of 1 is beyond the end of the file"});
    cases.push_back({"evlr_start.las", with_r([&](std::string& b) { set(b, 235, std::uint64_t(evlr - 1)); }),
                     "is not after the point data"});
    cases.push_back({"extra_type.las", with_r([](std::string& b) { b[375 + 54 + 2] = char(31); }),
                     "extra-bytes field 1 of the Extra Bytes VLR has the unknown data type 31"});
    cases.push_back({"extra_size.las", with_r([](std::string& b) { b[375 + 54 + 2] = char(10); }),
                     "the Extra Bytes VLR describes 8 bytes per point or more, the records have 4"});
    cases.push_back({"extra_vlr.las", with_r([](std::string& b) { set(b, 375 + 20, std::uint16_t(100)); }),
                     "the Extra Bytes VLR has 100 bytes, not a multiple of its 192-byte descriptors"});
  }
  for(const Case& c : cases)
  {
    const std::string path = write_file(c.name, c.bytes);
    const std::string from_file = message_of([&] { cas3::read_point_cloud(path); });
    BOOST_TEST_INFO(c.name << ": " << from_file);
    BOOST_TEST(from_file.find(c.reason) != std::string::npos);
    BOOST_TEST(from_file.rfind(path, 0) == 0u);  // names the file
    BOOST_TEST(from_file.find('\n') == std::string::npos);
    const std::string extension = c.name.substr(c.name.size() - 4);
    const std::string from_bytes = message_of([&] { cas3::parse_point_cloud(c.bytes, extension, c.name); });
    BOOST_TEST(from_bytes.find(c.reason) != std::string::npos, from_bytes);
  }

  // every prefix of a valid file, and every byte of its header set to
  // 0xFF: a result or a Read_error, never a crash or a read past the end
  for(std::size_t size = 0; size < good.size(); size += 7)
    BOOST_TEST(!message_of([&] { cas3::parse_point_cloud(good.substr(0, size), ".las", "p.las"); }).empty());
  for(std::size_t at = 0; at < 375; ++at)
  {
    std::string b = good;
    b[at] = char(0xFF);
    try
    {
      const cas3::Point_cloud cloud = cas3::parse_point_cloud(b, ".las", "q.las");
      for(const auto& p : cloud.points)
        BOOST_REQUIRE((std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())));
    }
    catch(const cas3::Read_error&) {}
  }
}

// The LAS 1.4 output: point format 7 keeping a LAS input's records, the
// curvature fields as extra bytes named in the Extra Bytes VLR, read back
// by the reader and by the tests' own parse of the VLR.
BOOST_AUTO_TEST_CASE(output_keeps_the_input_fields_and_names_the_extra_bytes)
{
  Spec s;
  s.minor = 2;
  s.format = 3;
  s.n = 40;
  const std::string path = write_file("input.las", las_bytes(s));
  cas3::Las_filter filter;
  filter.drop_withheld = true;
  const cas3::Point_cloud cloud = cas3::read_point_cloud(path, filter);
  const std::size_t n = cloud.points.size();
  std::vector<cas3::Layer> layers(2);
  layers[0].label = "rauto";
  layers[1].label = "25pct_k2";
  for(std::size_t l = 0; l < 2; ++l)
  {
    layers[l].values.resize(n * cas3::Layer::number_of_values);
    layers[l].source.resize(n);
    for(std::size_t i = 0; i < layers[l].values.size(); ++i)
      layers[l].values[i] = float(i) * 0.5f + float(l);
    for(std::size_t i = 0; i < n; ++i)
      layers[l].source[i] = std::uint8_t((i + l) % 3);
  }
  std::vector<bool> outlier(n);
  outlier[3] = true;
  std::ostringstream out;
  cas3::write_point_cloud_las(out, cloud.points, cloud.las, outlier, layers);
  const std::string bytes = out.str();

  const cas3::Point_cloud back = cas3::parse_point_cloud(bytes, ".las", "out.las");
  BOOST_TEST(back.las.header.version_minor == 4);
  BOOST_TEST(back.las.header.point_format == 7);
  BOOST_TEST((back.points == cloud.points));
  for(std::size_t i = 0; i < n; ++i)
  {
    const cas3::Las_record &a = cloud.las.records[i], &b = back.las.records[i];
    BOOST_REQUIRE((a.X == b.X && a.Y == b.Y && a.Z == b.Z && a.intensity == b.intensity &&
                   a.classification == b.classification && a.flags == b.flags && a.return_number == b.return_number &&
                   a.number_of_returns == b.number_of_returns && a.gps_time == b.gps_time && a.red == b.red &&
                   a.green == b.green && a.blue == b.blue && a.scan_angle == b.scan_angle &&
                   a.point_source_id == b.point_source_id && a.user_data == b.user_data));
  }
  // the header: 1.4, 375 bytes, one VLR, counts and bounds of the points written
  std::uint64_t count = 0;
  std::memcpy(&count, &bytes[247], 8);
  BOOST_TEST(count == n);
  std::uint32_t legacy = 1, vlrs = 0, offset = 0;
  std::memcpy(&legacy, &bytes[107], 4);
  std::memcpy(&vlrs, &bytes[100], 4);
  std::memcpy(&offset, &bytes[96], 4);
  BOOST_TEST(legacy == 0u);
  BOOST_TEST(vlrs == 1u);
  double min_x = 0, max_x = 0;
  std::memcpy(&max_x, &bytes[179], 8);
  std::memcpy(&min_x, &bytes[187], 8);
  double low = HUGE_VAL, high = -HUGE_VAL;
  for(const auto& p : cloud.points)
  {
    low = std::min(low, p.x());
    high = std::max(high, p.x());
  }
  BOOST_TEST(min_x == low);
  BOOST_TEST(max_x == high);
  // the Extra Bytes VLR: LASF_Spec, record 4, 192 bytes per field
  BOOST_TEST(std::string(&bytes[375 + 2]) == "LASF_Spec");
  std::uint16_t record_id = 0, length = 0, record_length = 0;
  std::memcpy(&record_id, &bytes[375 + 18], 2);
  std::memcpy(&length, &bytes[375 + 20], 2);
  std::memcpy(&record_length, &bytes[105], 2);
  BOOST_TEST(record_id == 4);
  const std::size_t fields = 1 + 2 * 16;
  BOOST_TEST(length == 192 * fields);
  BOOST_TEST(offset == 375 + 54 + 192 * fields);
  BOOST_TEST(record_length == 36 + 1 + 2 * (15 * 4 + 1));
  std::vector<std::string> names;
  std::vector<int> types;
  for(std::size_t k = 0; k < fields; ++k)
  {
    const char* d = &bytes[375 + 54 + 192 * k];
    names.push_back(std::string(d + 4, strnlen(d + 4, 32)));
    types.push_back(d[2]);
  }
  BOOST_TEST(names[0] == "outlier");
  BOOST_TEST(names[1] == "nx_rauto");
  BOOST_TEST(names[4] == "H_rauto");
  BOOST_TEST(names[16] == "source_rauto");
  BOOST_TEST(names[17 + 4] == "K_25pct_k2");
  BOOST_TEST(types[0] == 1);   // unsigned char
  BOOST_TEST(types[4] == 9);   // float
  // the values of point i, in the order of the descriptors
  for(std::size_t i = 0; i < n; ++i)
  {
    const char* extra = &bytes[offset + i * record_length + 36];
    BOOST_REQUIRE(extra[0] == (i == 3 ? 1 : 0));
    float h = 0;
    std::memcpy(&h, extra + 1 + 3 * 4, 4);
    BOOST_REQUIRE(h == layers[0].values[i * cas3::Layer::number_of_values + 3]);
    BOOST_REQUIRE(std::uint8_t(extra[1 + 60]) == layers[0].source[i]);
    std::memcpy(&h, extra + 1 + 61 + 3 * 4, 4);
    BOOST_REQUIRE(h == layers[1].values[i * cas3::Layer::number_of_values + 3]);
  }
}

// A LAS 1.4 input of point format 8 with extra bytes (a described float
// and 3 undescribed bytes) and a CRS (GeoTIFF keys in a VLR, WKT in an
// EVLR): the output is format 8 with its NIR, carries the input's extra
// bytes (their descriptors first) and CRS records with the WKT bit.
BOOST_AUTO_TEST_CASE(output_carries_the_input_extra_bytes_and_crs)
{
  Spec s;
  s.minor = 4;
  s.format = 8;
  s.n = 30;
  s.extra_bytes = 7;
  s.describe_extra = true;
  s.crs = true;
  s.evlr = true;
  s.vlr_bytes = 5;
  const cas3::Point_cloud cloud = cas3::parse_point_cloud(las_bytes(s), ".las", "input.las");
  const cas3::Las_header& in = cloud.las.header;
  BOOST_REQUIRE_EQUAL(in.crs.size(), 2u);
  BOOST_TEST(in.crs[0].record_id == 34735);
  BOOST_TEST(in.crs[0].data == geokeys);
  BOOST_TEST(in.crs[1].record_id == 2112);
  BOOST_TEST(in.crs[1].data == wkt + '\0');
  BOOST_REQUIRE_EQUAL(in.extra_fields.size(), 2u);
  BOOST_TEST(in.extra_fields[0].name == "reflectance");
  BOOST_TEST(in.extra_fields[1].name == "undescribed_extra_bytes");
  BOOST_TEST(in.extra_fields[1].offset == 4u);
  BOOST_TEST(in.extra_fields[1].size == 3u);
  BOOST_REQUIRE_EQUAL(cloud.las.extra_bytes.size(), 7 * s.n);
  BOOST_TEST(std::uint8_t(cloud.las.extra_bytes[0]) == 0xAB);

  const std::size_t n = cloud.points.size();
  std::vector<cas3::Layer> layers(1);
  layers[0].label = "r4s";
  layers[0].values.assign(n * cas3::Layer::number_of_values, 0.25f);
  layers[0].source.assign(n, 1);
  std::ostringstream out;
  cas3::write_point_cloud_las(out, cloud.points, cloud.las, std::vector<bool>(n), layers);
  const std::string bytes = out.str();
  const cas3::Point_cloud back = cas3::parse_point_cloud(bytes, ".las", "out.las");
  const cas3::Las_header& h = back.las.header;
  BOOST_TEST(h.point_format == 8);
  BOOST_TEST((back.points == cloud.points));
  for(std::size_t i = 0; i < n; ++i)
    BOOST_REQUIRE(back.las.records[i].nir == cloud.las.records[i].nir);
  BOOST_TEST((h.global_encoding & 16) == 16);
  BOOST_REQUIRE_EQUAL(h.crs.size(), 2u);
  for(std::size_t k = 0; k < 2; ++k)
    BOOST_TEST((h.crs[k].user_id == in.crs[k].user_id && h.crs[k].record_id == in.crs[k].record_id &&
                h.crs[k].data == in.crs[k].data));
  BOOST_REQUIRE_EQUAL(h.extra_fields.size(), 2u + 1 + 16);
  BOOST_TEST(h.extra_fields[0].descriptor == in.extra_fields[0].descriptor);
  BOOST_TEST(h.extra_fields[1].descriptor == in.extra_fields[1].descriptor);
  BOOST_TEST(h.extra_fields[2].name == "outlier");
  BOOST_TEST(h.extra_fields[6].name == "H_r4s");
  BOOST_TEST(h.extra_bytes == 7u + 1 + 61);
  for(std::size_t i = 0; i < n; ++i)
    BOOST_REQUIRE(std::equal(cloud.las.extra_bytes.begin() + std::ptrdiff_t(7 * i),
                             cloud.las.extra_bytes.begin() + std::ptrdiff_t(7 * i + 7),
                             back.las.extra_bytes.begin() + std::ptrdiff_t(h.extra_bytes * i)));
  // GeoTIFF keys alone keep the WKT bit clear, as the input has it
  s.minor = 2;
  s.format = 3;
  s.evlr = false;
  const cas3::Point_cloud geotiff = cas3::parse_point_cloud(las_bytes(s), ".las", "geotiff.las");
  cas3::Las_output_header carried;
  cas3::carry_las_input(geotiff.las.header, carried);
  BOOST_TEST(!carried.wkt);
  BOOST_TEST(carried.rgb);
  BOOST_TEST(!carried.nir);
  BOOST_TEST(carried.crs.size() == 1u);
}

// Points that do not come from a LAS file: format 6, a power-of-ten scale
// that holds their range, each coordinate within half a step.
BOOST_AUTO_TEST_CASE(output_of_other_points_chooses_a_scale)
{
  typedef cas3::Read_kernel::Point_3 Point;
  std::vector<Point> points;
  for(int i = 0; i < 100; ++i)
    points.emplace_back(512345.678 + 0.731 * i, -3.25 * i, 1e-3 * i * i);
  std::vector<cas3::Layer> layers(1);
  layers[0].label = "r4s";
  layers[0].values.assign(points.size() * cas3::Layer::number_of_values, 1.5f);
  layers[0].source.assign(points.size(), 0);
  std::ostringstream out;
  cas3::write_point_cloud_las(out, points, cas3::Las_input(), std::vector<bool>(points.size()), layers);
  const cas3::Point_cloud back = cas3::parse_point_cloud(out.str(), ".las", "other.las");
  BOOST_TEST(back.las.header.point_format == 6);
  BOOST_REQUIRE_EQUAL(back.points.size(), points.size());
  for(int k = 0; k < 3; ++k)
    BOOST_TEST(back.las.header.scale[k] <= 1e-6);
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int k = 0; k < 3; ++k)
      BOOST_REQUIRE(std::abs(back.points[i][k] - points[i][k]) <= 0.5 * back.las.header.scale[k] * (1 + 1e-9));
  for(const cas3::Las_record& r : back.las.records)
    BOOST_REQUIRE((r.return_number == 1 && r.number_of_returns == 1));

  // names too long for the VLR are refused before anything is written
  BOOST_CHECK_THROW(cas3::las_extra_fields({"a_very_long_layer_label_of_many_chars"}), std::invalid_argument);
  BOOST_CHECK_THROW(cas3::las_extra_fields(std::vector<std::string>(22, "r4s")), std::invalid_argument);
  BOOST_CHECK_NO_THROW(cas3::las_extra_fields(std::vector<std::string>(21, "r4s")));
}

BOOST_AUTO_TEST_SUITE_END()
