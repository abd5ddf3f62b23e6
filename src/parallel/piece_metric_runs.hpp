// A metric made at the vertices of a mesh read in pieces, as the runs of the file's vertices
// (docs/distributed.md §Reading in pieces): what `mpirun hocav metric` writes of the sources
// evaluated at the pieces' vertices (analytic, surface) and of a graded metric.
#pragma once

#include <vector>

#include "geom/sym_mat.hpp"
#include "parallel/implied_metric_runs.hpp"

namespace hocav {

// Every process at once, each with its piece of a file of `vertex_count` vertices and a metric per
// piece vertex, the same at every copy of a vertex: this process's run of the file's vertices with
// their metrics and their elements' summed measures (those of the pieces together).
template <int D>
VertexRunMetrics<D> runs_of_piece_metrics(const MeshPart<D>& piece, Index vertex_count, const std::vector<SymMat<D>>& metrics);

}  // namespace hocav
