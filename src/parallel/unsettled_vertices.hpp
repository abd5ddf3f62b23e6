// Where a part's loop left the mesh unadapted: the zones the next partition keeps inside its parts
// (docs/distributed.md §The scheme, step 4).
#pragma once

#include <vector>

#include "adapt/adaptation_metric.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

// An edge this long in the metric its loop adapted to was left unadapted: the loop's converged
// residue outside the unit window is spread everywhere but stays below it.
constexpr double kUnsettledEdgeLength = 3;

// Per vertex of `mesh`: an end of an element edge longer than kUnsettledEdgeLength in `metric`.
template <int D>
std::vector<char> unsettled_vertex_flags(const Mesh<D>& mesh, const AdaptationMetric<D>& metric, int threads);

}  // namespace hocav
