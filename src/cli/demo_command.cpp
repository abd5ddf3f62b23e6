// hocav demo [-o DIR] [--threads N] [--h H]
// The main job on built-in cases, no input needed: the paper's "Meshes 1" pipeline on the volume
// between two spheres (an isotropic mesh, a surface metric graded into the volume, adaptation to a
// unit mesh of it, P2 curving with the P3 surrogate of the boundary), the curving of the 2D
// shear-circle case (the paper's
// Fig. 1), and pictures of both: a planar cut through the curved 3D mesh, the curved 2D mesh,
// histograms of the edge gains and of the normalized Jacobians (SVG).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

#include "adapt/adaptation_driver.hpp"
#include "base/error.hpp"
#include "base/thread_pool.hpp"
#include "cases/case_registry.hpp"
#include "cli/command_support.hpp"
#include "cli/commands.hpp"
#include "cli/number_checks.hpp"
#include "io/atomic_output.hpp"
#include "io/output_set.hpp"
#include "mesh/measure.hpp"
#include "metric/analytic_metric.hpp"
#include "metric/surface_metric.hpp"
#include "picture/histogram_chart.hpp"
#include "picture/jacobian_picture.hpp"
#include "report/curved_vtu.hpp"
#include "report/mesh_summary.hpp"
#include "surface/boundary_choice.hpp"

namespace hocav {
namespace {

// The 3D case's metric, as `hocav metric --surface H/10,H --gradation 1.5` makes it: size H/10
// along the normals of both spheres, H (the --h option) along them, graded into the volume.
constexpr double kShellNormalRatio = 0.1, kShellGradation = 1.5;

struct DemoOptions {
  std::string directory = "out";
  int threads = every_core();
  double h = 0.25;  // the sphere-shell mesh's edge length and its metric's tangential size
};

void progress(const std::string& message) { std::cerr << "demo: " << message << '\n'; }

template <int D>
Mesh<D> generated(const std::string& name, const CaseValues& values) {
  progress("generating " + name);
  return std::get<Mesh<D>>(generate_case(find_case(name), values));
}

// The files of the run and what each holds, in the order they are written.
const std::vector<std::pair<std::string, std::string>> kDemoFiles{
    {"sphere-shell-p2.meshb", "the curved P2 mesh"},
    {"sphere-shell-p2.vtu", "the same for ParaView (set Nonlinear Subdivision Level >= 2)"},
    {"sphere-shell-report.json", "the run's figures (adaptation passes, lengths and qualities, Table-1 columns)"},
    {"sphere-shell-cut.svg", "a cut through the curved 3D mesh"},
    {"edge-gains.svg", "histogram of the gains of the volume edges"},
    {"normalized-jacobians.svg", "histogram of the min normalized Jacobians"},
    {"shear-circle-p2.svg", "the curved 2D mesh"},
};

std::string path_in(const DemoOptions& options, const std::string& name) {
  return (std::filesystem::path(options.directory) / name).string();
}

// The files written so far, listed at the end.
struct Written {
  std::vector<std::pair<std::string, std::string>> files;  // path, what it holds

