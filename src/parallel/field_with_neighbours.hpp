// The metric field of a part with a ring of its neighbours' elements (docs/distributed.md §Curving
// in the parts, step 4): a curved edge or a point just past the part's border is sampled in the
// elements there, as in the whole mesh's field, not in the affine extension of the part's own
// (which, past a thin boundary-layer element, runs away: a curved length of 9.5 where the whole
// field gives under 2.6).
#pragma once

#include <vector>

#include "metric/metric_field.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// Every process at once, each with its part (global ids on every vertex) and the log-metric of
// each of its vertices: the field on a back mesh of the part's vertices and elements, in their order
// (so its vertex v is the part's), then the elements of the other parts with a vertex on one of this
// part's interfaces, with their vertices and log-metrics. `bytes_sent` grows by what this process
// sent to others.
template <int D>
MetricField<D> field_with_neighbours(const MeshPart<D>& part, const std::vector<SymMat<D>>& log_metrics, long long& bytes_sent);

}  // namespace hocav
