#include "parallel/pieces_into_parts.hpp"

#include <chrono>
#include <numeric>

#include "base/stopwatch.hpp"
#include "io/gamma_mesh.hpp"
#include "io/node_metrics.hpp"
#include "io/record_run.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_graph.hpp"
#include "parallel/line_ids_by_ends.hpp"
#include "parallel/metrics_by_global_id.hpp"
#include "parallel/part_migration.hpp"

namespace hocav {

template <int D>
ScatteredPart<D> parts_of_pieces(MeshFilePiece<D> piece, const std::string& metric_path, std::int64_t seed) {
  const auto start = std::chrono::steady_clock::now();
  const RecordRun run{process_rank(), process_count()};
  const Index held_first = run.of(piece.vertex_count).first;
  const std::vector<SymMat<D>> held = metrics_of_rows<D>(read_metric_run(metric_path, D, piece.vertex_count, run));
  ScatteredPart<D> out;
  const std::vector<double> loads(static_cast<std::size_t>(piece.part.mesh.element_count()), 1.0);
  const std::vector<int> part_of = partition_distributed_part(piece.part, loads, {}, seed);
  std::vector<Index> element_ids(part_of.size());
  std::iota(element_ids.begin(), element_ids.end(), slice_start(piece.element_count, process_rank(), process_count()));
  out.element_ids = migrated_element_values(element_ids, part_of, &out.bytes_sent);
  out.facet_ids = migrated_facet_values(piece.part, piece.facet_ids, part_of, &out.bytes_sent);
  const std::vector<KnownLine> known = known_lines(piece.part, piece.line_ids);
  out.part = migrate_part(std::move(piece.part), part_of, &out.bytes_sent);
  piece = {};
  out.line_ids = line_ids_by_ends(out.part, known);
  out.metrics = metrics_by_global_id<D>(out.part.global_ids, held_first, held, out.bytes_sent);
  out.seconds = max_over_processes(seconds_since(start));
  return out;
}

template ScatteredPart<2> parts_of_pieces(MeshFilePiece<2>, const std::string&, std::int64_t);
template ScatteredPart<3> parts_of_pieces(MeshFilePiece<3>, const std::string&, std::int64_t);

}  // namespace hocav
