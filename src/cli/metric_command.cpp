// hocav metric MESH -o OUT.sol|.solb SOURCE [--gradation BETA] [source options]
//   SOURCE: --analytic NAME | --implied | --surface HN,HT | --hessian FIELD.sol|analytic:NAME | --input SOL
//         | --from BACK.mesh --from-metric BACK.sol
// A metric field on a mesh from one of the sources of docs/method.md §10, or interpolated from another
// mesh's metric (log-Euclidean, docs/method.md §2: to measure a remesher's output in its input metric),
// optionally graded, written with one row per node of the mesh file in the file's own node numbering.
// P2 mid nodes get the analytic or interpolated field at the node, or the input's row there;
// otherwise (and after gradation) the log-Euclidean mean of the metrics of their edge's two vertices.
#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "base/error.hpp"
#include "base/memory_budget.hpp"
#include "cli/command_support.hpp"
#include "cli/commands.hpp"
#include "cli/metric_sources.hpp"
#include "cli/number_checks.hpp"
#include "geom/sym_functions.hpp"
#include "io/gamma_mesh.hpp"
#include "io/node_metrics.hpp"
#include "io/output_set.hpp"
#include "io/record_run.hpp"
#include "metric/analytic_field.hpp"
#include "metric/analytic_metric.hpp"
#include "metric/gradation.hpp"
#include "metric/hessian_metric.hpp"
#include "metric/implied_metric.hpp"
#include "metric/surface_metric.hpp"
#include "parallel/boundary_of_parts.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_gradation.hpp"
#include "parallel/hessian_metric_runs.hpp"
#include "parallel/implied_metric_runs.hpp"
#include "parallel/mesh_file_pieces.hpp"
#include "parallel/metrics_by_global_id.hpp"
#include "parallel/piece_facet_orientation.hpp"
#include "parallel/piece_metric_runs.hpp"
#include "parallel/solution_file_runs.hpp"
#include "report/mesh_summary.hpp"

