// The distributed P1 adaptation loop, ParMmg's scheme (docs/distributed.md §The scheme): rank 0
// cuts the mesh along a space-filling curve and scatters the pieces, which PT-Scotch partitions by
// the metric's predicted output per element; each process adapts its part with the interfaces
// frozen, and PT-Scotch cuts the distributed mesh again
// so that the old interfaces fall inside parts, the elements migrating between processes. After the
// fourth time the elements near the last interfaces go, interface by interface, to one of its two
// processes, and those near the seams left and the poor elements to rank 0, which run the serial
// loop there with the rest frozen; then every process ends with its part (PartsEnd: the output
// settled, measured, curved and written in runs from the parts).
#pragma once

#include <functional>
#include <optional>

#include "adapt/adaptation_loop.hpp"
#include "parallel/back_mesh_share.hpp"
#include "parallel/distributed_iteration.hpp"
#include "parallel/mesh_file_runs.hpp"
#include "parallel/mesh_parts.hpp"
#include "parallel/share_metric.hpp"

namespace hocav {

// Whole-mesh remeshing iterations (ParMmg's scheme; its default is 3 iterations), each partitioned
// so that the last one's interfaces fall inside parts (docs/distributed.md §The scheme).
constexpr int kDistributedIterations = 4;

// The report's entries after the whole-mesh iterations (docs/distributed.md §The scheme, step 5): the
// last runs in the parts, then on rank 0.
constexpr int kLastRunsInParts = kDistributedIterations + 1;
constexpr int kLastRunsOnRoot = kDistributedIterations + 2;

// The region of the last runs: the elements within this many rings of the last interfaces' vertices
// and of the poor elements' (one ring holds every element of a frozen vertex's ball; a second gives
// the loop room), whose own frozen border lies in the adapted region.
constexpr int kInterfaceBandRings = 2;

// What every process does with its part at the end of the loop (docs/distributed.md §The end in the
// parts): its part after the last runs (compact, with topology,
// global ids and pinned flags), and the target metric around it; it returns what it wrote.
template <int D>
using PartsEnd = std::function<MeshFileCounts(MeshPart<D>&, const AdaptationMetric<D>&)>;

// On rank 0: adapts `mesh` (P1, with topology) with every process (the others in
// serve_distributed_adaptation), the same interface as adapt_to_metric. `mesh` is the metric's back
// mesh, if it has one: the iterations' gradual metric starts from its own (docs/distributed.md). The mesh is compact and has
// its topology on return; the run's passes are each iteration's, summed over the parts, then those
// of the last serial runs near the last interfaces (docs/distributed.md). `partition_seed`: the
// partitioner's (element_partition.hpp; 0: its own). Every process ends with `end` on its part and
// `mesh` is left empty; the last runs' figures count what it wrote.
template <int D>
AdaptationRun adapt_distributed(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                                const AdaptationSettings& settings, std::int64_t partition_seed,
                                const std::function<void(const DistributedIteration&)>& on_iteration, const PartsEnd<D>& end);

// On the other ranks: adapts their parts in the whole-mesh iterations and the last runs, then ends
// with `end` on their parts (adapt_distributed), with the metric remade on
// the shares of the back mesh around them (docs/distributed.md §The back mesh in shares) from what
// rank 0 broadcasts (the size bounds, the Hausdorff distance) and `analytic`, the job's analytic
// metric if it has one. `geometry` is made from the input's boundary as rank 0's; `settings` is the
// job's but for the Hausdorff distance, which rank 0 sends. `end` as rank 0's.
template <int D>
void serve_distributed_adaptation(const std::optional<AnalyticMetricSpec>& analytic, const BoundaryGeometry<D>* geometry,
                                  AdaptationSettings settings, const PartsEnd<D>& end);

// What every process starts a run from pieces with (docs/distributed.md §Adapting from pieces): its
// piece of the input (read in pieces, prepared and classified; global ids the file's), its
// elements' predicted output in the first iteration's metric, its piece as its home share of the
// back mesh; the metric's recipe and the gradual steps, the same on every process.
template <int D>
struct PiecesStart {
  MeshPart<D> part;
  std::vector<double> loads;
  BackMeshShare<D> home;
  MetricRecipe recipe;
  int steps = 1;
};

// Every process at once: adapts the pieces of `start` as adapt_distributed adapts rank 0's whole
// mesh, no process holding the whole mesh or back mesh. The first partition is PT-Scotch's cut of
// the pieces by their loads; rank 0's last runs take their metric from the shares as the parts do;
// every process ends with `end` on its part. The run's figures (passes summed over the parts) on
// rank 0.
template <int D>
AdaptationRun adapt_distributed_from_pieces(PiecesStart<D> start, const BoundaryGeometry<D>* geometry, const AdaptationSettings& settings,
                                            std::int64_t partition_seed,
                                            const std::function<void(const DistributedIteration&)>& on_iteration, const PartsEnd<D>& end);

}  // namespace hocav
