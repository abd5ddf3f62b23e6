#include "io/node_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"

namespace hocav {

SolutionField read_metric_for_mesh(const std::string& metric_path, const MeshFileContent& mesh_file, bool with_edge_nodes) {
  SolutionFileContent content = read_solution_file(metric_path);
  add_metric_of_sizes(content, metric_path);
  const SolutionField& field = checked_metric_field(content, metric_path, dimension_of(mesh_file.mesh), mesh_file.file_node_count);
  SolutionField rows{field.kind, field.dimension, {}};
  auto components = static_cast<std::size_t>(field.components());
  auto append_row = [&](Index file_node) {
    auto first = field.values.begin() + static_cast<std::ptrdiff_t>(file_node * components);
    rows.values.insert(rows.values.end(), first, first + static_cast<std::ptrdiff_t>(components));
  };
  rows.values.reserve(components * (mesh_file.vertex_file_ids.size() + mesh_file.edge_node_file_ids.size()));
  for (Index file_node : mesh_file.vertex_file_ids) append_row(file_node);
  if (with_edge_nodes)
    for (Index file_node : mesh_file.edge_node_file_ids) append_row(file_node);
  return rows;
}

SolutionField read_metric_run(const std::string& metric_path, int dimension, Index vertex_count, const RecordRun& run) {
  SolutionFileContent content = read_solution_file_run(metric_path, run);
  const Index first = run.of(content.count).first;
  add_metric_of_sizes(content, metric_path, first);
  return checked_metric_field(content, metric_path, dimension, vertex_count, first);
}

namespace {

// The first scalar field of `content` (of a mesh of `dimension` and `node_count` nodes), checked:
// one value per node.
const SolutionField& checked_scalar_field(const SolutionFileContent& content, const std::string& path, int dimension, Index node_count) {
  if (content.dimension != dimension)
    throw Error(path + ": Dimension: the solution is " + std::to_string(content.dimension) + "D but the mesh is " +
                std::to_string(dimension) + "D");
  const SolutionField* scalar = content.first_of_kind(SolutionKind::kScalar);
  if (!scalar) throw Error(path + ": SolAtVertices: no scalar field (type 1)");
  if (content.count != node_count)
    throw Error(path + ": SolAtVertices: " + std::to_string(content.count) + " values for a mesh of " + std::to_string(node_count) +
                " nodes");
  return *scalar;
}

double finite_value(const SolutionField& scalar, Index row, Index first_row, const std::string& path) {
  const double value = scalar.values[static_cast<std::size_t>(row - first_row)];
  if (!std::isfinite(value)) throw Error(path + ": SolAtVertices: value at node " + one_based(row) + " is not finite");
  return value;
}

}  // namespace

std::vector<double> read_scalar_for_mesh(const std::string& solution_path, const MeshFileContent& mesh_file) {
  const SolutionFileContent content = read_solution_file(solution_path);
  const SolutionField& scalar = checked_scalar_field(content, solution_path, dimension_of(mesh_file.mesh), mesh_file.file_node_count);
  std::vector<double> values;
  values.reserve(mesh_file.vertex_file_ids.size());
  for (Index file_node : mesh_file.vertex_file_ids) values.push_back(finite_value(scalar, file_node, 0, solution_path));
  return values;
}

std::vector<double> read_scalar_run(const std::string& solution_path, int dimension, Index vertex_count, const RecordRun& run) {
  const SolutionFileContent content = read_solution_file_run(solution_path, run);
  const SolutionField& scalar = checked_scalar_field(content, solution_path, dimension, vertex_count);
  const auto [first, last] = run.of(vertex_count);
  std::vector<double> values;
  for (Index row = first; row < last; ++row) values.push_back(finite_value(scalar, row, first, solution_path));
  return values;
}

template <int D>
std::vector<SymMat<D>> metrics_of_rows(const SolutionField& rows) {
  std::vector<SymMat<D>> metrics(rows.values.size() / SymMat<D>::kEntryCount);
  for (std::size_t v = 0; v < metrics.size(); ++v)
    std::copy_n(rows.values.begin() + static_cast<std::ptrdiff_t>(v * SymMat<D>::kEntryCount), SymMat<D>::kEntryCount,
                metrics[v].entries.begin());
  return metrics;
}

template <int D>
SolutionField rows_of_metrics(const std::vector<SymMat<D>>& metrics) {
  SolutionField rows{SolutionKind::kSymmetricMatrix, D, {}};
  rows.values.reserve(metrics.size() * SymMat<D>::kEntryCount);
  for (const SymMat<D>& metric : metrics) rows.values.insert(rows.values.end(), metric.entries.begin(), metric.entries.end());
  return rows;
}

template std::vector<SymMat<2>> metrics_of_rows(const SolutionField&);
template std::vector<SymMat<3>> metrics_of_rows(const SolutionField&);
template SolutionField rows_of_metrics(const std::vector<SymMat<2>>&);
template SolutionField rows_of_metrics(const std::vector<SymMat<3>>&);

}  // namespace hocav
