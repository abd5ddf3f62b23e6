// The distributed P1 adaptation loop, ParMmg's scheme (docs/distributed.md §The scheme): rank 0
// partitions the mesh by the metric's predicted output per element, each process adapts its part
// with the interfaces frozen, rank 0 merges the parts by global vertex ids and partitions again so
// that the old interfaces fall inside parts; kDistributedIterations times.
#pragma once

#include <functional>

#include "adapt/adaptation_loop.hpp"

namespace hocav {

// Remeshing iterations: ParMmg's default is 3; the first here freezes the input's interfaces, as
// coarse as the input, and a fourth brought the 4-process test case within 1% of the serial run
// (docs/distributed.md).
constexpr int kDistributedIterations = 4;

struct DistributedIteration {
  int iteration = 0;                          // 1-based
  Index vertices = 0, elements = 0;           // of the merged mesh
  Index interface_vertices = 0;               // shared by parts in the iteration
  Index interface_faces = 0;                  // between parts, each counted once
  long long bytes_sent = 0;                   // parts out and back, without the input's broadcast
  double seconds = 0, seconds_partition = 0;  // the iteration, and its partitioning and split on rank 0
};

// On rank 0: adapts `mesh` (P1, with topology) with every process (the others in
// serve_distributed_adaptation), the same interface as adapt_to_metric. The mesh is compact and has
// its topology on return; the run's passes are each iteration's, summed over the parts, then those
// of the last serial run from the last interfaces (docs/distributed.md).
template <int D>
AdaptationRun adapt_distributed(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                                const AdaptationSettings& settings, const std::function<void(const DistributedIteration&)>& on_iteration);

// On the other ranks: adapts the parts rank 0 sends until it says stop.
template <int D>
void serve_distributed_adaptation(const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                                  const AdaptationSettings& settings);

}  // namespace hocav
