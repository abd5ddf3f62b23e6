// Distributed curving (docs/distributed.md §Curving): rank 0 partitions the mesh, each process
// curves its part with its interfaces frozen (interface vertices not reinserted, no boundary
// proposal on an interface edge), rank 0 merges the parts, partitions again with the old interfaces
// inside parts, and each process curves there the old interfaces' vertices: every interface edge
// is curved by one process only, in the second round.
#pragma once

#include <cstdint>
#include <functional>

#include "adapt/curving_run.hpp"

namespace hocav {

// The first round curves every part; the second the vertices of its interfaces, on the elements
// near them cut into as many parts; the third those the second froze again, near them in one part
// (rank 0's). A round with nothing pending is not run.
constexpr int kDistributedCurvingRounds = 3;

// PT-Scotch's seed for a curving's first partition: the same mesh, the same parts.
constexpr std::int64_t kCurvingPartitionSeed = 0;

struct DistributedCurvingRound {
  int round = 0;                           // 1-based
  int rounds = kDistributedCurvingRounds;  // at most
  Index interface_faces = 0;               // between parts, each counted once
  Index interface_vertices = 0;            // shared by parts in the round
  // Rounds 2 and 3: the vertices pending (on the interfaces of every round before) that lie on this
  // round's too (not reinserted).
  Index old_interface_vertices_frozen_again = 0;
  long long cavities = 0;    // prepared, summed over the parts
  long long bytes_sent = 0;  // parts out and back, with their metrics
  double seconds = 0;
};

// On rank 0: curves `mesh` (P1 or P2, compact, every vertex in an element) with every process (the
// others in serve_distributed_curving), the same interface as curve_in_metric. The field's back
// mesh and the mesh the geometry was made from have the mesh's vertices with the same ids (the
// input, or the adapted mesh); the other processes have the same geometry. The report's Table-1
// figures are measured on the merged mesh; its counters sum the parts' and rounds'.
template <int D>
CurvingReport curve_distributed(Mesh<D>& mesh, const MetricField<D>& field, const BoundaryGeometry<D>* geometry,
                                const CurvingOptions& options, const std::function<void(const DistributedCurvingRound&)>& on_round);

// On the other ranks: curves the parts rank 0 sends until it says stop.
template <int D>
void serve_distributed_curving(const BoundaryGeometry<D>* geometry, const CurvingOptions& options);

}  // namespace hocav
