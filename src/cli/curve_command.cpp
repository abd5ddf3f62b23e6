// hocav curve IN --metric SOL -o OUT [--surface p3|cad:FILE|none] [--jacobian-floor X] [--passes N]
//                [--threads N] [--quadrature RULE] [--report R.json] [--vtu V.vtu]
// The paper's algorithm: propose boundary curvature, then reinsert every volume vertex with the P2
// cavity operator, and write the curved P2 mesh with the Table-1 figures.
#include <iostream>
#include <memory>
#include <optional>

#include "adapt/proposal_node_source.hpp"
#include "adapt/reinsertion_curving.hpp"
#include "base/error.hpp"
#include "cli/command_support.hpp"
#include "cli/commands.hpp"
#include "geom/sym_functions.hpp"
#include "io/atomic_output.hpp"
#include "mesh/consistency.hpp"
#include "report/curving_report.hpp"
#include "surface/cad_boundary_gmsh.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

struct CurveOptions {
  std::string input, metric, output, report, vtu, surface = "p3", quadrature = "simpson";
  double jacobian_floor = 0.01;
  int passes = 1;
  int threads = 1;
  bool quiet = false;
};

// The metric at every output node (vertices, then P2 nodes from the back mesh), for the .vtu.
template <int D>
SolutionField metric_at_nodes(const Mesh<D>& mesh, const MetricField<D>& field) {
  std::vector<SymMat<D>> metrics;
  for (Index v = 0; v < mesh.vertex_count(); ++v) metrics.push_back(exp_sym(field.vertex_log_metric(v)));
  for (Index e = 0; e < mesh.edge_count(); ++e) metrics.push_back(exp_sym(field.log_metric_at(mesh.edge_node(e))));
  return rows_of_metrics(metrics);
}

// The geometry boundary edges are curved onto: none, the P3 surrogate of the input boundary, or a
// CAD file.
template <int D>
std::unique_ptr<BoundaryGeometry<D>> boundary_geometry(const std::string& surface, const Mesh<D>& mesh) {
  if (surface == "none") return nullptr;
  if (surface == "p3") return std::make_unique<P3Surrogate<D>>(mesh);
  if (surface.starts_with("cad:") && surface.size() > 4) return std::make_unique<CadBoundary<D>>(surface.substr(4), mesh);
  throw Error("--surface: 'p3', 'cad:FILE' or 'none', not '" + surface + "'");
}

template <int D>
void curve(Mesh<D>& mesh, const MeshFileContent& file, const CurveOptions& options) {
  const auto geometry = boundary_geometry<D>(options.surface, mesh);
  std::optional<BoundaryProposals<D>> proposals;
  std::optional<ProposalNodeSource<D>> boundary_nodes;
  if (geometry) {
    proposals.emplace(mesh, *geometry);
    boundary_nodes.emplace(*proposals);
  }
  const SolutionField rows = read_metric_for_mesh(options.metric, file, false);
  const MetricField<D> field(mesh, metrics_of_rows<D>(rows));
  const Index points_before = mesh.vertex_count();

  ReinsertionOptions reinsertion;
  reinsertion.cavity.jacobian_floor = options.jacobian_floor;
  reinsertion.passes = options.passes;
  reinsertion.threads = options.threads;
  const QuadratureRule rule = quadrature_rule_named(options.quadrature);
  reinsertion.cavity.optimizer.rule = &rule;
  int reported = 0;
  if (!options.quiet && mesh.vertex_count() > 20000)
    reinsertion.progress = [&](double fraction) {
      for (; reported < static_cast<int>(10 * fraction); ++reported) std::cerr << "curving: " << 10 * (reported + 1) << "%\n";
    };
  ReinsertionResult result =
      curve_by_reinsertion<D>(mesh, field, boundary_nodes ? &*boundary_nodes : nullptr, reinsertion);

  ConsistencyOptions consistency;
  consistency.require_positive_orientation = false;
  if (auto problems = check_consistency(mesh, consistency); !problems.empty())
    throw Error("internal error: the curved mesh is inconsistent: " + problems.front());
  CurvingReport report = make_curving_report(mesh, field, points_before, result,
                                             proposals ? static_cast<Index>(proposals->size()) : 0);
  report.threads = options.threads;

  write_mesh_file(options.output, mesh);
  if (!options.vtu.empty()) {
    VtuData data;
    data.point_fields.push_back(metric_tensor_field<D>(metric_at_nodes(mesh, field)));
    data.cell_fields = jacobian_cell_fields(mesh);
    write_vtu(options.vtu, mesh, data);
  }
  if (!options.report.empty()) {
    AtomicOutput out(options.report);
    write_curving_report_json(out.stream(), report);
    out.commit();
  }
  if (!options.quiet) {
    std::cout << "curved " << options.input << " -> " << options.output << '\n';
    write_curving_report_table(std::cout, report);
  }
}

}  // namespace

void add_curve_command(CLI::App& app) {
  auto options = std::make_shared<CurveOptions>();
  CLI::App* command = app.add_subcommand(
      "curve", "Curve a mesh in its metric: reinsert every volume vertex with the P2 cavity operator");
  command->add_option("input", options->input, "mesh to curve (.mesh, .meshb, .msh; P1 or P2)")->required();
  command->add_option("--metric", options->metric, "metric at the input's nodes (.sol/.solb)")->required();
  command->add_option("-o,--output", options->output, "curved P2 mesh to write (.mesh, .meshb, .msh, .vtu)")->required();
  command->add_option("--surface", options->surface, "boundary curvature: p3 (a cubic surrogate of the input boundary), cad:FILE (a STEP or BREP model; "
                      "facet refs name its surfaces or are matched by proximity), none")->capture_default_str();
  command->add_option("--jacobian-floor", options->jacobian_floor,
                      "every element the operator creates keeps its min normalized Jacobian above this")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command->add_option("--quadrature", options->quadrature,
                      "rule of the length the optimizer minimizes: simpson, trapezoid (the paper's), gauss-N")
      ->capture_default_str();
  command->add_option("--passes", options->passes, "reinsertion passes over the volume vertices")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  command->add_option("--threads", options->threads,
                      "threads that prepare independent cavities at once (the output does not depend on it)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  command->add_option("--report", options->report, "write the run's figures (Table-1 columns, counters) as JSON");
  command->add_option("--vtu", options->vtu, "also write a .vtu for ParaView (metric and min normalized Jacobian)");
  command->add_flag("-q,--quiet", options->quiet, "print nothing on success");
  command->callback([options] {
    MeshFileContent file = read_mesh_file(options->input);
    std::visit([&](auto& mesh) { curve(mesh, file, *options); }, file.mesh);
  });
}

}  // namespace hocav
