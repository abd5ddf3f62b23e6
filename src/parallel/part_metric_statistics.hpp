// The figures of a distributed mesh's output (`hocav adapt`'s edge lengths and qualities,
// mesh_statistics.hpp) measured in its parts, no process holding the whole (docs/distributed.md §The
// end in the parts): each element by its part, each edge once.
#pragma once

#include <span>

#include "parallel/mesh_parts.hpp"
#include "report/mesh_statistics.hpp"

namespace hocav {

// Every process at once, each with its part (P1, compact, global ids, pinned flags) and
// `vertex_metrics` at its vertices (.sol rows, as compute_metric_statistics takes them): the whole
// mesh's figures, on every process. An edge whose two ends other parts may hold (interface vertices,
// pinned ones) goes to the process its ends' global ids hash to, which counts it once; the parts'
// tallies add up in rank order. The figures are compute_metric_statistics's on the whole mesh, their
// sums in another order.
template <int D>
MetricStatistics distributed_metric_statistics(const MeshPart<D>& part, std::span<const double> vertex_metrics, int threads);

}  // namespace hocav
