// evaluate_surfaces: accuracy of the end-to-end pipeline (points -> surface
// -> normal, H, K per input point) against exact truth, with the metrics of
// the manual ("Measured: Advancing Front against the Solid Boundary"), and
// CGAL's Monge_via_jet_fitting as the peer.
//
//   evaluate_surfaces [--case NAME,...] [--sizes 20000,100000] [--large]
//                     [--noise 0,0.1,0.3] [--neighborhoods LIST] [--rings 1,2,3]
//                     [--normals] [--scale-factor 1] [--jet-samples 5000] [--no-jet]
//                     [--data DIR] [--csv FILE] [--write-points DIR] [--list] [--check-truth]
//                     [--calibration] [--reference-draws N] [--help]
//
// Neighborhoods of the curvature fit (--neighborhoods, default
// auto,k1,k2,k3,2s,4s,8s,16s): k2 a ring size, auto the automatic radius
// per point, 4s a radius in measured sample spacings, 0.01 a radius in model
// units; --rings 1,2,3 is short for k1,k2,k3. --scale-factor F extracts the
// surface at F times the automatic scale (default 1: the automatic scale).
//
// Cases (--list prints them): the closed surfaces ellipsoid (1 : 0.7 : 0.4),
// torus (R = 1, r = 0.35), bumpy_sphere (r = 1 + 0.02 sin(10x) sin(10y)
// sin(10z) in the direction (x, y, z)); the open surfaces ellipsoid_cap
// (z > 0.1), torus_patch (a quarter: around angle and tube angle in
// [0, pi], the top half of half the ring), bumpy_cap (z > 0.2), plane (the
// square [-1, 1]^2); the unit sphere; each at every size (--large adds 1M) and noise level
// r: Gaussian noise along the true normal of standard deviation
// r * spacing, spacing = sqrt(area / n). Then two clean 20k details:
// fine_bumps (amplitude 0.005, frequency 40) and dent_bumps (the same bumps
// on a sphere with one smooth dent), the latter judged against the truth
// with the bumps and against the truth of the smooth dented sphere
// (dent_bumps~smooth). Finally the real scans kitten.xyz, oni.pwn,
// ball.ply, building.ply from --data (default: the build tree's copy of
// libcgal-demo's, see CMakeLists.txt), whose reference normals are the only truth: each is run
// given its normals ([normals]) and as x y z only ([xyz]).
// Synthetic data is given to the pipeline without normals unless
// --normals (then the true normals). The exact plane at noise 0 gets a
// 1e-4 * spacing normal jitter, since coplanar points do not span 3D.
//
// Metrics per case: coverage (share of input points with finite values),
// orientation (share of covered points whose normal agrees with the true
// one; for open surfaces and scans not given normals the larger of it and
// its complement, H then being compared after that global flip; given
// normals, the plain share, whether the pipeline uses them or not),
// median and 90th percentile of |H_est - H_true| over covered points
// divided by the median |H_true| over all points (likewise K), at the best
// fixed neighborhood (smallest median H error, chosen with the truth) and,
// in their own columns, at the automatic one (chosen per point from the data
// alone), with the median radius it chose in spacings; the median H error
// of every neighborhood; surface components when the pipeline reports
// them; the peer's best k and its errors (on --jet-samples points spread
// over the sample; k in {60,120,240,480} on noisy data, {12,24} on clean
// data, {400,1000} for dent_bumps~smooth, whose truth summarizes many
// points; normal sign from the truth). For the plane the H columns hold
// median (p90) |H| * spacing, marked '*'. Scans: best is the best oriented
// neighborhood, and the per-neighborhood column holds orientation; a scan
// given as x y z only notes the best orientation that one side per
// connected piece of the surface could reach (what no rule that orients
// whole sheets can exceed).
// The pipeline is called in one place only: run_pipeline().
// --check-truth compares the generators' truth with closed forms and exits.
// --write-points DIR also writes each synthetic sample as DIR/NAME_N_NOISE.xyz
// and its truth, the true normal, H and K of each point, as
// DIR/NAME_N_NOISE_truth.txt (the manual's bump figures are made from
// dent_bumps_20000_0.xyz).
// --calibration prints, per synthetic sample and layer, how the reported
// uncertainties match the errors (calibration()); --reference-draws N adds,
// on noisy samples, a `reference` line scored the same way with each
// point's standard uncertainty measured rather than estimated: the root
// mean square of the layer's errors there over N other noise draws of the
// same points. On a clean sample the error is fixed by the sample, and its
// own size is that reference.
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include "cas3_analytic_surfaces.h"
#include "cas3_benchmark.h"
#include "cas3_jet_fitting.h"
#include "cas3_layer_names.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef cas3_analytic::Truth_sample<Point, Vector> Sample;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;

const double nan_value = std::numeric_limits<double>::quiet_NaN();

// ---------------------------------------------------------------------------
// The pipeline under test: the only place that calls the package.

struct Layer
{
  std::string label;           // as given: k2, auto, 4s, 0.01
  bool automatic = false;
  std::vector<Vector> normal;  // per input point; NaN where undefined
  std::vector<double> H, K;    // per input point; NaN where undefined
  std::vector<double> H_sigma, K_sigma;  // their standard uncertainties
  std::vector<double> H_noise_sigma;     // the noise's part of H's
  std::vector<double> radius;  // per input point, in measured spacings; NaN where undefined
  int components = -1;         // surface components, -1 when not reported
  std::vector<int> piece;      // per input point, the connected piece of the surface its vertex is on; -1 off it
};

// A --neighborhoods item: `k2` (ring size), `auto`, `4s` (spacings) or
// `0.01` (model units).
CAS3::Neighborhood neighborhood_of(const std::string& item)
{
  if(!item.empty() && item[0] == 'k')
  {
    std::size_t used = 0;
    int k = 0;
    try { k = std::stoi(item.substr(1), &used); }
    catch(const std::exception&) { used = 0; }
    if(used == 0 || used + 1 != item.size() || k < 1)
      throw std::invalid_argument("bad ring size '" + item + "'");
    return CAS3::Neighborhood::rings(k);
  }
  return cas3::parse_radius(item);
}

