#include "parallel/peer_iteration.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>

#include "base/stopwatch.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distinct_ids.hpp"
#include "parallel/interface_refinement.hpp"
#include "parallel/part_adaptation.hpp"
#include "parallel/part_migration.hpp"
#include "parallel/unsettled_vertices.hpp"

namespace hocav {
namespace {

// Every process's `bytes` to rank 0 (empty elsewhere).
std::vector<std::vector<std::byte>> gathered_on_root(std::vector<std::byte> bytes) {
  std::vector<std::vector<std::byte>> outgoing(static_cast<std::size_t>(process_count()));
  outgoing[0] = std::move(bytes);
  std::vector<std::vector<std::byte>> incoming = exchange_bytes(outgoing);
  if (process_rank() != 0) incoming.clear();
  return incoming;
}

// Per vertex: on the part's interfaces, or `unsettled`: the next partition cuts elsewhere, so that
// its parts adapt them (docs/distributed.md §The scheme, step 4).
template <int D>
std::vector<char> zone_to_keep_inside(const Mesh<D>& mesh, std::vector<char> unsettled) {
  const std::vector<char> interface = interface_vertex_flags(mesh);
  for (std::size_t v = 0; v < unsettled.size(); ++v) unsettled[v] = unsettled[v] || interface[v];
  return unsettled;
}

}  // namespace

AdaptationRun runs_combined_on_root(const AdaptationRun& run) {
  std::vector<AdaptationRun> unpacked;
  for (const std::vector<std::byte>& bytes : gathered_on_root(pack_run(run))) unpacked.push_back(unpack_run(bytes));
  return process_rank() == 0 ? combined(unpacked) : AdaptationRun{};
}

template <int D>
void count_whole_mesh(const MeshPart<D>& part, DistributedIteration& figures) {
  const std::vector<Index> shared = global_ids_of(part, interface_vertex_flags(part.mesh));
  figures.interface_vertices = distinct_count(shared);
  figures.vertices = sum_over_processes(part.mesh.vertex_count() - static_cast<Index>(shared.size())) + figures.interface_vertices;
  figures.elements = sum_over_processes(part.mesh.element_count());
  const auto interface_facets = std::count(part.mesh.facet_refs().begin(), part.mesh.facet_refs().end(), kInterfaceRef);
  figures.interface_faces = sum_over_processes(static_cast<Index>(interface_facets)) / 2;
}

template <int D>
void number_new_vertices(MeshPart<D>& part, Index& next_global_id) {
  const auto fresh = static_cast<Index>(std::count(part.global_ids.begin(), part.global_ids.end(), kNoIndex));
  const std::vector<Index> counts = all_gather_value(fresh);
  Index id = next_global_id + std::accumulate(counts.begin(), counts.begin() + process_rank(), Index{0});
  for (Index& global : part.global_ids)
    if (global == kNoIndex) global = id++;
  next_global_id += std::accumulate(counts.begin(), counts.end(), Index{0});
}

template <int D>
PeerIterationResult run_peer_iteration(MeshPart<D>& part, Index& next_global_id, const PeerIteration<D>& iteration,
                                       DistributedIteration& figures) {
  const auto start = std::chrono::steady_clock::now();
  const InterfaceRefinement refined = refine_interfaces(part, iteration.metric, iteration.geometry, next_global_id);
  figures.interface_edges_split = refined.edges_split;
  figures.interface_faces_turned = refined.faces_turned;
  const auto [run, own] = adapt_part_measured(part, iteration.metric, iteration.geometry, iteration.settings);
  number_new_vertices(part, next_global_id);
  count_whole_mesh(part, figures);
  for (const PartFigures& each : all_gather_value(own)) {
    figures.part_seconds.push_back(each.seconds);
    figures.peak_memory_bytes.push_back(each.peak_memory_bytes);
  }
  const PeerIterationResult result{runs_combined_on_root(run)};

  const auto moving = std::chrono::steady_clock::now();
  std::vector<char> unsettled = unsettled_vertex_flags(part.mesh, iteration.metric, iteration.settings.threads);
  figures.unsettled_vertices = distinct_count(global_ids_of(part, unsettled));
  long long bytes_sent = 0;
  if (iteration.next_metric)
    part = repartition(std::move(part), expected_element_counts(part.mesh, *iteration.next_metric),
                       zone_to_keep_inside(part.mesh, std::move(unsettled)), iteration.partition_seed, &bytes_sent);
  figures.bytes_sent += sum_over_processes(bytes_sent);
  figures.seconds_partition += seconds_since(moving);
  figures.seconds += seconds_since(start);
  return result;
}

template void count_whole_mesh(const MeshPart<2>&, DistributedIteration&);
template void count_whole_mesh(const MeshPart<3>&, DistributedIteration&);
template void number_new_vertices(MeshPart<2>&, Index&);
template void number_new_vertices(MeshPart<3>&, Index&);
template PeerIterationResult run_peer_iteration(MeshPart<2>&, Index&, const PeerIteration<2>&, DistributedIteration&);
template PeerIterationResult run_peer_iteration(MeshPart<3>&, Index&, const PeerIteration<3>&, DistributedIteration&);

}  // namespace hocav
