#include "adapt/adaptation_driver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "adapt/hausdorff_metric.hpp"
#include "base/memory_budget.hpp"
#include "base/stopwatch.hpp"
#include "geom/sym_eigen.hpp"
#include "io/node_metrics.hpp"
#include "mesh/input_check.hpp"
#include "mesh/measure.hpp"
#include "metric/gradation.hpp"

namespace hocav {

template <int D>
AdaptationReport report_of_input(const Mesh<D>& input) {
  AdaptationReport report;
  report.dimension = D;
  report.input_vertices = input.vertex_count();
  report.input_elements = input.element_count();
  return report;
}

template <int D>
AdaptedMesh<D> adapt_in_metric(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                               const AdaptationSettings& settings) {
  AdaptedMesh<D> out;
  AdaptationReport& report = out.report;
  report = report_of_input(mesh);
  auto start = std::chrono::steady_clock::now();
  report.run = adapt_to_metric(mesh, metric, geometry, settings);
  // The metric at the adapted vertices, which keep it when the boundary settles (it moves with the mesh).
  const std::vector<SymMat<D>> metrics = metrics_at_vertices(mesh, metric, settings.threads);
  if (geometry) report.settling = settle_boundary<D>(mesh, metrics, *geometry, settings.feature_angle_degrees);
  report.seconds_adapt = seconds_since(start);
  report.output_vertices = mesh.vertex_count();
  report.output_elements = mesh.element_count();

  if (settings.measure_output) report.measures = compute_metric_statistics(mesh, rows_of_metrics(metrics).values, settings.threads);
  out.field = std::make_unique<MetricField<D>>(mesh, metrics);
  report.peak_memory_bytes = peak_resident_bytes();
  return out;
}

template <int D>
void curve_adapted_mesh(AdaptedMesh<D>& adapted, Mesh<D>& mesh, const BoundaryGeometry<D>* geometry, const CurvingOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  adapted.report.curving = curve_in_metric(mesh, *adapted.field, geometry, options);
  adapted.report.seconds_curve = seconds_since(start);
  adapted.report.peak_memory_bytes = peak_resident_bytes();
}

template <int D>
void adapt_curved_mesh(AdaptedMesh<D>& adapted, Mesh<D>& mesh, const CurvingOptions& options, int max_passes,
                       const CurvedPassGeometry<D>& geometry) {
  AdaptationReport& report = adapted.report;
  report.curved_passes = adapt_curved(mesh, *adapted.field, cavity_options(options), max_passes, options.threads, geometry);
  check_curved_consistency(mesh);
  report.output_vertices = mesh.vertex_count();
  report.output_elements = mesh.element_count();
  measure_curved_output(*report.curving, mesh, *adapted.field, options.threads);
  report.peak_memory_bytes = peak_resident_bytes();
}

namespace {

// The size floor's share of the input's diagonal (bounds_above_floor).
constexpr double kSmallestRelativeSize = 1e-6;

template <int D>
AdaptationMetric<D> metric_within(const AdaptationSetup<D>& out, const AdaptationJob<D>& job, const SizeBounds& bounds) {
  if (out.field) return AdaptationMetric<D>(*out.field, bounds);
  return AdaptationMetric<D>(*job.analytic, bounds, out.hausdorff_field ? &*out.hausdorff_field : nullptr);
}

// An analytic metric's Hausdorff bound: a field on the input, kept when the bound is finer than the
// metric at some vertex of the input.
template <int D>
void bound_analytic_metric(AdaptationSetup<D>& out, const Mesh<D>& input, const AnalyticMetricSpec& analytic, const HausdorffBound& bound) {
  const std::vector<SymMat<D>> given = analytic_metric_at_vertices(analytic, input);
  const std::vector<SymMat<D>> bounds = hausdorff_metrics<D>(input, *out.geometry, bound, given);
  for (Index v = 0; v < input.vertex_count(); ++v) out.hausdorff_bounded_vertices += within_bound(given[v], bounds[v]) != given[v];
  if (out.hausdorff_bounded_vertices > 0) out.hausdorff_field.emplace(input, bounds);
}

template <int D>
void make_job_metric(AdaptationSetup<D>& out, const Mesh<D>& input, std::vector<SymMat<D>> metrics, const AdaptationJob<D>& job) {
  const HausdorffBound bound = hausdorff_bound_of(job, out.settings.hausd);
  if (job.analytic && out.geometry) bound_analytic_metric(out, input, *job.analytic, bound);
  if (!job.analytic) {
    if (out.geometry) out.hausdorff_bounded_vertices = bound_metrics_by_hausdorff(input, metrics, *out.geometry, bound);
    if (job.gradation) grade_metrics(input, metrics, {*job.gradation});
    out.field.emplace(input, metrics);
  }
  const double smallest = smallest_size_at_vertices(input, metric_within(out, job, job.bounds));
  const SizeBounds bounds = bounds_above_floor(job, smallest, bounding_box_diagonal(input));
  out.metric.emplace(metric_within(out, job, bounds));
}

}  // namespace

template <int D>
double smallest_size_at_vertices(const Mesh<D>& input, const AdaptationMetric<D>& metric) {
  double largest_eigenvalue = 0;
  Index hint = kNoIndex;
  for (const Vec<D>& x : input.vertices()) {
    const SymEigen<D> eigen = spd_eigen(metric.metric_at(x, hint));
    for (int k = 0; k < D; ++k) largest_eigenvalue = std::max(largest_eigenvalue, eigen.values[k]);
  }
  return 1 / std::sqrt(largest_eigenvalue);
}

template <int D>
SizeBounds bounds_above_floor(const AdaptationJob<D>& job, double smallest_asked, double diagonal) {
  SizeBounds bounds = job.bounds;
  const double floor = kSmallestRelativeSize * diagonal;
  const double smallest = std::min(bounds.h_min > 0 ? bounds.h_min : 1e300, smallest_asked);
  if (smallest < floor) {
    if (job.warn) {
      std::ostringstream warning;
      warning << job.metric_name << ": sizes down to " << smallest << " asked, below what the geometry allows; clamped to " << floor
              << " (1e-6 of the input's diagonal)";
      job.warn(warning.str());
    }
    bounds.h_min = std::min(floor, bounds.h_max);
  }
  return bounds;
}

template <int D>
void warn_if_hausdorff_bounds_nothing(const AdaptationJob<D>& job, bool has_geometry) {
  const bool relative_given = job.hausd_relative.value_or(0) > 0;
  if ((job.hausd || relative_given) && !has_geometry && job.warn) {
    const char* given = job.hausd && relative_given ? "--hausd, --hausd-relative" : job.hausd ? "--hausd" : "--hausd-relative";
    job.warn(std::string("the Hausdorff bound (") + given + ") bounds nothing without a boundary geometry (--surface none)");
  }
}

template <int D>
HausdorffBound hausdorff_bound_of(const AdaptationJob<D>& job, double hausd) {
  return {hausd, job.angle, job.hausd_relative.value_or(job.curving ? kCurvedRelativeHausd : 0)};
}

void check_adaptation_fits(const std::string& name, double expected_elements) {
  check_memory_fits(
      "adapting " + name + " (the metric asks for about " + std::to_string(static_cast<long long>(expected_elements)) + " elements)",
      expected_elements, kAdaptationBytesPerElement);
}

template <int D>
AdaptationSettings job_settings(const AdaptationJob<D>& job, double hausd) {
  AdaptationSettings settings;
  settings.max_passes = job.iterations;
  settings.feature_angle_degrees = job.angle;
  settings.hausd = hausd;
  settings.threads = job.threads;
  settings.progress = job.pass_progress;
  settings.measure_output = job.measure_output;
  return settings;
}

template <int D>
std::unique_ptr<AdaptationSetup<D>> set_up_adaptation(const Mesh<D>& input, std::vector<SymMat<D>> metrics, const AdaptationJob<D>& job,
                                                      const std::string& name) {
  auto setup = std::make_unique<AdaptationSetup<D>>();
  setup->geometry = job.geometry(input);
  warn_if_hausdorff_bounds_nothing(job, setup->geometry != nullptr);
  setup->settings = job_settings(job, job.hausd.value_or(kRelativeHausd * bounding_box_diagonal(input)));
  make_job_metric(*setup, input, std::move(metrics), job);
  check_adaptation_fits(name, expected_element_count(input, *setup->metric));
  return setup;
}

template <int D>
void prepare_boundary(Mesh<D>& mesh, const std::string& name, const std::function<void(const std::string&)>& warn) {
  prepare_input_mesh(mesh, name, warn);
  mesh.orient_boundary_facets_outward();
}

template <int D>
AdaptedMesh<D> run_adaptation_job(Mesh<D>& mesh, std::vector<SymMat<D>> metrics, const AdaptationJob<D>& job, const std::string& name) {
  mesh.forget_edges();
  prepare_boundary(mesh, name, job.warn);  // before the geometry is made of it
  const auto setup = set_up_adaptation(mesh, std::move(metrics), job, name);
  AdaptedMesh<D> adapted = adapt_in_metric(mesh, *setup->metric, setup->geometry.get(), setup->settings);
  adapted.report.hausdorff_bounded_vertices = setup->hausdorff_bounded_vertices;
  if (job.curving) {
    CurvingOptions curving = *job.curving;
    if (job.before_curving) job.before_curving(mesh, curving);
    setup->geometry.reset();                           // a CAD model is open once at a time (gmsh's one model per thread)
    const auto curving_geometry = job.geometry(mesh);  // of the adapted boundary
    curve_adapted_mesh(adapted, mesh, curving_geometry.get(), curving);
    if (job.curved) adapt_curved_mesh(adapted, mesh, curving, job.iterations, {curving_geometry.get(), job.angle});
    if (setup->settings.measure_output) adapted.report.curved_measures = measure_curved(mesh, *adapted.field, curving.threads);
  }
  return adapted;
}

template double smallest_size_at_vertices(const Mesh<2>&, const AdaptationMetric<2>&);
template double smallest_size_at_vertices(const Mesh<3>&, const AdaptationMetric<3>&);
template SizeBounds bounds_above_floor(const AdaptationJob<2>&, double, double);
template SizeBounds bounds_above_floor(const AdaptationJob<3>&, double, double);
template void warn_if_hausdorff_bounds_nothing(const AdaptationJob<2>&, bool);
template void warn_if_hausdorff_bounds_nothing(const AdaptationJob<3>&, bool);
template HausdorffBound hausdorff_bound_of(const AdaptationJob<2>&, double);
template HausdorffBound hausdorff_bound_of(const AdaptationJob<3>&, double);
template AdaptationSettings job_settings(const AdaptationJob<2>&, double);
template AdaptationSettings job_settings(const AdaptationJob<3>&, double);
template void prepare_boundary(Mesh<2>&, const std::string&, const std::function<void(const std::string&)>&);
template void prepare_boundary(Mesh<3>&, const std::string&, const std::function<void(const std::string&)>&);
template AdaptedMesh<2> run_adaptation_job(Mesh<2>&, std::vector<SymMat<2>>, const AdaptationJob<2>&, const std::string&);
template AdaptedMesh<3> run_adaptation_job(Mesh<3>&, std::vector<SymMat<3>>, const AdaptationJob<3>&, const std::string&);
template std::unique_ptr<AdaptationSetup<2>> set_up_adaptation(const Mesh<2>&, std::vector<SymMat<2>>, const AdaptationJob<2>&,
                                                               const std::string&);
template std::unique_ptr<AdaptationSetup<3>> set_up_adaptation(const Mesh<3>&, std::vector<SymMat<3>>, const AdaptationJob<3>&,
                                                               const std::string&);
template AdaptationReport report_of_input(const Mesh<2>&);
template AdaptationReport report_of_input(const Mesh<3>&);
template AdaptedMesh<2> adapt_in_metric(Mesh<2>&, const AdaptationMetric<2>&, const BoundaryGeometry<2>*, const AdaptationSettings&);
template AdaptedMesh<3> adapt_in_metric(Mesh<3>&, const AdaptationMetric<3>&, const BoundaryGeometry<3>*, const AdaptationSettings&);
template void adapt_curved_mesh(AdaptedMesh<2>&, Mesh<2>&, const CurvingOptions&, int, const CurvedPassGeometry<2>&);
template void adapt_curved_mesh(AdaptedMesh<3>&, Mesh<3>&, const CurvingOptions&, int, const CurvedPassGeometry<3>&);
template void curve_adapted_mesh(AdaptedMesh<2>&, Mesh<2>&, const BoundaryGeometry<2>*, const CurvingOptions&);
template void curve_adapted_mesh(AdaptedMesh<3>&, Mesh<3>&, const BoundaryGeometry<3>*, const CurvingOptions&);

}  // namespace hocav
