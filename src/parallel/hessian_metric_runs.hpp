// The Lp metric of a scalar field's Hessian (docs/method.md §10) on a mesh read in pieces
// (mesh_file_pieces.hpp), each vertex's at the process whose run of the file's vertices holds it
// (docs/distributed.md §Reading in pieces): no process holds the whole mesh.
#pragma once

#include <string>

#include "metric/hessian_source.hpp"
#include "parallel/implied_metric_runs.hpp"

namespace hocav {

// Every process at once, each with its piece (read_mesh_file_piece: its run of the file's elements,
// global ids the file's) of a file of `vertex_count` vertices: the Lp metric of `source` at this
// process's run of vertices, the sizes' defaults made of `diagonal` (the whole mesh's bounding-box
// diagonal). A field file's run is read by each process (read_scalar_run). Each vertex's stencil is
// gathered from the pieces in recover_hessians' order, so its Hessian is the serial one bit for bit;
// the metric's scale sums the density over the processes, so the metrics may differ from
// lp_metric's in their last bits. `measures` holds each vertex's elements' summed measure. Throws
// Error naming `path` and a vertex that no element uses or whose 3-ring does not determine a
// quadratic.
template <int D>
VertexRunMetrics<D> hessian_metric_by_runs(const MeshPart<D>& piece, Index vertex_count, const HessianSource& source, double diagonal,
                                           const std::string& path);

}  // namespace hocav
