// conformal_curvature: multi-scale curvature of a point cloud, end to end.
// Run with --help for the usage. Writes, into the output directory, a binary
// PLY (or, with --las, LAS 1.4) point cloud with every input point's values
// at every scale and neighborhood, one binary PLY surface per scale with the same values per
// vertex, and on request a CSV with a row per input point per layer; prints
// a summary table on stdout.
//
// The steps, a header each: the options (cas3_curvature_options.h), the
// reading (cas3_read_point_cloud.h), the library's computation, the files
// (cas3_curvature_output.h) written as one transaction
// (cas3_output_transaction.h), and the summary (cas3_curvature_summary.h).
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cas3_curvature_options.h"
#include "cas3_curvature_output.h"
#include "cas3_curvature_summary.h"
#include "cas3_layer_names.h"
#include "cas3_malloc_policy.h"
#include "cas3_output_transaction.h"
#include "cas3_read_point_cloud.h"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
typedef CAS3::Multiscale_curvatures<K> Analysis;

namespace {

// Progress lines on stderr, only once a run has taken more than a second:
// short runs stay silent.
class Progress
{
public:
  explicit Progress(bool quiet) : m_quiet(quiet) {}
  void operator()(const std::string& what) const
  {
    if(!m_quiet && std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count() > 1.0)
      std::cerr << "conformal_curvature: " << what << std::endl;
  }

private:
  bool m_quiet;
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

// The library's analysis of the cloud: outliers left out, points recentered,
// rescaled and smoothed as the options say, the conformal alpha shape built.
std::unique_ptr<Analysis> analyze(const cas3::Curvature_options& o, const cas3::Point_cloud& cloud)
{
  const std::vector<Point>& points = cloud.points;
  try
  {
    const auto np = CAS3::parameters::reference_normals(std::cref(cloud.normals),
      CAS3::parameters::orient_each_point(o.orient_each_point,
        CAS3::parameters::denoising(o.denoising, CAS3::parameters::surface_extraction(o.extraction))));
    return o.denoising_neighbors > 0
      ? std::make_unique<Analysis>(points.begin(), points.end(),
                                   CAS3::parameters::denoising_neighbors(o.denoising_neighbors, np))
      : std::make_unique<Analysis>(points.begin(), points.end(), np);
  }
  catch(const std::invalid_argument& e) { throw std::runtime_error(o.input + ": " + e.what()); }
}

int run(const cas3::Curvature_options& o)
{
  const Progress progress(o.quiet);
  std::vector<std::string> labels;
  for(const CAS3::Scale& scale : o.scales)
    for(const CAS3::Neighborhood& neighborhood : o.neighborhoods)
      labels.push_back(cas3::layer_label(scale, neighborhood, o.scales.size() > 1));
  if(o.las)  // before any work: layer names too long for LAS fail first
  {
    try { cas3::las_extra_fields(labels); }
    catch(const std::invalid_argument& e) { throw std::runtime_error(std::string("--las: ") + e.what()); }
  }
  cas3::Output_transaction output(o.output);  // before any work: an unwritable folder fails first
  const cas3::Point_cloud cloud = cas3::read_point_cloud(o.input, o.las_filter, o.las);
  if(o.las)  // and, before the work, the input's extra bytes that do not fit beside them
  {
    try { cas3::las_output_header(cloud.las, labels); }
    catch(const std::invalid_argument& e) { throw std::runtime_error(std::string("--las: ") + e.what()); }
  }
  const std::vector<Point>& points = cloud.points;
  progress("read " + std::to_string(points.size()) + " points");
  const std::unique_ptr<Analysis> analysis = analyze(o, cloud);
  std::vector<bool> is_outlier(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    is_outlier[i] = analysis->is_outlier(i);
  if(!analysis->outliers().empty())
    progress(std::to_string(analysis->outliers().size()) + " isolated far outliers left out");
  progress("built the conformal alpha shape");

  std::ofstream csv;
  if(o.csv)
  {
    csv = output.open("curvatures.csv", false);
    csv << cas3::csv_header();
  }
  std::ostringstream summary;
  if(cloud.las.present)
    summary << cas3::las_input_summary(o.input, cloud.las.header, cloud.las.filter, cloud.las.counts) << "\n";
  summary << cas3::summary_head(o.input, *analysis);
  std::vector<cas3::Layer> layers;
  std::vector<std::string> uncertainty;  // per layer, for the summary's last line
  for(const CAS3::Scale& scale : o.scales)
  {
    const double a = analysis->scale_value(scale);
    Analysis::Surface surface;
    const CAS3::Surface_report report = analysis->surface(a, surface);
    progress("scale " + cas3::scale_text(scale) + ": surface of " + std::to_string(report.number_of_faces) + " faces");
    summary << cas3::summary_scale_line(cas3::scale_text(scale), report);
    cas3::return_freed_memory();
    // each layer is kept in float as soon as it is made: its values in
    // double are never all held at once
    auto layer_done = [&](std::size_t r, std::vector<CAS3::Point_curvature<K> >&& curvatures) {
      const CAS3::Neighborhood& neighborhood = o.neighborhoods[r];
      cas3::Layer layer(curvatures);
      layer.label = cas3::layer_label(scale, neighborhood, o.scales.size() > 1);
      layer.description = cas3::layer_description(*analysis, a, scale, neighborhood, layer.label);
      if(o.csv)
      {
        cas3::append_csv_rows(csv, points, a, neighborhood, curvatures, is_outlier);
        output.check(csv);
      }
      summary << cas3::summary_row(layer.label, a, curvatures) << "\n";
      uncertainty.push_back(cas3::summary_uncertainty_item(layer.label, cas3::median_relative_uncertainty(curvatures),
                                                          cas3::median_relative_uncertainty(curvatures, true)));
      progress("layer " + layer.label + ": curvature estimated");
      layers.push_back(std::move(layer));
    };
    // the last scale's fits need the shape no more: freed before them, it
    // is not held with their values
    if(&scale == &o.scales.back())
      std::move(*analysis).estimate_curvatures(surface, o.neighborhoods, o.estimator, layer_done);
    else
      analysis->estimate_curvatures(surface, o.neighborhoods, o.estimator, layer_done);
    if(!cloud.normals.empty())
      summary << cas3::summary_normals_line(cas3::scale_text(scale), report);
    std::ofstream ply = output.open("surface_" + cas3::scale_label(scale) + ".ply", true);
    cas3::write_surface(ply, surface, points, layers.data() + (layers.size() - o.neighborhoods.size()),
                        layers.data() + layers.size());
    output.close(ply);
  }
  std::ofstream cloud_file = output.open(o.las ? "curvatures.las" : "curvatures.ply", true);
  if(o.las)
    cas3::write_point_cloud_las(cloud_file, points, cloud.las, is_outlier, layers);
  else
    cas3::write_point_cloud(cloud_file, points, is_outlier, layers);
  output.close(cloud_file);
  if(o.csv)
    output.close(csv);
  output.commit();
  summary << cas3::summary_uncertainty_line(uncertainty);
  if(!o.quiet)
    std::cout << summary.str() << "results in " << o.output << "\n";
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char* argv[])
{
  cas3::use_transparent_huge_pages(argv);
  cas3::use_one_malloc_arena();
  try
  {
    const cas3::Curvature_options options = cas3::parse_curvature_options(argc, argv);
    if(options.help)
    {
      std::cout << cas3::curvature_usage();
      return EXIT_SUCCESS;
    }
    return run(options);
  }
  catch(const std::exception& e)  // one line: a bad option, input or output, or a library error
  {
    std::cerr << "conformal_curvature: " << e.what() << "\n";
  }
  return EXIT_FAILURE;
}
