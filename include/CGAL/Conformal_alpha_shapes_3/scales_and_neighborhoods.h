// Copyright (c) 2026 The Conformal_alpha_shapes_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_CONFORMAL_ALPHA_SHAPES_3_SCALES_AND_NEIGHBORHOODS_H
#define CGAL_CONFORMAL_ALPHA_SHAPES_3_SCALES_AND_NEIGHBORHOODS_H

// The vocabulary of a layer of multi-scale curvature: the scale `a` of the
// surface and the neighborhood of the fit.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Conformal_alpha_shapes_3 {

namespace internal {

// The finite number that `text` spells, followed or not by `suffix`
// (`has_suffix` says which); NaN when `text` is anything else.
inline double number_with_suffix(const std::string& text, char suffix, bool& has_suffix)
{
  has_suffix = !text.empty() && text.back() == suffix;
  const std::string number = has_suffix ? text.substr(0, text.size() - 1) : text;
  std::size_t used = 0;
  double value = std::numeric_limits<double>::quiet_NaN();
  try { value = std::stod(number, &used); }
  catch(const std::exception&) { used = 0; }
  return number.empty() || used != number.size() || !std::isfinite(value)
           ? std::numeric_limits<double>::quiet_NaN() : value;
}

} // namespace internal

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
A requested internal scale `a`: an absolute value, a quantile of the facet
values (the paper's "10%, 25%, 35%, 50%", see
`Conformal_alpha_shape_3::alpha_at_quantile()`), or automatic
(`suggest_scale()`, or `suggest_alpha()` for the solid boundary).
*/
class Scale
{
public:
  enum Kind { ABSOLUTE, QUANTILE, AUTOMATIC };

  static Scale absolute(double a) { return Scale(ABSOLUTE, a); }
  static Scale quantile(double q) { return Scale(QUANTILE, q); }
  static Scale automatic() { return Scale(AUTOMATIC, 0); }

  /// Parses `0.35` (absolute), `25%` (quantile) or `auto`.
  /// \throws std::invalid_argument on anything else, on a negative or
  /// non-finite value, and on a percentage outside `[0, 100]`.
  static Scale from_string(const std::string& text)
  {
    if(text == "auto")
      return automatic();
    bool percent = false;
    const double value = internal::number_with_suffix(text, '%', percent);
    if(!(value >= 0) || (percent && value > 100))
      throw std::invalid_argument("not a scale: '" + text + "' (expected a value >= 0, a percentage or 'auto')");
    return percent ? quantile(value / 100) : absolute(value);
  }

  Kind kind() const { return m_kind; }
  /// the absolute value or the quantile in `[0, 1]`
  double value() const { return m_value; }

  /// `0.35`, `25%` or `auto`, as `from_string()` reads it
  std::string label() const
  {
    if(m_kind == AUTOMATIC)
      return "auto";
    std::string s = std::to_string(m_kind == QUANTILE ? 100 * m_value : m_value);
    s.erase(s.find_last_not_of('0') + 1);
    if(s.back() == '.')
      s.pop_back();
    return m_kind == QUANTILE ? s + "%" : s;
  }

private:
  Scale(Kind kind, double value) : m_kind(kind), m_value(value) {}
  Kind m_kind;
  double m_value;
};

/*!
\ingroup PkgConformalAlphaShapes3Multiscale
The neighborhood of the curvature fit (see `estimate_vertex_curvatures()`):
a ring size, a radius in model units, a radius in multiples of the
measured sample spacing (`Noise_estimate::spacing`), or automatic: per
point, one of the radii `automatic_radii()` times the spacing, chosen from
the data alone.
*/
class Neighborhood
{
public:
  enum Kind { RINGS, RADIUS, SPACINGS, AUTOMATIC };

  static Neighborhood rings(int k) { return Neighborhood(RINGS, k); }
  static Neighborhood radius(double r) { return Neighborhood(RADIUS, r); }
  static Neighborhood spacings(double m) { return Neighborhood(SPACINGS, m); }
  static Neighborhood automatic() { return Neighborhood(AUTOMATIC, 0); }

  /// The candidates of the automatic choice, in spacings: 2 to 11.3 by
  /// factors of the square root of 2, then to 22.6 by factors of its
  /// square root (the larger radii, where noisy samples are fitted, more
  /// finely: the median H error of the automatic choice on the ellipsoid at
  /// 100k points with noise 0.1 spacing, 1.49% against 1.52% with steps of
  /// the square root of 2, and on the torus 1.53% against 1.72%; up to 19
  /// spacings only, 2.09% and 1.18%; measured when the candidates were
  /// fitted by quartics, see the manual).
  static std::vector<double> automatic_radii() { return {2, 2.83, 4, 5.66, 8, 11.3, 13.45, 16, 19, 22.6}; }

  /// Parses a radius: `0.01` (model units), `4s` (spacings) or `auto`.
  /// \throws std::invalid_argument on anything else and on a value that is
  /// not finite and positive.
  static Neighborhood radius_from_string(const std::string& text)
  {
    if(text == "auto")
      return automatic();
    bool in_spacings = false;
    const double value = internal::number_with_suffix(text, 's', in_spacings);
    if(!(value > 0))
      throw std::invalid_argument("not a radius: '" + text + "' (expected a value > 0, a multiple of the "
                                  "spacing as 4s, or 'auto')");
    return in_spacings ? spacings(value) : radius(value);
  }

  Kind kind() const { return m_kind; }
  /// the ring size, the radius or the number of spacings
  double value() const { return m_value; }

  /// `k2`, `r0.01`, `r4s` or `rauto`: usable in a name (`.` written `p`)
  std::string label() const
  {
    switch(m_kind)
    {
      case RINGS: return "k" + std::to_string(int(m_value));
      case AUTOMATIC: return "rauto";
      default: break;
    }
    std::ostringstream text;
    text << std::setprecision(6) << m_value;
    std::string number = text.str();
    std::replace(number.begin(), number.end(), '.', 'p');
    std::replace(number.begin(), number.end(), '-', 'm');
    std::replace(number.begin(), number.end(), '+', 'P');
    return "r" + number + (m_kind == SPACINGS ? "s" : "");
  }

private:
  Neighborhood(Kind kind, double value) : m_kind(kind), m_value(value) {}
  Kind m_kind;
  double m_value;
};

} // namespace Conformal_alpha_shapes_3
} // namespace CGAL

#endif // CGAL_CONFORMAL_ALPHA_SHAPES_3_SCALES_AND_NEIGHBORHOODS_H
