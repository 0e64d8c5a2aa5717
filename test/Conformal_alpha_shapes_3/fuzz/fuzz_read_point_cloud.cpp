// libFuzzer target: the point-file reader of the conformal_curvature program
// on arbitrary bytes. The first byte picks the format (.xyz, .pwn, .ply,
// .off, .obj, .las: its value modulo 6); the reader must either return
// finite points (and as many normals or none; for LAS, a record per point)
// or throw cas3::Read_error with a one-line message. A LAS file is also
// read in chunks (Las_file::read) of 1 to 17 records (by the input size),
// which must give the same records and extra bytes, and its extra-bytes
// fields must lie within the records' extra bytes.
#include "cas3_read_point_cloud.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0)
    return 0;
  static const char* const extensions[] = {".xyz", ".pwn", ".ply", ".off", ".obj", ".las"};
  const std::string extension = extensions[data[0] % 6];
  const std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try
  {
    const cas3::Point_cloud cloud = cas3::parse_point_cloud(bytes, extension, "fuzz" + extension);
    if(cloud.points.empty() || (!cloud.normals.empty() && cloud.normals.size() != cloud.points.size()))
      std::abort();
    for(const auto& p : cloud.points)
      if(!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())))
        std::abort();
    if(extension == ".las")
    {
      const cas3::Las_header& header = cloud.las.header;
      if(!cloud.las.present || cloud.las.records.size() != cloud.points.size()
         || cloud.las.extra_bytes.size() != cloud.points.size() * header.extra_bytes)
        std::abort();
      for(const cas3::Las_extra_bytes_field& f : header.extra_fields)
        if(f.offset + f.size > header.extra_bytes || f.descriptor.size() != 192)
          std::abort();
      cas3::Las_file file(bytes, "fuzz.las");
      const std::uint64_t chunk = 1 + size % 17;
      std::vector<cas3::Las_record> records;
      std::vector<char> extra;
      for(std::uint64_t first = 0; first < file.number_of_points(); first += chunk)
      {
        file.read(first, chunk, records, &extra);
        if(extra.size() != records.size() * header.extra_bytes
           || !std::equal(extra.begin(), extra.end(),
                          cloud.las.extra_bytes.begin() + std::ptrdiff_t(first * header.extra_bytes)))
          std::abort();
        for(std::size_t k = 0; k < records.size(); ++k)
        {
          const cas3::Las_record& a = records[k];
          const cas3::Las_record& b = cloud.las.records[std::size_t(first) + k];
          if(a.X != b.X || a.Y != b.Y || a.Z != b.Z || a.classification != b.classification)
            std::abort();
        }
      }
    }
  }
  catch(const cas3::Read_error& e)
  {
    const std::string what = e.what();
    if(what.empty() || what.find('\n') != std::string::npos)
      std::abort();
  }
  return 0;
}
