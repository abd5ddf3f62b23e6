#include "parallel/adaptation_from_pieces.hpp"

#include <span>

#include "adapt/hausdorff_metric.hpp"
#include "io/node_metrics.hpp"
#include "io/record_run.hpp"
#include "metric/analytic_metric.hpp"
#include "metric/surface_metric.hpp"
#include "parallel/boundary_of_parts.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distinct_ids.hpp"
#include "parallel/distributed_gradation.hpp"
#include "parallel/gradual_metric.hpp"
#include "parallel/hessian_metric_runs.hpp"
#include "parallel/implied_metric_runs.hpp"
#include "parallel/metrics_by_global_id.hpp"
#include "parallel/piece_classification.hpp"
#include "parallel/piece_facet_orientation.hpp"

namespace hocav {
namespace {

// This process's run of a metric given per file vertex: the metric file's rows, or the implied
// metric's run.
template <int D>
struct MetricRows {
  Index first = 0;              // the file id of its first vertex
  std::vector<SymMat<D>> held;  // per vertex of the run

  MetricRows(Index run_first, std::vector<SymMat<D>> run) : first(run_first), held(std::move(run)) {}
  MetricRows(const std::string& metric_path, Index vertex_count) {
    const RecordRun run{process_rank(), process_count()};
    first = run.of(vertex_count).first;
    held = metrics_of_rows<D>(read_metric_run(metric_path, D, vertex_count, run));
  }

  // Collective: the metrics of the vertices of global ids `ids`, each asked of the process whose run holds it.
  std::vector<SymMat<D>> of(std::span<const Index> ids) const {
    long long bytes_sent = 0;
    return metrics_by_global_id<D>(ids, first, held, bytes_sent);
  }
};

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

// Collective: the Hausdorff bound at the piece's vertices, as hausdorff_metrics makes it on the whole
// mesh: at the boundary's vertices from the whole `boundary` every process holds (`boundary_given`
// the given metrics there), graded into the pieces (grade_piece_metrics).
template <int D>
std::vector<SymMat<D>> piece_hausdorff_bounds(const MeshPart<D>& piece, const MeshPart<D>& boundary,
                                              const std::vector<SymMat<D>>& boundary_given, const BoundaryGeometry<D>& geometry,
                                              const HausdorffBound& bound, double diagonal) {
  const std::vector<SymMat<D>> at_boundary = hausdorff_metrics<D>(boundary.mesh, geometry, bound, boundary_given);
  std::vector<SymMat<D>> bounds(piece.global_ids.size(), unbounded_metric<D>(diagonal));
  const std::vector<Index> places = boundary_indices(piece, boundary.global_ids);
  for (std::size_t v = 0; v < places.size(); ++v)
    if (places[v] != kNoIndex) bounds[v] = at_boundary[static_cast<std::size_t>(places[v])];
  bool finer = false;  // than the given metric, somewhere on the boundary (the same on every process)
  for (std::size_t b = 0; b < at_boundary.size(); ++b) finer |= within_bound(boundary_given[b], at_boundary[b]) != boundary_given[b];
  if (finer) grade_piece_metrics(piece, bounds, {kHausdorffGradation});
  return bounds;
}

// Collective: how many of the whole mesh's vertices `bounds` makes finer than `given` (per piece vertex).
template <int D>
Index bounded_vertex_count(const MeshPart<D>& piece, const std::vector<SymMat<D>>& given, const std::vector<SymMat<D>>& bounds) {
  std::vector<Index> changed;
  for (std::size_t v = 0; v < given.size(); ++v)
    if (within_bound(given[v], bounds[v]) != given[v]) changed.push_back(piece.global_ids[v]);
  return distinct_count(changed);
}

// The metric on a piece before its size bounds: a field of the given metric (a file's rows or the
// implied metric), or the analytic metric with the field of its Hausdorff bound where it has one;
// and the input's own metric.
template <int D>
struct PieceMetric {
  std::optional<MetricField<D>> field;
  std::optional<MetricField<D>> input_metric;
  Index hausdorff_bounded_vertices = 0;

