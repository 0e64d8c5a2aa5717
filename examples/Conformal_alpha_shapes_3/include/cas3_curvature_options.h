// The command line of the conformal_curvature program: its usage text and
// the options it reads, checked before any work so that a mistyped flag
// fails at once, naming the flag and the item.
#ifndef CAS3_CURVATURE_OPTIONS_H
#define CAS3_CURVATURE_OPTIONS_H

#include "cas3_las.h"
#include "cas3_layer_names.h"

#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace cas3 {

inline const char* curvature_usage()
{
  return "usage: conformal_curvature [INPUT] [--alpha LIST] [--radius LIST] [--rings LIST]\n"
         "                           [--estimator NAME] [--denoise MODE] [--denoise-neighbors K]\n"
         "                           [--extraction NAME] [--values-follow-sheets] [--classes LIST]\n"
         "                           [--drop-withheld] [--returns WHICH] [--output DIR] [--las]\n"
         "                           [--csv] [--quiet] [--help]\n"
         "\n"
         "Multi-scale curvature of a point cloud on its conformal alpha shape.\n"
         "  INPUT            .xyz, .pwn, .ply, .off, .obj (meshes: their vertices) or\n"
         "                   .las (LAS 1.0 to 1.4, uncompressed: decompress .laz first);\n"
         "                   default: the bundled Stanford bunny sample\n"
         "  --alpha LIST     comma list of conformal scales a: values > 0 (0.5),\n"
         "                   quantiles of the facet values in (0%, 100%] (25%; the\n"
         "                   paper's figures use 10%,25%,35%,50%) and/or auto; default auto\n"
         "  --radius LIST    comma list of neighborhood radii of the curvature fit:\n"
         "                   model units (0.01), multiples of the measured sample\n"
         "                   spacing (4s) and/or auto (chosen per point from the data);\n"
         "                   default auto,2s,4s,8s,16s unless --rings is given\n"
         "  --rings LIST     comma list of ring sizes from 1 to 100, instead of or\n"
         "                   besides radii\n"
         "  --estimator NAME quadric (default), euler-least-squares or paper\n"
         "  --denoise MODE   auto (default: smooth when the estimated noise exceeds\n"
         "                   0.02 x spacing), on or off\n"
         "  --denoise-neighbors K  neighbors of the smoothing jet fit; default: from\n"
         "                   the estimated noise (24 to 64)\n"
         "  --extraction NAME front (default: one sheet per part, open or closed)\n"
         "                   or solid (the boundary of the enclosed solid)\n"
         "  --values-follow-sheets  with input normals, every point's values on its\n"
         "                   sheet's side (default: on its own normal's side where\n"
         "                   its sheet's normals are consistent)\n"
         "  --classes LIST   LAS input: keep the points of these classes (e.g. 2,6)\n"
         "  --drop-withheld  LAS input: leave out the points flagged withheld\n"
         "  --returns WHICH  LAS input: first, last or all (default) returns\n"
         "  --output DIR     default ./conformal_curvature_out\n"
         "  --las            write DIR/curvatures.las (LAS 1.4, point format 6, or 7\n"
         "                   with colors, 8 with NIR; a LAS input's fields, extra bytes\n"
         "                   and CRS kept; the values below as named extra bytes)\n"
         "                   instead of DIR/curvatures.ply\n"
         "  --csv            also write DIR/curvatures.csv, a row per point per layer\n"
         "  --quiet          no progress and no summary\n"
         "Writes DIR/curvatures.ply (binary point cloud: per point x y z, outlier,\n"
         "and per layer L = [scale_]neighborhood, e.g. r4s or 25pct_k2: nx_L ny_L\n"
         "nz_L H_L K_L k1_L k2_L d1x_L .. d2z_L radius_L distance_L source_L, where\n"
         "source 0 = the point's own surface vertex, 1 = the nearest surface point,\n"
         "2 = no value), then per layer shape_index_L curvedness_L (Koenderink's,\n"
         "from k1_L and k2_L: shape index +1 on caps, -1 on cups, NaN where flat)\n"
         "and DIR/surface_<scale>.ply per scale.\n"
         "The points are recentered and rescaled before the work (results are in the\n"
         "input's units); isolated far outliers are left out and get outlier = 1.\n"
         "A failed run exits with status 1 and one line on stderr, and leaves DIR\n"
         "as it was.\n"
         "Where the kernel gives transparent huge pages only on request, the program\n"
         "starts itself again with glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES\n"
         "(faster on large inputs), unless GLIBC_TUNABLES names that tunable already\n"
         "(glibc.malloc.hugetlb=0 keeps malloc's default).\n";
}

