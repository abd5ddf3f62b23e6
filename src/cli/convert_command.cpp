// hocav convert IN OUT [--metric SOL] [--metric-out SOL] [--order 1|2] [--meshb-version N]
// Reads any supported mesh, writes it in the format of OUT's extension. A metric given with the
// mesh is checked and carried to the output's node numbering; everything is validated before the
// first byte is written, and the mesh and its metric replace their targets together or not at all.
// Under mpirun a P1 Gamma mesh is read in pieces and written in runs, as a Gamma mesh, a .msh or a
// .vtu (docs/distributed.md §Writing in runs, §A .msh in runs, §A .vtu in runs).
#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>

#include "base/error.hpp"
#include "cli/command_support.hpp"
#include "cli/commands.hpp"
#include "io/gamma_mesh.hpp"
#include "io/node_metrics.hpp"
#include "io/output_set.hpp"
#include "io/vtu_file.hpp"
#include "parallel/communicator.hpp"
#include "parallel/gmsh_msh_runs.hpp"
#include "parallel/mesh_file_pieces.hpp"
#include "parallel/mesh_file_runs.hpp"
#include "parallel/output_file_runs.hpp"
#include "parallel/vtu_file_runs.hpp"
#include "report/curved_vtu.hpp"
#include "report/mesh_summary.hpp"

