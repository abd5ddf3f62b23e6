// The whole-mesh iterations of the distributed loop, peer to peer (docs/distributed.md §The scheme):
// every process adapts its part and numbers its new vertices; then PT-Scotch cuts the distributed
// dual graph again, with the faces near the iteration's interfaces heavy, and the elements migrate
// straight between processes. No process holds more than its part; the last iteration's parts stay
// where they are, for the last runs (distributed_adaptation.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "adapt/adaptation_loop.hpp"
#include "parallel/distributed_iteration.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

template <int D>
struct PeerIteration {
  const AdaptationMetric<D>& metric;  // the iteration's
  const BoundaryGeometry<D>* geometry;
  const AdaptationSettings& settings;  // the parts' loop's (part_settings)
  std::int64_t partition_seed;
  // The next iteration's metric, whose predicted output per element balances the next partition;
  // null for the last whole-mesh iteration, whose parts stay where they are.
  const AdaptationMetric<D>* next_metric;
};

// What an iteration leaves on rank 0 (empty elsewhere).
struct PeerIterationResult {
  AdaptationRun run;  // the parts' runs, combined
};

// Every process at once: the processes' runs combined (part_adaptation.hpp), on rank 0 (empty
// elsewhere).
AdaptationRun runs_combined_on_root(const AdaptationRun& run);

// Every process at once: the whole mesh's figures from the parts in `figures` (its vertices, those on
// interfaces once, its elements, its interface vertices and faces).
template <int D>
void count_whole_mesh(const MeshPart<D>& part, DistributedIteration& figures);

// Every process at once: numbers the part's new vertices (global id kNoIndex) from `next_global_id`,
// process after process, and advances it past every process's new vertices.
template <int D>
void number_new_vertices(MeshPart<D>& part, Index& next_global_id);

// Every process at once: adapts `part` (with global ids and pinned flags, no topology), numbers its
// new vertices from `next_global_id` (the same on every process, advanced past every process's new
// vertices), then migrates the elements as `iteration.next_metric` says. On rank 0, `figures` gets
// the iteration's figures but its number and metric fraction; its bytes sent and times are added to
// what it holds (the first iteration's scatter).
template <int D>
PeerIterationResult run_peer_iteration(MeshPart<D>& part, Index& next_global_id, const PeerIteration<D>& iteration,
                                       DistributedIteration& figures);

}  // namespace hocav
