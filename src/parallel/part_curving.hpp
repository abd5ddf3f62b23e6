// One part's curving in a distributed curving (docs/distributed.md §Curving, §Curving in the parts):
// the part in its own metric field, its interfaces frozen, and the figures the parts and rounds add
// up.
#pragma once

#include <span>
#include <type_traits>
#include <vector>

#include "adapt/curving_run.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// Rounds after the first reinsert the vertices of the first round's interfaces only, on the
// elements within this many rings of them (a vertex's cavity is its ball, and a correction bends
// the edges around it, one ring further); the rest of the mesh is in no part.
constexpr int kBandRings = 2;

// What a part's curving did.
struct PartCurving {
  P2CavityCounters counters;
  ProposalCompletion completion;
  double seconds = 0;
  long long proposals_left = 0;
};
static_assert(std::is_trivially_copyable_v<PartCurving>);

// Curves one part in `field`, made of its vertices' log-metrics on its mesh (unmeasured: the whole
// mesh's figures are measured apart): its interface vertices lie on boundary facets, so they are not reinserted,
// and the interface edges get no proposal; with a `region` (per vertex) only the region's vertices
// are reinserted and only edges with both ends in it get a proposal. `geometry_ids`: per vertex,
// its id in the mesh the geometry was made from (ProposalScope).
template <int D>
PartCurving curve_part(MeshPart<D>& part, const MetricField<D>& field, const std::vector<char>& region, std::span<const Index> geometry_ids,
                       const BoundaryGeometry<D>* geometry, const CurvingOptions& options);

// The parts of a round as one: counts summed, times the slowest part's.
void add_part(PartCurving& round, const PartCurving& part);

// The rounds as one: counts and times summed.
void add_round(PartCurving& total, const PartCurving& round);

}  // namespace hocav
