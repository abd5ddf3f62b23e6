// hocav stats MESH [--metric SOL] [--json] [--threads N]: counts, refs, P1 measures, the consistency verdict, the
// certified Jacobian figures and memory of a mesh; with a metric, the edge lengths and element
// qualities in it and its largest anisotropy. A table for people or one JSON object. An invalid mesh (inconsistent, or an
// element not certified positive) is reported in full, then named on stderr with exit code 2, so
// that scripts stop on it as they would with a checker.
#include <iostream>
#include <memory>

#include "base/error.hpp"
#include "base/thread_pool.hpp"
#include "cli/command_support.hpp"
#include "cli/commands.hpp"
#include "io/node_metrics.hpp"
#include "report/mesh_statistics.hpp"

namespace hocav {
namespace {

struct StatsOptions {
  std::string mesh, metric;
  bool json = false;
  int threads = every_core();
};

void run_stats(const StatsOptions& options) {
  MeshFileContent file = read_mesh_file(options.mesh);
  MeshStatistics statistics = std::visit(
      [&](auto& mesh) {
        std::vector<double> node_metrics;  // vertices, then P2 nodes
        if (!options.metric.empty()) node_metrics = read_metric_for_mesh(options.metric, file, mesh.is_p2()).values;
        return compute_mesh_statistics(mesh, node_metrics, options.threads);
      },
      file.mesh);
  if (options.json)
    write_statistics_json(std::cout, statistics, options.mesh, options.metric);
  else
    write_statistics_table(std::cout, statistics, options.mesh, options.metric);
  if (!statistics.valid()) {
    std::cout.flush();  // the report first, then the one-line verdict
    throw Error(options.mesh + ": invalid mesh: " + invalidity_summary(statistics));
  }
}

}  // namespace

void add_stats_command(CLI::App& app) {
  auto options = std::make_shared<StatsOptions>();
  CLI::App* command = app.add_subcommand(
      "stats",
      "Report a mesh: counts, refs, P1 measures, consistency, Jacobian figures, memory; edge lengths and element "
      "qualities in a metric. "
      "Exit code 2 when the mesh is invalid");
  command->add_option("mesh", options->mesh, "mesh to read (.mesh, .meshb, .msh)")->required();
  command->add_option("--metric", options->metric,
                      "metric of the mesh (.sol/.solb): adds the Riemannian edge lengths in the metric (min/mean/max, "
                      "histogram, share in [1/sqrt(2), sqrt(2)]), the elements' mean-ratio quality in it (min/mean, histogram, "
                      "share below 0.1) and the max anisotropy");
  command->add_flag("--json", options->json, "print one JSON object instead of the table");
  command->add_option("--threads", options->threads, "threads of the metric figures (the figures do not depend on it)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  command->callback([options] { run_stats(*options); });
}

}  // namespace hocav
