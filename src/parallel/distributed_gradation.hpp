// The size gradation (src/metric/gradation.hpp) of a metric given on a mesh in pieces or parts
// (docs/distributed.md §Adapting from pieces): no process holds the whole mesh.
#pragma once

#include <vector>

#include "metric/gradation.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// Every process at once, each with its piece (global ids, interface facets of ref kInterfaceRef
// towards the others) and the metric at its vertices. Rounds of: each process grades its piece's
// edges (grade_metrics), then the copies of every interface vertex meet at one process, which
// intersects them in rank order (within_bound: a copy at least as fine as the others is kept bit for
// bit) and sends the result to every holder; until no copy changes. Every edge of the whole mesh
// then meets the gradation within its tolerance, and the copies of a vertex are the same. A fixed
// point of the same constraints as the serial grading's, reached in another order: not the serial
// metrics to the last bits. Returns the rounds.
template <int D>
int grade_piece_metrics(const MeshPart<D>& piece, std::vector<SymMat<D>>& metrics, const GradationOptions& options);

}  // namespace hocav
