// The summary that conformal_curvature prints on stdout: the input, its
// noise and smoothing, how the surfaces were extracted and oriented, a line
// per scale and a row per layer. The benchmark of the default job makes the
// same rows.
#ifndef CAS3_CURVATURE_SUMMARY_H
#define CAS3_CURVATURE_SUMMARY_H

#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace cas3 {

// The 5%, 50% and 95% quantiles of the finite values, for the summaries.
inline std::string quantiles(std::vector<double> values)
{
  values.erase(std::remove_if(values.begin(), values.end(), [](double x) { return !std::isfinite(x); }),
               values.end());
  if(values.empty())
    return "            -            -            -";
  char text[64];
  auto nth = [&](double q) { return values.begin() + std::ptrdiff_t(q * double(values.size() - 1)); };
  // the median first: the other two are then found in its halves, which
  // saves a pass over the values (the same order statistics)
  const auto median = nth(0.5), low = nth(0.05), high = nth(0.95);
  std::nth_element(values.begin(), median, values.end());
  std::nth_element(values.begin(), low, median);
  if(high != median)
    std::nth_element(median + 1, high, values.end());
  std::snprintf(text, sizeof text, " %12.4g %12.4g %12.4g", *low, *median, *high);
  return text;
}

// The summary line of a layer: its label and scale, the shares of points
// with their own vertex, the nearest surface point and no value, the
// median radius, and the 5%, 50% and 95% quantiles of H and K.
template <class Kernel>
std::string summary_row(const std::string& label, double a,
                        const std::vector<CGAL::Conformal_alpha_shapes_3::Point_curvature<Kernel> >& curvatures)
{
  namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
  std::size_t count[3] = {0, 0, 0};
  std::vector<double> H, K, radius;
  for(const CAS3::Point_curvature<Kernel>& c : curvatures)
  {
    ++count[c.source];
    H.push_back(c.mean_curvature);
    K.push_back(c.gaussian_curvature);
    if(std::isfinite(c.radius))
      radius.push_back(c.radius);
  }
  if(!radius.empty())
    std::nth_element(radius.begin(), radius.begin() + std::ptrdiff_t(radius.size() / 2), radius.end());
  const double n = double(curvatures.size());
  char row[160];
  std::snprintf(row, sizeof row, "%-12s %10.4g %10.1f%% %7.1f%% %8.1f%% %14.4g", label.c_str(), a,
                100.0 * double(count[CAS3::SURFACE_VERTEX]) / n, 100.0 * double(count[CAS3::NEAREST_SURFACE_POINT]) / n,
                100.0 * double(count[CAS3::NO_VALUE]) / n, radius.empty() ? std::nan("") : radius[radius.size() / 2]);
  return row + std::string("  ") + quantiles(H) + "  " + quantiles(K);
}

// A layer is called noise-dominated when the median over its points of the
// part of sigma_H / |H| that the points' noise gives exceeds this: its
// values are then mostly noise; bias-dominated when the whole uncertainty's
// median does and the noise's does not: H changes over the neighborhood,
// and the value summarizes it rather than the point (the manual, section
// "Uncertainty").
constexpr double dominated_relative_uncertainty = 0.25;

// The median over the points with a value of sigma_H / |H|, or with
// `noise_part` of its noise's part; NaN without any.
template <class Kernel>
double median_relative_uncertainty(const std::vector<CGAL::Conformal_alpha_shapes_3::Point_curvature<Kernel> >& curvatures,
                                   bool noise_part = false)
{
  std::vector<double> relative;
  for(const auto& c : curvatures)
  {
    const double sigma = double(noise_part ? c.uncertainty.mean_curvature_noise : c.uncertainty.mean_curvature);
    const double r = sigma / std::abs(double(c.mean_curvature));
    if(!std::isnan(r))
      relative.push_back(r);
  }
  if(relative.empty())
    return std::nan("");
  const auto median = relative.begin() + std::ptrdiff_t(relative.size() / 2);
  std::nth_element(relative.begin(), median, relative.end());
  return *median;
}