  AdaptationMetric<D> within(const AdaptationJob<D>& job, const SizeBounds& bounds) const {
    if (job.analytic) return AdaptationMetric<D>(*job.analytic, bounds, field ? &*field : nullptr);
    return AdaptationMetric<D>(*field, bounds);
  }
};

// What a piece's metric is made of.
template <int D>
struct PieceMetricInputs {
  const MeshPart<D>& boundary;
  const BoundaryGeometry<D>* geometry;
  HausdorffBound bound;
  double diagonal;
  std::string metric_path;               // a metric file, or else (empty):
  std::optional<HessianSource> hessian;  // a Hessian's metric, or else
  std::optional<SurfaceSizes> surface;   // the surface metric, or else the analytic metric, or else the implied one
  std::string input;                     // the mesh file's path
};

// The given metric, before its bounds, at the piece's vertices and (with a geometry, or the surface
// metric) at the whole boundary's.
template <int D>
struct GivenMetric {
  std::vector<SymMat<D>> at_piece, at_boundary;
};

// Collective: the given metric: the analytic metric, or the surface metric (made of the whole
// boundary: its vertices' normals sum the facets of every piece), or the rows of a metric file or
// of the implied metric.
template <int D>
GivenMetric<D> given_metric(const MeshPart<D>& piece, const AdaptationJob<D>& job, const PieceMetricInputs<D>& in,
                            const MetricRows<D>& rows) {
  GivenMetric<D> out;
  if (job.analytic) {
    out.at_piece = analytic_metric_at_vertices(*job.analytic, piece.mesh);
    if (in.geometry) out.at_boundary = analytic_metric_at_vertices(*job.analytic, in.boundary.mesh);
  } else if (in.surface) {
    out.at_boundary = surface_metric_at_boundary(in.boundary.mesh, *in.surface);
    out.at_piece = values_from_boundary(piece, in.boundary.global_ids, out.at_boundary, surface_interior_metric<D>(*in.surface));
  } else {
    out.at_piece = rows.of(piece.global_ids);
    if (in.geometry) out.at_boundary = rows.of(in.boundary.global_ids);
  }
  return out;
}

// Collective: the piece's metric as make_job_metric makes the whole's: the Hausdorff bound, then
// the gradation.
template <int D>
PieceMetric<D> piece_metric(const MeshFilePiece<D>& piece, const AdaptationJob<D>& job, const PieceMetricInputs<D>& in) {
  const Mesh<D>& mesh = piece.part.mesh;
  VertexRunMetrics<D> implied = implied_metric_by_runs(piece.part, piece.vertex_count, in.input);  // (bit for bit the whole mesh's)
  const MetricRows<D> own_rows(implied.first, std::move(implied.metrics));
  std::optional<MetricRows<D>> file_rows;
  if (!in.metric_path.empty()) file_rows.emplace(in.metric_path, piece.vertex_count);
  if (in.hessian) {
    VertexRunMetrics<D> lp = hessian_metric_by_runs(piece.part, piece.vertex_count, *in.hessian, in.diagonal, in.input);
    file_rows.emplace(lp.first, std::move(lp.metrics));
  }
  GivenMetric<D> given_there = given_metric(piece.part, job, in, file_rows ? *file_rows : own_rows);
  std::vector<SymMat<D>>& given = given_there.at_piece;
  PieceMetric<D> out;
  if (in.geometry) {
    const std::vector<SymMat<D>>& at_boundary = given_there.at_boundary;
    const std::vector<SymMat<D>> bounds = piece_hausdorff_bounds(piece.part, in.boundary, at_boundary, *in.geometry, in.bound, in.diagonal);
    out.hausdorff_bounded_vertices = bounded_vertex_count(piece.part, given, bounds);
    if (job.analytic && out.hausdorff_bounded_vertices > 0) out.field.emplace(mesh, bounds);
    if (!job.analytic)
      for (std::size_t v = 0; v < given.size(); ++v) given[v] = within_bound(given[v], bounds[v]);
  }
  if (job.gradation) grade_piece_metrics(piece.part, given, {*job.gradation});
  if (!job.analytic) out.field.emplace(mesh, given);
  const std::vector<SymMat<D>> own = own_rows.of(piece.part.global_ids);
  if (out.field)
    out.input_metric.emplace(out.field->with_metrics(own));
  else
    out.input_metric.emplace(mesh, own);
  return out;
}

}  // namespace

template <int D>
PieceSetup<D> set_up_piece(MeshFilePiece<D> piece, const std::string& input, const PieceMetricSource& source, const AdaptationJob<D>& job) {
  Mesh<D>& mesh = piece.part.mesh;
  if (!mesh.has_topology()) mesh.build_topology();
  orient_piece_facets(piece.part, piece.facet_ids);
  const MeshPart<D> boundary = boundary_of_parts(piece.part);
  PieceSetup<D> setup;
  setup.geometry = job.geometry(boundary.mesh);  // (of the input's boundary, before the classification tags it)
  classify_piece_vertices(piece.part, boundary, job.angle);
  warn_if_hausdorff_bounds_nothing(job, setup.geometry != nullptr);
  const double diagonal = whole_diagonal(mesh);
  setup.settings = job_settings(job, job.hausd.value_or(kRelativeHausd * diagonal));
  const HausdorffBound bound = hausdorff_bound_of(job, setup.settings.hausd);
  std::optional<SurfaceSizes> surface;
  if (source.surface_sizes) surface = SurfaceSizes{(*source.surface_sizes)[0], (*source.surface_sizes)[1], source.h_max.value_or(diagonal)};
  const PieceMetric<D> given = piece_metric(
      piece, job, {boundary, setup.geometry.get(), bound, diagonal, source.metric_path, source.hessian, surface, input});
  setup.hausdorff_bounded_vertices = given.hausdorff_bounded_vertices;
  const double smallest = -max_over_processes(-smallest_size_at_vertices(mesh, given.within(job, job.bounds)));
  const AdaptationMetric<D> metric = given.within(job, bounds_above_floor(job, smallest, diagonal));
  check_adaptation_fits(input, sum_over_processes(expected_element_count(mesh, metric)));
  const MetricField<D>& input_metric = *given.input_metric;
  PiecesStart<D>& start = setup.start;
  start.steps = max_over_processes(gradual_steps(mesh, input_metric, metric, kDistributedIterations - 1));
  start.loads = expected_element_counts(mesh, metric.partway_from(input_metric, gradual_fraction(1, start.steps)));
  start.home = home_of_piece(piece.part, metric, input_metric);
  start.recipe = recipe_of(metric);
  start.part = std::move(piece.part);
  return setup;
}

template PieceSetup<2> set_up_piece(MeshFilePiece<2>, const std::string&, const PieceMetricSource&, const AdaptationJob<2>&);
template PieceSetup<3> set_up_piece(MeshFilePiece<3>, const std::string&, const PieceMetricSource&, const AdaptationJob<3>&);

}  // namespace hocav
