// The paper's pipeline as `hocav adapt`, `hocav demo` and the Python module run it: the P1
// adaptation loop, the metric measured on its output, then (optionally) the curving of
// `hocav curve` in that metric (docs/adaptation.md).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "adapt/adaptation_loop.hpp"
#include "adapt/curved_adaptation.hpp"
#include "adapt/curving_run.hpp"
#include "adapt/hausdorff_metric.hpp"
#include "report/adaptation_report.hpp"

namespace hocav {

template <int D>
struct AdaptedMesh {
  AdaptationReport report;
  // The metric on the adapted mesh (its vertices carry the clamped metric the loop used): the
  // curving's field and the .vtu's.
  std::unique_ptr<MetricField<D>> field;
};

// The report of an adaptation of `input`, before it runs: the dimension and the input's counts.
template <int D>
AdaptationReport report_of_input(const Mesh<D>& input);

// Adapts `mesh` (P1, compact) to `metric` (adapt_to_metric), new boundary points on `geometry` (may
// be null). Fills the report's figures from the input's and output's counts, and its peak memory.
template <int D>
AdaptedMesh<D> adapt_in_metric(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                               const AdaptationSettings& settings);

// Then curves the adapted `mesh` in `adapted.field` (curve_in_metric; `geometry` is usually made from
// the adapted mesh) and adds the curving's figures, time and the peak memory to the report.
template <int D>
void curve_adapted_mesh(AdaptedMesh<D>& adapted, Mesh<D>& mesh, const BoundaryGeometry<D>* geometry, const CurvingOptions& options);

// Then runs at most `max_passes` curved passes on the curved `mesh` (adapt_curved, in `adapted.field`,
// its boundary operations on `geometry`), and measures the output again into the report.
template <int D>
void adapt_curved_mesh(AdaptedMesh<D>& adapted, Mesh<D>& mesh, const CurvingOptions& options, int max_passes,
                       const CurvedPassGeometry<D>& geometry);

// `hocav adapt`'s job with its options as values (docs/usage.md): the metric set up, the memory
// checked, the adaptation, then (with `curving`) the curving.
template <int D>
struct AdaptationJob {
  std::optional<AnalyticMetricSpec> analytic;  // the metric, evaluated exactly; else the one given per vertex
  SizeBounds bounds;
  std::optional<double> gradation;  // grades the given metric first
  std::optional<double> hausd;      // default kRelativeHausd × the input's bounding box diagonal
  // HausdorffBound::relative_to_size (0: none); default kCurvedRelativeHausd with `curving`, none without.
  std::optional<double> hausd_relative;
  double angle = 45;                      // AdaptationSettings::feature_angle_degrees
  int iterations = 20;                    // AdaptationSettings::max_passes
  int threads = 1;                        // AdaptationSettings::threads
  std::optional<CurvingOptions> curving;  // order 2
  bool curved = false;                    // then curved passes (needs curving; at most `iterations`)
  // The boundary geometry of a mesh (the input's for the adaptation, the adapted one's for the
  // curving); may return null (no geometry).
  std::function<std::unique_ptr<BoundaryGeometry<D>>(const Mesh<D>&)> geometry;
  std::function<void(int, int)> pass_progress;  // AdaptationSettings::progress
  bool measure_output = true;                   // AdaptationSettings::measure_output
  // Warnings on the way ("<metric_name>: sizes down to ... clamped"), when set.
  std::string metric_name = "the metric";
  std::function<void(const std::string&)> warn;
  // Called with the adapted mesh just before its curving, e.g. to set the curving's progress.
  std::function<void(const Mesh<D>&, CurvingOptions&)> before_curving;
};

// The smallest size `metric` asks at the vertices of `input`.
template <int D>
double smallest_size_at_vertices(const Mesh<D>& input, const AdaptationMetric<D>& metric);

// The job's size bounds, h_min raised to 1e-6 of the input's bounding-box `diagonal` when the
// metric asks for sizes down to `smallest_asked` below it (said through job.warn): elements that
// small lose the digits their orientation and volume tests need, and the loop could not converge.
template <int D>
SizeBounds bounds_above_floor(const AdaptationJob<D>& job, double smallest_asked, double diagonal);

// Says through job.warn that a Hausdorff bound the job gives bounds nothing without a geometry.
template <int D>
void warn_if_hausdorff_bounds_nothing(const AdaptationJob<D>& job, bool has_geometry);

// The job's Hausdorff bound with distance `hausd` (the settings'): its relative bound, by default
// kCurvedRelativeHausd with curving and none without.
template <int D>
HausdorffBound hausdorff_bound_of(const AdaptationJob<D>& job, double hausd);

// Refuses (Error naming the mesh `name`) an adaptation whose metric asks for more elements than
// the memory holds.
void check_adaptation_fits(const std::string& name, double expected_elements);

// The loop's settings of a job; `hausd` the Hausdorff distance (the job's, or its default from the input).
template <int D>
AdaptationSettings job_settings(const AdaptationJob<D>& job, double hausd);

// What a job adapts with (on rank 0 of a distributed run): the input's copy as back mesh with its
// (graded) metric, or the analytic metric; the size bounds; the boundary geometry of the input; the
// loop's settings.
template <int D>
struct AdaptationSetup {
  std::optional<MetricField<D>> field;
  std::optional<MetricField<D>> hausdorff_field;  // an analytic metric's Hausdorff bound, where it is finer
  std::optional<AdaptationMetric<D>> metric;
  std::unique_ptr<BoundaryGeometry<D>> geometry;
  AdaptationSettings settings;
  // The input's vertices whose metric the Hausdorff bound made finer (hausdorff_metric.hpp).
  Index hausdorff_bounded_vertices = 0;
};

// Sets up `job` on `input` (P1), `metrics` the metric at its vertices (empty with an analytic metric),
// after checking that the memory fits (`name` names the mesh in that error). The setup holds what it
// needs of `input` (the fields copy their back mesh). Held by pointer: the metric refers to the field.
template <int D>
std::unique_ptr<AdaptationSetup<D>> set_up_adaptation(const Mesh<D>& input, std::vector<SymMat<D>> metrics, const AdaptationJob<D>& job,
                                                      const std::string& name);

// The input as the loop needs it: its elements positive (a mesh given all inverted is reoriented,
// said through `warn`), a facet on every face of the domain's boundary (made
// with ref 0 where the input gives none, said through `warn`, which may be empty) and every
// boundary facet ordered outward (the cavity operator makes them so, and the boundary tests
// compare the two). The adaptation does it itself; a caller that cuts the mesh first does it before.
template <int D>
void prepare_boundary(Mesh<D>& mesh, const std::string& name, const std::function<void(const std::string&)>& warn);

// Runs `job` on `mesh` (P1 or P2, whose nodes are dropped), `metrics` the metric at its vertices
// (empty with an analytic metric). `name` names the mesh in errors (a job too large for the memory).
template <int D>
AdaptedMesh<D> run_adaptation_job(Mesh<D>& mesh, std::vector<SymMat<D>> metrics, const AdaptationJob<D>& job, const std::string& name);

}  // namespace hocav
