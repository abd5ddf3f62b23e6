// The curving of a distributed adaptation's output where the adaptation ends, in its parts
// (docs/distributed.md §Curving in the parts): no process gathers the adapted mesh. Every process
// curves its part with its interfaces frozen; a copy of the elements near each interface goes to one
// of its two processes, which curves the interface's vertices there and sends the parts the nodes it
// wrote (where three or more parts met, rank 0 does so last); each part then measures itself, and
// the figures add up.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "adapt/curved_adaptation.hpp"
#include "adapt/curving_run.hpp"
#include "parallel/curved_passes_in_parts.hpp"
#include "parallel/distributed_curving.hpp"
#include "parallel/mesh_file_runs.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// What the curving did, the same on every process.
struct CurvingInParts {
  // As a serial curving's, but the counts of the output (elements, points before and after),
  // which the file's writing gives.
  CurvingReport report;
  std::optional<CurvedMeasures> curved;  // with measure_curved: the curved lengths and qualities
  // The parts, then the interfaces' bands, then (3 or more processes) their seams on rank 0; a round
  // not run has round 0.
  std::array<DistributedCurvingRound, 3> rounds{};
  Index deferred_gains_in_parts = 0;          // edge gains measured in a part's own field past its border
  std::optional<CurvedPassesInParts> passes;  // with curved passes (adapt --curved)
};

// The geometry the curving makes of the boundary gathered from the parts (boundary_of_parts), null
// for none. Shared: it may be one the caller holds (a CAD model, of which one is open at a time).
template <int D>
using PartsGeometryMaker = std::function<std::shared_ptr<const BoundaryGeometry<D>>(const Mesh<D>& boundary)>;

// Every process at once, each with its part of a mesh (P1 or P2, compact, global ids, pinned flags)
// and the metric at its vertices: the part becomes P2 and curved, on the geometry `make_geometry`
// makes of the whole mesh's boundary, gathered from the parts (its bytes in the first round's). The
// second round reinserts the first round's interface vertices, on the elements within kBandRings
// rings of them, copied interface by interface onto the lighter of its two processes, which sends
// the parts the nodes of the edges it did not freeze; a third round, on rank 0, those left on the
// bands' seams. With `passes` (max_passes > 0), the curved passes follow (adapt_curved_in_parts, on the
// same geometry), which move elements between processes; the figures are measured after them.
template <int D>
CurvingInParts curve_in_parts(MeshPart<D>& part, std::vector<SymMat<D>> metrics, const PartsGeometryMaker<D>& make_geometry,
                              const CurvingOptions& options, bool measure_curved, const CurvedPassesSettings& passes = {});

// The report's counts (elements, points before and after) those of the file the parts wrote.
void count_curved_output(CurvingReport& report, const MeshFileCounts& counts);

}  // namespace hocav