namespace hocav {
namespace {

enum class Source { kAnalytic, kImplied, kSurface, kHessian, kInput, kInterpolated };

struct MetricOptions {
  std::string mesh, output;
  std::string analytic, hessian, input;
  std::string back_mesh, back_metric;  // --from, --from-metric
  bool implied = false;
  std::vector<double> surface;  // h_n, h_t
  std::optional<double> gradation;
  std::optional<double> h, h_min, h_max, center, radius, width, complexity, norm;
  std::string axis;
  std::vector<double> origin;
};

Source chosen_source(const MetricOptions& options) {
  std::vector<Source> given;
  if (!options.analytic.empty()) given.push_back(Source::kAnalytic);
  if (options.implied) given.push_back(Source::kImplied);
  if (!options.surface.empty()) given.push_back(Source::kSurface);
  if (!options.hessian.empty()) given.push_back(Source::kHessian);
  if (!options.input.empty()) given.push_back(Source::kInput);
  if (!options.back_mesh.empty()) given.push_back(Source::kInterpolated);
  if (given.size() != 1)
    throw Error(
        "give exactly one metric source: --analytic NAME, --implied, --surface HN,HT, --hessian FIELD, --input SOL "
        "or --from MESH --from-metric SOL");
  return given.front();
}

// Options that belong to other sources, or to another analytic metric, are refused rather than
// silently ignored.
void check_options_apply(const MetricOptions& options, Source source) {
  const bool analytic = source == Source::kAnalytic;
  const bool hessian = source == Source::kHessian;
  const bool linear = analytic && options.analytic == "linear";
  const bool shear = analytic && options.analytic.starts_with("shear-");
  const bool uniform = analytic && !linear && !shear;  // or an unknown name, refused by name later
  const bool shaped = shear || (hessian && is_analytic_field(options.hessian));
  auto refuse_unless = [&options](bool given, bool applies, const char* what) {
    if (given && !applies)
      throw Error(std::string(what) + " does not apply to this metric source" +
                  (options.analytic.empty() ? "" : " (--analytic " + options.analytic + ")"));
  };
  refuse_unless(options.h.has_value(), uniform, "--h");
  refuse_unless(options.center.has_value() || !options.axis.empty(), linear, "--center, --axis");
  refuse_unless(options.radius.has_value() || options.width.has_value() || !options.origin.empty(), shaped, "--radius, --width, --origin");
  refuse_unless(options.h_min.has_value(), linear || shear || hessian, "--h-min");
  refuse_unless(options.h_max.has_value(), linear || shear || hessian || source == Source::kSurface, "--h-max");
  refuse_unless(options.complexity.has_value() || options.norm.has_value(), hessian, "--complexity, --norm");
  refuse_unless(!options.back_metric.empty(), source == Source::kInterpolated, "--from-metric");
  if (source == Source::kInterpolated && options.back_metric.empty()) throw Error("--from needs --from-metric SOL");
  if (options.h_min && options.h_max && *options.h_min > *options.h_max)
    throw Error("--h-min must not exceed --h-max (the smallest size first)");
  if (hessian && !options.complexity) throw Error("--hessian needs --complexity N");
  if (source == Source::kSurface && !options.gradation)
    throw Error("--surface needs --gradation BETA to carry the boundary sizes into the volume");
}

template <int D>
std::array<double, 3> origin_of(const MetricOptions& options) {
  std::array<double, 3> origin{0, 0, 0};
  if (options.origin.empty()) return origin;
  if (options.origin.size() != static_cast<std::size_t>(D))
    throw Error("--origin needs " + std::to_string(D) + " coordinates for a " + std::to_string(D) + "D mesh");
  std::copy(options.origin.begin(), options.origin.end(), origin.begin());
  return origin;
}

template <int D>
AnalyticMetricSpec analytic_metric_spec(const MetricOptions& options) {
  AnalyticMetricSpec spec;
  spec.name = options.analytic;
  spec.h = options.h.value_or(spec.h);
  spec.h_min = options.h_min.value_or(spec.h_min);
  spec.h_max = options.h_max.value_or(spec.h_max);
  if (!options.axis.empty()) spec.axis = options.axis[0] - 'x';
  spec.center = options.center.value_or(spec.center);
  spec.radius = options.radius.value_or(spec.radius);
  spec.width = options.width.value_or(spec.width);
  spec.origin = origin_of<D>(options);
  return spec;
}

template <int D>
HessianSource hessian_source(const MetricOptions& options) {
  HessianSource source;
  source.field = options.hessian;
  source.shape.radius = options.radius.value_or(source.shape.radius);
  source.shape.width = options.width.value_or(source.shape.width);
  source.shape.origin = origin_of<D>(options);
  source.complexity = *options.complexity;
  source.norm = options.norm;
  source.h_min = options.h_min;
  source.h_max = options.h_max;
  return source;
}

// The metric at the vertices and, when the source knows them exactly, at the P2 nodes (else empty).
template <int D>
struct SourceMetrics {
  std::vector<SymMat<D>> vertices, edge_nodes;
};

// The back mesh's metric interpolated at the nodes of `mesh` (MetricField: log-Euclidean in the back
// element containing the node, extended affinely just outside the back mesh).
template <int D>
SourceMetrics<D> interpolated_metrics(const Mesh<D>& mesh, const MetricOptions& options) {
  MeshFileContent back_file = read_mesh_file(options.back_mesh);
  const auto* back = std::get_if<Mesh<D>>(&back_file.mesh);
  if (back == nullptr) throw Error(options.back_mesh + ": the back mesh is not " + std::to_string(D) + "D like the mesh");
  const MetricField<D> field(*back, metrics_of_rows<D>(read_metric_for_mesh(options.back_metric, back_file, false)));
  Index hint = kNoIndex;  // the edge nodes continue from the last vertex
  SourceMetrics<D> metrics;
  metrics.vertices = metrics_at(field, mesh.vertices(), hint);
  if (mesh.is_p2()) metrics.edge_nodes = metrics_at(field, mesh.edge_nodes(), hint);
  return metrics;
}

template <int D>
SourceMetrics<D> source_metrics(const Mesh<D>& mesh, const MeshFileContent& file, const MetricOptions& options, Source source) {
  switch (source) {
    case Source::kAnalytic: {
      AnalyticMetricSpec spec = analytic_metric_spec<D>(options);
      SourceMetrics<D> metrics{analytic_metric_at_vertices(spec, mesh), {}};
      if (mesh.is_p2())
        for (Index e = 0; e < mesh.edge_count(); ++e) metrics.edge_nodes.push_back(analytic_metric<D>(spec, mesh.edge_node(e)));
      return metrics;
    }
    case Source::kImplied: return {implied_metric_at_vertices(mesh), {}};
    case Source::kSurface: return {surface_source_metrics(mesh, options.surface[0], options.surface[1], options.h_max), {}};
    case Source::kHessian: return {hessian_source_metrics(mesh, file, hessian_source<D>(options)), {}};
    case Source::kInput: {
      std::vector<SymMat<D>> rows = metrics_of_rows<D>(read_metric_for_mesh(options.input, file, mesh.is_p2()));
      auto first_node = rows.begin() + mesh.vertex_count();
      return {std::vector<SymMat<D>>(rows.begin(), first_node), std::vector<SymMat<D>>(first_node, rows.end())};
    }
    case Source::kInterpolated: return interpolated_metrics(mesh, options);
  }
  throw Error("internal error: unknown metric source");
}

// The rows of the output: one per node of the mesh file, in the file's numbering.
template <int D>
SolutionField rows_in_file_order(const Mesh<D>& mesh, const MeshFileContent& file, const SourceMetrics<D>& metrics) {
  std::vector<SymMat<D>> rows(static_cast<std::size_t>(file.file_node_count));
  std::vector<bool> filled(rows.size(), false);
  auto put = [&](Index file_node, const SymMat<D>& metric) {
    rows[static_cast<std::size_t>(file_node)] = metric;
    filled[static_cast<std::size_t>(file_node)] = true;
  };
  for (Index v = 0; v < mesh.vertex_count(); ++v) put(file.vertex_file_ids[v], metrics.vertices[v]);
  if (mesh.is_p2()) {
    std::vector<SymMat<D>> logs;
    if (metrics.edge_nodes.empty())
      for (const SymMat<D>& metric : metrics.vertices) logs.push_back(log_spd(metric));
    for (Index e = 0; e < mesh.edge_count(); ++e) {
      auto [a, b] = mesh.edge_vertices(e);
      put(file.edge_node_file_ids[e], metrics.edge_nodes.empty() ? exp_sym(0.5 * (logs[a] + logs[b])) : metrics.edge_nodes[e]);
    }
  }
  for (std::size_t node = 0; node < filled.size(); ++node)
    if (!filled[node]) throw Error("node " + one_based(node) + " of the mesh file is neither a vertex nor a P2 node: it gets no metric");
  return rows_of_metrics(rows);
}

template <int D>
void write_metric(const Mesh<D>& mesh, const MeshFileContent& file, const MetricOptions& options, Source source, OutputSet& outputs) {
  check_memory_fits("the metric on " + options.mesh, mesh.element_count(), kMetricBytesPerElement);
  SourceMetrics<D> metrics = source_metrics(mesh, file, options, source);
  if (options.gradation) {
    grade_metrics(mesh, metrics.vertices, GradationOptions{*options.gradation});
    metrics.edge_nodes.clear();  // an exact value at a node would ignore the gradation
  }
  SolutionField rows = rows_in_file_order(mesh, file, metrics);
  write_solution_file(options.output, {D, rows.count(), {rows}});
  outputs.commit();
  std::cout << "wrote " << options.output << ": " << rows.count() << " metrics, complexity " << metric_complexity(mesh, metrics.vertices)
            << " (" << mesh_summary(mesh) << ")\n";
}

// Under mpirun: the surface metric at the piece's vertices, made on the whole boundary every process
// gathers, the pieces' facets oriented first as the serial metric takes their normals
// (orient_piece_facets).
template <int D>
std::vector<SymMat<D>> surface_metric_of_piece(MeshFilePiece<D>& file_piece, const MetricOptions& options) {
  MeshPart<D>& piece = file_piece.part;
  if (!piece.mesh.has_topology()) piece.mesh.build_topology();
  orient_piece_facets(piece, file_piece.facet_ids);
  const MeshPart<D> boundary = boundary_of_parts(piece);
  const SurfaceSizes sizes{options.surface[0], options.surface[1], options.h_max.value_or(whole_diagonal(piece.mesh))};
  return values_from_boundary(piece, boundary.global_ids, surface_metric_at_boundary(boundary.mesh, sizes),
                              surface_interior_metric<D>(sizes));
}

// Under mpirun: the metric at this process's run of the file's vertices, from its piece: the implied
// metric (the serial one bit for bit) or the Hessian's (hessian_metric_by_runs) made by runs; a
// metric file's rows, the analytic or the surface metric at the piece's vertices; graded across the
// pieces (grade_piece_metrics) with --gradation.
template <int D>
VertexRunMetrics<D> metric_by_runs(MeshFilePiece<D>& piece, const MetricOptions& options, Source source) {
  MeshPart<D>& part = piece.part;
  const Index count = piece.vertex_count;
  std::optional<VertexRunMetrics<D>> run;
  std::vector<SymMat<D>> at_piece;
  long long bytes_sent = 0;
  if (source == Source::kImplied) run = implied_metric_by_runs(part, count, options.mesh);
  if (source == Source::kHessian)
    run = hessian_metric_by_runs(part, count, hessian_source<D>(options), whole_diagonal(part.mesh), options.mesh);
  if (source == Source::kInput) {
    const RecordRun rows{process_rank(), process_count()};
    at_piece = metrics_by_global_id(part.global_ids, rows.of(count).first,
                                    metrics_of_rows<D>(read_metric_run(options.input, D, count, rows)), bytes_sent);
  }
  if (source == Source::kAnalytic) at_piece = analytic_metric_at_vertices(analytic_metric_spec<D>(options), part.mesh);
  if (source == Source::kSurface) at_piece = surface_metric_of_piece(piece, options);
  if (run && !options.gradation) return *run;
  if (run) at_piece = metrics_by_global_id(part.global_ids, run->first, run->metrics, bytes_sent);
  if (options.gradation) grade_piece_metrics(part, at_piece, {*options.gradation});
  return runs_of_piece_metrics(part, count, at_piece);
}

// Under mpirun (docs/distributed.md §Reading in pieces): each process reads its piece of the mesh,
// computes the metric of its run of the file's vertices (metric_by_runs) and writes it in place; no
// process holds the whole mesh. Returns the summary line.
template <int D>
std::string write_metric_in_pieces(const MetricOptions& options, Source source) {
  MeshFilePiece<D> piece = read_mesh_file_piece<D>(options.mesh);
  const VertexRunMetrics<D> run = metric_by_runs(piece, options, source);
  write_solution_runs(options.output, rows_of_metrics(run.metrics), run.first, piece.vertex_count);
  std::vector<double> volumes;  // vertex_volumes' (to the last bits): each element's measure shared among its vertices
  for (double measure : run.measures) volumes.push_back(measure / (D + 1));
  const double complexity = metric_complexity<D>(volumes, run.metrics);
  std::ostringstream line;
  line << "wrote " << options.output << ": " << piece.vertex_count << " metrics, complexity " << sum_over_processes(complexity) << " ("
       << p1_mesh_summary(D, piece.vertex_count, piece.element_count, piece.facet_count) << ", read in " << process_count() << " pieces)\n";
  return line.str();
}

void run_metric_in_pieces(const MetricOptions& options, Source source) {
  if (source == Source::kInterpolated)
    throw Error("under mpirun, hocav metric does not interpolate (--from): run it on one process (docs/distributed.md §Reading in pieces)");
  const std::string extension = file_extension(options.mesh);
  if (extension != ".mesh" && extension != ".meshb")
    throw Error(options.mesh + ": under mpirun, hocav metric reads Gamma meshes (.mesh, .meshb) in pieces, not '" + extension + "'");
  if (file_extension(options.output) != ".solb")
    throw Error(options.output + ": under mpirun, the metric is written as .solb (each process writes its rows in place)");
  std::optional<OutputSet> outputs;  // rank 0's, which checks the paths and writes the file's keywords
  if (process_rank() == 0) {
    outputs.emplace();
    outputs->add_input(options.mesh, "the input mesh");
    if (source == Source::kInput) outputs->add_input(options.input, "--input");
    if (source == Source::kHessian && !is_analytic_field(options.hessian)) outputs->add_input(options.hessian, "--hessian");
    outputs->add_output(options.output, "-o");
  }
  const std::string summary = gamma_mesh_dimension(options.mesh) == 2 ? write_metric_in_pieces<2>(options, source)
                                                                      : write_metric_in_pieces<3>(options, source);
  if (!outputs) return;
  outputs->commit();
  std::cout << summary;
}

void run_metric(const MetricOptions& options) {
  Source source = chosen_source(options);
  check_options_apply(options, source);
  std::string extension = file_extension(options.output);
  if (extension != ".sol" && extension != ".solb")
    throw Error(options.output + ": a metric is written as .sol or .solb, not '" + extension + "'");
  if (process_count() > 1) return run_metric_in_pieces(options, source);
  OutputSet outputs;
  outputs.add_input(options.mesh, "the input mesh");
  if (source == Source::kInput) outputs.add_input(options.input, "--input");
  if (source == Source::kHessian && !is_analytic_field(options.hessian)) outputs.add_input(options.hessian, "--hessian");
  if (source == Source::kInterpolated) {
    outputs.add_input(options.back_mesh, "--from");
    outputs.add_input(options.back_metric, "--from-metric");
  }
  outputs.add_output(options.output, "-o");
  MeshFileContent file = read_mesh_file(options.mesh);
  std::visit([&](const auto& mesh) { write_metric(mesh, file, options, source, outputs); }, file.mesh);
}

std::string names_text(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

void add_metric_command(CLI::App& app) {
  auto options = std::make_shared<MetricOptions>();
  CLI::App* command = app.add_subcommand(
      "metric",
      "Compute a metric on a mesh: analytic, implied, surface, Hessian-based, given or interpolated from another "
      "mesh's; optionally graded");
  command->add_option("mesh", options->mesh, "mesh to read (.mesh, .meshb, .msh)")->required();
  command->add_option("-o,--output", options->output, "metric to write (.sol, .solb), one row per node of MESH")->required();

  command->add_option("--analytic", options->analytic, "source: an analytic metric (" + names_text(analytic_metric_names()) + ")");
  command->add_flag("--implied", options->implied, "source: the metric in which MESH is a unit mesh");
  command
      ->add_option("--surface", options->surface,
                   "source: size HN along the boundary normal and HT along the boundary, carried inside by "
                   "--gradation (required)")
      ->delimiter(',')
      ->expected(2)
      ->check(finite_positive());
  command->add_option("--hessian", options->hessian,
                      "source: the Lp metric of the Hessian of a scalar field, FIELD.sol(b) at the nodes or "
                      "analytic:NAME (" +
                          names_text(analytic_field_names()) + ")");
  command->add_option("--input", options->input, "source: an existing metric of MESH (.sol/.solb), e.g. to grade it");
  command->add_option("--from", options->back_mesh,
                      "source: the metric of another mesh BACK (.mesh, .meshb, .msh; --from-metric) interpolated "
                      "log-Euclidean at the nodes of MESH, e.g. a remesher's input metric at its output");
  command->add_option("--from-metric", options->back_metric, "the metric of the --from mesh (.sol/.solb), one row per node");
  command->add_option("--gradation", options->gradation, "grade the metric: sizes grow by at most BETA > 1 per unit length")
      ->check(finite_positive());

  command->add_option("--h", options->h, "analytic uniform: size (default 0.1)")->check(finite_positive());
  command->add_option("--h-min", options->h_min, "analytic: smallest size (default 0.001); hessian: bound on |H| (default 1e-6 h-max)")
      ->check(finite_positive());
  command
      ->add_option("--h-max", options->h_max,
                   "analytic: largest size (default 0.1); hessian: bound on |H|, surface: initial interior size "
                   "(default for both: the bounding-box diagonal)")
      ->check(finite_positive());
  command->add_option("--axis", options->axis, "analytic linear: the axis the size varies along (x, y, z; default the last)")
      ->check(CLI::IsMember({"x", "y", "z"}));
  command->add_option("--center", options->center, "analytic linear: the coordinate of the smallest size (default 0.5)")
      ->check(finite_number());
  command->add_option("--radius", options->radius, "analytic shear-*, tanh-shock: radius of the layer (default 0.75)")
      ->check(finite_number());
  command->add_option("--width", options->width, "analytic shear-*, tanh-shock: width of the layer (default 0.05)")
      ->check(finite_positive());
  command->add_option("--origin", options->origin, "analytic shear-*, tanh-shock: centre X,Y[,Z] of the layer (default 0)")
      ->delimiter(',')
      ->expected(2, 3)
      ->check(finite_number());
  command->add_option("--complexity", options->complexity, "hessian: target complexity N (about the vertex count)")
      ->check(finite_positive());
  command->add_option("--norm", options->norm, "hessian: the p of the Lp norm of the error (default 2)")->check(finite_positive());
  command->callback([options] { run_metric(*options); });
}

}  // namespace hocav