// A mistake on the command line; what() is one line naming the flag.
struct Option_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Curvature_options
{
  std::string input = CGAL_CAS3_DEFAULT_INPUT;
  std::vector<CGAL::Conformal_alpha_shapes_3::Scale> scales = CGAL::Conformal_alpha_shapes_3::default_scales();
  std::vector<CGAL::Conformal_alpha_shapes_3::Neighborhood> neighborhoods =
    CGAL::Conformal_alpha_shapes_3::default_neighborhoods();
  CGAL::Conformal_alpha_shapes_3::Curvature_estimator estimator = CGAL::Conformal_alpha_shapes_3::QUADRIC_FIT;
  CGAL::Conformal_alpha_shapes_3::Denoising denoising = CGAL::Conformal_alpha_shapes_3::AUTOMATIC_DENOISING;
  unsigned int denoising_neighbors = 0;  // 0: as the library's plan says
  CGAL::Conformal_alpha_shapes_3::Surface_extraction extraction = CGAL::Conformal_alpha_shapes_3::ADVANCING_FRONT;
  Las_filter las_filter;  // LAS input only
  std::string output = "conformal_curvature_out";
  bool orient_each_point = true;
  bool las = false;  // curvatures.las instead of curvatures.ply
  bool csv = false;
  bool quiet = false;
  bool help = false;
};

namespace options_detail {

inline std::vector<std::string> split_list(const std::string& list)
{
  std::vector<std::string> items;
  std::stringstream in(list);
  std::string item;
  while(std::getline(in, item, ','))
    items.push_back(item);
  if(items.empty() || list.back() == ',' || std::find(items.begin(), items.end(), "") != items.end())
    throw Option_error("empty item in the list '" + list + "'");
  return items;
}

// Whether `item` spells a whole number from `low` to `high`, stored in `n`.
template <class Integer>
bool whole_number(const std::string& item, Integer low, Integer high, Integer& n)
{
  const auto r = std::from_chars(item.data(), item.data() + item.size(), n);
  return r.ec == std::errc() && r.ptr == item.data() + item.size() && n >= low && n <= high;
}

// Sets `value` to the choice that `name` names among `choices`, the values
// of the flag `flag`; an error names the flag, `what` it expected and the
// choices.
template <class Value>
void choose(Value& value, const std::string& flag, const std::string& what, const std::string& name,
            std::initializer_list<std::pair<const char*, Value> > choices)
{
  std::string names;
  for(const auto& choice : choices)
  {
    if(name == choice.first)
    {
      value = choice.second;
      return;
    }
    names += (names.empty() ? "" : ", ") + std::string(choice.first);
  }
  throw Option_error(flag + ": unknown " + what + " '" + name + "' (" + names + ")");
}

} // namespace options_detail

// One reader per option, shared by the command line and the Python module:
// `name` is the flag or the keyword, and starts every message.

// A list of scales: each one as parse_scale() reads it, above 0.
inline std::vector<CGAL::Conformal_alpha_shapes_3::Scale> parse_scales(const std::string& name,
                                                                        const std::vector<std::string>& items)
{
  typedef CGAL::Conformal_alpha_shapes_3::Scale Scale;
  std::vector<Scale> scales;
  for(const std::string& item : items)
  {
    try { scales.push_back(parse_scale(item)); }
    catch(const std::invalid_argument& e) { throw Option_error(name + ": " + e.what()); }
    if(scales.back().kind() != Scale::AUTOMATIC && !(scales.back().value() > 0))
      throw Option_error(name + ": a scale must be above 0 (a value > 0 or a quantile in (0%, 100%]): '" + item
                         + "'");
  }
  return scales;
}

// A neighborhood radius, as parse_radius() reads it.
inline CGAL::Conformal_alpha_shapes_3::Neighborhood parse_radius_option(const std::string& name,
                                                                        const std::string& item)
{
  try { return parse_radius(item); }
  catch(const std::invalid_argument& e) { throw Option_error(name + ": " + e.what()); }
}

// A ring size from 1 to 100.
inline CGAL::Conformal_alpha_shapes_3::Neighborhood parse_rings_option(const std::string& name,
                                                                       const std::string& item)
{
  int k = 0;
  if(!options_detail::whole_number(item, 1, 100, k))
    throw Option_error(name + ": not a ring size from 1 to 100: '" + item + "'");
  return CGAL::Conformal_alpha_shapes_3::Neighborhood::rings(k);
}

inline CGAL::Conformal_alpha_shapes_3::Curvature_estimator parse_estimator(const std::string& name,
                                                                           const std::string& text)
{
  namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
  CAS3::Curvature_estimator estimator = CAS3::QUADRIC_FIT;
  options_detail::choose(estimator, name, "estimator", text, {{"quadric", CAS3::QUADRIC_FIT},
    {"euler-least-squares", CAS3::EULER_LEAST_SQUARES_FIT}, {"paper", CAS3::PAPER_EULER_FIT}});
  return estimator;
}

