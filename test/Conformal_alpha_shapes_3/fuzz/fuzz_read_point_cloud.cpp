// libFuzzer target: the point-file reader of the conformal_curvature program
// on arbitrary bytes. The first byte picks the format; the reader must
// either return finite points (and as many normals or none) or throw
// cas3::Read_error with a one-line message.
#include "cas3_read_point_cloud.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0)
    return 0;
  static const char* const extensions[] = {".xyz", ".pwn", ".ply", ".off", ".obj"};
  const std::string extension = extensions[data[0] % 5];
  const std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try
  {
    const cas3::Point_cloud cloud = cas3::parse_point_cloud(bytes, extension, "fuzz" + extension);
    if(cloud.points.empty() || (!cloud.normals.empty() && cloud.normals.size() != cloud.points.size()))
      std::abort();
    for(const auto& p : cloud.points)
      if(!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())))
        std::abort();
  }
  catch(const cas3::Read_error& e)
  {
    const std::string what = e.what();
    if(what.empty() || what.find('\n') != std::string::npos)
      std::abort();
  }
  return 0;
}
