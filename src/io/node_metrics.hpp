// Per-node data read with a mesh file: the metric (or scalar field) of a .sol/.solb checked against
// the mesh file it goes with and renumbered to hocav's node order (docs/formats.md), and metric rows
// as matrices, both ways.
#pragma once

#include <string>
#include <vector>

#include "geom/sym_mat.hpp"
#include "io/mesh_file.hpp"
#include "io/solution_file.hpp"

namespace hocav {

// Reads the metric file given with a mesh file and checks it against that file (a symmetric matrix
// per file node, finite and positive definite). Returns its rows in the node order every writer
// uses: the mesh's vertices, then, when with_edge_nodes (a P2 mesh read as P2), each edge's node.
SolutionField read_metric_for_mesh(const std::string& metric_path, const MeshFileContent& mesh_file, bool with_edge_nodes);

// The metric rows of `run` of the file given with a P1 Gamma mesh file of `dimension` and
// `vertex_count` vertices (a mesh read in pieces), checked as read_metric_for_mesh checks the whole:
// the file's rows from run.of(vertex_count).first, which are those vertices' metrics.
SolutionField read_metric_run(const std::string& metric_path, int dimension, Index vertex_count, const RecordRun& run);

// The scalar field of a solution file given with a mesh file (the first scalar field, one finite
// value per file node), at the mesh's vertices.
std::vector<double> read_scalar_for_mesh(const std::string& solution_path, const MeshFileContent& mesh_file);

// The scalar field's values of `run` of the file given with a P1 Gamma mesh file of `dimension` and
// `vertex_count` vertices (a mesh read in pieces), checked as read_scalar_for_mesh checks the whole:
// the values of the file's vertices from run.of(vertex_count).first.
std::vector<double> read_scalar_run(const std::string& solution_path, int dimension, Index vertex_count, const RecordRun& run);

// Metric rows in .sol order and the matrices they hold, both ways.
template <int D>
std::vector<SymMat<D>> metrics_of_rows(const SolutionField& rows);
template <int D>
SolutionField rows_of_metrics(const std::vector<SymMat<D>>& metrics);

}  // namespace hocav
