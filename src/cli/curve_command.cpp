// hocav curve IN --metric SOL -o OUT [--surface p3|cad:FILE|none] [--jacobian-floor X] [--passes N]
//                [--threads N] [--quadrature RULE] [--report R.json] [--vtu V.vtu]
// The paper's algorithm: propose boundary curvature, then reinsert every volume vertex with the P2
// cavity operator, and write the curved P2 mesh with the Table-1 figures. Under `mpirun -np N`
// (N > 1) the curving is distributed: every process reads its piece of a P1 Gamma input (else rank 0
// reads the input and scatters it), the parts curve themselves and write the output in runs
// (docs/distributed.md §Curving from pieces, §Curving in the parts; §A .msh in runs), and a .vtu
// beside it (§A .vtu in runs).
#include <iostream>
#include <memory>
#include <optional>
#include <utility>

#include "base/memory_budget.hpp"
#include "base/thread_pool.hpp"
#include "cli/command_support.hpp"
#include "cli/commands.hpp"
#include "cli/number_checks.hpp"
#include "io/atomic_output.hpp"
#include "io/gamma_mesh.hpp"
#include "io/node_metrics.hpp"
#include "io/output_set.hpp"
#include "parallel/communicator.hpp"
#include "parallel/curving_in_parts.hpp"
#include "parallel/distributed_curving.hpp"
#include "parallel/mesh_file_pieces.hpp"
#include "parallel/output_file_runs.hpp"
#include "parallel/piece_input_check.hpp"
#include "parallel/pieces_into_parts.hpp"
#include "parallel/root_mesh_scatter.hpp"
#include "parallel/vtu_file_runs.hpp"
#include "report/curved_vtu.hpp"
#include "report/curving_report.hpp"
#include "surface/boundary_choice.hpp"

