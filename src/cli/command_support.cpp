#include "cli/command_support.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "adapt/curving_run.hpp"
#include "base/error.hpp"
#include "bezier/mesh_quality.hpp"
#include "cli/progress_line.hpp"
#include "geom/sym_functions.hpp"
#include "mesh/consistency.hpp"
#include "mesh/mesh_defects.hpp"
#include "surface/cad_boundary_gmsh.hpp"
#include "surface/p3_surrogate.hpp"

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

std::vector<double> read_scalar_for_mesh(const std::string& solution_path, const MeshFileContent& mesh_file) {
  SolutionFileContent content = read_solution_file(solution_path);
  if (content.dimension != dimension_of(mesh_file.mesh))
    throw Error(solution_path + ": Dimension: the solution is " + std::to_string(content.dimension) + "D but the mesh is " +
                std::to_string(dimension_of(mesh_file.mesh)) + "D");
  auto scalar = std::find_if(content.fields.begin(), content.fields.end(),
                             [](const SolutionField& field) { return field.kind == SolutionKind::kScalar; });
  if (scalar == content.fields.end()) throw Error(solution_path + ": SolAtVertices: no scalar field (type 1)");
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

template std::vector<SymMat<2>> metrics_of_rows(const SolutionField&);
template std::vector<SymMat<3>> metrics_of_rows(const SolutionField&);
template SolutionField rows_of_metrics(const std::vector<SymMat<2>>&);
template SolutionField rows_of_metrics(const std::vector<SymMat<3>>&);
template <int D>
std::vector<VtuField> jacobian_cell_fields(const Mesh<D>& mesh) {
  VtuField minimum{"min_normalized_jacobian", 1, {}}, scaled{"scaled_jacobian", 1, {}};
  for (const auto& quality : mesh_jacobian_quality(mesh, kReportedRefinement)) {
    minimum.values.push_back(quality.min_normalized_jacobian);
    scaled.values.push_back(quality.scaled_jacobian);
  }
  return {std::move(minimum), std::move(scaled)};
}

namespace {

// Curving meshes this large takes long enough to show its progress.
constexpr Index kProgressVertices = 20000;

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
std::unique_ptr<BoundaryGeometry<D>> boundary_geometry(const std::string& surface, const Mesh<D>& mesh) {
  if (surface == "none") return nullptr;
  if (surface == "p3") return std::make_unique<P3Surrogate<D>>(mesh);
  if (surface.starts_with("cad:") && surface.size() > 4) return std::make_unique<CadBoundary<D>>(surface.substr(4), mesh);
  throw Error("--surface: 'p3', 'cad:FILE' or 'none', not '" + surface + "'");
}

template <int D>
void check_input_mesh(const Mesh<D>& mesh, const std::string& path) {
  ConsistencyOptions consistency;
  consistency.require_positive_orientation = !mesh.is_p2();  // as stats: a valid curved element may be an inverted P1 one
  if (auto problems = check_consistency(mesh, consistency); !problems.empty())
    throw Error(path + ": inconsistent mesh: " + std::to_string(problems.size()) + (problems.size() == 1 ? " problem" : " problems") +
                " (first: " + problems.front() + "; see hocav stats)");
  if (const MeshDefects defects = find_mesh_defects(mesh); !defects.none())
    std::cerr << "hocav: warning: " << path << ": " << defects.summary() << '\n';
}

template <int D>
CurvingReport curve_in_metric(Mesh<D>& mesh, const MetricField<D>& field, const CurvingSettings& settings) {
  const auto geometry = boundary_geometry<D>(settings.surface, mesh);
  ReinsertionOptions reinsertion;
  reinsertion.cavity.jacobian_floor = settings.jacobian_floor;
  reinsertion.passes = settings.passes;
  reinsertion.threads = settings.threads;
  const QuadratureRule rule = quadrature_rule_named(settings.quadrature);
  reinsertion.cavity.optimizer.rule = &rule;
  std::optional<ProgressLine> progress;
  if (settings.progress && stderr_is_terminal() && mesh.vertex_count() > kProgressVertices) {
    const double total = static_cast<double>(volume_vertices(mesh).size()) * settings.passes;
    progress.emplace(std::cerr, "curving", "vertices", total);
    reinsertion.progress = [&progress, total](double fraction) { progress->update(fraction * total); };
  }
  CurvingReport report = curve_with_boundary<D>(mesh, field, geometry.get(), reinsertion).report;
  if (progress) progress->complete();  // the last few vertices are not reported

  ConsistencyOptions consistency;
  consistency.require_positive_orientation = false;
  if (auto problems = check_consistency(mesh, consistency); !problems.empty())
    throw Error("internal error: the curved mesh is inconsistent: " + problems.front());
  return report;
}

template <int D>
void write_curved_vtu(const std::string& path, const Mesh<D>& mesh, const MetricField<D>& field) {
  VtuData data;
  data.point_fields.push_back(metric_tensor_field<D>(metric_at_nodes(mesh, field)));
  data.cell_fields = jacobian_cell_fields(mesh);
  write_vtu(path, mesh, data);
}

template void check_input_mesh(const Mesh<2>&, const std::string&);
template void check_input_mesh(const Mesh<3>&, const std::string&);
template CurvingReport curve_in_metric(Mesh<2>&, const MetricField<2>&, const CurvingSettings&);
template CurvingReport curve_in_metric(Mesh<3>&, const MetricField<3>&, const CurvingSettings&);
template void write_curved_vtu(const std::string&, const Mesh<2>&, const MetricField<2>&);
template void write_curved_vtu(const std::string&, const Mesh<3>&, const MetricField<3>&);
template std::vector<VtuField> jacobian_cell_fields(const Mesh<2>&);
template std::vector<VtuField> jacobian_cell_fields(const Mesh<3>&);
template VtuField metric_tensor_field<2>(const SolutionField&);
template VtuField metric_tensor_field<3>(const SolutionField&);
template std::unique_ptr<BoundaryGeometry<2>> boundary_geometry(const std::string&, const Mesh<2>&);
template std::unique_ptr<BoundaryGeometry<3>> boundary_geometry(const std::string&, const Mesh<3>&);
template std::string mesh_summary(const Mesh<2>&);
template std::string mesh_summary(const Mesh<3>&);

}  // namespace hocav
