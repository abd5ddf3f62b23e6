// hocav adapt IN --metric SOL | --analytic NAME | --hessian FIELD --complexity N [--norm P]
//                | --surface-sizes HN,HT | --implied -o OUT [--order 2|1] [--hmin H] [--hmax H]
//                [--hgrad BETA] [--hausd D] [--hausd-relative C] [--angle DEG] [--surface p3|cad:FILE|none]
//                [--curved] [--jacobian-floor J] [--iterations N] [--threads N] [--partition-seed S] [--report R.json]
//                [--vtu V.vtu]
// Metric-based adaptation to a unit mesh (split, collapse, swap, smooth; boundary points on the
// geometry), then, with --order 2, the curving of `hocav curve` in the same metric. Under
// `mpirun -np N` (N > 1) the P1 loop and the curving are distributed (docs/distributed.md); every
// process reads its piece of the input when adapts_from_pieces says so, else rank 0 reads it; the
// parts curve the output (with --curved: and run the curved passes) and write it in runs (its --vtu
// too).
#include <chrono>
#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>

#include "adapt/adaptation_driver.hpp"
#include "base/memory_budget.hpp"
#include "base/stopwatch.hpp"
#include "base/thread_pool.hpp"
#include "cli/command_support.hpp"
#include "cli/commands.hpp"
#include "cli/metric_sources.hpp"
#include "cli/number_checks.hpp"
#include "io/atomic_output.hpp"
#include "io/gamma_mesh.hpp"
#include "io/node_metrics.hpp"
#include "io/output_set.hpp"
#include "mesh/boundary_mesh.hpp"
#include "metric/implied_metric.hpp"
#include "parallel/adaptation_from_pieces.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_adaptation.hpp"
#include "parallel/output_in_parts.hpp"
#include "parallel/part_message.hpp"
#include "parallel/piece_input_check.hpp"
#include "report/curved_vtu.hpp"
#include "surface/boundary_choice.hpp"

