// libFuzzer target: the whole pipeline on small clouds. The bytes become at
// most 60 points: in mode 0 (first byte even) each point is 3 raw doubles
// (NaN, infinities, 1e300 and subnormals included); in mode 1 each point is
// 3 signed bytes on a small grid, times a scale 2^(s - 64) read from the
// second byte (duplicates, coplanar and cospherical sets are common). Then:
// input hygiene, the conformal alpha shape, the automatic scale and a
// quantile, surface extraction and curvature at 1 and 2 rings, 4 spacings
// and the automatic radius. The only
// exception allowed is the documented std::invalid_argument.
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 2)
    return 0;
  std::vector<Point> points;
  if(data[0] % 2 == 0)
  {
    for(std::size_t at = 1; at + 24 <= size && points.size() < 60; at += 24)
    {
      double c[3];
      std::memcpy(c, data + at, 24);
      points.emplace_back(c[0], c[1], c[2]);
    }
  }
  else
  {
    const double scale = std::ldexp(1.0, int(data[1]) - 64);
    for(std::size_t at = 2; at + 3 <= size && points.size() < 60; at += 3)
      points.emplace_back(scale * static_cast<std::int8_t>(data[at]), scale * static_cast<std::int8_t>(data[at + 1]),
                          scale * static_cast<std::int8_t>(data[at + 2]));
  }
  try
  {
    const CAS3::Multiscale_curvatures<K> analysis(points.begin(), points.end());
    for(const CAS3::Scale& scale : {CAS3::Scale::automatic(), CAS3::Scale::quantile(0.5)})
    {
      CAS3::Multiscale_curvatures<K>::Surface surface;
      analysis.surface(analysis.scale_value(scale), surface);
      for(const CAS3::Neighborhood& neighborhood : {CAS3::Neighborhood::rings(1), CAS3::Neighborhood::rings(2),
                                                    CAS3::Neighborhood::spacings(4), CAS3::Neighborhood::automatic()})
      {
        const auto curvatures = analysis.estimate_curvatures(surface, {neighborhood}).front();
        if(curvatures.size() != points.size())
          std::abort();
      }
    }
  }
  catch(const std::invalid_argument&)
  {
  }
  return 0;
}