namespace hocav {
namespace {

struct CurveOptions {
  std::string input, metric, output, report, vtu;
  std::string surface = "p3", quadrature = "simpson";
  CurvingOptions curving;
  bool quiet = false;
};

CurvingOptions curving_options(const CurveOptions& options) {
  CurvingOptions curving = options.curving;
  curving.quadrature = quadrature_rule_named(options.quadrature);
  return curving;
}

template <int D>
CurvingReport curve_with_progress(Mesh<D>& mesh, const MetricField<D>& field, const BoundaryGeometry<D>* geometry, CurvingOptions curving,
                                  bool quiet) {
  CurvingProgress progress(mesh, curving.passes, !quiet);
  progress.attach(curving);
  CurvingReport report = curve_in_metric(mesh, field, geometry, curving);
  progress.complete();
  return report;
}

// Whether a distributed curving in the parts reads its input in pieces, no process holding the
// whole (docs/distributed.md §Curving from pieces): a P1 Gamma file. Else rank 0 reads it and
// scatters it.
bool reads_input_in_pieces(const CurveOptions& options) {
  return is_gamma_path(options.input) && !gamma_mesh_has_p2_keyword(options.input);
}

// Every process: its part curved on the geometry of the parts' boundary, and written in runs with
// the input's elements, facets and feature lines in their order (docs/distributed.md §Curving in the parts).
template <int D>
CurvingInParts curve_parts(ScatteredPart<D> scattered, const CurveOptions& options) {
  const PartsGeometryMaker<D> geometry = [choice = boundary_choice_named(options.surface)](const Mesh<D>& boundary) {
    return std::shared_ptr<const BoundaryGeometry<D>>(make_boundary_geometry<D>(choice, boundary));
  };
  // As the serial run's: the metric field of the input.
  const std::optional<MetricField<D>> field = options.vtu.empty()
                                                  ? std::nullopt
                                                  : std::optional<MetricField<D>>(std::in_place, scattered.part.mesh, scattered.metrics);
  CurvingInParts curving = curve_in_parts(scattered.part, std::move(scattered.metrics), geometry, curving_options(options), false);
  curving.rounds[0].bytes_sent += sum_over_processes(scattered.bytes_sent);
  curving.rounds[0].seconds += scattered.seconds;
  // (The curving keeps the part's elements, facets and lines in their order.)
  count_curved_output(curving.report, write_mesh_file_runs(options.output, scattered.part,
                                                           {scattered.element_ids, scattered.facet_ids, scattered.line_ids}));
  if (field) write_vtu_runs(options.vtu, scattered.part.mesh, curved_vtu_data(scattered.part.mesh, *field));
  return curving;
}

// Every process: its piece of the input and its run of the metric's rows read, the pieces prepared
// and checked as the serial run prepares and checks the whole, cut into parts and curved.
template <int D>
CurvingInParts curve_from_pieces(const CurveOptions& options) {
  MeshFilePiece<D> piece = read_mesh_file_piece<D>(options.input);
  prepare_input_piece(piece, options.input, warn_on_stderr);
  check_memory_fits("curving " + options.input + " in " + std::to_string(process_count()) + " parts",
                    static_cast<double>(piece.element_count) / process_count(), kCurvingBytesPerElement);
  return curve_parts(parts_of_pieces(std::move(piece), options.metric, kCurvingPartitionSeed), options);
}

// Every process of a curving in the parts: from pieces, or from what rank 0 scatters (`mesh` and
// `metrics`, empty on the other processes).
template <int D>
CurvingInParts curve_in_parts_from(bool pieces, Mesh<D> mesh, std::vector<SymMat<D>> metrics, const CurveOptions& options) {
  if (pieces) return curve_from_pieces<D>(options);
  return curve_parts(scatter_from_root(std::move(mesh), std::move(metrics), kCurvingPartitionSeed), options);
}

// The other processes of a curving in the parts: the plan rank 0 sends (the dimension, whether the
// input is read in pieces), then their share of the curving.
void serve_curving(const CurveOptions& options) {
  std::vector<int> plan;
  broadcast_values(plan);
  if (plan.at(0) == 2)
    curve_in_parts_from<2>(plan.at(1) != 0, {}, {}, options);
  else
    curve_in_parts_from<3>(plan.at(1) != 0, {}, {}, options);
}

// The report, then the outputs committed and the summary printed.
void finish_outputs(const CurveOptions& options, const CurvingReport& report, OutputSet& outputs) {
  if (!options.report.empty()) {
    AtomicOutput out(options.report);
    write_curving_report_json(out.stream(), report);
    out.commit();
  }
  outputs.commit();
  if (!options.quiet) {
    std::cout << "curved " << options.input << " -> " << options.output << '\n';
    write_curving_report_table(std::cout, report);
  }
}

// Rank 0 of a curving in the parts (several processes): the plan (the dimension, whether from pieces)
// to every process, then its share of the curving from pieces or from its set-up `mesh` and
// `metrics`; the report made of what the parts curved and wrote.
template <int D>
void curve_on_rank_0_of_parts(bool pieces, Mesh<D> mesh, std::vector<SymMat<D>> metrics, const CurveOptions& options, OutputSet& outputs) {
  std::vector<int> plan{D, pieces ? 1 : 0};
  broadcast_values(plan);
  const CurvingInParts curving = curve_in_parts_from(pieces, std::move(mesh), std::move(metrics), options);
  if (!options.quiet)
    for (const DistributedCurvingRound& round : curving.rounds)
      if (round.round > 0) print_curving_round(round);
  finish_outputs(options, curving.report, outputs);
}

template <int D>
void curve(Mesh<D>& mesh, const MeshFileContent& file, const CurveOptions& options, OutputSet& outputs) {
  // (Before the parts are cut; a boundary face without a facet would stay straight.)
  prepare_input_mesh(mesh, options.input, warn_on_stderr);
  check_mesh_or_warn(mesh, options.input);
  check_memory_fits("curving " + options.input, mesh.element_count(), kCurvingBytesPerElement);
  std::vector<SymMat<D>> metrics = metrics_of_rows<D>(read_metric_for_mesh(options.metric, file, false));
  if (process_count() > 1) return curve_on_rank_0_of_parts(false, std::move(mesh), std::move(metrics), options, outputs);
  const MetricField<D> field(mesh, std::exchange(metrics, {}));  // (the field keeps their logarithms)
  const auto geometry = make_boundary_geometry<D>(boundary_choice_named(options.surface), mesh);
  const CurvingReport report = curve_with_progress(mesh, field, geometry.get(), curving_options(options), options.quiet);

  write_mesh_file(options.output, mesh);
  if (!options.vtu.empty()) write_curved_vtu(options.vtu, mesh, field);
  finish_outputs(options, report, outputs);
}

void declare_curve_files(OutputSet& outputs, const CurveOptions& options) {
  outputs.add_input(options.input, "the input mesh");
  outputs.add_input(options.metric, "--metric");
  if (options.surface.starts_with("cad:")) outputs.add_input(options.surface.substr(4), "--surface cad:");
  check_writable_mesh_format(options.output);
  outputs.add_output(options.output, "-o");
  if (!options.report.empty()) outputs.add_output(options.report, "--report");
  if (!options.vtu.empty()) outputs.add_output(options.vtu, "--vtu");
}

}  // namespace

void add_curve_command(CLI::App& app) {
  auto options = std::make_shared<CurveOptions>();
  CLI::App* command = app.add_subcommand("curve", "Curve a mesh in its metric: reinsert every volume vertex with the P2 cavity operator");
  command->add_option("input", options->input, "mesh to curve (.mesh, .meshb, .msh; P1 or P2)")->required();
  command->add_option("--metric", options->metric, "metric at the input's nodes (.sol/.solb)")->required();
  command->add_option("-o,--output", options->output, "curved P2 mesh to write (.mesh, .meshb, .msh, .vtu)")->required();
  command
      ->add_option("--surface", options->surface,
                   "boundary curvature: p3 (a cubic surrogate of the input boundary), cad:FILE (a STEP or BREP model; "
                   "facet refs name its surfaces or are matched by proximity), none")
      ->capture_default_str();
  command
      ->add_option("--jacobian-floor", options->curving.jacobian_floor,
                   "every element the operator creates keeps its min normalized Jacobian above this")
      ->check(finite_range(0.0, 1.0, "0 to 1"))
      ->capture_default_str();
  command
      ->add_option("--quadrature", options->quadrature,
                   "rule of the length the optimizer minimizes: simpson, trapezoid (the paper's), gauss-N")
      ->capture_default_str();
  command->add_option("--passes", options->curving.passes, "reinsertion passes over the volume vertices")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  options->curving.threads = every_core();
  command
      ->add_option("--threads", options->curving.threads,
                   "threads that prepare independent cavities at once (default: every core; the output does not "
                   "depend on it)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  command->add_option("--report", options->report, "write the run's figures (Table-1 columns, counters) as JSON");
  command->add_option("--vtu", options->vtu, "also write a .vtu for ParaView (metric and min normalized Jacobian)");
  command->add_flag("-q,--quiet", options->quiet, "print nothing on success");
  command->callback([options] {
    if (process_rank() != 0) return serve_curving(*options);
    OutputSet outputs;
    declare_curve_files(outputs, *options);
    if (process_count() > 1 && reads_input_in_pieces(*options)) {
      if (gamma_mesh_dimension(options->input) == 2) return curve_on_rank_0_of_parts<2>(true, {}, {}, *options, outputs);
      return curve_on_rank_0_of_parts<3>(true, {}, {}, *options, outputs);
    }
    MeshFileContent file = read_mesh_file(options->input);
    std::visit([&](auto& mesh) { curve(mesh, file, *options, outputs); }, file.mesh);
  });
}

}  // namespace hocav
