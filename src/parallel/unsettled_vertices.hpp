// Where a part's loop left the mesh unadapted: the zones the next partition keeps inside its parts
// (docs/distributed.md §The scheme, step 4).
#pragma once

#include <vector>

#include "adapt/adaptation_metric.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

// An edge this long in the metric its loop adapted to was left unadapted: the loop's converged
// residue outside the unit window is spread everywhere but stays below it (up to about 2.3), and a
// bound of 6 let the 1M cube on 4 processes run away (docs/benchmarks.md "Sixty-second session").
constexpr double kUnsettledEdgeLength = 3;

// Per vertex of `mesh`: an end of an element edge longer than kUnsettledEdgeLength in `metric`.
template <int D>
std::vector<char> unsettled_vertex_flags(const Mesh<D>& mesh, const AdaptationMetric<D>& metric, int threads);

}  // namespace hocav
