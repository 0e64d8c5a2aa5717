// The color ramps of the program's surfaces and of the renderer: blue
// (concave) - white - red (convex) by a per-vertex curvature, grey where it
// is undefined, saturated at the 95th percentile of its magnitude, so that
// a few extreme values do not wash out the rest; and blue - white - red by
// a ratio, on a fixed logarithmic scale.
#ifndef CAS3_CURVATURE_COLORS_H
#define CAS3_CURVATURE_COLORS_H

#include <CGAL/IO/Color.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace cas3 {

// Writes into `color` (a vertex property map of CGAL::IO::Color) the ramp
// of `value` (a vertex property map of a floating-point type).
template <class Mesh, class ValueMap, class ColorMap>
void color_by_curvature(const Mesh& mesh, const ValueMap& value, ColorMap& color)
{
  std::vector<double> magnitude;
  for(auto v : mesh.vertices())
    if(std::isfinite(double(value[v])))
      magnitude.push_back(std::abs(double(value[v])));
  double saturation = 1;
  if(!magnitude.empty())
  {
    const std::size_t at = magnitude.size() * 95 / 100;
    std::nth_element(magnitude.begin(), magnitude.begin() + std::ptrdiff_t(at), magnitude.end());
    saturation = magnitude[at];
  }
  for(auto v : mesh.vertices())
  {
    const double x = double(value[v]);
    if(!std::isfinite(x) || !(saturation > 0))
    {
      color[v] = CGAL::IO::Color(128, 128, 128);
      continue;
    }
    const double t = (std::max)(-1.0, (std::min)(1.0, x / saturation));
    const unsigned char fade = static_cast<unsigned char>(255 * (1 - std::abs(t)) + 0.5);
    color[v] = t >= 0 ? CGAL::IO::Color(255, fade, fade) : CGAL::IO::Color(fade, fade, 255);
  }
}

// Writes into `color` the ramp of a ratio (a vertex property map of
// non-negative values, e.g. an uncertainty over its value's magnitude) on a
// logarithmic scale: blue at 1% or less, white at 10%, red at 100% or more,
// grey where it is undefined; fixed ends, so that two pictures compare.
template <class Mesh, class RatioMap, class ColorMap>
void color_by_ratio(const Mesh& mesh, const RatioMap& ratio, ColorMap& color)
{
  for(auto v : mesh.vertices())
  {
    const double x = double(ratio[v]);
    if(!(x >= 0) || !std::isfinite(x))
    {
      color[v] = CGAL::IO::Color(128, 128, 128);
      continue;
    }
    const double t = (std::max)(-1.0, (std::min)(1.0, std::log10((std::max)(x, 1e-300)) + 1));
    const unsigned char fade = static_cast<unsigned char>(255 * (1 - std::abs(t)) + 0.5);
    color[v] = t >= 0 ? CGAL::IO::Color(255, fade, fade) : CGAL::IO::Color(fade, fade, 255);
  }
}

} // namespace cas3

#endif // CAS3_CURVATURE_COLORS_H