// The automatic scale (times `scale_factor`), curvature with each
// neighborhood: what multiscale_curvatures(points,
// scales({Scale::automatic()}).neighborhoods(...)) computes, through
// Multiscale_curvatures to count the surface's parts.
// Values count only at input points that are vertices of the surface.
std::vector<Layer> run_pipeline(const std::vector<Point>& points, const std::vector<Vector>& normals,
                                const std::vector<std::string>& neighborhoods, double scale_factor)
{
  typedef CAS3::Multiscale_curvatures<Kernel> Analysis;
  const Analysis analysis(points.begin(), points.end(), CAS3::parameters::reference_normals(normals));
  Analysis::Surface surface;
  const double alpha = scale_factor * analysis.scale_value(CAS3::Scale::automatic());
  const int components = int(analysis.surface(alpha, surface).number_of_parts);
  const double spacing = analysis.noise().spacing;
  // the connected pieces of the surface (faces connected across edges)
  std::vector<int> piece(points.size(), -1);
  {
    auto face_piece = get(CGAL::dynamic_face_property_t<std::size_t>(), surface);
    CGAL::Polygon_mesh_processing::connected_components(surface, face_piece);
    auto input_index = surface.property_map<Analysis::Surface_vertex, std::size_t>("v:input_index").first;
    for(Analysis::Surface::Face_index f : surface.faces())
      for(Analysis::Surface_vertex v : CGAL::vertices_around_face(surface.halfedge(f), surface))
        piece[input_index[v]] = int(get(face_piece, f));
  }
  // all the neighborhoods in one call, as the program's job runs them
  std::vector<CAS3::Neighborhood> all;
  for(const std::string& item : neighborhoods)
    all.push_back(neighborhood_of(item));
  const std::vector<std::vector<CAS3::Point_curvature<Kernel> > > values = analysis.estimate_curvatures(surface, all);
  std::vector<Layer> layers;
  for(std::size_t k = 0; k < neighborhoods.size(); ++k)
  {
    const std::string& item = neighborhoods[k];
    const CAS3::Neighborhood& neighborhood = all[k];
    const std::vector<CAS3::Point_curvature<Kernel> >& per_point = values[k];
    Layer layer;
    layer.label = item;
    layer.automatic = neighborhood.kind() == CAS3::Neighborhood::AUTOMATIC;
    layer.components = components;
    layer.piece = piece;
    for(const CAS3::Point_curvature<Kernel>& p : per_point)
    {
      const bool ok = p.on_surface();
      layer.normal.push_back(ok ? p.normal : Vector(nan_value, nan_value, nan_value));
      layer.H.push_back(ok ? double(p.mean_curvature) : nan_value);
      layer.K.push_back(ok ? double(p.gaussian_curvature) : nan_value);
      layer.H_sigma.push_back(ok ? double(p.uncertainty.mean_curvature) : nan_value);
      layer.K_sigma.push_back(ok ? double(p.uncertainty.gaussian_curvature) : nan_value);
      layer.H_noise_sigma.push_back(ok ? double(p.uncertainty.mean_curvature_noise) : nan_value);
      layer.radius.push_back(ok && spacing > 0 ? p.radius / spacing : nan_value);
    }
    layers.push_back(std::move(layer));
  }
  return layers;
}

// ---------------------------------------------------------------------------
// Statistics

// processor time of the (single-threaded) pipeline: steadier than wall time
// on a shared machine
double cpu_seconds_since(std::clock_t start) { return double(std::clock() - start) / CLOCKS_PER_SEC; }

using cas3_test::median_abs;
using cas3_test::quantile;

struct Accuracy
{
  double coverage = nan_value, orientation = nan_value;
  double H_med = nan_value, H_p90 = nan_value, K_med = nan_value, K_p90 = nan_value;
};

// How a case is judged.
struct Judge
{
  bool planar = false;          // H columns: |H| * spacing; no K
  bool flip_allowed = false;    // orientation up to one global flip
  double H_scale = 1, K_scale = 1, spacing = 1;
};

// Errors of estimates (normals may be NaN) on the points `index` of `truth`.
Accuracy accuracy(const std::vector<Vector>& normal, const std::vector<double>& H, const std::vector<double>& K,
                  const std::vector<std::size_t>& index, const Sample& truth, const Judge& judge,
                  bool orientation = true)
{
  Accuracy a;
  std::size_t covered = 0, agree = 0;
  for(std::size_t j = 0; j < index.size(); ++j)
  {
    const std::size_t i = index[j];
    if(!std::isfinite(H[j]) || !std::isfinite(normal[j].x()))
      continue;
    ++covered;
    if(normal[j] * truth.normals[i] > 0)
      ++agree;
  }
  a.coverage = index.empty() ? nan_value : double(covered) / double(index.size());
  double share = covered ? double(agree) / double(covered) : nan_value;
  double sign = 1;
  if(judge.flip_allowed && share < 0.5)
  {
    share = 1 - share;
    sign = -1;
  }
  if(orientation)
    a.orientation = share;
  std::vector<double> eH, eK;
  for(std::size_t j = 0; j < index.size(); ++j)
  {
    const std::size_t i = index[j];
    if(!std::isfinite(H[j]) || !std::isfinite(normal[j].x()))
      continue;
    if(truth.mean_curvature.empty())
      continue;  // reference normals only
    if(judge.planar)
      eH.push_back(std::abs(H[j]) * judge.spacing);
    else
    {
      eH.push_back(std::abs(sign * H[j] - truth.mean_curvature[i]) / judge.H_scale);
      eK.push_back(std::abs(K[j] - truth.gaussian_curvature[i]) / judge.K_scale);
    }
  }
  a.H_med = quantile(eH, 0.5);
  a.H_p90 = quantile(eH, 0.9);
  a.K_med = quantile(eK, 0.5);
  a.K_p90 = quantile(eK, 0.9);
  return a;
}

