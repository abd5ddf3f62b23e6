// The curving of a distributed adaptation's output where the adaptation ends, in its parts
// (docs/distributed.md §Curving in the parts): no process gathers the adapted mesh. Every process
// curves its part with its interfaces frozen; a copy of the elements near the interfaces goes to rank
// 0, which curves the interfaces' vertices there and sends every process the nodes it wrote; each
// part then measures itself, and the figures add up.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "adapt/curved_adaptation.hpp"
#include "parallel/distributed_curving.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// What the curving did, the same on every process (but the rounds' vertex counts: rank 0's).
struct CurvingInParts {
  // As a serial curving's, but the counts of the output (elements, points before and after),
  // which the file's writing gives.
  CurvingReport report;
  std::optional<CurvedMeasures> curved;             // with measure_curved: the curved lengths and qualities
  std::array<DistributedCurvingRound, 2> rounds{};  // the parts, then the band on rank 0
  Index deferred_gains_in_parts = 0;                // edge gains measured in a part's own field past its border
};

// Every process at once, each with its part of the adapted mesh (P1, compact, global ids, pinned
// flags) and the metric at its vertices: the part becomes P2 and curved. `boundary` is the whole
// mesh's (boundary_of_parts) and `geometry` is made of it (may be null). The second round
// reinserts the first round's interface vertices, on the elements within kBandRings rings of them,
// in one part on rank 0, which sends every process the nodes of the edges it did not freeze.
template <int D>
CurvingInParts curve_in_parts(MeshPart<D>& part, const std::vector<SymMat<D>>& metrics, const MeshPart<D>& boundary,
                              const BoundaryGeometry<D>* geometry, const CurvingOptions& options, bool measure_curved);

}  // namespace hocav