inline CGAL::Conformal_alpha_shapes_3::Denoising parse_denoising(const std::string& name, const std::string& text)
{
  namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
  CAS3::Denoising denoising = CAS3::AUTOMATIC_DENOISING;
  options_detail::choose(denoising, name, "mode", text, {{"auto", CAS3::AUTOMATIC_DENOISING},
    {"on", CAS3::ALWAYS_DENOISE}, {"off", CAS3::NEVER_DENOISE}});
  return denoising;
}

// A neighbor count of the smoothing jet fit, at least 7.
inline unsigned int parse_denoising_neighbors(const std::string& name, const std::string& item)
{
  unsigned int neighbors = 0;
  if(!options_detail::whole_number(item, 7u, ~0u, neighbors))
    throw Option_error(name + ": not a neighbor count >= 7: '" + item + "'");
  return neighbors;
}

inline CGAL::Conformal_alpha_shapes_3::Surface_extraction parse_extraction(const std::string& name,
                                                                           const std::string& text)
{
  namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
  CAS3::Surface_extraction extraction = CAS3::ADVANCING_FRONT;
  options_detail::choose(extraction, name, "extraction", text,
                         {{"front", CAS3::ADVANCING_FRONT}, {"solid", CAS3::SOLID_BOUNDARY}});
  return extraction;
}

// A list of LAS classes, each from 0 to 255.
inline std::vector<int> parse_las_classes(const std::string& name, const std::vector<std::string>& items)
{
  std::vector<int> classes;
  for(const std::string& item : items)
  {
    int c = 0;
    if(!options_detail::whole_number(item, 0, 255, c))
      throw Option_error(name + ": not a LAS class from 0 to 255: '" + item + "'");
    classes.push_back(c);
  }
  return classes;
}

inline Las_filter::Returns parse_las_returns(const std::string& name, const std::string& text)
{
  Las_filter::Returns returns = Las_filter::ALL_RETURNS;
  options_detail::choose(returns, name, "returns", text, {{"all", Las_filter::ALL_RETURNS},
    {"first", Las_filter::FIRST_RETURNS}, {"last", Las_filter::LAST_RETURNS}});
  return returns;
}

// Reads the command line. Throws Option_error.
inline Curvature_options parse_curvature_options(int argc, char* argv[])
{
  using options_detail::split_list;
  Curvature_options o;
  bool input_given = false, neighborhoods_given = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc || (std::string(argv[i + 1]).rfind("--", 0) == 0))
        throw Option_error("option " + arg + " needs a value");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h")
      o.help = true;
    else if(arg == "--quiet")
      o.quiet = true;
    else if(arg == "--csv")
      o.csv = true;
    else if(arg == "--values-follow-sheets")
      o.orient_each_point = false;
    else if(arg == "--las")
      o.las = true;
    else if(arg == "--classes")
      o.las_filter.classes = parse_las_classes(arg, split_list(value()));
    else if(arg == "--drop-withheld")
      o.las_filter.drop_withheld = true;
    else if(arg == "--returns")
      o.las_filter.returns = parse_las_returns(arg, value());
    else if(arg == "--alpha")
      o.scales = parse_scales(arg, split_list(value()));
    else if(arg == "--rings" || arg == "--radius")
    {
      if(!neighborhoods_given)
        o.neighborhoods.clear();
      neighborhoods_given = true;
      for(const std::string& item : split_list(value()))
        o.neighborhoods.push_back(arg == "--radius" ? parse_radius_option(arg, item) : parse_rings_option(arg, item));
    }
    else if(arg == "--estimator")
      o.estimator = parse_estimator(arg, value());
    else if(arg == "--denoise")
      o.denoising = parse_denoising(arg, value());
    else if(arg == "--denoise-neighbors")
      o.denoising_neighbors = parse_denoising_neighbors(arg, value());
    else if(arg == "--extraction")
      o.extraction = parse_extraction(arg, value());
    else if(arg == "--output")
    {
      o.output = value();
      if(o.output.empty())
        throw Option_error("--output: empty directory name");
    }
    else if(!arg.empty() && arg[0] == '-')
      throw Option_error("unknown option " + arg);
    else if(input_given)
      throw Option_error("more than one input file: " + o.input + ", " + arg);
    else
    {
      o.input = arg;
      input_given = true;
    }
  }
  std::string extension = o.input.size() >= 4 ? o.input.substr(o.input.size() - 4) : "";
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if(o.las_filter.active() && extension != ".las" && extension != ".laz")
    throw Option_error("--classes, --drop-withheld and --returns filter LAS input (.las), not " + o.input);
  return o;
}

} // namespace cas3

#endif // CAS3_CURVATURE_OPTIONS_H