namespace hocav {
namespace {

struct AdaptOptions {
  std::string input, metric, analytic, output, report, vtu, surface = "p3";
  std::string hessian;  // the Lp metric of a field's Hessian (metric_sources.hpp)
  std::optional<double> complexity, norm;
  std::vector<double> surface_sizes;  // HN, HT: the surface metric (needs --hgrad)
  bool implied = false;
  int order = 2;
  std::optional<double> h_min, h_max, gradation;
  std::optional<double> hausd_given;
  std::optional<double> hausd_relative;
  double angle = 45;
  double jacobian_floor = 0.01;
  int iterations = 20;
  int threads = every_core();
  std::int64_t partition_seed = 0;  // mpirun: the partitioner's random seed (0: its own)
  bool curved = false;
  bool quiet = false;
};

void check_options(const AdaptOptions& o) {
  const int sources = !o.metric.empty() + !o.analytic.empty() + !o.hessian.empty() + !o.surface_sizes.empty() + o.implied;
  if (sources != 1)
    throw Error(
        "give exactly one metric source: --metric SOL, --analytic NAME, --hessian FIELD --complexity N, --surface-sizes HN,HT or "
        "--implied");
  if (o.hessian.empty() != !o.complexity) throw Error("--hessian and --complexity N go together");
  if (o.norm && o.hessian.empty()) throw Error("--norm applies to --hessian only");
  if (!o.surface_sizes.empty() && !o.gradation)
    throw Error("--surface-sizes needs --hgrad BETA to carry the boundary sizes into the volume");
  if (o.curved && o.order == 1) throw Error("--curved adapts the curved mesh: it needs --order 2");
  if (o.h_min && o.h_max && *o.h_min > *o.h_max) throw Error("--hmin must not exceed --hmax");
  if (o.gradation && !o.analytic.empty())
    throw Error("--hgrad grades a metric given on a mesh: make one with `hocav metric --analytic NAME --gradation BETA`");
}

// A loop stopped by --iterations is worth a warning (non_convergence_summary says why).
void warn_if_not_converged(const AdaptOptions& o, const AdaptationReport& report) {
  if (const std::string why = non_convergence_summary(report); !why.empty()) warn_on_stderr(o.input + ": " + why);
}

// The metric source as warnings name it.
std::string metric_source_name(const AdaptOptions& o) {
  if (!o.metric.empty()) return o.metric;
  if (!o.analytic.empty()) return "--analytic " + o.analytic;
  if (!o.hessian.empty()) return "--hessian " + o.hessian;
  return o.implied ? "--implied" : "--surface-sizes";
}

// The Lp metric of --hessian FIELD --complexity N [--norm P] (sizes bounded by --hmin, --hmax).
HessianSource hessian_source(const AdaptOptions& o) {
  HessianSource source;
  source.field = o.hessian;
  source.complexity = *o.complexity;
  source.norm = o.norm;
  source.h_min = o.h_min;
  source.h_max = o.h_max;
  return source;
}

// The metric at the input's vertices (none for an analytic metric, evaluated at every vertex).
template <int D>
std::vector<SymMat<D>> vertex_metrics(const Mesh<D>& mesh, const MeshFileContent& file, const AdaptOptions& o) {
  if (!o.metric.empty()) return metrics_of_rows<D>(read_metric_for_mesh(o.metric, file, false));
  if (!o.hessian.empty()) return hessian_source_metrics(mesh, file, hessian_source(o));
  if (!o.surface_sizes.empty()) return surface_source_metrics(mesh, o.surface_sizes[0], o.surface_sizes[1], o.h_max);
  if (o.implied) return implied_metric_at_vertices(mesh);
  return {};
}

// The command's options as the library's job.
template <int D>
AdaptationJob<D> adaptation_job(const AdaptOptions& o) {
  AdaptationJob<D> job;
  if (!o.analytic.empty()) {
    job.analytic.emplace();
    job.analytic->name = o.analytic;
  }
  job.bounds = {o.h_min.value_or(0), o.h_max.value_or(1e300)};
  job.gradation = o.gradation;
  job.hausd = o.hausd_given;
  job.hausd_relative = o.hausd_relative;
  job.angle = o.angle;
  job.iterations = o.iterations;
  job.threads = o.threads;
  job.measure_output = !o.quiet || !o.report.empty();  // (what -q would not print)
  job.metric_name = metric_source_name(o);
  job.warn = warn_on_stderr;
  if (o.order == 2) {
    job.curving.emplace();
    job.curving->jacobian_floor = o.jacobian_floor;
    job.curving->threads = o.threads;
    job.curved = o.curved;
  }
  job.geometry = [surface = boundary_choice_named(o.surface)](const Mesh<D>& mesh) { return make_boundary_geometry<D>(surface, mesh); };
  if (!o.quiet) job.pass_progress = [](int pass, int cap) { std::cerr << "adapting: pass " << pass << " (at most " << cap << ")\n"; };
  return job;
}

// "lo-hi" of a rank's figures, each scaled by `unit`.
template <typename T>
std::string rank_range(const std::vector<T>& values, double unit) {
  if (values.empty()) return "-";
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  std::ostringstream text;
  text << std::setprecision(3) << static_cast<double>(*lo) / unit << "-" << static_cast<double>(*hi) / unit;
  return text.str();
}

void print_iteration(const DistributedIteration& figures) {
  std::ostringstream line, timing;  // figures to 3 digits: "metric 0.333 of the way", "0.0586 s"
  line << std::setprecision(3) << "distributed: ";
  timing << std::setprecision(3);
  if (figures.iteration == kLastRunsInParts) {
    line << "the last runs in the parts: " << figures.region_elements
         << " elements near the interfaces, each interface's with one of its processes, " << figures.elements << " elements after them, ";
    timing << "runs " << rank_range(figures.part_seconds, 1) << " s";
  } else if (figures.iteration == kLastRunsOnRoot) {
    line << "the last runs on rank 0: " << figures.region_elements
         << " elements where the parts' regions met and around the poor ones left, " << figures.elements << " elements after them, ";
    timing << "runs " << figures.part_seconds.at(0) << " s";
  } else {
    line << "iteration " << figures.iteration << " of " << kDistributedIterations << ": metric " << figures.metric_fraction
         << " of the way, " << process_count() << " parts (their interfaces refined first: " << figures.interface_edges_split
         << " edges split, " << figures.interface_faces_turned << " faces turned), " << figures.interface_faces << " interface faces, "
         << figures.interface_vertices << " of " << figures.vertices << " vertices on the interfaces, " << figures.unsettled_vertices
         << " at edges left longer than 3, ";
    timing << "partition " << figures.seconds_partition << " s; parts " << rank_range(figures.part_seconds, 1) << " s";
  }
  line << figures.bytes_sent << " bytes sent, " << figures.seconds << " s (" << timing.str() << ", peak memory "
       << rank_range(figures.peak_memory_bytes, 1 << 20) << " MiB per rank)\n";
  std::cerr << line.str();
}

// Prints each distributed iteration's figures (unless quiet) and keeps them in `iterations`.
std::function<void(const DistributedIteration&)> iteration_printer(const AdaptOptions& o, std::vector<DistributedIteration>& iterations) {
  return [&iterations, quiet = o.quiet](const DistributedIteration& figures) {
    if (!quiet) print_iteration(figures);
    iterations.push_back(figures);
  };
}

// The boundary of `mesh` to every process, whose geometry is made from it (the same as rank 0's):
// no other process holds the whole mesh (docs/distributed.md §What each process holds).
template <int D>
void broadcast_boundary(const Mesh<D>& mesh) {
  std::vector<std::byte> bytes = pack_part(boundary_mesh_of(mesh), {});
  broadcast_bytes(bytes);
}

// With --order 2, the parts' curving: the geometry of the adapted boundary as the serial run makes
// it, but a CAD model's, which is the adaptation's own `geometry` (one gmsh model is open at a time;
// the adapted mesh keeps the input's refs, which match it to the model).
template <int D>
std::optional<PartsCurvingStep<D>> parts_curving(const AdaptOptions& o, const AdaptationJob<D>& job, const BoundaryGeometry<D>* geometry) {
  if (!job.curving) return std::nullopt;
  PartsCurvingStep<D> step;
  if (boundary_choice_named(o.surface).kind == BoundaryKind::kCad)
    step.geometry = [geometry](const Mesh<D>&) { return std::shared_ptr<const BoundaryGeometry<D>>(std::shared_ptr<void>(), geometry); };
  else
    step.geometry = [make = job.geometry](const Mesh<D>& boundary) { return std::shared_ptr<const BoundaryGeometry<D>>(make(boundary)); };
  step.options = *job.curving;
  if (job.curved) step.passes = {job.iterations, job.angle};
  return step;
}

// The end in the parts with `geometry` and `settings` (rank 0's or the job's), its figures to `output`.
template <int D>
PartsEnd<D> end_in_parts(const AdaptOptions& o, const AdaptationJob<D>& job, const BoundaryGeometry<D>* geometry,
                         const AdaptationSettings& settings, std::optional<OutputInParts>& output) {
  return
      [&o, geometry, &settings, &output, curving = parts_curving(o, job, geometry)](MeshPart<D>& part, const AdaptationMetric<D>& metric) {
        output = finish_adaptation_in_parts(part, metric, geometry, settings, o.output, o.vtu, curving ? &*curving : nullptr);
        return output->counts;
      };
}

// The other processes: the same job, serving rank 0's distributed loop with the geometry of the
// input's boundary, then ending in their parts.
template <int D>
void serve_adaptation(const AdaptOptions& o, const std::vector<std::byte>& input_boundary) {
  AdaptationJob<D> job = adaptation_job<D>(o);
  job.warn = {};  // rank 0 warns
  job.pass_progress = {};
  const auto geometry = job.geometry(unpack_part<D>(input_boundary).mesh);
  const AdaptationSettings settings = job_settings(job, 0);
  std::optional<OutputInParts> output;
  serve_distributed_adaptation(job.analytic, geometry.get(), settings, end_in_parts<D>(o, job, geometry.get(), settings, output));
}

// The report, then the outputs committed and the summary printed.
void finish_outputs(const AdaptOptions& o, const AdaptationReport& report, OutputSet& outputs) {
  warn_if_not_converged(o, report);
  if (!o.report.empty()) {
    AtomicOutput out(o.report);
    write_adaptation_report_json(out.stream(), report);
    out.commit();
  }
  outputs.commit();
  if (!o.quiet) {
    std::cout << "adapted " << o.input << " -> " << o.output << '\n';
    write_adaptation_report_table(std::cout, report);
    if (report.curving) write_curving_report_table(std::cout, *report.curving);
  }
}

void print_curved_pass_rounds(const CurvedPassesInParts& passes) {
  static const char* const kWhere[] = {"every part, its interfaces frozen", "each interface's region with one of its processes",
                                       "the regions' seams on rank 0"};
  for (std::size_t r = 0; r < passes.rounds.size(); ++r) {
    const CurvedPassRound& round = passes.rounds[r];
    if (round.elements == 0) continue;  // (not run: no seams)
    std::ostringstream line;
    line << std::setprecision(3) << "distributed: curved passes, round " << r + 1 << " (" << kWhere[r] << "): " << round.elements
         << " elements, " << round.moved_elements << " moved to another process, " << round.passes << " passes, " << round.bytes_sent
         << " bytes sent, " << round.seconds << " s\n";
    std::cerr << line.str();
  }
}

// Rank 0 of a run that ends in its parts: the report made of what the parts measured, curved and
// wrote (`output`; their boundary settled when `has_geometry`), the adaptation timed from `start`,
// then the outputs committed.
void finish_in_parts(AdaptationReport& report, const OutputInParts& output, bool has_geometry, std::chrono::steady_clock::time_point start,
                     const AdaptOptions& o, OutputSet& outputs) {
  if (!o.quiet && output.curving) {
    for (const DistributedCurvingRound& round : output.curving->rounds)
      if (round.round > 0) print_curving_round(round);
    if (output.curving->passes) print_curved_pass_rounds(*output.curving->passes);
  }
  if (!o.quiet) {
    std::ostringstream line;
    line << std::setprecision(3) << "distributed: the end in the parts: " << output.counts.vertices << " vertices and "
         << output.counts.elements << " elements settled, measured, " << (output.curving ? "curved, " : "") << "written in runs, "
         << output.seconds << " s";
    if (output.curving) line << " (" << output.curving->deferred_gains_in_parts << " edge gains measured past a part's border)";
    line << '\n';
    std::cerr << line.str();
  }
  if (has_geometry) report.settling = output.settling;
  report.output_vertices = output.counts.vertices;
  report.output_elements = output.counts.elements;
  if (output.measures) report.measures = *output.measures;
  report.seconds_adapt = seconds_since(start) - output.seconds_curve;
  if (output.curving) {
    report.curving = output.curving->report;
    report.curved_measures = output.curving->curved;
    report.seconds_curve = output.seconds_curve;
    if (output.curving->passes) {
      report.curved_passes = output.curving->passes->run;
      for (const CurvedPassRound& round : output.curving->passes->rounds) report.seconds_curve -= round.seconds;  // (as serially: apart)
    }
  }
  report.peak_memory_bytes = peak_resident_bytes();
  finish_outputs(o, report, outputs);
}

// Rank 0 of a distributed run, which ends in its parts: the job set up on the whole input as the
// serial run's, the distributed loop, and the report made of what the parts measured, curved and
// wrote.
template <int D>
void adapt_in_parts(Mesh<D>& mesh, std::vector<SymMat<D>> metrics, const AdaptOptions& o, OutputSet& outputs) {
  const AdaptationJob<D> job = adaptation_job<D>(o);
  mesh.forget_edges();
  const auto setup = set_up_adaptation(mesh, std::move(metrics), job, o.input);
  AdaptationReport report = report_of_input(mesh);
  report.hausdorff_bounded_vertices = setup->hausdorff_bounded_vertices;
  std::optional<OutputInParts> output;
  broadcast_boundary(mesh);
  const auto start = std::chrono::steady_clock::now();  // after the set-up, as the serial run's
  report.run = adapt_distributed(mesh, *setup->metric, setup->geometry.get(), setup->settings, o.partition_seed,
                                 iteration_printer(o, report.distributed_iterations),
                                 end_in_parts<D>(o, job, setup->geometry.get(), setup->settings, output));
  finish_in_parts(report, *output, setup->geometry != nullptr, start, o, outputs);
}

// Whether a distributed run reads its input in pieces, no process holding the whole
// (docs/distributed.md §Adapting from pieces): one that ends in its parts, from a P1 Gamma file,
// whatever its metric source. Else rank 0 reads the whole input and sets the run up.
bool adapts_from_pieces(const AdaptOptions& o) {
  return process_count() > 1 && is_gamma_path(o.input) && !gamma_mesh_has_p2_keyword(o.input);
}

// Every process of a run from pieces: its piece read and prepared, the run set up on the pieces
// together, the distributed loop, and on rank 0 (`outputs` given) the report.
template <int D>
void adapt_from_pieces(const AdaptOptions& o, OutputSet* outputs) {
  AdaptationJob<D> job = adaptation_job<D>(o);
  if (!outputs) job.warn = {}, job.pass_progress = {};  // (rank 0 says them)
  MeshFilePiece<D> piece = read_mesh_file_piece<D>(o.input);
  prepare_input_piece(piece, o.input, job.warn);
  AdaptationReport report;
  report.input_read_in_pieces = true;
  report.dimension = D;
  report.input_vertices = piece.vertex_count;
  report.input_elements = piece.element_count;
  PieceMetricSource source{o.metric, std::nullopt, std::nullopt, o.h_max};
  if (!o.hessian.empty()) source.hessian = hessian_source(o);
  if (!o.surface_sizes.empty()) source.surface_sizes = {o.surface_sizes[0], o.surface_sizes[1]};
  PieceSetup<D> setup = set_up_piece(std::move(piece), o.input, source, job);
  report.hausdorff_bounded_vertices = setup.hausdorff_bounded_vertices;
  std::optional<OutputInParts> output;
  const BoundaryGeometry<D>* geometry = setup.geometry.get();
  const auto start = std::chrono::steady_clock::now();  // after the set-up, as the serial run's
  report.run = adapt_distributed_from_pieces<D>(std::move(setup.start), geometry, setup.settings, o.partition_seed,
                                                iteration_printer(o, report.distributed_iterations),
                                                end_in_parts<D>(o, job, geometry, setup.settings, output));
  if (outputs) finish_in_parts(report, *output, geometry != nullptr, start, o, *outputs);
}

// The other processes: a run from pieces, or rank 0's distributed run from its input.
void serve_adaptation(const AdaptOptions& o) {
  std::vector<int> plan;  // rank 0's: the dimension of a run from pieces, 0 for a run from its input
  broadcast_values(plan);
  if (plan.at(0) == 2) return adapt_from_pieces<2>(o, nullptr);
  if (plan.at(0) == 3) return adapt_from_pieces<3>(o, nullptr);
  std::vector<std::byte> input_boundary;
  broadcast_bytes(input_boundary);
  if (packed_dimension(input_boundary) == 2)
    serve_adaptation<2>(o, input_boundary);
  else
    serve_adaptation<3>(o, input_boundary);
}

template <int D>
void adapt(Mesh<D>& mesh, const MeshFileContent& file, const AdaptOptions& o, OutputSet& outputs) {
  prepare_boundary<D>(mesh, o.input, warn_on_stderr);
  check_mesh_or_warn(mesh, o.input);  // (prepared before the parts are cut: each rank's geometry is the serial run's)
  std::vector<SymMat<D>> metrics = vertex_metrics(mesh, file, o);
  if (process_count() > 1) return adapt_in_parts(mesh, std::move(metrics), o, outputs);
  AdaptationJob<D> job = adaptation_job<D>(o);
  std::optional<CurvingProgress> progress;  // drawn on a terminal, unless quiet
  job.before_curving = [&progress, &o](const Mesh<D>& adapted, CurvingOptions& curving) {
    progress.emplace(adapted, curving.passes, !o.quiet);
    progress->attach(curving);
  };
  AdaptedMesh<D> adapted = run_adaptation_job(mesh, std::move(metrics), job, o.input);
  if (progress) progress->complete();
  write_mesh_file(o.output, mesh);
  if (!o.vtu.empty()) write_curved_vtu(o.vtu, mesh, *adapted.field);
  finish_outputs(o, adapted.report, outputs);
}

void declare_adapt_files(OutputSet& outputs, const AdaptOptions& o) {
  outputs.add_input(o.input, "the input mesh");
  if (!o.metric.empty()) outputs.add_input(o.metric, "--metric");
  if (!o.hessian.empty() && !is_analytic_field(o.hessian)) outputs.add_input(o.hessian, "--hessian");
  if (o.surface.starts_with("cad:")) outputs.add_input(o.surface.substr(4), "--surface cad:");
  check_writable_mesh_format(o.output);
  outputs.add_output(o.output, "-o");
  if (!o.report.empty()) outputs.add_output(o.report, "--report");
  if (!o.vtu.empty()) outputs.add_output(o.vtu, "--vtu");
}

}  // namespace

void add_adapt_command(CLI::App& app) {
  auto o = std::make_shared<AdaptOptions>();
  CLI::App* command = app.add_subcommand("adapt", "Adapt a mesh to a metric (a unit mesh: split, collapse, swap, smooth), then curve it");
  command->add_option("input", o->input, "mesh to adapt (.mesh, .meshb, .msh; P1, or P2 whose nodes are dropped)")->required();
  command->add_option("--metric", o->metric, "metric at the input's vertices (.sol/.solb); the input is the back mesh");
  command->add_option(
      "--analytic", o->analytic, "or an analytic metric, evaluated exactly at every vertex (" + [] {
        std::string names;
        for (const auto& n : analytic_metric_names()) names += (names.empty() ? "" : ", ") + n;
        return names;
      }() + ")");
  command->add_option("--hessian", o->hessian,
                      "or the Lp metric of a field's Hessian: FIELD.sol(b) at the input's nodes, or analytic:NAME (as hocav metric)");
  command->add_option("--complexity", o->complexity, "--hessian: the target complexity N (about the vertex count)")
      ->check(finite_positive());
  command->add_option("--norm", o->norm, "--hessian: the p of the Lp norm of the error (default 2)")->check(finite_positive());
  command
      ->add_option("--surface-sizes", o->surface_sizes,
                   "or size HN along the boundary normal and HT along the boundary (hocav metric --surface), carried inside by --hgrad")
      ->delimiter(',')
      ->expected(2)
      ->check(finite_positive());
  command->add_flag("--implied", o->implied, "or the metric in which the input is a unit mesh");
  command->add_option("-o,--output", o->output, "adapted mesh to write (.mesh, .meshb, .msh, .vtu)")->required();
  command->add_option("--order", o->order, "2: curve the adapted mesh (P2 output); 1: stop after the P1 adaptation")
      ->check(CLI::IsMember({1, 2}))
      ->capture_default_str();
  command->add_option("--hmin", o->h_min, "smallest size: the metric's sizes are clamped to it")->check(finite_positive());
  command->add_option("--hmax", o->h_max, "largest size: the metric's sizes are clamped to it")->check(finite_positive());
  command->add_option("--hgrad", o->gradation, "grade the metric first: sizes grow by at most BETA > 1 per unit length")
      ->check(finite_range(1.0 + 1e-12, 1e6, "BETA > 1"));
  command
      ->add_option("--hausd", o->hausd_given,
                   "bound on the distance from the boundary to the geometry: the metric is refined along curved boundaries, and no "
                   "collapse or move puts a facet farther (default 0.01 x the bounding box's diagonal)")
      ->check(finite_positive());
  command
      ->add_option("--hausd-relative", o->hausd_relative,
                   "also bound that distance at each boundary vertex by C x the smallest size the metric asks there, 0 for none "
                   "(a curved wall's sag within its first layer, so that the curving can put the wall on the geometry; default: 1 "
                   "with --order 2, none with --order 1)")
      ->check(finite_range(0.0, std::numeric_limits<double>::max(), "C >= 0"));
  command->add_option("--angle", o->angle, "boundary sides meeting at more than this dihedral angle are ridges (degrees)")
      ->check(finite_range(0.0, 180.0, "0 to 180"))
      ->capture_default_str();
  command
      ->add_option("--surface", o->surface,
                   "geometry of new boundary points and P2 nodes: p3 (a cubic surrogate of the input boundary), cad:FILE, none")
      ->capture_default_str();
  command->add_flag("--curved", o->curved,
                    "then curved passes: split and collapse by curved length, every P2 operation certified (docs/adaptation.md)");
  command->add_option("--jacobian-floor", o->jacobian_floor, "curving: every element keeps its min normalized Jacobian above this")
      ->check(finite_range(0.0, 1.0, "0 to 1"))
      ->capture_default_str();
  command->add_option("--iterations", o->iterations, "at most this many passes of the adaptation loop")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command
      ->add_option("--threads", o->threads,
                   "threads of the swaps, smoothing, collapse tests and curving (the output does not depend on it)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  command
      ->add_option("--partition-seed", o->partition_seed,
                   "mpirun: the partitioner's random seed (0: its own); another seed cuts the mesh elsewhere, to measure how much "
                   "a distributed run depends on its cuts")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_option("--report", o->report, "write the run's figures (passes, lengths, qualities, Table-1 columns) as JSON");
  command->add_option("--vtu", o->vtu, "also write a .vtu for ParaView (metric and min normalized Jacobian)");
  command->add_flag("-q,--quiet", o->quiet, "print nothing on success");
  command->callback([o] {
    check_options(*o);
    if (process_rank() != 0) return serve_adaptation(*o);
    OutputSet outputs;
    declare_adapt_files(outputs, *o);
    if (process_count() > 1) {
      std::vector<int> plan{adapts_from_pieces(*o) ? gamma_mesh_dimension(o->input) : 0};
      broadcast_values(plan);
      if (plan[0] == 2) return adapt_from_pieces<2>(*o, &outputs);
      if (plan[0] == 3) return adapt_from_pieces<3>(*o, &outputs);
    }
    MeshFileContent file = read_mesh_file(o->input);
    std::visit([&](auto& mesh) { adapt(mesh, file, *o, outputs); }, file.mesh);
  });
}

}  // namespace hocav