// How the reported uncertainties match the errors of a layer: the shares
// of covered points whose H (K) error is within 2 sigma, the ratio of the
// median sigma to the median absolute error, the ratio of the median H
// error of the 10% of points of largest relative sigma (sigma / |H|) to
// that of the others (`ranking`: absolute errors; `relative_ranking`:
// relative errors, |error| / |true H|, the pair a user masking by relative
// sigma reads), and the median relative sigma of H.
struct Calibration
{
  double H_within = nan_value, K_within = nan_value, H_ratio = nan_value, K_ratio = nan_value;
  double H_noise_ratio = nan_value;  // the noise's part of sigma alone: 1.48 where the error is noise
  double ranking = nan_value, relative_ranking = nan_value, relative = nan_value;
};

// The median of the second values of the 10% of `pairs` of largest first
// value over that of the others.
double top_tenth_ratio(std::vector<std::pair<double, double> > pairs)
{
  std::sort(pairs.begin(), pairs.end());
  const std::size_t top = pairs.size() - pairs.size() / 10;
  std::vector<double> rest, largest;
  for(std::size_t k = 0; k < pairs.size(); ++k)
    (k < top ? rest : largest).push_back(pairs[k].second);
  return quantile(largest, 0.5) / quantile(rest, 0.5);
}

// The absolute errors of H and K at point i of a layer; false where the
// layer has no value there. H takes the sign that agrees with the truth
// (open surfaces may be flipped).
bool point_errors(const Layer& layer, const Sample& truth, const Judge& judge, std::size_t i, double& e_H,
                  double& e_K)
{
  if(!std::isfinite(layer.H[i]) || !std::isfinite(layer.normal[i].x()))
    return false;
  const double sign = judge.flip_allowed && layer.normal[i] * truth.normals[i] < 0 ? -1 : 1;
  e_H = std::abs(sign * layer.H[i] - truth.mean_curvature[i]);
  e_K = std::abs(layer.K[i] - truth.gaussian_curvature[i]);
  return true;
}

Calibration calibration(const Layer& layer, const Sample& truth, const Judge& judge)
{
  Calibration c;
  if(truth.mean_curvature.empty() || judge.planar)
    return c;
  std::vector<double> eH, eK, sH, sK, sH_noise, relative;
  std::size_t H_in = 0, K_in = 0;
  // (relative sigma, H error), (relative sigma, relative H error)
  std::vector<std::pair<double, double> > by_relative, relative_by_relative;
  for(std::size_t i = 0; i < layer.H.size(); ++i)
  {
    double e_H = 0, e_K = 0;
    if(!std::isfinite(layer.H_sigma[i]) || !point_errors(layer, truth, judge, i, e_H, e_K))
      continue;
    eH.push_back(e_H);
    eK.push_back(e_K);
    sH.push_back(layer.H_sigma[i]);
    sK.push_back(layer.K_sigma[i]);
    sH_noise.push_back(layer.H_noise_sigma[i]);
    H_in += e_H <= 2 * layer.H_sigma[i] ? 1 : 0;
    K_in += e_K <= 2 * layer.K_sigma[i] ? 1 : 0;
    const double r = layer.H_sigma[i] / (std::abs(layer.H[i]) + 1e-300);
    relative.push_back(r);
    by_relative.emplace_back(r, e_H / judge.H_scale);
    relative_by_relative.emplace_back(r, e_H / (std::abs(truth.mean_curvature[i]) + 1e-300));
  }
  if(eH.empty())
    return c;
  c.H_within = double(H_in) / double(eH.size());
  c.K_within = double(K_in) / double(eK.size());
  c.H_ratio = quantile(sH, 0.5) / quantile(eH, 0.5);
  c.K_ratio = quantile(sK, 0.5) / quantile(eK, 0.5);
  c.H_noise_ratio = quantile(sH_noise, 0.5) / quantile(eH, 0.5);
  c.relative = quantile(relative, 0.5);
  c.ranking = top_tenth_ratio(by_relative);
  c.relative_ranking = top_tenth_ratio(relative_by_relative);
  return c;
}

// ---------------------------------------------------------------------------
// The peer: degree 2 jet, degree 2 Monge form, on the k nearest neighbors.

struct Jet_accuracy
{
  int k = 0;
  Accuracy accuracy;
};

std::vector<Jet_accuracy> jet_accuracy(const Sample& s, const Sample& truth, const std::vector<int>& ks,
                                       std::size_t samples, const Judge& judge)
{
  const std::vector<std::size_t> index = cas3_test::spread_indices(s.points.size(), samples);
  const cas3_test::Jet_estimates<Kernel> jet = cas3_test::jet_fitting<Kernel>(s.points, truth.normals, index, ks);
  std::vector<Jet_accuracy> out;
  for(std::size_t j = 0; j < ks.size(); ++j)
    out.push_back(Jet_accuracy{ks[j], accuracy(jet.normal[j], jet.H[j], jet.K[j], index, truth, judge)});
  return out;
}

// ---------------------------------------------------------------------------
// The table

struct Row
{
  std::string name;
  std::size_t n = 0;
  std::string noise = "-";
  double coverage = nan_value, orientation = nan_value;
  int components = -1;
  std::string neighborhoods;
  std::string best;  // the fixed neighborhood of smallest median H error
  bool planar = false;
  double H_med = nan_value, H_p90 = nan_value, K_med = nan_value, K_p90 = nan_value;
  // the automatic neighborhood, and the median radius it chose in spacings
  double auto_H_med = nan_value, auto_H_p90 = nan_value, auto_K_med = nan_value, auto_K_p90 = nan_value;
  double auto_radius = nan_value;
  int jet_k = 0;
  double jet_H_med = nan_value, jet_H_p90 = nan_value, jet_K_med = nan_value;
  double seconds = nan_value;
  std::string layers;  // median H error of every neighborhood: "k1:3.2 auto:1.1"
  std::string note;
};

std::string percent(double x)
{
  if(!std::isfinite(x))
    return "-";
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", 100 * x);
  return b;
}

