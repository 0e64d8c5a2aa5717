// How the conformal_curvature program spells scales, neighborhoods and
// layers: it reads "0.35", "25%" and "auto" as scales and "0.01", "4s" and
// "auto" as radii, and names layers "rauto", "r4s", "r0p01", "k2" or
// "25pct_k2". Kept apart from the rest of the program and depending only on
// the library's Scale and Neighborhood, so that other front ends (a Python
// module) name layers exactly as the program does.
#ifndef CAS3_LAYER_NAMES_H
#define CAS3_LAYER_NAMES_H

#include <CGAL/Conformal_alpha_shapes_3/scales_and_neighborhoods.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace cas3 {

namespace layer_names_detail {

// What an item of a list of scales or radii spells: `auto`, or a finite
// number followed or not by `suffix`; `value` is NaN when it is neither.
struct Item
{
  bool automatic;
  bool suffixed;
  double value;
};

inline Item read_item(const std::string& text, char suffix)
{
  const bool suffixed = !text.empty() && text.back() == suffix;
  const std::string number = suffixed ? text.substr(0, text.size() - 1) : text;
  std::size_t used = 0;
  double value = std::numeric_limits<double>::quiet_NaN();
  try { value = std::stod(number, &used); }
  catch(const std::exception&) { used = 0; }
  if(number.empty() || used != number.size() || !std::isfinite(value))
    value = std::numeric_limits<double>::quiet_NaN();
  return Item{text == "auto", suffixed, value};
}

} // namespace layer_names_detail

// Reads `0.35` (absolute), `25%` (quantile) or `auto`. Throws
// std::invalid_argument on anything else, on a negative or non-finite
// value, and on a percentage outside [0, 100].
inline CGAL::Conformal_alpha_shapes_3::Scale parse_scale(const std::string& text)
{
  typedef CGAL::Conformal_alpha_shapes_3::Scale Scale;
  const layer_names_detail::Item item = layer_names_detail::read_item(text, '%');
  if(item.automatic)
    return Scale::automatic();
  if(!(item.value >= 0) || (item.suffixed && item.value > 100))
    throw std::invalid_argument("not a scale: '" + text + "' (expected a value >= 0, a percentage or 'auto')");
  return item.suffixed ? Scale::quantile(item.value / 100) : Scale::absolute(item.value);
}

// Reads a radius: `0.01` (model units), `4s` (spacings) or `auto`. Throws
// std::invalid_argument on anything else and on a value that is not finite
// and positive.
inline CGAL::Conformal_alpha_shapes_3::Neighborhood parse_radius(const std::string& text)
{
  typedef CGAL::Conformal_alpha_shapes_3::Neighborhood Neighborhood;
  const layer_names_detail::Item item = layer_names_detail::read_item(text, 's');
  if(item.automatic)
    return Neighborhood::automatic();
  if(!(item.value > 0))
    throw std::invalid_argument("not a radius: '" + text + "' (expected a value > 0, a multiple of the "
                                "spacing as 4s, or 'auto')");
  return item.suffixed ? Neighborhood::spacings(item.value) : Neighborhood::radius(item.value);
}

// `0.35`, `25%` or `auto`, as parse_scale() reads it: for messages.
inline std::string scale_text(const CGAL::Conformal_alpha_shapes_3::Scale& scale)
{
  typedef CGAL::Conformal_alpha_shapes_3::Scale Scale;
  if(scale.kind() == Scale::AUTOMATIC)
    return "auto";
  std::string s = std::to_string(scale.kind() == Scale::QUANTILE ? 100 * scale.value() : scale.value());
  s.erase(s.find_last_not_of('0') + 1);
  if(s.back() == '.')
    s.pop_back();
  return scale.kind() == Scale::QUANTILE ? s + "%" : s;
}

// `0p35`, `25pct` or `auto`: scale_text() usable in a file or property name.
inline std::string scale_label(const CGAL::Conformal_alpha_shapes_3::Scale& scale)
{
  std::string label = scale_text(scale);
  if(!label.empty() && label.back() == '%')
    label = label.substr(0, label.size() - 1) + "pct";
  std::replace(label.begin(), label.end(), '.', 'p');
  return label;
}

// `k2`, `r0p01`, `r4s` or `rauto`: usable in a name (`.` written `p`).
inline std::string neighborhood_label(const CGAL::Conformal_alpha_shapes_3::Neighborhood& neighborhood)
{
  typedef CGAL::Conformal_alpha_shapes_3::Neighborhood Neighborhood;
  switch(neighborhood.kind())
  {
    case Neighborhood::RINGS: return "k" + std::to_string(int(neighborhood.value()));
    case Neighborhood::AUTOMATIC: return "rauto";
    default: break;
  }
  std::ostringstream text;
  text << std::setprecision(6) << neighborhood.value();
  std::string number = text.str();
  std::replace(number.begin(), number.end(), '.', 'p');
  std::replace(number.begin(), number.end(), '-', 'm');
  std::replace(number.begin(), number.end(), '+', 'P');
  return "r" + number + (neighborhood.kind() == Neighborhood::SPACINGS ? "s" : "");
}

// The label of a layer, `[scale_]neighborhood` (`r4s`, `25pct_k2`): the
// scale part only when a run has several scales, so that the default job's
// names stay short.
inline std::string layer_label(const CGAL::Conformal_alpha_shapes_3::Scale& scale,
                               const CGAL::Conformal_alpha_shapes_3::Neighborhood& neighborhood,
                               bool several_scales)
{
  return (several_scales ? scale_label(scale) + "_" : std::string()) + neighborhood_label(neighborhood);
}

} // namespace cas3

#endif // CAS3_LAYER_NAMES_H