  // The path of file `name` (one of kDemoFiles) in the output folder, recorded with what it holds.
  std::string path(const DemoOptions& options, const std::string& name) {
    const auto file = std::find_if(kDemoFiles.begin(), kDemoFiles.end(), [&name](const auto& entry) { return entry.first == name; });
    files.emplace_back(path_in(options, name), file->second);
    return files.back().first;
  }
};

void write_histograms(const std::vector<double>& gains, const std::vector<double>& jacobians, const DemoOptions& options,
                      Written& written) {
  constexpr int kBins = 25;
  double gain_lower = 0, gain_upper = 0.05;
  for (double gain : gains) {
    gain_lower = std::min(gain_lower, gain);
    gain_upper = std::max(gain_upper, gain);
  }
  write_svg(written.path(options, "edge-gains.svg"),
            histogram_chart(summarize_values(gains, kBins, gain_lower, gain_upper),
                            {"Gain of each volume edge (sphere shell)", "gain 1 − ℓ(curved) / ℓ(straight), lengths in the metric",
                             "edges (logarithmic)", std::nullopt, true}));
  write_svg(written.path(options, "normalized-jacobians.svg"),
            histogram_chart(summarize_values(jacobians, 2 * kBins, 0, 2),
                            {"Min normalized Jacobian of each tetrahedron (sphere shell)",
                             "min of J / |J_straight| over the element (1: as the straight element)", "tetrahedra", kJacobianColors}));
}

// Generates the sphere-shell case and its surface metric, adapts the mesh to the metric, curves
// the unit mesh and writes it; draws its cut and histograms.
AdaptationReport run_sphere_shell(const DemoOptions& options, Written& written) {
  Mesh<3> mesh = generated<3>("sphere-shell", {{"h", options.h}});
  progress("surface metric graded into the volume (" + mesh_summary(mesh) + ")");
  std::vector<SymMat<3>> metrics = surface_metric_at_vertices(
      mesh, SurfaceSizes{kShellNormalRatio * options.h, options.h, bounding_box_diagonal(mesh)});
  // `hocav adapt`'s job: the Hausdorff bound, then the gradation, the P3 surrogate of the input's
  // boundary for the adaptation and of the adapted one's for the curving.
  AdaptationJob<3> job;
  job.gradation = kShellGradation;
  job.threads = options.threads;
  job.geometry = [](const Mesh<3>& m) { return make_boundary_geometry<3>({BoundaryKind::kP3Surrogate, ""}, m); };
  job.pass_progress = [](int pass, int cap) {
    progress("adapting: pass " + std::to_string(pass) + " (at most " + std::to_string(cap) + ")");
  };
  job.curving.emplace();
  job.curving->threads = options.threads;
  std::optional<CurvingProgress> curving_progress;
  job.before_curving = [&curving_progress](const Mesh<3>& adapted, CurvingOptions& curving) {
    curving_progress.emplace(adapted, curving.passes, true);
    curving_progress->attach(curving);
  };
  progress("adapting to it, then curving on " + std::to_string(options.threads) + " threads");
  AdaptedMesh<3> adapted = run_adaptation_job(mesh, std::move(metrics), job, "the demo's sphere shell");
  if (curving_progress) curving_progress->complete();
  const AdaptationReport& report = adapted.report;
  const MetricField<3>& field = *adapted.field;

  progress("writing the P2 mesh, its .vtu and the report");
  write_mesh_file(written.path(options, "sphere-shell-p2.meshb"), mesh);
  write_curved_vtu(written.path(options, "sphere-shell-p2.vtu"), mesh, field);
  {
    AtomicOutput out(written.path(options, "sphere-shell-report.json"));
    write_adaptation_report_json(out.stream(), report);
    out.commit();
  }

  progress("drawing the cut z = 0 and the histograms");
  const std::vector<double> jacobians = min_normalized_jacobians(mesh);
  char subtitle[200];
  std::snprintf(subtitle, sizeof subtitle,
                "adapted to a surface metric (normal size %.3g, tangential %.3g) and curved; each section filled by its "
                "element's min normalized Jacobian",
                kShellNormalRatio * options.h, options.h);
  const JacobianPictureOptions figure{"Adapted and curved sphere shell, cut by the plane z = 0", subtitle,
                                      Rect{{{0.28, 0.28}}, {{0.58, 0.58}}},  // the detail: where the inner sphere meets x = y
                                      CutPlane{}};
  write_svg(written.path(options, "sphere-shell-cut.svg"), jacobian_picture(mesh, jacobians, figure));
  write_histograms(volume_edge_gains(mesh, field, options.threads), jacobians, options, written);
  return report;
}

// The 2D case, the paper's Fig. 1: the shear-circle case (a unit mesh of the shear-circle metric,
// whose options default to the analytic metric's) curved in that metric, drawn exactly.
CurvingReport run_shear_circle(const DemoOptions& options, Written& written) {
  Mesh<2> mesh = generated<2>("shear-circle", {});
  AnalyticMetricSpec shear;
  shear.name = "shear-circle";
  const MetricField<2> field(mesh, analytic_metric_at_vertices(shear, mesh));
  progress("curving it in its metric (" + mesh_summary(mesh) + ")");
  CurvingOptions curving;
  curving.threads = options.threads;
  const auto surface = make_boundary_geometry<2>({BoundaryKind::kP3Surrogate, ""}, mesh);
  const CurvingReport report = curve_in_metric(mesh, field, surface.get(), curving);
  const JacobianPictureOptions figure{"Shear-circle case (the paper's Fig. 1), curved",
                                      "P2 triangles drawn exactly (quadratic Bézier edges), filled by their min normalized Jacobian; "
                                      "sizes 0.001 across the circle r = 0.75, 0.1 along it",
                                      Rect{{{-0.06, 0.69}}, {{0.06, 0.81}}},  // the detail: the layer at its top
                                      CutPlane{}};
  write_svg(written.path(options, "shear-circle-p2.svg"), jacobian_picture(mesh, min_normalized_jacobians(mesh), figure));
  return report;
}

void run_demo(const DemoOptions& options) {
  std::error_code error;
  std::filesystem::create_directories(options.directory, error);
  if (error || !std::filesystem::is_directory(options.directory))
    throw Error(options.directory + ": cannot make this output folder" + (error ? " (" + error.message() + ")" : ""));
  OutputSet outputs;
  for (const auto& file : kDemoFiles) outputs.add_output(path_in(options, file.first), "-o");
  Written written;
  const AdaptationReport shell = run_sphere_shell(options, written);
  const CurvingReport shear_circle = run_shear_circle(options, written);
  outputs.commit();
  std::cout << "adapted the sphere shell to its metric, then curved it:\n";
  write_adaptation_report_table(std::cout, shell);
  write_curving_report_table(std::cout, *shell.curving);
  char line[200];
  std::snprintf(line, sizeof line,
                "curved the shear circle (2D): %d triangles, normalized Jacobian min %.3g, gain avg / max %.2f%% / %.1f%%",
                shear_circle.elements, shear_circle.normalized_jacobian.min, 100 * shear_circle.average_gain, 100 * shear_circle.max_gain);
  std::cout << line << '\n';
  std::size_t width = 0;
  for (const auto& file : written.files) width = std::max(width, file.first.size());
  std::cout << "files:\n";
  for (const auto& [path, what] : written.files)
    std::cout << "  " << std::left << std::setw(static_cast<int>(width)) << path << "  " << what << '\n';
}

}  // namespace

void add_demo_command(CLI::App& app) {
  auto options = std::make_shared<DemoOptions>();
  CLI::App* command = app.add_subcommand(
      "demo",
      "The main job, no input needed: adapt the sphere-shell case to a surface metric and curve it (and the 2D "
      "shear circle), write the P2 mesh, the report and pictures");
  command->add_option("-o,--output", options->directory, "folder of the output files (created if needed)")->capture_default_str();
  command->add_option("--threads", options->threads, "threads of the curving (the output does not depend on it)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  command
      ->add_option("--h", options->h,
                   "the sphere-shell mesh's edge length and its metric's tangential size; the normal size is a tenth "
                   "(smaller: more tetrahedra: 121,094 at 0.2)")
      ->check(finite_range(0.02, 0.5, "0.02 to 0.5"))
      ->capture_default_str();
  command->callback([options] { run_demo(*options); });
}

}  // namespace hocav