// The summary's part of a layer in the uncertainty line: its label, its
// median relative uncertainty of H in percent (`relative`) and, by that of
// the noise's part (`relative_noise`), "noise-dominated" or "bias-dominated".
inline std::string summary_uncertainty_item(const std::string& label, double relative, double relative_noise)
{
  char text[96];
  const char* const cause = relative_noise > dominated_relative_uncertainty ? " noise-dominated"
                            : relative > dominated_relative_uncertainty     ? " bias-dominated"
                                                                            : "";
  if(!std::isfinite(relative))
    std::snprintf(text, sizeof text, "%s -", label.c_str());
  else
    std::snprintf(text, sizeof text, "%s %.3g%%%s", label.c_str(), 100 * relative, cause);
  return text;
}

// The line of the layers' uncertainty items.
inline std::string summary_uncertainty_line(const std::vector<std::string>& items)
{
  std::string line = "uncertainty of H (median sigma/|H|):";
  for(std::size_t k = 0; k < items.size(); ++k)
    line += (k == 0 ? " " : ", ") + items[k];
  return line + "\n";
}

// The head of the summary: the input and its outliers, the noise and the
// smoothing, the surface and its orientation, and the header of the rows.
template <class Kernel>
std::string summary_head(const std::string& input, const CGAL::Conformal_alpha_shapes_3::Multiscale_curvatures<Kernel>& analysis)
{
  namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
  std::string head = input + ": " + std::to_string(analysis.number_of_input_points()) + " points";
  if(analysis.number_of_merged_points() > 0)
    head += ", " + std::to_string(analysis.number_of_merged_points())
            + " written more than once (merged, each copy given its point's values)";
  if(!analysis.outliers().empty())
    head += ", " + std::to_string(analysis.outliers().size()) + " isolated far outliers left out (outlier column)";
  const CAS3::Noise_estimate noise = analysis.noise();
  char text[200];
  std::snprintf(text, sizeof text, "noise: %.3g x spacing (spacing %.4g)%s; ", noise.noise, noise.spacing,
                noise.shows_unresolved_detail() ? ", mostly unresolved detail" : "");
  const CAS3::Denoising_plan& smoothing = analysis.denoising();
  head += "\n" + std::string(text)
          + (smoothing.passes == 0 ? std::string("no smoothing\n")
             : "smoothed by " + std::to_string(smoothing.passes) + " jet pass(es) over "
               + std::to_string(smoothing.neighbors) + " neighbors before building the shape\n");
  head += "surface: " + std::string(analysis.extraction() == CAS3::ADVANCING_FRONT ? "advancing front" : "solid boundary")
          + "; orientation: "
          + (analysis.has_reference_normals()
               ? "the majority of the input normals, per sheet where they are consistent; values per point there"
               : "closed sheets outward, open sheets away from the center (up where that nearly cancels), with those they "
                 "continue across gaps")
          + "\n";
  return head + "layer               a  own vertex  nearest  no value  radius(median)"
                "    H:  5%          50%          95%      K:  5%          50%          95%\n";
}

// The line of a scale (`scale`, as the user wrote it): the parts of its
// surface and the points off it.
inline std::string summary_scale_line(const std::string& scale, const CGAL::Conformal_alpha_shapes_3::Surface_report& report)
{
  return "scale " + scale + ": " + std::to_string(report.number_of_parts) + " parts ("
         + std::to_string(report.number_of_closed_parts) + " closed, " + std::to_string(report.number_of_open_parts())
         + " open), " + std::to_string(report.number_of_points_off_surface) + " points off the surface\n";
}

// How far the oriented sheets of a surface follow the input normals, and
// whether some sheets' normals were not consistent: a line for the scale
// `scale` of the surface's `report`.
inline std::string summary_normals_line(const std::string& scale, const CGAL::Conformal_alpha_shapes_3::Surface_report& report)
{
  char line[320];
  std::snprintf(line, sizeof line, "scale %s: the sheets agree with the input normals at %.1f%% of their vertices\n",
                scale.c_str(), 100.0 * report.reference_normal_agreement);
  std::string text = line;
  if(report.number_of_sheets_with_inconsistent_normals > 0)
    text += "warning: the input normals of " + std::to_string(report.number_of_sheets_with_inconsistent_normals)
            + " sheet(s) at scale " + scale
            + " point about as often to one side as to the other (unoriented normals?): those sheets are oriented "
              "as without normals\n";
  return text;
}

} // namespace cas3

#endif // CAS3_CURVATURE_SUMMARY_H
