#include "parallel/adaptation_from_pieces.hpp"

#include "base/error.hpp"
#include "base/memory_budget.hpp"
#include "geom/box.hpp"
#include "io/node_metrics.hpp"
#include "io/record_run.hpp"
#include "parallel/communicator.hpp"
#include "parallel/gradual_metric.hpp"
#include "parallel/implied_metric_runs.hpp"
#include "parallel/metrics_by_global_id.hpp"
#include "parallel/piece_classification.hpp"

namespace hocav {
namespace {

// The diagonal of the whole mesh's bounding box, from every piece's.
template <int D>
double whole_diagonal(const Mesh<D>& piece) {
  Box<D> own = Box<D>::empty();
  for (const Vec<D>& x : piece.vertices()) own.add(x);
  Box<D> whole = Box<D>::empty();
  for (const Box<D>& each : all_gather_value(own)) whole.add(each);
  return whole.is_empty() ? 0 : norm(whole.upper - whole.lower);
}

// The piece's vertices' metrics from the metric file, each row read by the process whose run holds it.
template <int D>
std::vector<SymMat<D>> given_metrics(const MeshFilePiece<D>& piece, const std::string& metric_path) {
  const RecordRun run{process_rank(), process_count()};
  long long bytes_sent = 0;
  const std::vector<SymMat<D>> held = metrics_of_rows<D>(read_metric_run(metric_path, D, piece.vertex_count, run));
  return metrics_by_global_id<D>(piece.part.global_ids, run.of(piece.vertex_count).first, held, bytes_sent);
}

// The piece's vertices' implied metrics, bit for bit the whole mesh's.
template <int D>
std::vector<SymMat<D>> implied_metrics(const MeshFilePiece<D>& piece, const std::string& input) {
  const VertexRunMetrics<D> run = implied_metric_by_runs(piece.part, piece.vertex_count, input);
  long long bytes_sent = 0;
  return metrics_by_global_id<D>(piece.part.global_ids, run.first, run.metrics, bytes_sent);
}

// The piece as its home share of the back mesh: its elements and vertices, and per field
// (share_log_metrics) the log-metric at each vertex.
template <int D>
BackMeshShare<D> home_of_piece(const MeshPart<D>& piece, const AdaptationMetric<D>& metric, const MetricField<D>& input_metric) {
  BackMeshShare<D> home;
  for (Index v = 0; v < piece.mesh.vertex_count(); ++v) home.mesh.add_vertex(piece.mesh.vertex(v));
  for (Index k = 0; k < piece.mesh.element_count(); ++k) home.mesh.add_element(piece.mesh.element(k));
  home.global_ids = piece.global_ids;
  home.log_metrics = share_log_metrics(metric, input_metric);
  return home;
}

}  // namespace

template <int D>
PieceSetup<D> set_up_piece(MeshFilePiece<D> piece, const std::string& input, const std::string& metric_path, const AdaptationJob<D>& job) {
  if (job.analytic || job.gradation) throw Error("adapting from pieces takes a metric file, without --hgrad");
  Mesh<D>& mesh = piece.part.mesh;
  if (!mesh.has_topology()) mesh.build_topology();
  mesh.orient_boundary_facets_outward();
  classify_piece_vertices(piece.part, job.angle);
  warn_if_hausdorff_bounds_nothing(job, false);
  const double diagonal = whole_diagonal(mesh);
  PieceSetup<D> setup;
  setup.settings = job_settings(job, job.hausd.value_or(kRelativeHausd * diagonal));
  const MetricField<D> field(mesh, given_metrics(piece, metric_path));
  const MetricField<D> input_metric = field.with_metrics(implied_metrics(piece, input));
  const double smallest = -max_over_processes(-smallest_size_at_vertices(mesh, AdaptationMetric<D>(field, job.bounds)));
  const AdaptationMetric<D> metric(field, bounds_above_floor(job, smallest, diagonal));
  const double expected = sum_over_processes(expected_element_count(mesh, metric));
  check_memory_fits("adapting " + input + " (the metric asks for about " + std::to_string(static_cast<long long>(expected)) + " elements)",
                    expected, kAdaptationBytesPerElement);
  PiecesStart<D>& start = setup.start;
  start.steps = max_over_processes(gradual_steps(mesh, input_metric, metric, kDistributedIterations - 1));
  start.loads = expected_element_counts(mesh, metric.partway_from(input_metric, gradual_fraction(1, start.steps)));
  start.home = home_of_piece(piece.part, metric, input_metric);
  start.recipe = recipe_of(metric);
  start.part = std::move(piece.part);
  return setup;
}

template PieceSetup<2> set_up_piece(MeshFilePiece<2>, const std::string&, const std::string&, const AdaptationJob<2>&);
template PieceSetup<3> set_up_piece(MeshFilePiece<3>, const std::string&, const std::string&, const AdaptationJob<3>&);

}  // namespace hocav
