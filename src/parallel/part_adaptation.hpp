// One part's adaptation in the distributed loop (docs/distributed.md §The scheme): the serial loop
// on the part with its interfaces frozen and the early limits, its global ids and pinned flags
// carried through, the tags its own classification made at the interfaces dropped; its figures and
// its run as messages.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "adapt/adaptation_loop.hpp"
#include "adapt/boundary_settling.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// The settings of a part's loop: the run's, splitting no edge at an interface vertex and stopping
// two passes after the loop's window closes (docs/distributed.md §Frozen interfaces coarser than the
// metric), its ridges from the tags the whole mesh's classification made (§Parts).
AdaptationSettings part_settings(const AdaptationSettings& settings);

// A part's wall time and its process's peak memory, for the iteration's figures.
struct PartFigures {
  double seconds = 0;
  long long peak_memory_bytes = 0;
};

// Runs `change` on the part's mesh with the part's global ids and pinned flags following its
// vertices through every operation and compaction (vertex attributes): a new vertex gets kNoIndex
// and 0.
template <int D>
void change_keeping_global_ids(MeshPart<D>& part, const std::function<void(Mesh<D>&)>& change);

// Adapts `part` (without topology; with it on return) with `settings` as they are: its vertices keep
// their global ids and pinned flags, new vertices get kNoIndex and 0. The corners and the feature
// lines on interface edges that the part's own classification adds are dropped: the interfaces are
// no features of the whole mesh. Says how long it took and the process's peak memory after it.
template <int D>
std::pair<AdaptationRun, PartFigures> adapt_part_measured(MeshPart<D>& part, const AdaptationMetric<D>& metric,
                                                          const BoundaryGeometry<D>* geometry, const AdaptationSettings& settings);

// The boundary settling after the loop (boundary_settling.hpp) on `part` (with topology), `metrics` at
// its vertices: its interface vertices are frozen as every required vertex is, so both sides of an
// interface stay identical; the tags the part's own classification adds are dropped as above.
template <int D>
BoundarySettling settle_part_boundary(MeshPart<D>& part, std::span<const SymMat<D>> metrics, const BoundaryGeometry<D>& geometry,
                                      double feature_angle_degrees);

// A run as bytes and back.
std::vector<std::byte> pack_run(const AdaptationRun& run);
AdaptationRun unpack_run(const std::vector<std::byte>& bytes);

// The parts' runs as one: pass i sums the parts' passes i (their times: the slowest part's).
AdaptationRun combined(const std::vector<AdaptationRun>& runs);

}  // namespace hocav
