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

std::vector<double> read_scalar_for_mesh(const std::string& solution_path, const MeshFileContent& mesh_file) {
  SolutionFileContent content = read_solution_file(solution_path);
  if (content.dimension != dimension_of(mesh_file.mesh))
    throw Error(solution_path + ": Dimension: the solution is " + std::to_string(content.dimension) + "D but the mesh is " +
                std::to_string(dimension_of(mesh_file.mesh)) + "D");
  const SolutionField* scalar = content.first_of_kind(SolutionKind::kScalar);
  if (!scalar) throw Error(solution_path + ": SolAtVertices: no scalar field (type 1)");
  if (scalar->count() != mesh_file.file_node_count)
    throw Error(solution_path + ": SolAtVertices: " + std::to_string(scalar->count()) + " values for a mesh of " +
                std::to_string(mesh_file.file_node_count) + " nodes");
  std::vector<double> values;
  values.reserve(mesh_file.vertex_file_ids.size());
  for (Index file_node : mesh_file.vertex_file_ids) {
    double value = scalar->values[static_cast<std::size_t>(file_node)];
    if (!std::isfinite(value))
      throw Error(solution_path + ": SolAtVertices: value at node " + std::to_string(file_node + 1) + " is not finite");
    values.push_back(value);
  }
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
