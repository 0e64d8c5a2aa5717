// The compiled half of the Python module `conformal_alpha_shapes`: numpy
// arrays in, the library's public functions, numpy arrays out. Argument
// shapes and types are checked by the Python half (conformal_alpha_shapes/
// __init__.py) and again here, so that this module never crashes on what a
// caller passes. The GIL is released while the library computes, which
// stops on Ctrl-C (without_gil) and reports its progress (Checkpoint).
#include <CGAL/Conformal_alpha_shapes_3/interruption.h>
#include <CGAL/Conformal_alpha_shapes_3/match_regions.h>
#include <CGAL/Conformal_alpha_shapes_3/multiscale_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "cas3_curvature_options.h"
#include "cas3_curvature_output.h"
#include "cas3_layer_names.h"
#include "cas3_malloc_policy.h"
#include "cas3_read_point_cloud.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <tuple>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace py = pybind11;
namespace CAS3 = CGAL::Conformal_alpha_shapes_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CAS3::Multiscale_curvatures<K> Analysis;
typedef Analysis::Shape Shape;
typedef Analysis::Surface Surface;
typedef py::array_t<double, py::array::c_style | py::array::forcecast> Doubles;

namespace {

// The rows of an (N, 3) array; `what` names it in the message.
std::size_t check_rows(const py::array& a, const char* what)
{
  if(a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error(std::string(what) + " must be an (N, 3) array");
  return std::size_t(a.shape(0));
}

template <class T>
std::vector<T> to_triples(const Doubles& a, const char* what)
{
  const std::size_t n = check_rows(a, what);
  const double* p = a.data();
  std::vector<T> out;
  out.reserve(n);
  for(std::size_t i = 0; i < n; ++i, p += 3)
    out.emplace_back(p[0], p[1], p[2]);
  return out;
}

// Caps TBB's threads for the life of the object; 0 leaves them as they are.
class Thread_cap
{
public:
  explicit Thread_cap(int threads)
  {
    if(threads < 0)
      throw py::value_error("threads must be >= 1, or None for all");
#ifdef CGAL_LINKED_WITH_TBB
    if(threads > 0)
      m_control.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#endif
  }

private:
#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> m_control;
#endif
};

// The caller's progress(stage, fraction) over the steps of a computation,
// and Ctrl-C. Each step spans a share of [0, 1] in proportion to the time it
// is expected to take (Step_costs). At a step's start the fraction is the end
// of the step before; inside it, the library's interruption checks (every
// 20 ms or so of its work, see without_gil) move it on with the time spent
// against the time expected, slowing down near the step's end, which it
// reaches only when the step ends. The callable is called at each step's
// start and at most every 0.1 s inside; the fractions never decrease, and
// the last call is ("done", 1.0).
class Checkpoint
{
  typedef std::chrono::steady_clock Clock;
  struct State
  {
    py::object progress;
    std::string stage;
    double begin = 0, end = 0, expected_seconds = 1, reported = -1;
    Clock::time_point started = Clock::now(), last_call = Clock::now();
  };

public:
  explicit Checkpoint(py::object progress = py::none()) : m_state(std::make_shared<State>())
  {
    m_state->progress = std::move(progress);
  }

  // With the GIL released: enters the step `stage`, which ends at fraction
  // `end` and is expected to take `seconds`; raises KeyboardInterrupt on Ctrl-C.
  void step(const std::string& stage, double end, double seconds) const
  {
    py::gil_scoped_acquire gil;
    if(PyErr_CheckSignals() != 0)
      throw py::error_already_set();
    State& s = *m_state;
    s.begin = (std::max)(s.end, 0.0);
    s.end = (std::min)((std::max)(end, s.begin), 1.0);
    s.stage = stage;
    s.expected_seconds = (std::max)(seconds, 1e-3);
    s.started = Clock::now();
    report(s.begin, true);
  }

  // With the GIL held: the fraction moved on by the time spent in the step.
  void tick() const
  {
    State& s = *m_state;
    if(s.progress.is_none() || Clock::now() - s.last_call < std::chrono::milliseconds(100))
      return;
    const double x = seconds_in_step() / s.expected_seconds;
    // linear up to 0.8 of the step, then approaching its end
    const double g = x <= 0.8 ? x : 0.8 + 0.2 * (1 - std::exp(-(x - 0.8) / 0.2));
    report(s.begin + (s.end - s.begin) * g, false);
  }

  // With the GIL released: the last call, ("done", 1.0).
  void finish() const
  {
    py::gil_scoped_acquire gil;
    m_state->stage = "done";
    m_state->end = 1.0;
    report(1.0, true);
  }

  double seconds_in_step() const
  {
    return std::chrono::duration<double>(Clock::now() - m_state->started).count();
  }
  // the fraction the current step ends at
  double end_of_step() const { return m_state->end; }

private:
  void report(double fraction, bool always) const
  {
    State& s = *m_state;
    fraction = (std::max)(fraction, s.reported);
    if(s.progress.is_none() || (!always && fraction <= s.reported))
      return;
    s.progress(s.stage, fraction);
    s.reported = fraction;
    s.last_call = Clock::now();
  }

  std::shared_ptr<State> m_state;
};

// Runs `work()` with the GIL released, and stops it on Ctrl-C: the
// library's loops call the check below every 20 ms or so on this thread
// (interruption.h); it takes the GIL, and when Python has a signal's
// exception (KeyboardInterrupt) asks the library to stop, which unwinds
// `work()` with Interrupted, turned back into the Python exception here.
// With a `checkpoint`, the same checks move its progress on; an exception of
// the progress callable stops the work the same way.
template <class Work>
auto without_gil(Work work, const Checkpoint* checkpoint = nullptr)
{
  std::unique_ptr<py::error_already_set> pending;
  const CAS3::Scoped_interruption_check check([&pending, checkpoint] {
    py::gil_scoped_acquire gil;
    if(PyErr_CheckSignals() != 0)
    {
      pending = std::make_unique<py::error_already_set>();
      return true;
    }
    if(checkpoint)
    {
      try { checkpoint->tick(); }
      catch(py::error_already_set& e)
      {
        pending = std::make_unique<py::error_already_set>(std::move(e));
        return true;
      }
    }
    return false;
  });
  try
  {
    auto result = [&] {
      py::gil_scoped_release release;
      return work();
    }();
    if(pending)  // asked to stop as the work ended
      throw py::error_already_set(*pending);
    return result;
  }
  catch(const CAS3::Interrupted&)
  {
    if(pending)
      throw py::error_already_set(*pending);
    throw;
  }
}

template <class T>
py::array_t<T> new_array(std::size_t n)
{
  return py::array_t<T>(std::vector<py::ssize_t>{py::ssize_t(n)});
}
py::array_t<double> new_triples(std::size_t n)
{
  return py::array_t<double>(std::vector<py::ssize_t>{py::ssize_t(n), 3});
}
void put_triple(double* p, std::size_t i, const Vector& v)
{
  p[3 * i] = v.x();
  p[3 * i + 1] = v.y();
  p[3 * i + 2] = v.z();
}

// A layer as a dict of numpy arrays: normal, H, K, k1, k2, d1, d2, radius of
// each value (a Point_curvature or a mesh's Vertex_curvature), and for
// points their source and distance.
template <class Value>
py::dict layer_arrays(const std::vector<Value>& values)
{
  constexpr bool of_points = std::is_same<Value, CAS3::Point_curvature<K> >::value;
  const std::size_t n = values.size();
  py::array_t<double> normal = new_triples(n), d1 = new_triples(n), d2 = new_triples(n);
  py::array_t<double> H = new_array<double>(n), Kg = new_array<double>(n), k1 = new_array<double>(n),
                      k2 = new_array<double>(n), radius = new_array<double>(n);
  double *pn = normal.mutable_data(), *p1 = d1.mutable_data(), *p2 = d2.mutable_data();
  double *pH = H.mutable_data(), *pK = Kg.mutable_data(), *pk1 = k1.mutable_data(), *pk2 = k2.mutable_data();
  double* pr = radius.mutable_data();
  py::array_t<double> H_sigma = new_array<double>(n), K_sigma = new_array<double>(n),
                      normal_sigma = new_array<double>(n), H_noise_sigma = new_array<double>(n);
  double *psH = H_sigma.mutable_data(), *psK = K_sigma.mutable_data(), *psn = normal_sigma.mutable_data();
  double* psHn = H_noise_sigma.mutable_data();
  for(std::size_t i = 0; i < n; ++i)
  {
    const Value& c = values[i];
    psH[i] = c.uncertainty.mean_curvature;
    psK[i] = c.uncertainty.gaussian_curvature;
    psn[i] = c.uncertainty.normal_degrees;
    psHn[i] = c.uncertainty.mean_curvature_noise;
    put_triple(pn, i, c.normal);
    put_triple(p1, i, c.principal.max_direction);
    put_triple(p2, i, c.principal.min_direction);
    if constexpr(of_points)
    {
      pH[i] = c.mean_curvature;
      pK[i] = c.gaussian_curvature;
    }
    else
    {
      pH[i] = c.mean_curvature();
      pK[i] = c.gaussian_curvature();
    }
    pk1[i] = c.principal.max_curvature;
    pk2[i] = c.principal.min_curvature;
    pr[i] = c.radius;
  }
  py::dict layer;
  layer["normal"] = normal;
  layer["H"] = H;
  layer["K"] = Kg;
  layer["k1"] = k1;
  layer["k2"] = k2;
  layer["d1"] = d1;
  layer["d2"] = d2;
  layer["radius"] = radius;
  layer["H_sigma"] = H_sigma;
  layer["K_sigma"] = K_sigma;
  layer["normal_sigma"] = normal_sigma;
  layer["H_noise_sigma"] = H_noise_sigma;
  if constexpr(of_points)
  {
    py::array_t<double> distance = new_array<double>(n);
    py::array_t<std::uint8_t> source = new_array<std::uint8_t>(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      distance.mutable_data()[i] = values[i].distance;
      source.mutable_data()[i] = std::uint8_t(values[i].source);
    }
    layer["source"] = source;
    layer["distance"] = distance;
  }
  return layer;
}

py::dict report_dict(const CAS3::Surface_report& r)
{
  py::dict d;
  d["faces"] = r.number_of_faces;
  d["vertices"] = r.number_of_vertices;
  d["parts"] = r.number_of_parts;
  d["closed_parts"] = r.number_of_closed_parts;
  d["points_off_surface"] = r.number_of_points_off_surface;
  d["fraction_of_points_on_surface"] = r.fraction_of_points_on_surface();
  d["sheets_with_inconsistent_normals"] = r.number_of_sheets_with_inconsistent_normals;
  d["normal_agreement"] = r.reference_normal_agreement;
  return d;
}

struct Job_options
{
  std::vector<CAS3::Scale> scales;
  std::vector<CAS3::Neighborhood> neighborhoods;
  CAS3::Curvature_estimator estimator;
  CAS3::Denoising denoising;
  unsigned int denoising_neighbors;
  CAS3::Surface_extraction extraction;
};

// The options as the program reads them (the same readers and messages,
// named after the Python keywords); bad ones raise ValueError.
Job_options read_job_options(const std::vector<std::string>& scales, const std::vector<std::string>& radii,
                             const std::vector<std::string>& rings, const std::string& estimator,
                             const std::string& denoise, const std::string& denoise_neighbors,
                             const std::string& extraction)
{
  try
  {
    Job_options o;
    if(scales.empty())
      throw cas3::Option_error("scales: no scale given");
    o.scales = cas3::parse_scales("scales", scales);
    for(const std::string& item : radii)
      o.neighborhoods.push_back(cas3::parse_radius_option("radii", item));
    for(const std::string& item : rings)
      o.neighborhoods.push_back(cas3::parse_rings_option("rings", item));
    if(o.neighborhoods.empty())
      throw cas3::Option_error("radii, rings: no neighborhood given");
    o.estimator = cas3::parse_estimator("estimator", estimator);
    o.denoising = cas3::parse_denoising("denoise", denoise);
    o.denoising_neighbors =
      denoise_neighbors.empty() ? 0u : cas3::parse_denoising_neighbors("denoise_neighbors", denoise_neighbors);
    o.extraction = cas3::parse_extraction("extraction", extraction);
    return o;
  }
  catch(const cas3::Option_error& e) { throw py::value_error(e.what()); }
}

// The time the steps of a job take, relative to each other, per point: the
// Delaunay triangulation, poles and conformal values with the input checks,
// the noise estimate and the smoothing (about half of it with the noisy
// scans that are smoothed); the advancing front with the first surface cut
// from it, a later surface; the curvature of a surface, its transfer to the
// points and the arrays, per neighborhood (the automatic one fits up to 22.6
// spacings). Measured on 100k to 300k point ellipsoids, clean and noisy, on
// two cores; a step's share of the bar follows its share of the time.
struct Step_costs
{
  static double shape(CAS3::Denoising denoising)
  {
    return denoising == CAS3::ALWAYS_DENOISE ? 1.6 : denoising == CAS3::NEVER_DENOISE ? 1.0 : 1.3;
  }
  static constexpr double front_and_surface = 1.1;
  static constexpr double surface = 0.2;
  static double curvature(const std::vector<CAS3::Neighborhood>& neighborhoods)
  {
    double cost = 0.1;
    for(const CAS3::Neighborhood& n : neighborhoods)
      cost += n.kind() == CAS3::Neighborhood::AUTOMATIC ? 1.2 : n.kind() == CAS3::Neighborhood::RINGS ? 0.3 : 0.35;
    return cost;
  }
  // seconds per point of a cost of 1 before any step was timed (two cores)
  static constexpr double seconds_per_point = 1.5e-5;
};

// (vertices, faces, point_index) of a surface mesh with "v:input_index"
py::tuple mesh_arrays(const Surface& mesh)
{
  const auto index = mesh.property_map<Surface::Vertex_index, std::size_t>("v:input_index").first;
  py::array_t<double> vertices = new_triples(mesh.number_of_vertices());
  py::array_t<std::int64_t> point_index = new_array<std::int64_t>(mesh.number_of_vertices());
  std::vector<std::int64_t> number(mesh.num_vertices(), -1);
  std::size_t next = 0;
  for(Surface::Vertex_index v : mesh.vertices())
  {
    put_triple(vertices.mutable_data(), next, mesh.point(v) - CGAL::ORIGIN);
    point_index.mutable_data()[next] = std::int64_t(index[v]);
    number[v] = std::int64_t(next++);
  }
  py::array_t<std::int64_t> faces(std::vector<py::ssize_t>{py::ssize_t(mesh.number_of_faces()), 3});
  std::size_t f_next = 0;
  for(Surface::Face_index f : mesh.faces())
  {
    int j = 0;
    for(Surface::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      faces.mutable_data()[3 * f_next + std::size_t(j++)] = number[v];
    ++f_next;
  }
  return py::make_tuple(vertices, faces, point_index);
}

// The arrays of mesh_arrays() with "orientation_group": each face's (see
// the named parameter face_orientation_group_map of extract_surface()).
py::dict oriented_surface_arrays(const Surface& mesh)
{
  const py::tuple arrays = mesh_arrays(mesh);
  const auto group = mesh.property_map<Surface::Face_index, std::size_t>("f:orientation_group").first;
  py::array_t<std::int64_t> groups = new_array<std::int64_t>(mesh.number_of_faces());
  std::size_t next = 0;
  for(Surface::Face_index f : mesh.faces())
    groups.mutable_data()[next++] = group[f] == std::size_t(-1) ? -1 : std::int64_t(group[f]);
  py::dict surface;
  surface["vertices"] = arrays[0];
  surface["faces"] = arrays[1];
  surface["point_index"] = arrays[2];
  surface["orientation_group"] = groups;
  return surface;
}

// The program's job (conformal_curvature.cpp) without its files, split at
// its shape: the analysis is built once (with the decisions of a larger run
// when given), then gives its closing values or, per scale, its surface and
// per neighborhood a layer, each layer's values turned into numpy arrays as
// soon as they are computed. A tiled run keeps one on its worker between
// the two (the automatic scale is reduced over all tiles in between).
class Job
{
public:
  // `scales`: the number of scales the job's result() will have, or 0 when
  // only its closing values will be asked for (the shares of the progress)
  Job(const Doubles& points_array, const std::optional<Doubles>& normals_array, const Job_options& o, int threads,
      std::optional<double> given_spacing, std::optional<double> given_noise,
      std::optional<double> given_noise_24, const Checkpoint& checkpoint, std::size_t scales)
    : m_options(o), m_threads(threads), m_checkpoint(checkpoint)
  {
    const std::vector<Point> points = to_triples<Point>(points_array, "points");
    std::vector<Vector> normals;
    if(normals_array)
    {
      normals = to_triples<Vector>(*normals_array, "normals");
      if(normals.size() != points.size())
        throw py::value_error("normals must be an (N, 3) array of one normal per point: " +
                              std::to_string(normals.size()) + " normals for " + std::to_string(points.size()) +
                              " points");
    }
    const Thread_cap cap(m_threads);
    m_shape_cost = Step_costs::shape(o.denoising);
    const double total = m_shape_cost + (scales == 0 ? Step_costs::front_and_surface : rest_cost(scales));
    without_gil([&] {
      checkpoint.step("conformal alpha shape", m_shape_cost / total,
                      double(points.size()) * Step_costs::seconds_per_point * m_shape_cost);
      const auto np = CAS3::parameters::reference_normals(std::cref(normals),
        CAS3::parameters::denoising(o.denoising, CAS3::parameters::surface_extraction(o.extraction)));
      auto analyze = [&](const auto& with_noise) {
        return o.denoising_neighbors > 0
          ? std::make_unique<Analysis>(points.begin(), points.end(),
                                       CAS3::parameters::denoising_neighbors(o.denoising_neighbors, with_noise))
          : std::make_unique<Analysis>(points.begin(), points.end(), with_noise);
      };
      // the decisions of a larger run (the Python layer gives both or neither); without its 24-neighbor
      // reading, the automatic denoising decision reads the noise alone
      m_analysis = given_spacing
        ? analyze(CAS3::parameters::noise_estimate(
            CAS3::Noise_estimate{*given_spacing, *given_noise, given_noise_24.value_or(*given_noise)}, np))
        : analyze(np);
      return 0;
    }, &checkpoint);
    m_seconds_per_cost = checkpoint.seconds_in_step() / m_shape_cost;
  }

  // Per input point, the closing value of the front (NaN off it): a tile's
  // share of the automatic scale of a tiled run.
  py::array_t<double> closing_values() const
  {
    const Thread_cap cap(m_threads);
    const std::vector<double> closing = without_gil([&] {
      m_checkpoint.step("front", 1.0, m_seconds_per_cost * Step_costs::front_and_surface);
      std::vector<double> values = analysis().closing_values();
      m_checkpoint.finish();
      return values;
    }, &m_checkpoint);
    py::array_t<double> values = new_array<double>(closing.size());
    std::copy(closing.begin(), closing.end(), values.mutable_data());
    return values;
  }

  // The layers of `scales` and the run's decisions, as `multiscale_curvatures`
  // returns them: the job's last call, as in the program the shape is freed
  // before the last scale's fits, then the rest of the analysis; with
  // `with_surfaces`, each scale's surface (oriented_surface_arrays(): a
  // tile's driver orients its pieces as one run's vote would).
  py::dict result(const std::vector<CAS3::Scale>& scales, const Checkpoint& checkpoint,
                  bool with_surfaces = false)
  {
    this->analysis();  // raises when the shape was released
    Analysis& analysis = *m_analysis;
    const Job_options& o = m_options;
    const Thread_cap cap(m_threads);
    // the shares of the steps, the shape's done
    const double total = m_shape_cost + rest_cost(scales.size());
    double done = m_shape_cost;
    auto step = [&](const std::string& stage, double cost) {
      done += cost;
      checkpoint.step(stage, done / total, m_seconds_per_cost * cost);
    };
    for(const CAS3::Neighborhood& n : o.neighborhoods)
      if(n.kind() == CAS3::Neighborhood::SPACINGS || n.kind() == CAS3::Neighborhood::AUTOMATIC)
        if(!(analysis.noise().spacing > 0))
          throw py::value_error(
            "multiscale_curvatures: radii in sample spacings ('auto', '4s') need the sample spacing, estimated "
            "from each point's 24 nearest neighbors, but it could not be estimated on these " +
            std::to_string(analysis.number_of_input_points()) +
            " points (at least 25 are needed, not all coincident or on a line); give the radii as lengths "
            "(radii=[0.1]) or rings (rings=[1]), or spacing= and noise=");
    py::list layers;
    py::list surfaces;
    without_gil([&] {
      for(const CAS3::Scale& scale : scales)
      {
        step("surface at scale " + cas3::scale_text(scale),
             &scale == &scales.front() ? Step_costs::front_and_surface : Step_costs::surface);
        const double a = analysis.scale_value(scale);
        Surface surface;
        const CAS3::Surface_report report = analysis.surface(a, surface);
        cas3::return_freed_memory();  // as the program does: the front's copy was freed mid-heap
        if(with_surfaces)
        {
          py::gil_scoped_acquire gil;
          surfaces.append(oriented_surface_arrays(surface));
        }
        step("curvature at scale " + cas3::scale_text(scale), Step_costs::curvature(o.neighborhoods));
        // each layer becomes its arrays as soon as it is made: the point
        // layers' values are never all held at once
        auto layer_done = [&](std::size_t r, std::vector<CAS3::Point_curvature<K> >&& values) {
          const std::string label = cas3::layer_label(scale, o.neighborhoods[r], scales.size() > 1);
          {
            py::gil_scoped_acquire gil;
            py::dict layer = layer_arrays(values);
            layer["name"] = label;
            layer["a"] = a;
            layer["description"] = cas3::layer_description(analysis, a, scale, o.neighborhoods[r], label);
            layer["surface"] = report_dict(report);
            layers.append(layer);
            checkpoint.tick();
          }
        };
        if(&scale == &scales.back())
          std::move(analysis).estimate_curvatures(surface, o.neighborhoods, o.estimator, layer_done);
        else
          analysis.estimate_curvatures(surface, o.neighborhoods, o.estimator, layer_done);
      }
      checkpoint.finish();
      return 0;
    }, &checkpoint);
    const std::size_t n = analysis.number_of_input_points();
    py::array_t<bool> outlier = new_array<bool>(n);
    for(std::size_t i = 0; i < n; ++i)
      outlier.mutable_data()[i] = analysis.is_outlier(i);
    const CAS3::Noise_estimate noise = analysis.noise();
    const CAS3::Denoising_plan denoising = analysis.denoising();
    py::dict result;
    result["layers"] = layers;
    if(with_surfaces)
      result["surfaces"] = surfaces;
    result["outlier"] = outlier;
    result["spacing"] = noise.spacing;
    result["noise"] = noise.noise;
    result["noise_24"] = noise.noise_24;
    result["calls_for_denoising"] = noise.calls_for_denoising();
    result["denoised"] = denoising.passes > 0;
    result["merged"] = analysis.number_of_merged_points();
    result["denoising_passes"] = denoising.passes;
    result["denoising_neighbors"] = denoising.neighbors;
    release();
    return result;
  }

  // Frees the shape, letting other threads run meanwhile (it is large).
  void release()
  {
    py::gil_scoped_release release;
    m_analysis.reset();
  }

private:
  // the cost of the steps after the shape, for `scales` scales
  double rest_cost(std::size_t scales) const
  {
    const double per_scale = Step_costs::surface + Step_costs::curvature(m_options.neighborhoods);
    return Step_costs::front_and_surface - Step_costs::surface + double((std::max)(scales, std::size_t(1))) * per_scale;
  }

  const Analysis& analysis() const
  {
    if(!m_analysis)
      throw py::value_error("this job's shape was released");
    return *m_analysis;
  }

  Job_options m_options;
  int m_threads;
  Checkpoint m_checkpoint;  // the progress of the shape and of closing_values()
  double m_shape_cost = 1, m_seconds_per_cost = 1;
  std::unique_ptr<Analysis> m_analysis;
};

// The program's job in one call.
py::dict multiscale_curvatures(const Doubles& points_array, const std::optional<Doubles>& normals_array,
                               const std::vector<std::string>& scales, const std::vector<std::string>& radii,
                               const std::vector<std::string>& rings, const std::string& estimator,
                               const std::string& denoise, const std::string& denoise_neighbors,
                               const std::string& extraction, int threads, py::object progress,
                               std::optional<double> given_spacing, std::optional<double> given_noise,
                               std::optional<double> given_noise_24)
{
  const Job_options o =
    read_job_options(scales, radii, rings, estimator, denoise, denoise_neighbors, extraction);
  const Checkpoint checkpoint(std::move(progress));
  Job job(points_array, normals_array, o, threads, given_spacing, given_noise, given_noise_24, checkpoint,
          o.scales.size());
  return job.result(o.scales, checkpoint);
}

// The layers of a result (a list of the dicts of its Layer objects) as the
// program holds them: floats, in the order of cas3::Layer::value_names().
std::vector<cas3::Layer> layers_from_python(const py::list& layers, std::size_t n, const std::string& what)
{
  std::vector<cas3::Layer> out;
  for(py::handle h : layers)
  {
    const py::dict d = py::reinterpret_borrow<py::dict>(h);
    cas3::Layer layer;
    layer.label = d["name"].cast<std::string>();
    layer.description = d["description"].cast<std::string>();
    layer.values.resize(n * cas3::Layer::number_of_values);
    layer.source.resize(n);
    // the columns in the file's order (cas3::Layer::value_names())
    const char* const triples[3] = {"normal", "d1", "d2"};
    const int triple_column[3] = {0, 7, 10};
    const char* const scalars[10] = {"H", "K", "k1", "k2", "radius", "distance", "H_sigma", "K_sigma",
                                     "normal_sigma", "H_noise_sigma"};
    const int scalar_column[10] = {3, 4, 5, 6, 13, 14, 15, 16, 17, 18};
    for(int t = 0; t < 3; ++t)
    {
      const Doubles a = d[triples[t]].cast<Doubles>();
      if(check_rows(a, triples[t]) != n)
        throw py::value_error(what + ": " + triples[t] + " has not one row per point");
      for(std::size_t i = 0; i < n; ++i)
        for(int j = 0; j < 3; ++j)
          layer.values[i * cas3::Layer::number_of_values + std::size_t(triple_column[t] + j)] =
            float(a.data()[3 * i + std::size_t(j)]);
    }
    for(int s = 0; s < 10; ++s)
    {
      if(s >= 6 && !d.contains(scalars[s]))  // layers without uncertainties (LAS output)
      {
        for(std::size_t i = 0; i < n; ++i)
          layer.values[i * cas3::Layer::number_of_values + std::size_t(scalar_column[s])] = std::nanf("");
        continue;
      }
      const Doubles a = d[scalars[s]].cast<Doubles>();
      if(std::size_t(a.size()) != n)
        throw py::value_error(what + ": " + scalars[s] + " has not one value per point");
      for(std::size_t i = 0; i < n; ++i)
        layer.values[i * cas3::Layer::number_of_values + std::size_t(scalar_column[s])] = float(a.data()[i]);
    }
    const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> source =
      d["source"].cast<py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> >();
    if(std::size_t(source.size()) != n)
      throw py::value_error(what + ": source has not one value per point");
    std::copy(source.data(), source.data() + n, layer.source.begin());
    out.push_back(std::move(layer));
  }
  return out;
}

std::vector<bool> outlier_flags(const py::array_t<bool>& outlier, std::size_t n, const std::string& what)
{
  if(std::size_t(outlier.size()) != n)
    throw py::value_error(what + ": one outlier flag per point");
  std::vector<bool> is_outlier(n);
  for(std::size_t i = 0; i < n; ++i)
    is_outlier[i] = outlier.at(py::ssize_t(i));
  return is_outlier;
}

// Writes the program's curvatures.ply from the arrays of a result: the same
// bytes, since the values are turned into floats as the program does.
void write_point_cloud(const std::string& path, const Doubles& points_array, const py::array_t<bool>& outlier,
                       const py::list& layers)
{
  const std::vector<Point> points = to_triples<Point>(points_array, "points");
  const std::vector<bool> is_outlier = outlier_flags(outlier, points.size(), "write_ply");
  const std::vector<cas3::Layer> out = layers_from_python(layers, points.size(), "write_ply");
  py::gil_scoped_release release;
  std::ofstream file(path, std::ios::binary);
  if(!file)
    throw std::runtime_error("write_ply: cannot open " + path);
  cas3::write_point_cloud(file, points, is_outlier, out);
  file.close();
  if(!file)
    throw std::runtime_error("write_ply: cannot write " + path);
}

// ---- LAS: the records' fields as numpy arrays, and back

// The fields of `records` as a dict of (N,) arrays, and their extra bytes
// (`stride` per record in `extra`) as extra_bytes, an (N, stride) array of
// uint8.
py::dict las_fields_dict(const std::vector<cas3::Las_record>& records, const std::vector<char>& extra,
                         std::size_t stride)
{
  const std::size_t n = records.size();
  py::array_t<std::uint8_t> extra_bytes(std::vector<py::ssize_t>{py::ssize_t(n), py::ssize_t(stride)});
  if(n * stride > 0)
    std::memcpy(extra_bytes.mutable_data(), extra.data(), n * stride);
  auto X = new_array<std::int32_t>(n), Y = new_array<std::int32_t>(n), Z = new_array<std::int32_t>(n);
  auto intensity = new_array<std::uint16_t>(n), point_source_id = new_array<std::uint16_t>(n);
  auto return_number = new_array<std::uint8_t>(n), number_of_returns = new_array<std::uint8_t>(n);
  auto classification = new_array<std::uint8_t>(n), user_data = new_array<std::uint8_t>(n);
  auto scanner_channel = new_array<std::uint8_t>(n), scan_direction = new_array<std::uint8_t>(n);
  auto edge = new_array<std::uint8_t>(n);
  auto synthetic = new_array<bool>(n), key_point = new_array<bool>(n), withheld = new_array<bool>(n),
       overlap = new_array<bool>(n);
  auto scan_angle = new_array<std::int16_t>(n);
  auto gps_time = new_array<double>(n);
  auto red = new_array<std::uint16_t>(n), green = new_array<std::uint16_t>(n), blue = new_array<std::uint16_t>(n),
       nir = new_array<std::uint16_t>(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const cas3::Las_record& r = records[i];
    const py::ssize_t k = py::ssize_t(i);
    X.mutable_at(k) = r.X;
    Y.mutable_at(k) = r.Y;
    Z.mutable_at(k) = r.Z;
    intensity.mutable_at(k) = r.intensity;
    return_number.mutable_at(k) = r.return_number;
    number_of_returns.mutable_at(k) = r.number_of_returns;
    classification.mutable_at(k) = r.classification;
    synthetic.mutable_at(k) = (r.flags & cas3::Las_record::SYNTHETIC) != 0;
    key_point.mutable_at(k) = (r.flags & cas3::Las_record::KEY_POINT) != 0;
    withheld.mutable_at(k) = (r.flags & cas3::Las_record::WITHHELD) != 0;
    overlap.mutable_at(k) = (r.flags & cas3::Las_record::OVERLAP) != 0;
    scanner_channel.mutable_at(k) = r.scanner_channel;
    scan_direction.mutable_at(k) = r.scan_direction;
    edge.mutable_at(k) = r.edge_of_flight_line;
    user_data.mutable_at(k) = r.user_data;
    scan_angle.mutable_at(k) = r.scan_angle;
    point_source_id.mutable_at(k) = r.point_source_id;
    gps_time.mutable_at(k) = r.gps_time;
    red.mutable_at(k) = r.red;
    green.mutable_at(k) = r.green;
    blue.mutable_at(k) = r.blue;
    nir.mutable_at(k) = r.nir;
  }
  py::dict d;
  d["X"] = X; d["Y"] = Y; d["Z"] = Z;
  d["intensity"] = intensity;
  d["return_number"] = return_number;
  d["number_of_returns"] = number_of_returns;
  d["classification"] = classification;
  d["synthetic"] = synthetic;
  d["key_point"] = key_point;
  d["withheld"] = withheld;
  d["overlap"] = overlap;
  d["scanner_channel"] = scanner_channel;
  d["scan_direction"] = scan_direction;
  d["edge_of_flight_line"] = edge;
  d["user_data"] = user_data;
  d["scan_angle"] = scan_angle;
  d["point_source_id"] = point_source_id;
  d["gps_time"] = gps_time;
  d["red"] = red; d["green"] = green; d["blue"] = blue; d["nir"] = nir;
  d["extra_bytes"] = extra_bytes;
  return d;
}

template <class T>
py::array_t<T, py::array::c_style | py::array::forcecast> field(const py::dict& fields, const char* name,
                                                                std::size_t n)
{
  if(!fields.contains(name))
    throw py::value_error(std::string("write_las: the LAS fields have no '") + name + "'");
  auto a = fields[name].cast<py::array_t<T, py::array::c_style | py::array::forcecast> >();
  if(a.ndim() != 1 || std::size_t(a.size()) != n)
    throw py::value_error(std::string("write_las: the LAS field '") + name + "' has not one value per point");
  return a;
}

// The records of the fields of las_fields_dict().
std::vector<cas3::Las_record> las_records_of(const py::dict& fields, std::size_t n)
{
  std::vector<cas3::Las_record> records(n);
  auto X = field<std::int32_t>(fields, "X", n), Y = field<std::int32_t>(fields, "Y", n),
       Z = field<std::int32_t>(fields, "Z", n);
  auto intensity = field<std::uint16_t>(fields, "intensity", n);
  auto return_number = field<std::uint8_t>(fields, "return_number", n);
  auto number_of_returns = field<std::uint8_t>(fields, "number_of_returns", n);
  auto classification = field<std::uint8_t>(fields, "classification", n);
  auto synthetic = field<bool>(fields, "synthetic", n), key_point = field<bool>(fields, "key_point", n),
       withheld = field<bool>(fields, "withheld", n), overlap = field<bool>(fields, "overlap", n);
  auto scanner_channel = field<std::uint8_t>(fields, "scanner_channel", n);
  auto scan_direction = field<std::uint8_t>(fields, "scan_direction", n);
  auto edge = field<std::uint8_t>(fields, "edge_of_flight_line", n);
  auto user_data = field<std::uint8_t>(fields, "user_data", n);
  auto scan_angle = field<std::int16_t>(fields, "scan_angle", n);
  auto point_source_id = field<std::uint16_t>(fields, "point_source_id", n);
  auto gps_time = field<double>(fields, "gps_time", n);
  auto red = field<std::uint16_t>(fields, "red", n), green = field<std::uint16_t>(fields, "green", n),
       blue = field<std::uint16_t>(fields, "blue", n), nir = field<std::uint16_t>(fields, "nir", n);
  for(std::size_t i = 0; i < n; ++i)
  {
    cas3::Las_record& r = records[i];
    r.X = X.data()[i];
    r.Y = Y.data()[i];
    r.Z = Z.data()[i];
    r.intensity = intensity.data()[i];
    r.return_number = return_number.data()[i];
    r.number_of_returns = number_of_returns.data()[i];
    r.classification = classification.data()[i];
    r.flags = std::uint8_t((synthetic.data()[i] ? 1 : 0) | (key_point.data()[i] ? 2 : 0) | (withheld.data()[i] ? 4 : 0)
                           | (overlap.data()[i] ? 8 : 0));
    r.scanner_channel = scanner_channel.data()[i];
    r.scan_direction = scan_direction.data()[i];
    r.edge_of_flight_line = edge.data()[i];
    r.user_data = user_data.data()[i];
    r.scan_angle = scan_angle.data()[i];
    r.point_source_id = point_source_id.data()[i];
    r.gps_time = gps_time.data()[i];
    r.red = red.data()[i];
    r.green = green.data()[i];
    r.blue = blue.data()[i];
    r.nir = nir.data()[i];
  }
  return records;
}

// The extra bytes of las_fields_dict(), `stride` per record, for `n` records.
std::vector<char> las_extra_bytes_of(const py::dict& fields, std::size_t n, std::size_t stride)
{
  if(!fields.contains("extra_bytes"))
    throw py::value_error("write_las: the LAS fields have no 'extra_bytes'");
  auto a = fields["extra_bytes"].cast<py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> >();
  if(a.ndim() != 2 || std::size_t(a.shape(0)) != n || std::size_t(a.shape(1)) != stride)
    throw py::value_error("write_las: the LAS field 'extra_bytes' is not " + std::to_string(stride)
                          + " bytes per point, as the input's header says");
  const char* p = reinterpret_cast<const char*>(a.data());
  return std::vector<char>(p, p + n * stride);
}

cas3::Las_filter las_filter_of(const std::vector<std::string>& classes, bool drop_withheld, const std::string& returns)
{
  cas3::Las_filter filter;
  try
  {
    filter.classes = cas3::parse_las_classes("classes", classes);
    filter.returns = cas3::parse_las_returns("returns", returns);
  }
  catch(const cas3::Option_error& e) { throw py::value_error(e.what()); }
  filter.drop_withheld = drop_withheld;
  return filter;
}

// A text field of a LAS file as a str, a character per byte (Latin-1), and back.
py::object text_of(const std::string& bytes)
{
  return py::bytes(bytes).attr("decode")("latin-1");
}
std::string bytes_of_text(const py::handle& text)
{
  return text.attr("encode")("latin-1").cast<std::string>();
}

py::dict las_header_dict(const cas3::Las_header& h)
{
  py::dict d;
  d["version"] = std::to_string(h.version_major) + "." + std::to_string(h.version_minor);
  d["point_format"] = h.point_format;
  d["number_of_points"] = h.number_of_points;
  d["scale"] = py::make_tuple(h.scale[0], h.scale[1], h.scale[2]);
  d["offset"] = py::make_tuple(h.offset[0], h.offset[1], h.offset[2]);
  d["rgb"] = cas3::las_detail::has_rgb(h.point_format);
  d["file_source_id"] = h.file_source_id;
  d["global_encoding"] = h.global_encoding;
  d["creation_day"] = h.creation_day;
  d["creation_year"] = h.creation_year;
  d["nir"] = cas3::las_detail::has_nir(h.point_format);
  d["extra_bytes_length"] = h.extra_bytes;
  py::list extra;
  for(const cas3::Las_extra_bytes_field& f : h.extra_fields)
  {
    py::dict e;
    e["name"] = text_of(f.name);
    e["data_type"] = int(std::uint8_t(f.descriptor[2]));
    e["offset"] = f.offset;
    e["size"] = f.size;
    e["descriptor"] = py::bytes(f.descriptor);
    extra.append(e);
  }
  d["extra_bytes"] = extra;
  py::list crs;
  for(const cas3::Las_vlr& v : h.crs)
  {
    py::dict r;
    r["user_id"] = text_of(v.user_id);
    r["record_id"] = v.record_id;
    r["description"] = text_of(v.description);
    r["data"] = py::bytes(v.data);
    crs.append(r);
  }
  d["crs"] = crs;
  return d;
}

py::dict counts_dict(const cas3::Las_filter_counts& c)
{
  py::dict d;
  d["read"] = c.read;
  d["classes"] = c.classes;
  d["withheld"] = c.withheld;
  d["returns"] = c.returns;
  return d;
}

py::array_t<double> points_array(const std::vector<Point>& points)
{
  py::array_t<double> out = new_triples(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    put_triple(out.mutable_data(), i, points[i] - CGAL::ORIGIN);
  return out;
}

// The program's reader: .xyz, .pwn, .ply, .off, .obj, .las (with the
// filters). A dict: points, normals (or None), and for LAS las (its
// header), fields (las_fields_dict()), counts and summary.
py::dict read_point_cloud(const std::string& path, const std::vector<std::string>& classes, bool drop_withheld,
                          const std::string& returns)
{
  const cas3::Las_filter filter = las_filter_of(classes, drop_withheld, returns);
  cas3::Point_cloud cloud;
  {
    py::gil_scoped_release release;
    try { cloud = cas3::read_point_cloud(path, filter); }
    catch(const cas3::Read_error& e) { throw std::invalid_argument(e.what()); }
  }
  if(filter.active() && !cloud.las.present)
    throw py::value_error(path + ": classes, drop_withheld and returns filter LAS input (.las)");
  py::dict d;
  d["points"] = points_array(cloud.points);
  if(cloud.normals.empty())
    d["normals"] = py::none();
  else
  {
    py::array_t<double> normals = new_triples(cloud.normals.size());
    for(std::size_t i = 0; i < cloud.normals.size(); ++i)
      put_triple(normals.mutable_data(), i, cloud.normals[i]);
    d["normals"] = normals;
  }
  if(cloud.las.present)
  {
    d["las"] = las_header_dict(cloud.las.header);
    d["fields"] = las_fields_dict(cloud.las.records, cloud.las.extra_bytes, cloud.las.header.extra_bytes);
    d["counts"] = counts_dict(cloud.las.counts);
    d["summary"] = cas3::las_input_summary(path, cloud.las.header, filter, cloud.las.counts);
  }
  return d;
}

// The records first to first + count - 1 of the LAS file `path` that the
// filters keep, read without the rest: a dict of points, fields (with
// `with_fields`, else None), counts (of this range) and las (the header).
py::dict read_las_chunk(const std::string& path, std::uint64_t first, std::uint64_t count,
                        const std::vector<std::string>& classes, bool drop_withheld, const std::string& returns,
                        bool with_fields)
{
  const cas3::Las_filter filter = las_filter_of(classes, drop_withheld, returns);
  const std::vector<bool> class_kept = cas3::las_classes_kept(filter);
  cas3::Las_filter_counts counts;
  std::vector<cas3::Las_record> records, kept;
  std::vector<char> extra, kept_extra;
  std::vector<Point> points;
  cas3::Las_header header;
  {
    py::gil_scoped_release release;
    try
    {
      cas3::Las_file file(path);
      header = file.header();
      file.read(first, count, records, &extra);
      const std::size_t stride = header.extra_bytes;
      for(std::size_t i = 0; i < records.size(); ++i)
      {
        if(!cas3::keep_las_record(records[i], filter, class_kept, counts))
          continue;
        const std::array<double, 3> p = file.position(records[i]);
        if(!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
          throw cas3::Read_error(path + ": point " + std::to_string(first + i) + ": coordinate is NaN or infinite");
        points.emplace_back(p[0], p[1], p[2]);
        if(!with_fields)
          continue;
        kept.push_back(records[i]);
        kept_extra.insert(kept_extra.end(), extra.begin() + std::ptrdiff_t(i * stride),
                          extra.begin() + std::ptrdiff_t((i + 1) * stride));
      }
    }
    catch(const cas3::Read_error& e) { throw std::invalid_argument(e.what()); }
  }
  py::dict d;
  d["points"] = points_array(points);
  d["fields"] = with_fields ? py::object(las_fields_dict(kept, kept_extra, header.extra_bytes))
                            : py::object(py::none());
  d["counts"] = counts_dict(counts);
  d["las"] = las_header_dict(header);
  return d;
}

// What write_las and the tiles' LAS writer share: the output header of
// `info` and the layers' labels. `info` is the header dict of a LAS input
// (las_header_dict(): what carry_las_input() keeps of it), or holds the
// scale, offset and rgb of other points.
cas3::Las_output_header las_output_header(const py::dict& info, const std::vector<std::string>& labels)
{
  cas3::Las_output_header h;
  try { h.extra = cas3::las_extra_fields(labels); }
  catch(const std::invalid_argument& e) { throw py::value_error(e.what()); }
  const auto scale = info["scale"].cast<std::vector<double> >(), offset = info["offset"].cast<std::vector<double> >();
  if(scale.size() != 3 || offset.size() != 3)
    throw py::value_error("write_las: scale and offset have three values");
  for(int k = 0; k < 3; ++k)
  {
    if(!std::isfinite(scale[std::size_t(k)]) || scale[std::size_t(k)] == 0 || !std::isfinite(offset[std::size_t(k)]))
      throw py::value_error("write_las: a scale that is not finite and nonzero, or an offset that is not finite");
    h.scale[k] = scale[std::size_t(k)];
    h.offset[k] = offset[std::size_t(k)];
  }
  if(!info.contains("point_format"))
  {
    h.rgb = info["rgb"].cast<bool>();
    return h;
  }
  cas3::Las_header in;
  in.point_format = info["point_format"].cast<int>();
  if(in.point_format < 0 || in.point_format > 10)
    throw py::value_error("write_las: the point format of a LAS input is 0 to 10");
  std::copy(h.scale, h.scale + 3, in.scale);
  std::copy(h.offset, h.offset + 3, in.offset);
  in.file_source_id = info["file_source_id"].cast<std::uint16_t>();
  in.global_encoding = info["global_encoding"].cast<std::uint16_t>();
  in.creation_day = info["creation_day"].cast<std::uint16_t>();
  in.creation_year = info["creation_year"].cast<std::uint16_t>();
  in.extra_bytes = info["extra_bytes_length"].cast<std::size_t>();
  std::string descriptors;
  for(const py::handle field : info["extra_bytes"].cast<py::list>())
    descriptors += field["descriptor"].cast<std::string>();
  for(const py::handle record : info["crs"].cast<py::list>())
  {
    cas3::Las_vlr v;
    v.user_id = bytes_of_text(record["user_id"]);
    v.record_id = record["record_id"].cast<std::uint16_t>();
    v.description = bytes_of_text(record["description"]);
    v.data = record["data"].cast<std::string>();
    in.crs.push_back(v);
  }
  try
  {
    in.extra_fields = cas3::las_detail::extra_bytes_fields(descriptors, in.extra_bytes, "write_las");
    cas3::carry_las_input(in, h);
  }
  catch(const std::exception& e) { throw py::value_error(e.what()); }
  return h;
}

// The scale and offset of points that do not come from a LAS file, from
// their bounds: ((sx, sy, sz), (ox, oy, oz)).
py::tuple las_scale(const std::vector<double>& low, const std::vector<double>& high)
{
  if(low.size() != 3 || high.size() != 3)
    throw py::value_error("las_scale: three lows and three highs");
  cas3::Las_output_header h;
  try { cas3::choose_las_scale(low.data(), high.data(), h); }
  catch(const std::invalid_argument& e) { throw py::value_error(e.what()); }
  return py::make_tuple(py::make_tuple(h.scale[0], h.scale[1], h.scale[2]),
                        py::make_tuple(h.offset[0], h.offset[1], h.offset[2]));
}

// The point records of a LAS 1.4 file (format 6, 7 or 8, the input's extra
// bytes and those of the layers) for the points, their outlier flags and
// the layers: the LAS input's fields when `fields` is a dict
// (las_fields_dict(), with `info` its header's dict), else the
// points written with the scale and offset of `info`. Returns (bytes,
// stats) where stats holds the records' smallest and largest scaled
// integers (min, max) and their counts by return (by_return), for
// las_header().
py::tuple las_records(const Doubles& points_array_in, const py::array_t<bool>& outlier, const py::list& layers,
                      const py::object& fields, const py::dict& info)
{
  const std::vector<Point> points = to_triples<Point>(points_array_in, "points");
  const std::size_t n = points.size();
  const std::vector<bool> is_outlier = outlier_flags(outlier, n, "write_las");
  const std::vector<cas3::Layer> values = layers_from_python(layers, n, "write_las");
  std::vector<std::string> labels;
  for(const cas3::Layer& layer : values)
    labels.push_back(layer.label);
  cas3::Las_output_header h = las_output_header(info, labels);
  std::vector<cas3::Las_record> records;
  std::vector<char> extra;
  const std::size_t stride = info.contains("extra_bytes_length") ? info["extra_bytes_length"].cast<std::size_t>() : 0;
  if(!fields.is_none())
  {
    records = las_records_of(fields.cast<py::dict>(), n);
    if(!h.carried.empty())
      extra = las_extra_bytes_of(fields.cast<py::dict>(), n, stride);
  }
  else if(!h.carried.empty())
    throw py::value_error("write_las: the extra bytes of a LAS input need its fields");
  else
  {
    records.resize(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      const double xyz[3] = {points[i].x(), points[i].y(), points[i].z()};
      for(int k = 0; k < 3; ++k)
        if(!(std::abs((xyz[k] - h.offset[k]) / h.scale[k]) < 2147483647.0))
          throw py::value_error("write_las: point " + std::to_string(i) + " is beyond the range of the scale and offset");
      cas3::quantize_las(h, xyz, records[i]);
      records[i].return_number = records[i].number_of_returns = 1;
    }
  }
  std::ostringstream out;
  {
    py::gil_scoped_release release;
    cas3::write_las_point_records(
      out, n, h, [&](std::size_t i) { return records[i]; }, [&](std::size_t i) { return extra.data() + i * stride; },
      is_outlier, values);
  }
  std::int64_t low[3] = {INT32_MAX, INT32_MAX, INT32_MAX}, high[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
  std::vector<std::uint64_t> by_return(15, 0);
  for(const cas3::Las_record& r : records)
  {
    const std::int32_t xyz[3] = {r.X, r.Y, r.Z};
    for(int k = 0; k < 3; ++k)
    {
      low[k] = std::min<std::int64_t>(low[k], xyz[k]);
      high[k] = std::max<std::int64_t>(high[k], xyz[k]);
    }
    if(r.return_number >= 1 && r.return_number <= 15)
      ++by_return[r.return_number - 1u];
  }
  py::dict stats;
  stats["min"] = py::make_tuple(low[0], low[1], low[2]);
  stats["max"] = py::make_tuple(high[0], high[1], high[2]);
  stats["by_return"] = by_return;
  return py::make_tuple(py::bytes(out.str()), stats);
}

// The bytes before and after the point records of a LAS 1.4 file of
// `count` records of las_records() (info, labels), with the merged stats of
// its chunks: (the header and VLRs, the EVLRs).
py::tuple las_header(const py::dict& info, const std::vector<std::string>& labels, std::uint64_t count,
                     const std::vector<std::int64_t>& low, const std::vector<std::int64_t>& high,
                     const std::vector<std::uint64_t>& by_return)
{
  cas3::Las_output_header h = las_output_header(info, labels);
  if(low.size() != 3 || high.size() != 3 || by_return.size() != 15)
    throw py::value_error("las_header: three lows, three highs, 15 counts by return");
  h.number_of_points = count;
  for(int k = 0; k < 3; ++k)
  {
    h.min[k] = count == 0 ? 0 : double(low[std::size_t(k)]) * h.scale[k] + h.offset[k];
    h.max[k] = count == 0 ? 0 : double(high[std::size_t(k)]) * h.scale[k] + h.offset[k];
    if(h.scale[k] < 0)
      std::swap(h.min[k], h.max[k]);
  }
  std::copy(by_return.begin(), by_return.end(), h.points_by_return);
  return py::make_tuple(py::bytes(cas3::las_header_bytes(h)), py::bytes(cas3::las_evlr_bytes(h)));
}

CAS3::Surface_extraction extraction_named(const std::string& name)
{
  try { return cas3::parse_extraction("extraction", name); }
  catch(const cas3::Option_error& e) { throw py::value_error(e.what()); }
}

// A Conformal_alpha_shape_3 of the caller's points, in their coordinates.
class Shape_handle
{
public:
  Shape_handle(const Doubles& points_array, const std::optional<Doubles>& local_scales)
  {
    const std::vector<Point> points = to_triples<Point>(points_array, "points");
    std::vector<double> scales;
    if(local_scales)
    {
      if(local_scales->ndim() != 1 || std::size_t(local_scales->shape(0)) != points.size())
        throw py::value_error("local_scales must be an (N,) array, one value per point");
      scales.assign(local_scales->data(), local_scales->data() + points.size());
    }
    m_shape = std::make_unique<Shape>();
    without_gil([&] {
      return local_scales ? m_shape->make_conformal_alpha_shape(points.begin(), points.end(),
                                                                CAS3::parameters::local_feature_sizes(scales))
                          : m_shape->make_conformal_alpha_shape(points.begin(), points.end());
    });
  }

  std::size_t number_of_input_points() const { return m_shape->number_of_input_points(); }
  int dimension() const { return m_shape->dimension(); }

  // per input point, the local feature size of its vertex
  py::array_t<double> local_feature_sizes() const
  {
    const std::size_t n = m_shape->number_of_input_points();
    py::array_t<double> values = new_array<double>(n);
    for(std::size_t i = 0; i < n; ++i)
      values.mutable_data()[i] = m_shape->local_feature_size(m_shape->input_vertex(i));
    return values;
  }

  py::array_t<double> spectrum() const
  {
    py::array_t<double> values = new_array<double>(m_shape->number_of_alphas());
    std::copy(m_shape->alpha_begin(), m_shape->alpha_end(), values.mutable_data());
    return values;
  }
  double alpha_at_quantile(double q) const { return m_shape->alpha_at_quantile(q); }

  double suggest_scale(const std::string& extraction, std::optional<double> coverage) const
  {
    const CAS3::Surface_extraction method = extraction_named(extraction);
    return without_gil([&] {
      return coverage ? CAS3::suggest_scale(*m_shape, CAS3::parameters::coverage(
                                                        *coverage, CAS3::parameters::surface_extraction(method)))
                      : CAS3::suggest_scale(*m_shape, CAS3::parameters::surface_extraction(method));
    });
  }

  py::dict classify_facets(double a) const
  {
    if(!(a >= 0))
      throw py::value_error("classify_facets: the scale a must be >= 0");
    std::size_t count[4] = {0, 0, 0, 0};
    for(auto f : m_shape->finite_facets())
      ++count[int(m_shape->classify(f, a))];
    py::dict d;
    d["exterior"] = count[Shape::EXTERIOR];
    d["singular"] = count[Shape::SINGULAR];
    d["regular"] = count[Shape::REGULAR];
    d["interior"] = count[Shape::INTERIOR];
    return d;
  }

  py::tuple surface(std::optional<double> a, const std::string& extraction) const
  {
    if(a && !(*a >= 0))
      throw py::value_error("surface: the scale a must be >= 0 (or None for the automatic scale), got " +
                            std::to_string(*a));
    const CAS3::Surface_extraction method = extraction_named(extraction);
    Surface mesh;
    without_gil([&] {
      const double scale = a ? *a : CAS3::suggest_scale(*m_shape, CAS3::parameters::surface_extraction(method));
      auto index = mesh.add_property_map<Surface::Vertex_index, std::size_t>("v:input_index").first;
      return CAS3::extract_surface(*m_shape, scale, mesh, CAS3::parameters::vertex_input_index_map(
                                                            index, CAS3::parameters::surface_extraction(method)));
    });
    return mesh_arrays(mesh);
  }

private:
  std::unique_ptr<Shape> m_shape;
};

// estimate_vertex_curvatures() on the triangle mesh (vertices, faces).
py::dict vertex_curvatures(const Doubles& vertices_array,
                           const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& faces_array,
                           std::optional<int> rings, std::optional<double> radius, const std::string& estimator)
{
  const std::vector<Point> vertices = to_triples<Point>(vertices_array, "vertices");
  if(faces_array.ndim() != 2 || faces_array.shape(1) != 3)
    throw py::value_error("faces must be an (F, 3) array of vertex indices");
  if(rings && radius)
    throw py::value_error("vertex_curvatures: give rings or radius, not both");
  CAS3::Curvature_estimator method;
  try { method = cas3::parse_estimator("estimator", estimator); }
  catch(const cas3::Option_error& e) { throw py::value_error(e.what()); }
  const CAS3::Neighborhood neighborhood = radius ? CAS3::Neighborhood::radius(*radius)
                                                 : CAS3::Neighborhood::rings(rings ? *rings : 1);
  Surface mesh;
  for(const Point& p : vertices)
    mesh.add_vertex(p);
  const std::int64_t* f = faces_array.data();
  for(py::ssize_t i = 0; i < faces_array.shape(0); ++i, f += 3)
  {
    for(int j = 0; j < 3; ++j)
      if(f[j] < 0 || std::size_t(f[j]) >= vertices.size())
        throw py::value_error("faces: face " + std::to_string(i) + " names vertex " + std::to_string(f[j]) +
                              ", not in [0, " + std::to_string(vertices.size()) + ")");
    if(f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
      throw py::value_error("faces: face " + std::to_string(i) + " repeats a vertex");
    if(mesh.add_face(Surface::Vertex_index(std::uint32_t(f[0])), Surface::Vertex_index(std::uint32_t(f[1])),
                     Surface::Vertex_index(std::uint32_t(f[2]))) == Surface::null_face())
      throw py::value_error("faces: face " + std::to_string(i) +
                            " cannot be added to an oriented 2-manifold with the faces before it");
  }
  const std::vector<CAS3::Vertex_curvature<K> > values = without_gil([&] {
    return CAS3::estimate_vertex_curvatures<CGAL::Parallel_if_available_tag>(
      mesh, std::vector<CAS3::Neighborhood>{neighborhood}, CAS3::parameters::estimator(method)).front();
  });
  return layer_arrays(values);
}

// The isolated far outliers of the points, by the rule of the pipeline's
// input hygiene (the manual, "Input Rules"), and the later copies of the
// points kept (equal to an earlier point): a tiled run applies it to each
// tile with its halo before its global noise estimate.
py::tuple input_outliers(const Doubles& points_array)
{
  const std::vector<Point> points = to_triples<Point>(points_array, "points");
  CAS3::internal::Normalized_input<K> input;
  without_gil([&] {
    input = CAS3::internal::normalize_input<K>(points);
    return 0;
  });
  py::array_t<bool> outlier = new_array<bool>(points.size()), copy = new_array<bool>(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    outlier.mutable_data()[i] = input.is_outlier[i];
    copy.mutable_data()[i] = false;
  }
  for(const auto& c : input.copies)
    copy.mutable_data()[c.first] = true;
  return py::make_tuple(outlier, copy);
}

// The rows of `points` among the `k` nearest of each of `rows` (itself
// included, ties at the k-th distance included), increasing: what the fits
// of the noise estimate at those rows read.
py::array_t<std::int64_t> nearest_rows(const Doubles& points_array, const py::array_t<std::int64_t>& rows_array,
                                       unsigned int k)
{
  const std::vector<Point> points = to_triples<Point>(points_array, "points");
  const std::vector<std::int64_t> rows(rows_array.data(), rows_array.data() + rows_array.size());
  for(std::int64_t r : rows)
    if(r < 0 || std::size_t(r) >= points.size())
      throw py::value_error("nearest_rows: row " + std::to_string(r) + " is not a row of the points");
  std::vector<std::int64_t> found;
  without_gil([&] {
    typedef CGAL::Search_traits_3<K> Base_traits;
    typedef CGAL::Search_traits_adapter<std::size_t, CGAL::Pointer_property_map<Point>::const_type, Base_traits> Traits;
    typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
    const auto point_map = CGAL::make_property_map(points);
    std::vector<std::size_t> ids(points.size());
    std::iota(ids.begin(), ids.end(), std::size_t(0));
    typename Search::Tree tree(ids.begin(), ids.end(), typename Search::Tree::Splitter(), Traits(point_map));
    const typename Search::Distance distance(point_map);
    std::vector<char> taken(points.size(), 0);
    for(std::int64_t r : rows)
    {
      // past the k-th distance by one more than the ties seen so far, until no tie is left out
      for(unsigned int more = 1;; more *= 2)
      {
        std::vector<std::pair<std::size_t, double> > hits;
        for(const auto& hit : Search(tree, points[std::size_t(r)], k + more, 0, true, distance))
          hits.emplace_back(hit.first, hit.second);
        const double limit = hits.size() >= k ? hits[k - 1].second * (1 + 1e-9) : std::numeric_limits<double>::infinity();
        if(hits.size() < k + more || hits.back().second > limit)
        {
          for(const auto& hit : hits)
            if(hit.second <= limit)
              taken[hit.first] = 1;
          break;
        }
      }
    }
    for(std::size_t i = 0; i < points.size(); ++i)
      if(taken[i])
        found.push_back(std::int64_t(i));
    return 0;
  });
  py::array_t<std::int64_t> out = new_array<std::int64_t>(found.size());
  std::copy(found.begin(), found.end(), out.mutable_data());
  return out;
}

py::dict estimate_noise(const Doubles& points_array)
{
  const std::vector<Point> points = to_triples<Point>(points_array, "points");
  const CAS3::Noise_estimate e = without_gil([&] { return CAS3::estimate_noise(points); });
  py::dict d;
  d["noise"] = e.noise;
  d["noise_24"] = e.noise_24;
  d["spacing"] = e.spacing;
  d["calls_for_denoising"] = e.calls_for_denoising();
  return d;
}

py::array_t<double> denoise(const Doubles& points_array, std::optional<int> neighbors)
{
  std::vector<Point> points = to_triples<Point>(points_array, "points");
  if(neighbors && *neighbors < 7)
    throw py::value_error("denoise: neighbors must be >= 7, got " + std::to_string(*neighbors));
  without_gil([&] {
    const CAS3::Noise_estimate noise = CAS3::estimate_noise(points);
    if(!(noise.spacing > 0))
      throw std::invalid_argument("denoise: the noise and the sample spacing, estimated from each point's 24 nearest "
                                  "neighbors, could not be estimated on these " + std::to_string(points.size()) +
                                  " points (at least 25 are needed, not all coincident or on a line)");
    const CAS3::Denoising_plan plan =
      CAS3::denoising_plan(noise, CAS3::ALWAYS_DENOISE, neighbors ? unsigned(*neighbors) : 0u);
    CAS3::denoise(points, plan);
    return plan.passes;
  });
  py::array_t<double> out = new_triples(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    put_triple(out.mutable_data(), i, points[i] - CGAL::ORIGIN);
  return out;
}


// Region matching (region_descriptors.h, match_regions.h): numpy in and out;
// the Python half (matching.py) checks the arguments and makes the classes.

// What region_descriptors() reads of a point's curvature in a layer.
struct Layer_value
{
  struct
  {
    double max_curvature, min_curvature;
  } principal;
  double radius;
};

typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Indices;
typedef std::array<double, 3> Xyz;

std::vector<Xyz> to_xyz(const Doubles& a, const char* what)
{
  const std::size_t n = check_rows(a, what);
  std::vector<Xyz> out(n);
  std::copy(a.data(), a.data() + 3 * n, out.front().data());
  return out;
}

py::array_t<std::int64_t> index_array(const std::vector<std::size_t>& values)
{
  py::array_t<std::int64_t> out = new_array<std::int64_t>(values.size());
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

py::array_t<std::int64_t> farthest_point_sample(const Doubles& points_array, std::size_t n, std::size_t first)
{
  const std::vector<Point> points = to_triples<Point>(points_array, "points");
  return index_array(without_gil([&] {
    return CAS3::farthest_point_sample(points, n, CAS3::parameters::first_point_index(first));
  }));
}

// The descriptors of `centers`: (descriptors (M, D), histogram bins, weights, kinds).
py::tuple region_descriptors(const Doubles& points_array, const Doubles& k1, const Doubles& k2, const Doubles& radius,
                             const Indices& centers_array, const std::optional<Doubles>& normals_array,
                             const std::optional<Doubles>& center_normals_array, const std::vector<double>& rings,
                             const std::vector<double>& ring_weights, int shape_bins, int curvedness_bins,
                             double curvedness_range, int geometry_bins, double dense_radius, std::size_t thinning,
                             int threads)
{
  const std::vector<Point> points = to_triples<Point>(points_array, "points");
  const std::size_t n = points.size();
  if(k1.ndim() != 2 || k2.ndim() != 2 || radius.ndim() != 2 || k1.shape(0) != k2.shape(0)
     || k1.shape(0) != radius.shape(0) || k1.shape(1) != k2.shape(1) || k1.shape(1) != radius.shape(1))
    throw py::value_error("region_descriptors: k1, k2 and radius must be (layers, N) arrays of one shape");
  std::vector<std::vector<Layer_value> > layers(std::size_t(k1.shape(0)));
  for(std::size_t l = 0; l < layers.size(); ++l)
    for(std::size_t i = 0; i < std::size_t(k1.shape(1)); ++i)
      layers[l].push_back({{k1.at(l, i), k2.at(l, i)}, radius.at(l, i)});
  const std::vector<std::int64_t> centers(centers_array.data(), centers_array.data() + centers_array.size());
  const auto options = CAS3::parameters::ring_radii(rings, CAS3::parameters::ring_weights(ring_weights,
    CAS3::parameters::shape_index_bins(shape_bins, CAS3::parameters::curvedness_bins(curvedness_bins,
    CAS3::parameters::curvedness_range(curvedness_range, CAS3::parameters::geometry_bins(geometry_bins,
    CAS3::parameters::dense_radius(dense_radius, CAS3::parameters::thinning(thinning))))))));
  const Thread_cap cap(threads);
  CAS3::Region_descriptors r;
  if(normals_array)
  {
    const std::vector<Vector> normals = to_triples<Vector>(*normals_array, "normals");
    const std::vector<Vector> center_normals =
      center_normals_array ? to_triples<Vector>(*center_normals_array, "center_normals") : normals;
    if(normals.size() != n || center_normals.size() != n)
      throw py::value_error("region_descriptors: " + std::to_string(n) + " points but "
                            + std::to_string((std::min)(normals.size(), center_normals.size())) + " normals");
    typedef std::tuple<Point, Vector, Vector> Oriented;
    std::vector<Oriented> oriented;
    for(std::size_t i = 0; i < n; ++i)
      oriented.emplace_back(points[i], normals[i], center_normals[i]);
    r = without_gil([&] {
      return CAS3::region_descriptors<CGAL::Parallel_if_available_tag>(
        oriented, layers, centers,
        CAS3::parameters::center_normal_map(CGAL::Nth_of_tuple_property_map<2, Oriented>(), options)
          .point_map(CGAL::Nth_of_tuple_property_map<0, Oriented>())
          .normal_map(CGAL::Nth_of_tuple_property_map<1, Oriented>()));
    });
  }
  else
    r = without_gil([&] { return CAS3::region_descriptors<CGAL::Parallel_if_available_tag>(points, layers, centers, options); });
  py::array_t<double> descriptors(std::vector<py::ssize_t>{py::ssize_t(r.size()), py::ssize_t(r.width)});
  std::copy(r.values.begin(), r.values.end(), descriptors.mutable_data());
  return py::make_tuple(descriptors, r.histogram_bins, r.histogram_weights, r.histogram_kinds);
}

// The C++ form of a Python Regions.
CAS3::Region_descriptors regions_of(const py::object& regions)
{
  CAS3::Region_descriptors r;
  const Doubles points = regions.attr("points").cast<Doubles>();
  const Indices centers = regions.attr("centers").cast<Indices>();
  const Doubles values = regions.attr("descriptors").cast<Doubles>();
  const std::vector<Xyz> xyz = to_xyz(points, "points");
  for(py::ssize_t i = 0; i < centers.size(); ++i)
  {
    r.centers.push_back(std::size_t(centers.data()[i]));
    r.center_points.push_back(xyz.at(r.centers.back()));
  }
  r.rings = regions.attr("rings").cast<std::vector<double> >();
  const auto bins = regions.attr("bins").cast<std::pair<int, int> >();
  r.shape_index_bins = bins.first;
  r.curvedness_bins = bins.second;
  r.histogram_bins = regions.attr("histogram_bins").cast<std::vector<int> >();
  r.histogram_weights = regions.attr("histogram_weights").cast<std::vector<double> >();
  r.histogram_kinds = regions.attr("histogram_kinds").cast<std::vector<int> >();
  r.width = values.ndim() == 2 ? std::size_t(values.shape(1)) : 0;
  if(values.ndim() != 2 || std::size_t(values.shape(0)) != r.size())
    throw py::value_error("the regions' descriptors must be a (centres, values) array");
  r.values.assign(values.data(), values.data() + values.size());
  return r;
}

py::array_t<double> histogram_distances(const py::object& a_regions, const py::object& b_regions, bool balance,
                                        int threads)
{
  const CAS3::Region_descriptors a = regions_of(a_regions), b = regions_of(b_regions);
  const Thread_cap cap(threads);
  const std::vector<double> d =
    without_gil([&] { return CAS3::histogram_distances<CGAL::Parallel_if_available_tag>(a, b, balance); });
  py::array_t<double> out(std::vector<py::ssize_t>{py::ssize_t(a.size()), py::ssize_t(b.size())});
  std::copy(d.begin(), d.end(), out.mutable_data());
  return out;
}

py::tuple motion_arrays(const CAS3::Rigid_motion& m)
{
  py::array_t<double> r(std::vector<py::ssize_t>{3, 3}), t = new_array<double>(3);
  for(int i = 0; i < 3; ++i)
  {
    std::copy(m.rotation[std::size_t(i)].begin(), m.rotation[std::size_t(i)].end(), r.mutable_data() + 3 * i);
    t.mutable_data()[i] = m.translation[std::size_t(i)];
  }
  return py::make_tuple(r, t);
}

py::array_t<bool> bool_array(const std::vector<bool>& values)
{
  py::array_t<bool> out = new_array<bool>(values.size());
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

py::tuple fit_rigid(const Doubles& source, const Doubles& target, const std::optional<Doubles>& weights)
{
  std::vector<double> w;
  if(weights)
    w.assign(weights->data(), weights->data() + weights->size());
  return motion_arrays(CAS3::fit_rigid(to_xyz(source, "source"), to_xyz(target, "target"), w));
}

py::tuple register_correspondences(const Doubles& source, const Doubles& target, double tolerance,
                                   std::size_t iterations, unsigned int seed)
{
  const std::vector<Xyz> s = to_xyz(source, "source"), t = to_xyz(target, "target");
  const CAS3::Registration r = without_gil([&] {
    return CAS3::register_correspondences(s, t, CAS3::parameters::inlier_tolerance(tolerance)
                                                  .number_of_iterations(iterations).random_seed(seed));
  });
  const py::tuple motion = motion_arrays(r.motion);
  return py::make_tuple(motion[0], motion[1], bool_array(r.inliers));
}

// (candidates, scores, rotation, translation, inliers, reranked), the index arrays (M, top)
py::tuple match_regions(const py::object& a_regions, const py::object& b_regions, std::size_t top, std::size_t pool,
                        double tolerance, std::size_t iterations, unsigned int seed, int threads, bool balance)
{
  const CAS3::Region_descriptors a = regions_of(a_regions), b = regions_of(b_regions);
  const Thread_cap cap(threads);
  const CAS3::Region_matches m = without_gil([&] {
    return CAS3::match_regions<CGAL::Parallel_if_available_tag>(
      a, b, CAS3::parameters::number_of_candidates(top, CAS3::parameters::candidate_pool(pool,
            CAS3::parameters::inlier_tolerance(tolerance, CAS3::parameters::balance_kinds(balance))))
              .number_of_iterations(iterations).random_seed(seed));
  });
  const std::vector<py::ssize_t> shape{py::ssize_t(a.size()), py::ssize_t(m.top)};
  py::array_t<std::int64_t> candidates(shape), reranked(shape);
  py::array_t<double> scores(shape);
  std::copy(m.candidates.begin(), m.candidates.end(), candidates.mutable_data());
  std::copy(m.reranked.begin(), m.reranked.end(), reranked.mutable_data());
  std::copy(m.scores.begin(), m.scores.end(), scores.mutable_data());
  const py::tuple motion = motion_arrays(m.motion);
  return py::make_tuple(candidates, scores, motion[0], motion[1], bool_array(m.inliers), reranked);
}

} // namespace

PYBIND11_MODULE(_native, m)
{
  m.doc() = "The compiled part of conformal_alpha_shapes; use the package, not this module.";
  m.attr("__version__") = CGAL_CAS3_VERSION;
  m.def("multiscale_curvatures", &multiscale_curvatures, py::arg("points"), py::arg("normals"),
        py::arg("scales"), py::arg("radii"), py::arg("rings"), py::arg("estimator"), py::arg("denoise"),
        py::arg("denoise_neighbors"), py::arg("extraction"), py::arg("threads"), py::arg("progress"),
        py::arg("spacing"), py::arg("noise"), py::arg("noise_24"));
  // a job of the given options but its scales, which `result` takes
  py::class_<Job>(m, "Job")
    .def(py::init([](const Doubles& points, const std::optional<Doubles>& normals,
                     const std::vector<std::string>& radii, const std::vector<std::string>& rings,
                     const std::string& estimator, const std::string& denoise,
                     const std::string& denoise_neighbors, const std::string& extraction, int threads,
                     py::object progress, std::optional<double> spacing, std::optional<double> noise,
                     std::optional<double> noise_24, std::size_t scales) {
           const Job_options o =
             read_job_options({"auto"}, radii, rings, estimator, denoise, denoise_neighbors, extraction);
           return std::make_unique<Job>(points, normals, o, threads, spacing, noise, noise_24,
                                        Checkpoint(std::move(progress)), scales);
         }),
         py::arg("points"), py::arg("normals"), py::arg("radii"), py::arg("rings"), py::arg("estimator"),
         py::arg("denoise"), py::arg("denoise_neighbors"), py::arg("extraction"), py::arg("threads"),
         py::arg("progress"), py::arg("spacing"), py::arg("noise"), py::arg("noise_24"), py::arg("scales") = 1)
    .def("closing_values", &Job::closing_values)
    .def("result", [](Job& job, const std::vector<std::string>& scales, py::object progress) {
           return job.result(read_job_options(scales, {"auto"}, {}, "quadric", "auto", "", "front").scales,
                             Checkpoint(std::move(progress)), true);
         })
    .def("release", &Job::release);
  m.def("write_point_cloud", &write_point_cloud);
  m.def("read_point_cloud", &read_point_cloud, py::arg("path"), py::arg("classes"), py::arg("drop_withheld"),
        py::arg("returns"));
  m.def("read_las_chunk", &read_las_chunk, py::arg("path"), py::arg("first"), py::arg("count"), py::arg("classes"),
        py::arg("drop_withheld"), py::arg("returns"), py::arg("with_fields"));
  m.def("las_scale", &las_scale);
  m.def("las_records", &las_records, py::arg("points"), py::arg("outlier"), py::arg("layers"), py::arg("fields"),
        py::arg("info"));
  m.def("las_header", &las_header, py::arg("info"), py::arg("labels"), py::arg("count"), py::arg("low"),
        py::arg("high"), py::arg("by_return"));
  m.def("vertex_curvatures", &vertex_curvatures, py::arg("vertices"), py::arg("faces"), py::arg("rings"),
        py::arg("radius"), py::arg("estimator"));
  m.def("estimate_noise", &estimate_noise);
  m.def("input_outliers", &input_outliers);
  m.def("nearest_rows", &nearest_rows);
  m.def("denoise", &denoise);
  py::class_<Shape_handle>(m, "Shape")
    .def(py::init<const Doubles&, const std::optional<Doubles>&>())
    .def("number_of_input_points", &Shape_handle::number_of_input_points)
    .def("dimension", &Shape_handle::dimension)
    .def("local_feature_sizes", &Shape_handle::local_feature_sizes)
    .def("spectrum", &Shape_handle::spectrum)
    .def("alpha_at_quantile", &Shape_handle::alpha_at_quantile)
    .def("suggest_scale", &Shape_handle::suggest_scale)
    .def("classify_facets", &Shape_handle::classify_facets)
    .def("surface", &Shape_handle::surface);
  m.def("farthest_point_sample", &farthest_point_sample);
  m.def("region_descriptors", &region_descriptors);
  m.def("histogram_distances", &histogram_distances);
  m.def("fit_rigid", &fit_rigid);
  m.def("register_correspondences", &register_correspondences);
  m.def("match_regions", &match_regions);
}
