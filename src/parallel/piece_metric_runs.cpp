#include "parallel/piece_metric_runs.hpp"

#include <cmath>

#include "io/record_run.hpp"
#include "mesh/measure.hpp"
#include "parallel/communicator.hpp"

namespace hocav {
namespace {

// What a piece tells a vertex's process: the vertex's metric and its elements' summed measure there.
template <int D>
struct PieceVertexMetric {
  Index id;
  SymMat<D> metric;
  double measure;
};

}  // namespace

template <int D>
VertexRunMetrics<D> runs_of_piece_metrics(const MeshPart<D>& piece, Index vertex_count, const std::vector<SymMat<D>>& metrics) {
  const std::vector<double> measure = vertex_element_measures(piece.mesh);
  std::vector<std::vector<PieceVertexMetric<D>>> outgoing(static_cast<std::size_t>(process_count()));
  for (std::size_t v = 0; v < piece.global_ids.size(); ++v) {
    const Index id = piece.global_ids[v];
    outgoing[static_cast<std::size_t>(slice_holding(id, vertex_count, process_count()))].push_back({id, metrics[v], measure[v]});
  }
  VertexRunMetrics<D> run;
  run.first = slice_start(vertex_count, process_rank(), process_count());
  const auto size = static_cast<std::size_t>(slice_start(vertex_count, process_rank() + 1, process_count()) - run.first);
  run.metrics.resize(size);
  run.measures.assign(size, 0.0);
  for (const PieceVertexMetric<D>& vertex : exchange_values_joined(outgoing)) {
    run.metrics[static_cast<std::size_t>(vertex.id - run.first)] = vertex.metric;
    run.measures[static_cast<std::size_t>(vertex.id - run.first)] += vertex.measure;
  }
  return run;
}

template VertexRunMetrics<2> runs_of_piece_metrics(const MeshPart<2>&, Index, const std::vector<SymMat<2>>&);
template VertexRunMetrics<3> runs_of_piece_metrics(const MeshPart<3>&, Index, const std::vector<SymMat<3>>&);

}  // namespace hocav
