// The implied metric (docs/method.md §10) of a mesh read in pieces (mesh_file_pieces.hpp), each
// vertex's at the process whose run of the file's vertices holds it (docs/distributed.md §Reading
// in pieces): no process holds the whole mesh.
#pragma once

#include <string>
#include <vector>

#include "geom/sym_mat.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

template <int D>
struct VertexRunMetrics {
  Index first = 0;                 // the file id of the run's first vertex
  std::vector<SymMat<D>> metrics;  // per vertex of the run
  std::vector<double> measures;    // per vertex of the run: the summed measure of its elements
};

// Every process at once, each with its piece (read_mesh_file_piece: its run of the file's elements,
// global ids the file's) of a file of `vertex_count` vertices: the implied metric of this process's
// run of vertices, bit for bit implied_metric_at_vertices' on the whole mesh. A vertex whose
// elements all lie in one piece gets that piece's sum; one whose elements lie in several gets their
// shares element by element, summed in the file's order as the serial sum is. Throws Error naming
// `path` and the element for a flat element, or the vertex for one that no element uses.
template <int D>
VertexRunMetrics<D> implied_metric_by_runs(const MeshPart<D>& piece, Index vertex_count, const std::string& path);

}  // namespace hocav
