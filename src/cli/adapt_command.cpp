// hocav adapt IN --metric SOL | --analytic NAME -o OUT [--order 2|1] [--hmin H] [--hmax H]
//                [--hgrad BETA] [--hausd D] [--angle DEG] [--surface p3|cad:FILE|none]
//                [--jacobian-floor J] [--iterations N] [--threads N] [--report R.json] [--vtu V.vtu]
// Metric-based adaptation to a unit mesh (split, collapse, swap, smooth; boundary points on the
// geometry), then, with --order 2, the curving of `hocav curve` in the same metric.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "base/memory_budget.hpp"
#include "geom/sym_eigen.hpp"
#include "cli/adaptation_driver.hpp"
#include "cli/commands.hpp"
#include "cli/number_checks.hpp"
#include "io/atomic_output.hpp"
#include "io/output_set.hpp"
#include "mesh/measure.hpp"
#include "metric/gradation.hpp"

namespace hocav {
namespace {

struct AdaptOptions {
  std::string input, metric, analytic, output, report, vtu, surface = "p3";
  int order = 2;
  std::optional<double> h_min, h_max, gradation;
  double hausd = 0.01;  // relative to the bounding box's diagonal when --hausd is not given
  std::optional<double> hausd_given;
  double angle = 45;
  double jacobian_floor = 0.01;
  int iterations = 20;
  int threads = every_core();
  bool quiet = false;
};

void check_options(const AdaptOptions& o) {
  if (o.metric.empty() == o.analytic.empty()) throw Error("give exactly one metric source: --metric SOL or --analytic NAME");
  if (o.h_min && o.h_max && *o.h_min > *o.h_max) throw Error("--hmin must not exceed --hmax");
  if (o.gradation && !o.analytic.empty())
    throw Error("--hgrad grades a metric given on a mesh: make one with `hocav metric --analytic NAME --gradation BETA`");
}

// The metric of the run: the input mesh as back mesh with its graded metric, or the analytic field.
template <int D>
struct RunMetric {
  std::optional<MetricField<D>> field;
  std::optional<AdaptationMetric<D>> metric;
};

// Sizes below this share of the input's bounding-box diagonal are never asked for: elements that
// small lose the digits their orientation and volume tests need, and the loop could not converge.
constexpr double kSmallestRelativeSize = 1e-6;

// The smallest size the metric asks at the input's vertices.
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
AdaptationMetric<D> metric_within(const RunMetric<D>& run, const AdaptOptions& o, const SizeBounds& bounds) {
  if (run.field) return AdaptationMetric<D>(*run.field, bounds);
  AnalyticMetricSpec spec;
  spec.name = o.analytic;
  return AdaptationMetric<D>(spec, bounds);
}

template <int D>
void make_run_metric(RunMetric<D>& run, const Mesh<D>& input, const MeshFileContent& file, const AdaptOptions& o) {
  if (o.analytic.empty()) {
    std::vector<SymMat<D>> metrics = metrics_of_rows<D>(read_metric_for_mesh(o.metric, file, false));
    if (o.gradation) grade_metrics(input, metrics, {*o.gradation});
    run.field.emplace(input, metrics);
  }
  SizeBounds bounds{o.h_min.value_or(0), o.h_max.value_or(1e300)};
  const double floor = kSmallestRelativeSize * bounding_box_diagonal(input);
  const double smallest = std::min(bounds.h_min > 0 ? bounds.h_min : 1e300, smallest_size_at_vertices(input, metric_within(run, o, bounds)));
  if (smallest < floor) {
    std::cerr << "hocav adapt: warning: " << (o.analytic.empty() ? o.metric : "--analytic " + o.analytic) << ": sizes down to "
              << smallest << " asked, below what the geometry allows; clamped to " << floor << " (1e-6 of the input's diagonal)\n";
    bounds.h_min = std::min(floor, bounds.h_max);
  }
  run.metric.emplace(metric_within(run, o, bounds));
}

// The output's element count the metric asks for: its complexity ∫ √det M over the input (the
// metric at each element's centroid) divided by the metric volume of a regular unit simplex
// (√2/12 in 3D, √3/4 in 2D).
template <int D>
double expected_elements(const Mesh<D>& input, const AdaptationMetric<D>& metric) {
  double complexity = 0;
  Index hint = kNoIndex;
  for (Index k = 0; k < input.element_count(); ++k) {
    Vec<D> centroid{};
    for (Index v : input.element(k)) centroid = centroid + (1.0 / (D + 1)) * input.vertex(v);
    complexity += std::sqrt(determinant(metric.metric_at(centroid, hint))) * std::abs(element_measure(input, k));
  }
  return complexity / (D == 3 ? std::sqrt(2.0) / 12 : std::sqrt(3.0) / 4);
}

// The loop stops at --iterations passes at the latest; when it stops there the metric may ask for
// what the mesh cannot give (sizes below what corners, required entities or the geometry allow, or
// a field too rough for its back mesh), and the user hears it.
void warn_if_not_converged(const AdaptOptions& o, const AdaptationReport& report) {
  if (report.run.converged || report.run.passes.empty()) return;
  const AdaptationPass& last = report.run.passes.back();
  std::cerr << "hocav adapt: warning: " << o.input << ": not converged after " << report.run.passes.size()
            << " passes (the last split " << last.splits.done << " and collapsed " << last.collapses.done << " edges; "
            << static_cast<int>(1000 * report.measures.unit_share) / 10.0
            << "% of edges unit); raise --iterations, or check that the metric asks for sizes the geometry allows\n";
}

template <int D>
void adapt(Mesh<D>& mesh, const MeshFileContent& file, const AdaptOptions& o, OutputSet& outputs) {
  check_input_mesh(mesh, o.input);
  mesh.forget_edges();
  const Mesh<D> input = mesh;
  RunMetric<D> run;
  make_run_metric(run, input, file, o);
  const double expected = expected_elements(input, *run.metric);
  check_memory_fits("adapting " + o.input + " (the metric asks for about " + std::to_string(static_cast<long long>(expected)) +
                        " elements)",
                    expected, kAdaptationBytesPerElement);
  const auto geometry = boundary_geometry<D>(o.surface, input);

  AdaptationSettings settings;
  settings.max_passes = o.iterations;
  settings.feature_angle_degrees = o.angle;
  settings.threads = o.threads;
  settings.hausd = o.hausd_given.value_or(o.hausd * bounding_box_diagonal(input));
  if (!o.quiet) settings.progress = [](int pass, int cap) { std::cerr << "adapting: pass " << pass << " (at most " << cap << ")\n"; };
  std::optional<CurvingSettings> curving;
  if (o.order == 2) curving = CurvingSettings{o.surface, "simpson", o.jacobian_floor, 1, o.threads, !o.quiet};
  const AdaptedMesh<D> adapted = adapt_and_curve(mesh, *run.metric, geometry.get(), settings, curving);
  const AdaptationReport& report = adapted.report;
  warn_if_not_converged(o, report);

  write_mesh_file(o.output, mesh);
  if (!o.vtu.empty()) write_curved_vtu(o.vtu, mesh, *adapted.field);
  if (!o.report.empty()) {
    AtomicOutput out(o.report);
    write_adaptation_report_json(out.stream(), report);
    out.commit();
  }
  outputs.commit();
  if (!o.quiet) {
    std::cout << "adapted " << o.input << " -> " << o.output << '\n';
    write_adaptation_report_table(std::cout, report);
    if (report.curving) write_curving_report_table(std::cout, *report.curving);
  }
}

void declare_adapt_files(OutputSet& outputs, const AdaptOptions& o) {
  outputs.add_input(o.input, "the input mesh");
  if (!o.metric.empty()) outputs.add_input(o.metric, "--metric");
  if (o.surface.starts_with("cad:")) outputs.add_input(o.surface.substr(4), "--surface cad:");
  check_writable_mesh_format(o.output);
  outputs.add_output(o.output, "-o");
  if (!o.report.empty()) outputs.add_output(o.report, "--report");
  if (!o.vtu.empty()) outputs.add_output(o.vtu, "--vtu");
}

}  // namespace

void add_adapt_command(CLI::App& app) {
  auto o = std::make_shared<AdaptOptions>();
  CLI::App* command = app.add_subcommand("adapt", "Adapt a mesh to a metric (a unit mesh: split, collapse, swap, smooth), then curve it");
  command->add_option("input", o->input, "mesh to adapt (.mesh, .meshb, .msh; P1, or P2 whose nodes are dropped)")->required();
  command->add_option("--metric", o->metric, "metric at the input's vertices (.sol/.solb); the input is the back mesh");
  command->add_option("--analytic", o->analytic, "or an analytic metric, evaluated exactly at every vertex (" +
                                                     [] {
                                                       std::string names;
                                                       for (const auto& n : analytic_metric_names()) names += (names.empty() ? "" : ", ") + n;
                                                       return names;
                                                     }() + ")");
  command->add_option("-o,--output", o->output, "adapted mesh to write (.mesh, .meshb, .msh, .vtu)")->required();
  command->add_option("--order", o->order, "2: curve the adapted mesh (P2 output); 1: stop after the P1 adaptation")
      ->check(CLI::IsMember({1, 2}))
      ->capture_default_str();
  command->add_option("--hmin", o->h_min, "smallest size: the metric's sizes are clamped to it")->check(finite_positive());
  command->add_option("--hmax", o->h_max, "largest size: the metric's sizes are clamped to it")->check(finite_positive());
  command->add_option("--hgrad", o->gradation, "grade the metric first: sizes grow by at most BETA > 1 per unit length")
      ->check(finite_range(1.0 + 1e-12, 1e6, "BETA > 1"));
  command->add_option("--hausd", o->hausd_given,
                      "largest distance from a new boundary facet to the geometry (default 0.01 x the bounding box's diagonal)")
      ->check(finite_positive());
  command->add_option("--angle", o->angle, "boundary sides meeting at more than this dihedral angle are ridges (degrees)")
      ->check(finite_range(0.0, 180.0, "0 to 180"))
      ->capture_default_str();
  command->add_option("--surface", o->surface,
                      "geometry of new boundary points and P2 nodes: p3 (a cubic surrogate of the input boundary), cad:FILE, none")
      ->capture_default_str();
  command->add_option("--jacobian-floor", o->jacobian_floor, "curving: every element keeps its min normalized Jacobian above this")
      ->check(finite_range(0.0, 1.0, "0 to 1"))
      ->capture_default_str();
  command->add_option("--iterations", o->iterations, "at most this many passes of the adaptation loop")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command->add_option("--threads", o->threads, "threads of the swaps, smoothing, collapse tests and curving (the output does not depend on it)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  command->add_option("--report", o->report, "write the run's figures (passes, lengths, qualities, Table-1 columns) as JSON");
  command->add_option("--vtu", o->vtu, "also write a .vtu for ParaView (metric and min normalized Jacobian)");
  command->add_flag("-q,--quiet", o->quiet, "print nothing on success");
  command->callback([o] {
    check_options(*o);
    OutputSet outputs;
    declare_adapt_files(outputs, *o);
    MeshFileContent file = read_mesh_file(o->input);
    std::visit([&](auto& mesh) { adapt(mesh, file, *o, outputs); }, file.mesh);
  });
}

}  // namespace hocav
