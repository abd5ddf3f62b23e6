#include "report/curved_vtu.hpp"

#include <algorithm>

#include "bezier/mesh_quality.hpp"
#include "geom/sym_functions.hpp"
#include "io/node_metrics.hpp"

namespace hocav {
namespace {

// The metric at every output node (vertices, then P2 nodes from the back mesh), for the .vtu.
template <int D>
SolutionField metric_at_nodes(const Mesh<D>& mesh, const MetricField<D>& field) {
  std::vector<SymMat<D>> metrics;
  // Sampled at the vertices' positions: the mesh may be another than the field's back mesh (adapt).
  for (Index v = 0; v < mesh.vertex_count(); ++v) metrics.push_back(exp_sym(field.log_metric_at(mesh.vertex(v))));
  for (Index e = 0; e < mesh.edge_count(); ++e) metrics.push_back(exp_sym(field.log_metric_at(mesh.edge_node(e))));
  return rows_of_metrics(metrics);
}

}  // namespace

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

template <int D>
std::vector<VtuField> jacobian_cell_fields(const Mesh<D>& mesh) {
  VtuField minimum{"min_normalized_jacobian", 1, {}}, scaled{"scaled_jacobian", 1, {}};
  for (const auto& quality : mesh_jacobian_quality(mesh, kReportedRefinement)) {
    minimum.values.push_back(quality.min_normalized_jacobian);
    scaled.values.push_back(quality.scaled_jacobian);
  }
  return {std::move(minimum), std::move(scaled)};
}

template <int D>
VtuData curved_vtu_data(const Mesh<D>& mesh, const MetricField<D>& field) {
  VtuData data;
  data.point_fields.push_back(metric_tensor_field<D>(metric_at_nodes(mesh, field)));
  data.cell_fields = jacobian_cell_fields(mesh);
  return data;
}

template <int D>
void write_curved_vtu(const std::string& path, const Mesh<D>& mesh, const MetricField<D>& field) {
  write_vtu(path, mesh, curved_vtu_data(mesh, field));
}

template VtuField metric_tensor_field<2>(const SolutionField&);
template VtuField metric_tensor_field<3>(const SolutionField&);
template std::vector<VtuField> jacobian_cell_fields(const Mesh<2>&);
template std::vector<VtuField> jacobian_cell_fields(const Mesh<3>&);
template VtuData curved_vtu_data(const Mesh<2>&, const MetricField<2>&);
template VtuData curved_vtu_data(const Mesh<3>&, const MetricField<3>&);
template void write_curved_vtu(const std::string&, const Mesh<2>&, const MetricField<2>&);
template void write_curved_vtu(const std::string&, const Mesh<3>&, const MetricField<3>&);

}  // namespace hocav