namespace hocav {
namespace {

struct ConvertOptions {
  std::string input, output, metric, metric_output;
  int order = 0;  // 0 keeps the input's order
  int gamma_version = 0;
};

// Where the metric goes: --metric-out, or beside OUT as .sol (.solb for a .meshb OUT); a .vtu OUT
// carries the metric as point data, so no solution file unless asked for.
std::string metric_output_path(const ConvertOptions& options) {
  if (options.metric.empty()) return "";
  std::string path = options.metric_output;
  if (path.empty()) {
    std::string extension = file_extension(options.output);
    if (extension == ".vtu") return "";
    path = options.output.substr(0, options.output.size() - extension.size()) + (extension == ".meshb" ? ".solb" : ".sol");
  }
  std::string extension = file_extension(path);
  if (extension != ".sol" && extension != ".solb") throw Error(path + ": a metric is written as .sol or .solb, not '" + extension + "'");
  return path;
}

template <int D>
void change_order(Mesh<D>& mesh, int order, bool with_metric) {
  if (order == 1) mesh.make_p1();
  if (order == 2 && !mesh.is_p2()) {
    if (with_metric) throw Error("--order 2 with --metric: the metric has no values at the new P2 nodes (convert the mesh alone)");
    mesh.make_p2();
  }
}

template <int D>
void convert(Mesh<D>& mesh, const MeshFileContent& file, const ConvertOptions& options, OutputSet& outputs) {
  const std::string metric_output = metric_output_path(options);
  change_order(mesh, options.order, !options.metric.empty());
  std::optional<SolutionField> metric;
  if (!options.metric.empty()) metric = read_metric_for_mesh(options.metric, file, mesh.is_p2());

  if (file_extension(options.output) == ".vtu") {
    VtuData data;
    if (metric) data.point_fields.push_back(metric_tensor_field<D>(*metric));
    data.cell_fields = jacobian_cell_fields(mesh);
    write_vtu(options.output, mesh, data);
  } else {
    write_mesh_file(options.output, mesh, {options.gamma_version});
  }
  if (metric && !metric_output.empty()) write_solution_file(metric_output, {D, metric->count(), {*metric}}, options.gamma_version);
  outputs.commit();
  std::cout << "wrote " << options.output << (metric_output.empty() ? "" : " and " + metric_output) << ": " << mesh_summary(mesh) << '\n';
}

void declare_convert_files(OutputSet& outputs, const ConvertOptions& options) {
  outputs.add_input(options.input, "the input mesh");
  if (!options.metric.empty()) outputs.add_input(options.metric, "--metric");
  check_writable_mesh_format(options.output);
  outputs.add_output(options.output, "the output mesh");
  if (const std::string metric_output = metric_output_path(options); !metric_output.empty())
    outputs.add_output(metric_output, "the output metric");
}

// Every process reads its piece of the mesh and writes it in runs: no process holds the whole mesh.
// The output's vertices keep their numbers, and its elements (part after part), facets and feature
// lines their order. Returns the summary line.
template <int D>
std::string convert_in_pieces(const ConvertOptions& options) {
  const MeshFilePiece<D> piece = read_mesh_file_piece<D>(options.input);
  if (file_extension(options.output) == ".vtu") {  // (docs/distributed.md §A .vtu in runs)
    write_vtu_runs(options.output, piece.part.mesh, {{}, jacobian_cell_fields(piece.part.mesh)});
    const MeshFileCounts counts = distinct_mesh_counts(piece.part);
    const auto facets = static_cast<Index>(std::count_if(piece.part.mesh.facet_refs().begin(), piece.part.mesh.facet_refs().end(),
                                                         [](int ref) { return ref != kInterfaceRef; }));
    return "wrote " + options.output + ": " + p1_mesh_summary(D, counts.vertices, counts.elements, sum_over_processes(facets)) + " (in " +
           std::to_string(process_count()) + " pieces, a vertex of several a point of each)\n";
  }
  const auto file_facets = static_cast<std::size_t>(std::find(piece.facet_ids.begin(), piece.facet_ids.end(), kNoIndex) -
                                                    piece.facet_ids.begin());
  // The file's facets and lines in their order (the interface facets come last); its elements are
  // the pieces' runs.
  const EntityOrders orders{{}, std::span(piece.facet_ids).first(file_facets), piece.line_ids};
  const MeshFileCounts counts = file_extension(options.output) == ".msh"
                                    ? write_gmsh_msh_runs(options.output, piece.part, orders)
                                    : write_mesh_runs(options.output, piece.part, file_extension(options.output) == ".meshb",
                                                      options.gamma_version, orders);
  return "wrote " + options.output + ": " + p1_mesh_summary(D, counts.vertices, counts.elements, counts.facets) + " (in " +
         std::to_string(process_count()) + " pieces)\n";
}

void run_convert_in_pieces(const ConvertOptions& options) {
  if (!options.metric.empty() || options.order == 2)
    throw Error("under mpirun, hocav convert writes P1 meshes alone: no --metric, no --order 2 (docs/distributed.md §Writing in runs)");
  if (const std::string extension = file_extension(options.input); extension != ".mesh" && extension != ".meshb")
    throw Error(options.input + ": under mpirun, hocav convert reads Gamma meshes (.mesh, .meshb) in pieces, not '" + extension + "'");
  if (const std::string extension = file_extension(options.output);
      extension != ".mesh" && extension != ".meshb" && extension != ".msh" && extension != ".vtu")
    throw Error(options.output + ": under mpirun, hocav convert writes Gamma meshes (.mesh, .meshb), a .msh or a .vtu in runs, not '" +
                extension + "'");
  std::optional<OutputSet> outputs;  // rank 0's, which checks the paths and writes the file's keywords
  if (process_rank() == 0) {
    outputs.emplace();
    declare_convert_files(*outputs, options);
  }
  const std::string summary = gamma_mesh_dimension(options.input) == 2 ? convert_in_pieces<2>(options) : convert_in_pieces<3>(options);
  if (!outputs) return;
  outputs->commit();
  std::cout << summary;
}

}  // namespace

void add_convert_command(CLI::App& app) {
  auto options = std::make_shared<ConvertOptions>();
  CLI::App* command = app.add_subcommand("convert",
                                         "Convert a mesh (and its metric) between formats: .mesh .meshb .msh -> .mesh .meshb .msh .vtu");
  command->add_option("input", options->input, "mesh to read (.mesh, .meshb, .msh)")->required();
  command->add_option("output", options->output, "mesh to write; the format follows the extension (.mesh, .meshb, .msh, .vtu)")->required();
  command->add_option("--metric", options->metric, "metric of the input mesh (.sol/.solb, one matrix per file node)");
  command->add_option("--metric-out", options->metric_output,
                      "where to write the metric (default: OUT with extension .sol, .solb for a .meshb OUT; "
                      "none for a .vtu OUT, which carries the metric as point data)");
  command
      ->add_option("--order", options->order,
                   "element order of the output: 1 drops the P2 nodes, 2 adds straight ones (default: the input's)")
      ->check(CLI::IsMember({1, 2}));
  command
      ->add_option("--meshb-version", options->gamma_version,
                   "version of binary .meshb/.solb output: 1-4 (default: 3, or 4 when counts need 64 bits)")
      ->check(CLI::Range(1, 4));
  command->callback([options] {
    if (process_count() > 1) return run_convert_in_pieces(*options);
    OutputSet outputs;
    declare_convert_files(outputs, *options);
    MeshFileContent file = read_mesh_file(options->input);
    std::visit([&](auto& mesh) { convert(mesh, file, *options, outputs); }, file.mesh);
  });
}

}  // namespace hocav