// relative error in percent, or |H| * spacing for the plane
std::string error(double x, bool planar)
{
  if(!std::isfinite(x))
    return "-";
  char b[32];
  if(planar)
    std::snprintf(b, sizeof b, "%.4f*", x);
  else
    std::snprintf(b, sizeof b, "%.2f", 100 * x);
  return b;
}

std::string number(double x, const char* format = "%.6g")
{
  if(!std::isfinite(x))
    return "";
  char b[32];
  std::snprintf(b, sizeof b, format, x);
  return b;
}

void print_header()
{
  std::printf("%-18s %6s %5s %5s %5s %3s | %5s %6s %6s %6s %6s | %6s %6s %6s %6s %5s | %5s %6s %6s %6s | %6s %s\n",
              "case", "n", "noise", "cov%", "ori%", "cmp", "best", "H med", "H p90", "K med", "K p90", "autoHm",
              "autoHp", "autoKm", "autoKp", "r/s", "jet k", "jetHm", "jetHp", "jetKm", "cpu s", "H med per neighborhood");
}

void print_row(const Row& r)
{
  std::printf("%-18s %6zu %5s %5s %5s %3s | %5s %6s %6s %6s %6s | %6s %6s %6s %6s %5s | %5s %6s %6s %6s | %6s %s%s%s\n",
              r.name.c_str(), r.n, r.noise.c_str(), percent(r.coverage).c_str(), percent(r.orientation).c_str(),
              r.components < 0 ? "-" : std::to_string(r.components).c_str(), r.best.empty() ? "-" : r.best.c_str(),
              error(r.H_med, r.planar).c_str(), error(r.H_p90, r.planar).c_str(), error(r.K_med, false).c_str(),
              error(r.K_p90, false).c_str(), error(r.auto_H_med, r.planar).c_str(),
              error(r.auto_H_p90, r.planar).c_str(), error(r.auto_K_med, false).c_str(),
              error(r.auto_K_p90, false).c_str(), std::isfinite(r.auto_radius) ? number(r.auto_radius, "%.2f").c_str() : "-",
              r.jet_k ? std::to_string(r.jet_k).c_str() : "-", error(r.jet_H_med, r.planar).c_str(),
              error(r.jet_H_p90, r.planar).c_str(), error(r.jet_K_med, false).c_str(),
              number(r.seconds, "%.1f").c_str(), r.layers.c_str(), r.note.empty() ? "" : " ", r.note.c_str());
  std::fflush(stdout);
}

const char* csv_header = "case,n,noise,coverage,orientation,components,neighborhoods,best_fixed,H_measure,H_med,H_p90,"
                         "K_med,K_p90,auto_H_med,auto_H_p90,auto_K_med,auto_K_p90,auto_median_radius_spacings,"
                         "jet_best_k,jet_H_med,jet_H_p90,jet_K_med,pipeline_cpu_seconds,H_med_per_neighborhood,note\n";

void write_csv_row(std::ostream& out, const Row& r)
{
  out << r.name << ',' << r.n << ',' << r.noise << ',' << number(r.coverage) << ',' << number(r.orientation) << ','
      << (r.components < 0 ? std::string() : std::to_string(r.components)) << ",\"" << r.neighborhoods << "\","
      << r.best << ',' << (r.planar ? "abs_H_times_spacing" : "relative") << ',' << number(r.H_med) << ','
      << number(r.H_p90) << ',' << number(r.K_med) << ',' << number(r.K_p90) << ',' << number(r.auto_H_med) << ','
      << number(r.auto_H_p90) << ',' << number(r.auto_K_med) << ',' << number(r.auto_K_p90) << ','
      << number(r.auto_radius) << ',' << (r.jet_k ? std::to_string(r.jet_k) : std::string()) << ','
      << number(r.jet_H_med) << ',' << number(r.jet_H_p90) << ',' << number(r.jet_K_med) << ','
      << number(r.seconds, "%.2f") << ",\"" << r.layers << "\",\"" << r.note << "\"\n";
  out.flush();
}

// ---------------------------------------------------------------------------
// Options

struct Options
{
  std::vector<std::string> cases;  // empty: all
  std::vector<std::size_t> sizes = {20000, 100000};
  std::vector<double> noises = {0, 0.1, 0.3};
  std::vector<std::string> neighborhoods = {"auto", "k1", "k2", "k3", "2s", "4s", "8s", "16s"};
  bool large = false, normals = false, jet = true, calibration = false;
  double scale_factor = 1;
  std::size_t jet_samples = 5000;
  std::size_t reference_draws = 0;
  std::string data = CAS3_TEST_DATA;
  std::string csv;
  std::string write_points;  // a folder, or empty
  bool selected(const std::string& name) const
  {
    return cases.empty() || std::find(cases.begin(), cases.end(), name) != cases.end();
  }
};

template <class T>
std::vector<T> parse_list(const std::string& text)
{
  std::vector<T> v;
  std::stringstream list(text);
  std::string item;
  while(std::getline(list, item, ','))
  {
    std::stringstream s(item);
    T x;
    if(!(s >> x))
      throw std::invalid_argument("bad list item '" + item + "'");
    v.push_back(x);
  }
  return v;
}

// A count given on the command line: digits only.
std::size_t parse_count(const std::string& text)
{
  if(text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 9)
    throw std::invalid_argument("bad count '" + text + "'");
  return std::stoul(text);
}

