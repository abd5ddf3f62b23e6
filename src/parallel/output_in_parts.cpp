#include "parallel/output_in_parts.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

#include "base/stopwatch.hpp"
#include "io/node_metrics.hpp"
#include "parallel/communicator.hpp"
#include "parallel/output_file_runs.hpp"
#include "parallel/part_adaptation.hpp"
#include "parallel/part_metric_statistics.hpp"
#include "parallel/vtu_file_runs.hpp"
#include "report/curved_vtu.hpp"

namespace hocav {
namespace {

// Every part's settling as one.
BoundarySettling summed_over_processes(const BoundarySettling& own) {
  BoundarySettling sum;
  for (const BoundarySettling& each : all_gather_value(own)) {
    sum.off_geometry += each.off_geometry;
    sum.largest_distance = std::max(sum.largest_distance, each.largest_distance);
    sum.settled += each.settled;
    sum.partly += each.partly;
    sum.blocked += each.blocked;
    sum.largest_distance_left = std::max(sum.largest_distance_left, each.largest_distance_left);
    sum.inner_vertices_moved += each.inner_vertices_moved;
    sum.solver_iterations = std::max(sum.solver_iterations, each.solver_iterations);
    sum.rounds = std::max(sum.rounds, each.rounds);
    sum.seconds = std::max(sum.seconds, each.seconds);
  }
  return sum;
}

}  // namespace

template <int D>
OutputInParts finish_adaptation_in_parts(MeshPart<D>& part, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                                         const AdaptationSettings& settings, const std::string& path, const std::string& vtu,
                                         const PartsCurvingStep<D>* curving) {
  const auto start = std::chrono::steady_clock::now();
  OutputInParts out;
  if (!part.mesh.has_topology()) part.mesh.build_topology();
  std::vector<SymMat<D>> metrics = metrics_at_vertices(part.mesh, metric, settings.threads);
  if (geometry) out.settling = summed_over_processes(settle_part_boundary<D>(part, metrics, *geometry, settings.feature_angle_degrees));
  if (settings.measure_output) out.measures = distributed_metric_statistics(part, rows_of_metrics(metrics).values, settings.threads);
  // As the serial run's: the metric field of the adapted P1 mesh.
  const std::optional<MetricField<D>> field = vtu.empty() ? std::nullopt : std::optional<MetricField<D>>(std::in_place, part.mesh, metrics);
  if (curving) {
    const auto curving_start = std::chrono::steady_clock::now();
    out.curving = curve_in_parts(part, std::move(metrics), curving->geometry, curving->options, settings.measure_output, curving->passes);
    out.seconds_curve = max_over_processes(seconds_since(curving_start));
  }
  out.counts = write_mesh_file_runs(path, part);
  if (field) write_vtu_runs(vtu, part.mesh, curved_vtu_data(part.mesh, *field));
  if (out.curving) count_curved_output(out.curving->report, out.counts);
  out.seconds = max_over_processes(seconds_since(start));
  return out;
}

template OutputInParts finish_adaptation_in_parts(MeshPart<2>&, const AdaptationMetric<2>&, const BoundaryGeometry<2>*,
                                                  const AdaptationSettings&, const std::string&, const std::string&,
                                                  const PartsCurvingStep<2>*);
template OutputInParts finish_adaptation_in_parts(MeshPart<3>&, const AdaptationMetric<3>&, const BoundaryGeometry<3>*,
                                                  const AdaptationSettings&, const std::string&, const std::string&,
                                                  const PartsCurvingStep<3>*);

}  // namespace hocav
