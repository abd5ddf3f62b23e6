#include "cli/command_support.hpp"

#include <algorithm>

namespace hocav {

SolutionField read_metric_for_mesh(const std::string& metric_path, const MeshFileContent& mesh_file, bool with_edge_nodes) {
  SolutionFileContent content = read_solution_file(metric_path);
  const SolutionField& field =
      checked_metric_field(content, metric_path, dimension_of(mesh_file.mesh), mesh_file.file_node_count);
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

template <int D>
std::string mesh_summary(const Mesh<D>& mesh) {
  std::string summary = std::to_string(D) + "D P" + std::to_string(mesh.order()) + ": ";
  summary += std::to_string(mesh.vertex_count()) + " vertices, ";
  summary += std::to_string(mesh.element_count()) + (D == 2 ? " triangles, " : " tetrahedra, ");
  summary += std::to_string(mesh.facet_count()) + (D == 2 ? " boundary edges" : " boundary triangles");
  if (mesh.is_p2()) summary += ", " + std::to_string(mesh.edge_count()) + " P2 nodes";
  return summary;
}

template <int D>
VtuField metric_tensor_field(const SolutionField& metric) {
  VtuField field{"metric", 9, {}};
  auto components = static_cast<std::size_t>(metric.components());
  for (std::size_t first = 0; first < metric.values.size(); first += components)
    for (int row = 0; row < 3; ++row)
      for (int column = 0; column < 3; ++column) {
        int high = std::max(row, column), low = std::min(row, column);
        bool inside = row < D && column < D;
        field.values.push_back(inside ? metric.values[first + static_cast<std::size_t>(high * (high + 1) / 2 + low)] : 0.0);
      }
  return field;
}

template VtuField metric_tensor_field<2>(const SolutionField&);
template VtuField metric_tensor_field<3>(const SolutionField&);
template std::string mesh_summary(const Mesh<2>&);
template std::string mesh_summary(const Mesh<3>&);

}  // namespace hocav