std::string join(const std::vector<std::string>& v)
{
  std::string s;
  for(const std::string& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

std::string noise_label(double r)
{
  std::ostringstream s;
  s << r;
  return s.str();
}

// ---------------------------------------------------------------------------
// Cases

struct Shape
{
  std::string name;
  bool planar;
  std::function<Sample(std::size_t)> make;
};

std::vector<Shape> grid_shapes()
{
  using namespace cas3_analytic;
  const Bumpy_radius bumpy{0.02, 10, 0, 0.4, 1, 0, 0};
  return {
    {"ellipsoid", false, [](std::size_t n) { return ellipsoid_truth_sample<Point, Vector>(n, 1, 0.7, 0.4); }},
    {"torus", false, [](std::size_t n) { return torus_truth_sample<Point, Vector>(n, 1, 0.35); }},
    {"bumpy_sphere", false,
     [bumpy](std::size_t n) { return bumpy_sphere_truth_sample<Point, Vector>(n, bumpy); }},
    {"ellipsoid_cap", false,
     [](std::size_t n) { return ellipsoid_truth_sample<Point, Vector>(n, 1, 0.7, 0.4, 0.1); }},
    {"torus_patch", false,
     [](std::size_t n) { return torus_truth_sample<Point, Vector>(n, 1, 0.35, M_PI, 0, M_PI); }},
    {"bumpy_cap", false,
     [bumpy](std::size_t n) { return bumpy_sphere_truth_sample<Point, Vector>(n, bumpy, 0.2); }},
    {"plane", true, [](std::size_t n) { return square_truth_sample<Point, Vector>(n, 1); }},
    {"sphere", false, [](std::size_t n) { return ellipsoid_truth_sample<Point, Vector>(n, 1, 1, 1); }},
  };
}

const std::vector<std::string> extra_cases = {"fine_bumps", "dent_bumps"};
const std::vector<std::string> scan_cases = {"kitten", "oni", "ball", "building"};
const std::vector<std::string> scan_files = {"kitten.xyz", "oni.pwn", "ball.ply", "building.ply"};

Judge judge_of(const Sample& s, bool planar, bool flip_allowed)
{
  Judge j;
  j.planar = planar;
  j.flip_allowed = flip_allowed;
  j.spacing = s.spacing;
  if(!planar)
  {
    j.H_scale = median_abs(s.mean_curvature);
    j.K_scale = median_abs(s.gaussian_curvature);
  }
  return j;
}

// The calibration of a layer, one line, `kind` naming whose sigmas.
void print_calibration(const char* kind, const std::string& name, std::size_t n, double noise, const Layer& layer,
                       const Sample& truth, const Judge& judge)
{
  const Calibration c = calibration(layer, truth, judge);
  std::printf("%-11s %-10s %6zu %5s %-5s H within 2 sigma %5.1f%%  K %5.1f%%  median sigma/error H %5.2f"
              "  K %5.2f  top-10%% sigma error ratio %5.2f (relative errors %5.2f)  median sigma/|H| %7.3f"
              "  noise part H %5.2f\n",
              kind, name.c_str(), n, noise_label(noise).c_str(), layer.label.c_str(), 100 * c.H_within,
              100 * c.K_within, c.H_ratio, c.K_ratio, c.ranking, c.relative_ranking, c.relative, c.H_noise_ratio);
}

// `layers` with each point's standard uncertainty measured: the root mean
// square of the layer's errors there over `draws`, other noise draws of the
// same sample (--reference-draws); NaN where no draw has a value. Its
// "noise part" is all of it, noise and bias being measured together. A
// draw whose pipeline fails is left out, with a message.
std::vector<Layer> reference_sigmas(std::vector<Layer> layers, const std::vector<Sample>& draws, const Sample& truth,
                                    const Judge& judge, const Options& o)
{
  const std::size_t n = truth.points.size();
  std::vector<std::vector<double> > sum_H(layers.size(), std::vector<double>(n, 0)), sum_K = sum_H, count = sum_H;
  for(const Sample& draw : draws)
  {
    std::vector<Layer> values;
    try
    {
      values = run_pipeline(draw.points, o.normals ? draw.normals : std::vector<Vector>(), o.neighborhoods,
                            o.scale_factor);
    }
    catch(const std::exception& e)
    {
      std::cerr << "evaluate_surfaces: a reference draw left out, the pipeline failed: " << e.what() << "\n";
    }
    for(std::size_t k = 0; k < values.size(); ++k)
      for(std::size_t i = 0; i < n; ++i)
      {
        double e_H = 0, e_K = 0;
        if(!point_errors(values[k], truth, judge, i, e_H, e_K))
          continue;
        sum_H[k][i] += e_H * e_H;
        sum_K[k][i] += e_K * e_K;
        count[k][i] += 1;
      }
  }
  for(std::size_t k = 0; k < layers.size(); ++k)
    for(std::size_t i = 0; i < n; ++i)
    {
      const double c = count[k][i];
      layers[k].H_sigma[i] = c > 0 ? std::sqrt(sum_H[k][i] / c) : nan_value;
      layers[k].K_sigma[i] = c > 0 ? std::sqrt(sum_K[k][i] / c) : nan_value;
      layers[k].H_noise_sigma[i] = layers[k].H_sigma[i];
    }
  return layers;
}

// Runs the pipeline and the peer on `s`, one row per truth in `truths`
// (the first is the sample itself), the peer with the k of `jet_ks[t]`.
void evaluate_synthetic(const Sample& s, const std::vector<const Sample*>& truths,
                        const std::vector<std::string>& names, const std::vector<std::vector<int> >& jet_ks,
                        bool planar, double noise, const Options& o, std::vector<Row>& rows, std::ostream* csv,
                        const std::vector<Sample>& draws = std::vector<Sample>())
{
  if(!o.write_points.empty())
  {
    char name[64];
    std::snprintf(name, sizeof name, "_%zu_%g.xyz", s.points.size(), noise);
    std::ofstream out(o.write_points + "/" + names.front() + name);
    out.precision(17);
    for(const Point& p : s.points)
      out << p << "\n";
    std::snprintf(name, sizeof name, "_%zu_%g_truth.txt", s.points.size(), noise);
    std::ofstream truth(o.write_points + "/" + names.front() + name);
    truth.precision(17);
    for(std::size_t i = 0; i < s.points.size(); ++i)
      truth << s.normals[i] << " " << s.mean_curvature[i] << " " << s.gaussian_curvature[i] << "\n";
  }
  std::vector<Layer> layers;
  std::string failure;
  const std::clock_t start = std::clock();
  try
  {
    layers = run_pipeline(s.points, o.normals ? s.normals : std::vector<Vector>(), o.neighborhoods, o.scale_factor);
  }
  catch(const std::exception& e)
  {
    failure = std::string("pipeline failed: ") + e.what();
  }
  const double seconds = cpu_seconds_since(start);
  std::vector<std::size_t> all(s.points.size());
  for(std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  for(std::size_t t = 0; t < truths.size(); ++t)
  {
    const Sample& truth = *truths[t];
    const Judge judge = judge_of(truth, planar, !truth.closed && !o.normals);
    Row row;
    row.name = names[t];
    row.n = s.points.size();
    row.noise = noise_label(noise);
    row.neighborhoods = join(o.neighborhoods);
    row.planar = planar;
    row.seconds = seconds;
    row.note = failure;
    double best = std::numeric_limits<double>::infinity();
    if(o.calibration && t == 0 && !draws.empty() && !layers.empty())
      for(const Layer& layer : reference_sigmas(layers, draws, truth, judge, o))
        print_calibration("reference", names[t], s.points.size(), noise, layer, truth, judge);
    for(const Layer& layer : layers)
    {
      if(o.calibration)
        print_calibration("calibration", names[t], s.points.size(), noise, layer, truth, judge);
      const Accuracy a = accuracy(layer.normal, layer.H, layer.K, all, truth, judge);
      row.layers += (row.layers.empty() ? "" : " ") + layer.label + ":" + error(a.H_med, planar);
      if(row.components < 0)
        row.components = layer.components;
      if(layer.automatic)
      {
        // its own columns: its radius is chosen from the data, never by the truth
        row.auto_H_med = a.H_med;
        row.auto_H_p90 = a.H_p90;
        row.auto_K_med = a.K_med;
        row.auto_K_p90 = a.K_p90;
        std::vector<double> radii;
        for(double r : layer.radius)
          if(std::isfinite(r)) radii.push_back(r);
        row.auto_radius = quantile(radii, 0.5);
        if(!std::isfinite(row.coverage))
        {
          row.coverage = a.coverage;
          row.orientation = a.orientation;
        }
        continue;
      }
      const double key = std::isfinite(a.H_med) ? a.H_med : std::numeric_limits<double>::max();
      if(row.best.empty() || key < best)
      {
        best = key;
        row.best = layer.label;
        row.coverage = a.coverage;
        row.orientation = a.orientation;
        row.H_med = a.H_med;
        row.H_p90 = a.H_p90;
        row.K_med = a.K_med;
        row.K_p90 = a.K_p90;
      }
    }
    if(o.jet)
    {
      Judge jet_judge = judge;
      jet_judge.flip_allowed = false;  // its sign comes from the truth
      double jet_best = std::numeric_limits<double>::infinity();
      for(const Jet_accuracy& j : jet_accuracy(s, truth, jet_ks[t], o.jet_samples, jet_judge))
        if(row.jet_k == 0 || j.accuracy.H_med < jet_best)
        {
          jet_best = j.accuracy.H_med;
          row.jet_k = j.k;
          row.jet_H_med = j.accuracy.H_med;
          row.jet_H_p90 = j.accuracy.H_p90;
          row.jet_K_med = j.accuracy.K_med;
        }
    }
    print_row(row);
    if(csv)
      write_csv_row(*csv, row);
    rows.push_back(row);
  }
}

// The best orientation that one side per connected piece of the surface
// (`Layer::piece`) could give: per piece, the larger of its covered points
// whose normal agrees with the truth and those whose normal does not. No
// rule that orients whole pieces, as the surface's sheets are, does better.
double best_per_piece(const Layer& layer, const Sample& truth)
{
  std::vector<std::size_t> agree, covered;
  for(std::size_t i = 0; i < layer.normal.size(); ++i)
  {
    if(layer.piece[i] < 0 || !std::isfinite(layer.normal[i].x()))
      continue;
    const std::size_t p = std::size_t(layer.piece[i]);
    if(p >= covered.size())
    {
      covered.resize(p + 1, 0);
      agree.resize(p + 1, 0);
    }
    ++covered[p];
    agree[p] += layer.normal[i] * truth.normals[i] > 0 ? 1 : 0;
  }
  std::size_t best = 0, total = 0;
  for(std::size_t p = 0; p < covered.size(); ++p)
  {
    best += (std::max)(agree[p], covered[p] - agree[p]);
    total += covered[p];
  }
  return total ? double(best) / double(total) : nan_value;
}

// x y z nx ny nz per line (.xyz, .pwn), or an ascii PLY with x y z nx ny nz.
bool read_oriented_points(const std::string& file, std::vector<Point>& points, std::vector<Vector>& normals)
{
  std::ifstream in(file);
  if(!in)
    return false;
  std::string line;
  std::vector<int> column(6, -1);
  std::size_t properties = 6;
  const bool ply = file.size() > 4 && file.substr(file.size() - 4) == ".ply";
  if(ply)
  {
    properties = 0;
    const char* names[6] = {"x", "y", "z", "nx", "ny", "nz"};
    bool in_vertex = false;
    while(std::getline(in, line))
    {
      std::istringstream s(line);
      std::string word, type, name;
      s >> word;
      if(word == "format" && line.find("ascii") == std::string::npos)
        return false;
      if(word == "element")
      {
        s >> name;
        in_vertex = name == "vertex";
      }
      if(word == "property" && in_vertex)
      {
        s >> type >> name;
        for(int c = 0; c < 6; ++c)
          if(name == names[c]) column[c] = int(properties);
        ++properties;
      }
      if(word == "end_header")
        break;
    }
    for(int c : column)
      if(c < 0) return false;
  }
  else
    for(int c = 0; c < 6; ++c) column[c] = c;
  std::vector<double> v(properties);
  while(std::getline(in, line))
  {
    std::istringstream s(line);
    std::size_t read = 0;
    while(read < properties && (s >> v[read])) ++read;
    if(read < properties)
    {
      if(ply) break;  // faces or the end
      continue;
    }
    points.push_back(Point(v[column[0]], v[column[1]], v[column[2]]));
    normals.push_back(Vector(v[column[3]], v[column[4]], v[column[5]]));
  }
  return !points.empty();
}

void evaluate_scan(const std::string& name, const std::string& file, const Options& o, std::vector<Row>& rows,
                   std::ostream* csv)
{
  std::vector<Point> points;
  std::vector<Vector> normals;
  if(!read_oriented_points(file, points, normals))
  {
    Row row;
    row.name = name;
    row.note = "cannot read " + file;
    print_row(row);
    return;
  }
  Sample truth;
  truth.points = points;
  truth.normals = normals;
  for(int given = 1; given >= 0; --given)
  {
    Row row;
    row.name = name + (given ? "[normals]" : "[xyz]");
    row.n = points.size();
    row.neighborhoods = join(o.neighborhoods);
    std::vector<Layer> layers;
    const std::clock_t start = std::clock();
    try
    {
      layers = run_pipeline(points, given ? normals : std::vector<Vector>(), o.neighborhoods, o.scale_factor);
    }
    catch(const std::exception& e)
    {
      row.note = std::string("pipeline failed: ") + e.what();
    }
    row.seconds = cpu_seconds_since(start);
    Judge judge;
    judge.flip_allowed = !given;
    std::vector<std::size_t> all(points.size());
    for(std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    // reference normals only: the best neighborhood is the best oriented one
    const Layer* best_layer = nullptr;
    for(const Layer& layer : layers)
    {
      const Accuracy a = accuracy(layer.normal, layer.H, layer.K, all, truth, judge);
      row.layers += (row.layers.empty() ? "" : " ") + layer.label + ":" + percent(a.orientation);
      if(row.best.empty() || a.orientation > row.orientation)
      {
        row.best = layer.label;
        row.coverage = a.coverage;
        row.orientation = a.orientation;
        row.components = layer.components;
        best_layer = &layer;
      }
    }
    if(!given && best_layer)
      row.note = "one side per surface piece at best: " + percent(best_per_piece(*best_layer, truth));
    print_row(row);
    if(csv)
      write_csv_row(*csv, row);
    rows.push_back(row);
  }
}

// The truth of the generators against closed forms: torus (k1 = 1/r,
// k2 = cos v / (R + r cos v)), ellipsoid (K = 1 / (a^2 b^2 c^2 s^2) and
// H = |x^2 + y^2 + z^2 - a^2 - b^2 - c^2| / (2 a^2 b^2 c^2 s^(3/2)),
// s = x^2/a^4 + y^2/b^4 + z^2/c^4), its area (Knud Thomsen's formula, within
// 1.1%), and the torus area 4 pi^2 R r.
bool check_truth()
{
  double worst = 0;
  const Sample t = cas3_analytic::torus_truth_sample<Point, Vector>(2000, 1, 0.35);
  for(std::size_t i = 0; i < t.points.size(); ++i)
  {
    const Point& p = t.points[i];
    const double cos_v = (std::sqrt(p.x() * p.x() + p.y() * p.y()) - 1) / 0.35;
    const double k1 = 1 / 0.35, k2 = cos_v / (1 + 0.35 * cos_v);
    worst = std::max({worst, std::abs(t.mean_curvature[i] - (k1 + k2) / 2), std::abs(t.gaussian_curvature[i] - k1 * k2),
                      std::abs(t.normals[i].squared_length() - 1)});
  }
  const double a = 1, b = 0.7, c = 0.4;
  const Sample e = cas3_analytic::ellipsoid_truth_sample<Point, Vector>(2000, a, b, c);
  for(std::size_t i = 0; i < e.points.size(); ++i)
  {
    const Point& p = e.points[i];
    const double s = p.x() * p.x() / (a * a * a * a) + p.y() * p.y() / (b * b * b * b) + p.z() * p.z() / (c * c * c * c);
    const double K = 1 / (a * a * b * b * c * c * s * s);
    const double H = std::abs(p.x() * p.x() + p.y() * p.y() + p.z() * p.z() - a * a - b * b - c * c) /
                     (2 * a * a * b * b * c * c * std::pow(s, 1.5));
    worst = std::max({worst, std::abs(e.gaussian_curvature[i] / K - 1), std::abs(e.mean_curvature[i] / H - 1)});
  }
  const double q = 1.6075;
  const double thomsen =
    4 * M_PI * std::pow((std::pow(a * b, q) + std::pow(a * c, q) + std::pow(b * c, q)) / 3, 1 / q);
  const bool ok = worst < 1e-9 && std::abs(e.area / thomsen - 1) < 0.011 &&
                  std::abs(t.area / (4 * M_PI * M_PI * 0.35) - 1) < 1e-12;
  std::printf("truth check: largest error %.2g; ellipsoid area %.5f (Thomsen %.5f); torus area %.5f (exact %.5f): %s\n",
              worst, e.area, thomsen, t.area, 4 * M_PI * M_PI * 0.35, ok ? "ok" : "FAILED");
  return ok;
}

int main(int argc, char* argv[])
{
  Options o;
  try
  {
    for(int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      const bool value = i + 1 < argc;
      if(arg == "--case" && value) o.cases = parse_list<std::string>(argv[++i]);
      else if(arg == "--sizes" && value) o.sizes = parse_list<std::size_t>(argv[++i]);
      else if(arg == "--noise" && value) o.noises = parse_list<double>(argv[++i]);
      else if(arg == "--neighborhoods" && value) o.neighborhoods = parse_list<std::string>(argv[++i]);
      else if(arg == "--rings" && value)
      {
        o.neighborhoods.clear();
        for(int k : parse_list<int>(argv[++i])) o.neighborhoods.push_back("k" + std::to_string(k));
      }
      else if(arg == "--scale-factor" && value) o.scale_factor = std::stod(argv[++i]);
      else if(arg == "--jet-samples" && value) o.jet_samples = parse_count(argv[++i]);
      else if(arg == "--reference-draws" && value) o.reference_draws = parse_count(argv[++i]);
      else if(arg == "--data" && value) o.data = argv[++i];
      else if(arg == "--csv" && value) o.csv = argv[++i];
      else if(arg == "--write-points" && value) o.write_points = argv[++i];
      else if(arg == "--large") o.large = true;
      else if(arg == "--normals") o.normals = true;
      else if(arg == "--no-jet") o.jet = false;
      else if(arg == "--calibration") o.calibration = true;
      else if(arg == "--check-truth") return check_truth() ? EXIT_SUCCESS : EXIT_FAILURE;
      else if(arg == "--help")
      {
        std::cout << "evaluate_surfaces [--case NAME,...] [--sizes 20000,100000] [--large] [--noise 0,0.1,0.3]\n"
                     "                  [--neighborhoods auto,k1,k2,k3,2s,4s,8s,16s] [--rings 1,2,3] [--normals]\n"
                     "                  [--scale-factor 1] [--jet-samples 5000] [--no-jet] [--data DIR] [--csv FILE]\n"
                     "                  [--write-points DIR] [--list] [--check-truth] [--calibration]\n"
                     "                  [--reference-draws N]\n"
                     "neighborhoods: k2 ring size, auto, 4s spacings, 0.01 model units (see evaluate_surfaces.cpp)\n";
        return EXIT_SUCCESS;
      }
      else if(arg == "--list")
      {
        for(const Shape& s : grid_shapes()) std::cout << s.name << "\n";
        for(const std::string& s : extra_cases) std::cout << s << "\n";
        for(const std::string& s : scan_cases) std::cout << s << "\n";
        return EXIT_SUCCESS;
      }
      else
        throw std::invalid_argument("unknown option " + arg);
    }
    if(o.neighborhoods.empty())
      throw std::invalid_argument("no neighborhood");
    for(const std::string& item : o.neighborhoods) neighborhood_of(item);  // throws on a bad item
  }
  catch(const std::exception& e)
  {
    std::cerr << "evaluate_surfaces: " << e.what() << " (see the top of evaluate_surfaces.cpp)\n";
    return EXIT_FAILURE;
  }
  if(o.large && std::find(o.sizes.begin(), o.sizes.end(), std::size_t(1000000)) == o.sizes.end())
    o.sizes.push_back(1000000);

  std::ofstream csv_file;
  std::ostream* csv = nullptr;
  if(!o.csv.empty())
  {
    csv_file.open(o.csv);
    if(!csv_file)
    {
      std::cerr << "evaluate_surfaces: cannot write " << o.csv << "\n";
      return EXIT_FAILURE;
    }
    cas3_benchmark::write_csv_provenance(csv_file, argc, argv);
    csv_file << csv_header;
    csv = &csv_file;
  }

  std::printf("errors in %% of the median |true value|; '*': median |H| * spacing (plane); orientation up to one\n"
              "global flip for open surfaces and scans without given normals; best: the fixed neighborhood of\n"
              "smallest median H error; auto: the automatic one, r/s its median radius in spacings; jet: CGAL\n"
              "Monge_via_jet_fitting (degree 2/2) on %s points, k from {60,120,240,480} (noisy), {12,24} (clean),\n"
              "{400,1000} (dent_bumps~smooth); neighborhoods %s\n",
              o.jet_samples ? std::to_string(o.jet_samples).c_str() : "all", join(o.neighborhoods).c_str());
  print_header();
  std::vector<Row> rows;
  const cas3_benchmark::Phase total;

  const std::vector<Shape> shapes = grid_shapes();
  for(std::size_t shape_index = 0; shape_index < shapes.size(); ++shape_index)
  {
    const Shape& shape = shapes[shape_index];
    if(!o.selected(shape.name))
      continue;
    for(std::size_t n : o.sizes)
    {
      const Sample clean = shape.make(n);
      for(double r : o.noises)
      {
        Sample s = clean;
        // the same noise for a case whatever else is selected
        const unsigned seed = unsigned(1000 * shape_index + n + std::lround(1000 * r));
        if(shape.planar && r == 0)
          cas3_analytic::add_normal_noise(s, 1e-4, seed);
        else
          cas3_analytic::add_normal_noise(s, r, seed);
        const std::vector<int> ks = r > 0 ? std::vector<int>{60, 120, 240, 480} : std::vector<int>{12, 24};
        std::vector<Sample> draws;
        for(std::size_t m = 1; o.calibration && r > 0 && m <= o.reference_draws; ++m)
        {
          draws.push_back(clean);
          cas3_analytic::add_normal_noise(draws.back(), r, seed + unsigned(7919 * m));
        }
        evaluate_synthetic(s, {&s}, {shape.name}, {ks}, shape.planar, r, o, rows, csv, draws);
      }
    }
  }

  // clean 20k details
  {
    cas3_analytic::Bumpy_radius fine{0.005, 40, 0, 0.4, 1, 0, 0};
    if(o.selected("fine_bumps"))
    {
      const Sample s = cas3_analytic::bumpy_sphere_truth_sample<Point, Vector>(20000, fine, -INFINITY, 15);
      evaluate_synthetic(s, {&s}, {"fine_bumps"}, {{12, 24}}, false, 0, o, rows, csv);
    }
    if(o.selected("dent_bumps"))
    {
      cas3_analytic::Bumpy_radius dent = fine;
      dent.dent_depth = 0.25;
      dent.dent_width = 0.4;
      Sample smooth;
      const Sample s = cas3_analytic::bumpy_sphere_truth_sample<Point, Vector>(20000, dent, -INFINITY, 16, &smooth);
      // the smooth truth is the summary of many points: the peer's k to match
      evaluate_synthetic(s, {&s, &smooth}, {"dent_bumps", "dent_bumps~smooth"}, {{12, 24}, {400, 1000}}, false, 0,
                         o, rows, csv);
    }
  }

  for(std::size_t i = 0; i < scan_cases.size(); ++i)
    if(o.selected(scan_cases[i]))
      evaluate_scan(scan_cases[i], o.data + "/" + scan_files[i], o, rows, csv);

  std::printf("total %.1f s wall\n", total.seconds());
  return EXIT_SUCCESS;
}
