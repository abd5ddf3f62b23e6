#include "parallel/distributed_adaptation.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>

#include "adapt/metric_measures.hpp"
#include "adapt/vertex_classes.hpp"
#include "base/memory_budget.hpp"
#include "base/stopwatch.hpp"
#include "metric/implied_metric.hpp"
#include "parallel/back_mesh_share.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/gradual_metric.hpp"
#include "parallel/last_run_region.hpp"
#include "parallel/part_adaptation.hpp"
#include "parallel/part_migration.hpp"
#include "parallel/peer_iteration.hpp"
#include "parallel/share_metric.hpp"
#include "parallel/spatial_cut.hpp"

namespace hocav {
namespace {

// The input's own metric (docs/method.md §10), on the metric's back mesh when that is the input: rank
// 0 then holds one copy of the input and its point locator, not two.
template <int D>
MetricField<D> input_metric_of(const Mesh<D>& input, const AdaptationMetric<D>& metric) {
  const std::vector<SymMat<D>> implied = implied_metric_at_vertices(input);
  const MetricField<D>* field = metric.field();
  return field && field->is_on(input) ? field->with_metrics(implied) : MetricField<D>(input, implied);
}

// The last interfaces' vertices and their neighbours (per vertex of `mesh`): the region of the last
// pass, which mends what the parts could not mend next to their frozen interfaces.
template <int D>
std::vector<char> around_interfaces(const Mesh<D>& mesh, const std::vector<char>& interface_vertex) {
  const std::vector<char> near = elements_near(mesh, interface_vertex, 1);
  std::vector<char> region(interface_vertex.size(), 0);
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (near[k])
      for (Index v : mesh.element(k)) region[v] = 1;
  return region;
}

// Collective: the metric on the back mesh around `mesh` (a part), gathered from every process's home
// share (empty for an empty `mesh`); its bytes and time in rank 0's `figures`. Gathered afresh for
// every part: keeping the last share, to send only what a part's region gained, cost more memory
// than it saved in messages (docs/distributed.md §The back mesh in shares).
template <int D>
std::unique_ptr<ShareMetric<D>> gathered_metric(const BackMeshShare<D>& home, const MetricRecipe& recipe, const Mesh<D>& mesh,
                                                DistributedIteration& figures) {
  const auto start = std::chrono::steady_clock::now();
  long long bytes = 0;
  auto near = std::make_unique<ShareMetric<D>>(share_around(home, share_region(mesh), &bytes), recipe);
  figures.back_mesh_bytes += sum_over_processes(bytes);
  figures.seconds += seconds_since(start);
  return near;
}

// Collective: `values` (per element of rank 0's whole mesh; empty elsewhere) to the processes, each
// its part's under `part_of`, in the order migrate_part gives the part's elements (rank 0's).
std::vector<double> scattered_by_part(const std::vector<double>& values, std::span<const int> part_of) {
  std::vector<std::vector<double>> outgoing(static_cast<std::size_t>(process_count()));
  for (std::size_t k = 0; k < part_of.size(); ++k) outgoing[static_cast<std::size_t>(part_of[k])].push_back(values[k]);
  return values_of_bytes<double>(exchange_bytes(bytes_of_messages(outgoing)).at(0));
}

// Collective: the first partition, from the first cut's pieces (scattered from rank 0 with `loads`,
// their elements' predicted output in the first iteration's metric): PT-Scotch cuts the pieces'
// distributed graph, and the elements migrate. Its bytes and time in rank 0's `figures`.
template <int D>
void partition_first(MeshPart<D>& part, std::span<const double> loads, std::int64_t partition_seed, DistributedIteration& figures) {
  const auto start = std::chrono::steady_clock::now();
  long long bytes_sent = 0;
  part = repartition(std::move(part), loads, {}, partition_seed, &bytes_sent);
  figures.bytes_sent += sum_over_processes(bytes_sent);
  figures.seconds_partition += seconds_since(start);
  figures.seconds += seconds_since(start);
}

// Per vertex of a part: on an element of quality below kPoorQuality in `metric`.
template <int D>
std::vector<char> poor_element_vertices(const Mesh<D>& mesh, const AdaptationMetric<D>& metric) {
  std::vector<char> seeds(static_cast<std::size_t>(mesh.vertex_count()), 0);
  const std::vector<SymMat<D>> at = metrics_at_vertices(mesh, metric, 1);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const auto& element = mesh.element(k);
    SimplexPoints<D> points;
    std::array<SymMat<D>, D + 1> metrics;
    for (int i = 0; i <= D; ++i) points[i] = mesh.vertex(element[i]), metrics[i] = at[element[i]];
    if (mean_metric_ratio<D>(points, metrics) < kPoorQuality)
      for (Index v : element) seeds[v] = 1;
  }
  return seeds;
}

// What the whole-mesh iterations leave: on rank 0 their runs; on every process the next global id.
struct WholeMeshResult {
  AdaptationRun run;
  Index next_global_id = 0;
};

// The whole-mesh iterations, 1 to kDistributedIterations, on every process at once and peer to
// peer (peer_iteration.hpp), from the processes' parts of the first partition; the parts of the last
// stay where they are. Each adapts to the metric its share of the way from the input's own.
template <int D>
struct WholeMeshIterations {
  MetricRecipe recipe;  // the target's
  int steps;            // gradual_steps, rank 0's
  const BoundaryGeometry<D>* geometry;
  AdaptationSettings settings;  // the parts' loop's (part_settings)
  std::int64_t partition_seed;
  // Rank 0's: the metric on the whole back mesh, a fraction of the way from the input's own (rank 0
  // asks for no share: it holds the whole); empty on the other processes, and on every process of
  // a run from pieces.
  std::function<AdaptationMetric<D>(double)> whole_metric;
  // A run from pieces: no process holds the whole back mesh, so rank 0 gathers its metric for the
  // last runs from the shares too.
  bool shares_only = false;

  // `first` holds the figures of the first cut's scatter.
  WholeMeshResult run(MeshPart<D>& part, const BackMeshShare<D>& home, DistributedIteration first,
                      const std::function<void(const DistributedIteration&)>& on_iteration) const {
    WholeMeshResult all;
    all.next_global_id = max_over_processes(
        part.global_ids.empty() ? Index{0} : *std::max_element(part.global_ids.begin(), part.global_ids.end()) + 1);
    for (int iteration = 1; iteration <= kDistributedIterations; ++iteration) {
      const double fraction = gradual_fraction(iteration, steps);
      DistributedIteration figures = iteration == 1 ? first : DistributedIteration{};
      figures.iteration = iteration;
      figures.metric_fraction = fraction;
      const std::unique_ptr<ShareMetric<D>> near = gathered_metric(home, recipe, whole_metric ? Mesh<D>{} : part.mesh, figures);
      const auto partway = [&](double to) { return whole_metric ? whole_metric(to) : near->partway(to); };
      const AdaptationMetric<D> iteration_metric = partway(fraction);
      std::optional<AdaptationMetric<D>> next;
      if (iteration < kDistributedIterations) next = partway(gradual_fraction(iteration + 1, steps));
      // The last iteration's parts stay, and no later iteration finishes what an early stop leaves far
      // from their interfaces (the last runs take only a region): they stop as the serial loop does.
      AdaptationSettings iteration_settings = settings;
      if (!next) iteration_settings.passes_after_window_closes = -1;
      const PeerIteration<D> step{iteration_metric, geometry, iteration_settings, partition_seed, next ? &*next : nullptr};
      const PeerIterationResult result = run_peer_iteration(part, all.next_global_id, step, figures);
      all.run.passes.insert(all.run.passes.end(), result.run.passes.begin(), result.run.passes.end());
      all.run.caps_removed += result.run.caps_removed;
      if (process_rank() == 0 && on_iteration) on_iteration(figures);
    }
    return all;
  }
};

// The last runs, serial on a part that holds a region of the last runs (docs/distributed.md §The
// scheme, step 5). The first tries first the seeds' neighbours, the second what the first left (its poor
// elements and edges outside the unit window) with its window open again: a run that closed its
// window early cannot collapse what it made later. The part's border with the others' parts stays
// frozen. Their passes, in order; the second's flags.
template <int D>
AdaptationRun last_serial_runs(MeshPart<D>& part, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                               const AdaptationSettings& settings, const std::vector<char>& seeds) {
  AdaptationSettings last = part_settings(settings);  // a part's loop, the last word: no early stop
  last.passes_after_window_closes = -1;
  last.splits_at_required_vertices = SplitsAtRequiredVertices::kNone;
  last.first_pass_vertices = around_interfaces(part.mesh, seeds);
  last.first_pass_unfinished_edges = true;
  AdaptationRun run = adapt_part_measured(part, metric, geometry, last).first;
  last.first_pass_vertices.assign(static_cast<std::size_t>(part.mesh.vertex_count()), 0);
  const AdaptationRun again = adapt_part_measured(part, metric, geometry, last).first;
  run.passes.insert(run.passes.end(), again.passes.begin(), again.passes.end());
  run.converged = again.converged;
  run.stopped_with_window_open = again.stopped_with_window_open;
  run.caps_removed += again.caps_removed;
  return run;
}

// Rank 0's job in the last runs: its metric (the target on the whole back mesh; null in a run from
// pieces, where it is gathered around the region from the shares), the geometry and the serial
// loop's settings.
template <int D>
struct RootRuns {
  const AdaptationMetric<D>* metric;
  const BoundaryGeometry<D>* geometry;
  const AdaptationSettings& settings;
};

// What the last runs in the parts leave for those on rank 0: the global ids of the seams' vertices
// (of faces between two processes' regions) and of the poor elements', every process's, and the
// next global id.
struct RootSeeds {
  std::vector<Index> ids;
  Index next_global_id = 0;
};

// Collective: the global ids that the processes name as seeds of the last runs on rank 0, their
// `seams`' and their poor elements' in `metric`, every process's on every process: a poor element's
// neighbours across a part's border are another process's.
template <int D>
std::vector<Index> root_seeds(const MeshPart<D>& part, std::vector<Index> seams, const AdaptationMetric<D>& metric) {
  const std::vector<char> poor = poor_element_vertices(part.mesh, metric);
  for (Index v = 0; v < part.mesh.vertex_count(); ++v)
    if (poor[v]) seams.push_back(part.global_ids[v]);
  return all_gather_values_joined(seams);
}

// Collective, after the whole-mesh iterations (docs/distributed.md §The scheme, step 5): the elements
// within kInterfaceBandRings rings of the last interfaces go, interface by interface, to one of its
// two processes (cut_last_run_region), and every process runs the last serial runs on its part so
// made, from the interfaces' vertices it took. Returns rank 0's runs (the processes' combined) and
// the seeds of the runs on rank 0 (the seams and the poor elements left); the figures in rank 0's
// `figures`.
template <int D>
std::pair<AdaptationRun, RootSeeds> last_runs_in_parts(MeshPart<D>& part, const WholeMeshResult& whole, const RootRuns<D>* root,
                                                       const WholeMeshIterations<D>& iterations, const BackMeshShare<D>& home,
                                                       DistributedIteration& figures) {
  const auto start = std::chrono::steady_clock::now();
  const RegionCut cut = cut_last_run_region(part, kInterfaceBandRings);
  figures.region_elements = sum_over_processes(cut.region_elements);
  const std::vector<Index> seed_ids = exchange_values_joined(cut.seeds_to);
  long long bytes_sent = 0;
  part = migrate_part(std::move(part), cut.destination, &bytes_sent);
  figures.bytes_sent += sum_over_processes(bytes_sent);
  const std::unique_ptr<ShareMetric<D>> near = gathered_metric(home, iterations.recipe, iterations.whole_metric ? Mesh<D>{} : part.mesh,
                                                               figures);
  const auto runs_start = std::chrono::steady_clock::now();
  const AdaptationMetric<D> metric = root && root->metric ? *root->metric : near->partway(1);
  const AdaptationRun run = last_serial_runs(part, metric, iterations.geometry, iterations.settings, flags_of_global_ids(part, seed_ids));
  const PartFigures own{seconds_since(runs_start), peak_resident_bytes()};
  for (const PartFigures& each : all_gather_value(own)) {
    figures.part_seconds.push_back(each.seconds);
    figures.peak_memory_bytes.push_back(each.peak_memory_bytes);
  }
  RootSeeds next{{}, whole.next_global_id};
  number_new_vertices(part, next.next_global_id);
  count_whole_mesh(part, figures);
  next.ids = root_seeds(part, cut.seams, metric);
  figures.seconds += seconds_since(start);
  return {runs_combined_on_root(run), std::move(next)};
}

// Collective, after the last runs in the parts (docs/distributed.md §The scheme, step 5): the elements
// within kInterfaceBandRings rings of the seams (`seeds`) go to rank 0 (the others stay), rank 0
// runs the last serial runs there (none when no element is near a seed). Returns rank 0's runs;
// their figures in rank 0's `figures`.
template <int D>
AdaptationRun last_runs_on_root(MeshPart<D>& part, const RootSeeds& seeds, const RootRuns<D>* root,
                                const WholeMeshIterations<D>& iterations, const BackMeshShare<D>& home, DistributedIteration& figures) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<char> near = elements_near(part.mesh, flags_of_global_ids(part, seeds.ids), kInterfaceBandRings);
  std::vector<int> destination(near.size(), process_rank());
  for (std::size_t k = 0; k < near.size(); ++k)
    if (near[k]) destination[k] = 0;
  figures.region_elements = sum_over_processes(static_cast<Index>(std::count(near.begin(), near.end(), 1)));
  // (Without a region, rank 0's part had its last runs in the parts' already.)
  const bool runs = root && figures.region_elements > 0;
  long long bytes_sent = 0;
  part = migrate_part(std::move(part), destination, &bytes_sent);
  std::unique_ptr<ShareMetric<D>> region_metric;  // rank 0's, in a run from pieces
  if (iterations.shares_only) region_metric = gathered_metric(home, iterations.recipe, runs ? part.mesh : Mesh<D>{}, figures);
  AdaptationRun run;
  PartFigures own{0, peak_resident_bytes()};
  if (runs) {
    const auto runs_start = std::chrono::steady_clock::now();
    const AdaptationMetric<D> metric = region_metric ? region_metric->partway(1) : *root->metric;
    run = last_serial_runs(part, metric, root->geometry, root->settings, flags_of_global_ids(part, seeds.ids));
    own = {seconds_since(runs_start), peak_resident_bytes()};
    Index next_global_id = seeds.next_global_id;
    for (Index& global : part.global_ids)
      if (global == kNoIndex) global = next_global_id++;
  }
  for (const PartFigures& each : all_gather_value(own)) {
    figures.part_seconds.push_back(each.seconds);
    figures.peak_memory_bytes.push_back(each.peak_memory_bytes);
  }
  figures.bytes_sent += sum_over_processes(bytes_sent);
  figures.seconds = seconds_since(start);
  return run;
}

// The figures of the last runs (`iteration`: kLastRunsInParts or kLastRunsOnRoot), before them.
DistributedIteration last_runs_figures(int iteration) {
  DistributedIteration figures;
  figures.iteration = iteration;
  figures.metric_fraction = 1;
  return figures;
}

// Collective: `end` on every process's part, with the target gathered around it from the shares;
// what it wrote in `figures`.
template <int D>
void end_in_every_part(MeshPart<D>& part, const BackMeshShare<D>& home, const MetricRecipe& recipe, const PartsEnd<D>& end,
                       DistributedIteration& figures) {
  const std::unique_ptr<ShareMetric<D>> near = gathered_metric(home, recipe, part.mesh, figures);
  const MeshFileCounts written = end(part, near->partway(1));
  figures.vertices = written.vertices;
  figures.elements = written.elements;
}

// The whole-mesh iterations' runs, then the last runs' (whose flags are the joined run's, unless
// they made no pass: rank 0 without a region).
AdaptationRun joined_runs(AdaptationRun run, const AdaptationRun& last) {
  if (last.passes.empty()) return run;
  run.passes.insert(run.passes.end(), last.passes.begin(), last.passes.end());
  run.converged = last.converged;
  run.stopped_with_window_open = last.stopped_with_window_open;
  run.caps_removed += last.caps_removed;
  return run;
}

// What rank 0 made of the run that the other processes need, broadcast.
struct RunShape {
  SizeBounds bounds;                // the metric's size bounds
  bool hausdorff = false;           // an analytic metric with a Hausdorff bound field
  double hausd = 0;                 // AdaptationSettings::hausd
  int steps = 1;                    // gradual_steps
  std::int64_t partition_seed = 0;  // the partitioner's
};

}  // namespace

template <int D>
AdaptationRun adapt_distributed(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                                const AdaptationSettings& settings, std::int64_t partition_seed,
                                const std::function<void(const DistributedIteration&)>& on_iteration, const PartsEnd<D>& end) {
  // The whole mesh's corners and feature lines first, as the serial loop finds them: a part sees
  // only its share of the boundary (docs/distributed.md §Parts).
  classify_vertices(mesh, settings.feature_angle_degrees);
  // The input's own metric, where the gradual metric starts.
  const MetricField<D> input_metric = input_metric_of(mesh, metric);
  const MetricRecipe recipe = recipe_of(metric);
  std::vector<RunShape> shape{{recipe.bounds, recipe.hausdorff, settings.hausd,
                               gradual_steps(mesh, input_metric, metric, kDistributedIterations - 1), partition_seed}};
  broadcast_values(shape);
  const int steps = shape[0].steps;
  const WholeMeshIterations<D> whole{recipe,         steps,
                                     geometry,       part_settings(settings),
                                     partition_seed, [&](double fraction) { return metric.partway_from(input_metric, fraction); }};
  // The first cut, of the whole mesh: the parts scattered from rank 0, and with them the processes'
  // home shares of the back mesh (the input). PT-Scotch then cuts the parts' distributed graph.
  const auto start = std::chrono::steady_clock::now();
  DistributedIteration first;
  const std::vector<double> loads = expected_element_counts(mesh, metric.partway_from(input_metric, gradual_fraction(1, steps)));
  const std::vector<int> part_of = spatial_cut(mesh, loads, process_count());
  const BackMeshShare<D> home = scatter_back_mesh(mesh, part_of, share_log_metrics(metric, input_metric), &first.back_mesh_bytes);
  MeshPart<D> part = migrate_part(whole_mesh_part(std::move(mesh)), part_of, &first.bytes_sent);
  first.seconds_partition = first.seconds = seconds_since(start);
  partition_first(part, scattered_by_part(loads, part_of), partition_seed, first);
  const WholeMeshResult whole_result = whole.run(part, home, first, on_iteration);
  const RootRuns<D> root{&metric, geometry, settings};
  DistributedIteration in_parts = last_runs_figures(kLastRunsInParts);
  const auto [parts_run, seams] = last_runs_in_parts(part, whole_result, &root, whole, home, in_parts);
  if (on_iteration) on_iteration(in_parts);
  DistributedIteration last_figures = last_runs_figures(kLastRunsOnRoot);
  const AdaptationRun last = last_runs_on_root(part, seams, &root, whole, home, last_figures);
  gathered_metric(home, recipe, Mesh<D>{}, last_figures);  // (rank 0 holds the whole back mesh; the others gather their shares)
  const MeshFileCounts written = end(part, metric);
  last_figures.vertices = written.vertices;
  last_figures.elements = written.elements;
  if (on_iteration) on_iteration(last_figures);
  return joined_runs(joined_runs(whole_result.run, parts_run), last);
}

template <int D>
void serve_distributed_adaptation(const std::optional<AnalyticMetricSpec>& analytic, const BoundaryGeometry<D>* geometry,
                                  AdaptationSettings settings, const PartsEnd<D>& end) {
  std::vector<RunShape> shape;  // rank 0's
  broadcast_values(shape);
  settings.hausd = shape.at(0).hausd;
  const MetricRecipe recipe{analytic, shape[0].bounds, shape[0].hausdorff};
  const WholeMeshIterations<D> whole{recipe, shape[0].steps, geometry, part_settings(settings), shape[0].partition_seed, {}};
  const BackMeshShare<D> home = scatter_back_mesh(Mesh<D>{}, {}, {});
  MeshPart<D> part = migrate_part(MeshPart<D>{}, {});
  DistributedIteration unused;  // (rank 0 keeps the figures)
  partition_first(part, scattered_by_part({}, {}), whole.partition_seed, unused);
  const WholeMeshResult whole_result = whole.run(part, home, {}, {});
  const RootSeeds seams = last_runs_in_parts<D>(part, whole_result, nullptr, whole, home, unused).second;
  last_runs_on_root<D>(part, seams, nullptr, whole, home, unused);
  end_in_every_part(part, home, recipe, end, unused);
}

template <int D>
AdaptationRun adapt_distributed_from_pieces(PiecesStart<D> start, const BoundaryGeometry<D>* geometry, const AdaptationSettings& settings,
                                            std::int64_t partition_seed,
                                            const std::function<void(const DistributedIteration&)>& on_iteration, const PartsEnd<D>& end) {
  const WholeMeshIterations<D> whole{start.recipe, start.steps, geometry, part_settings(settings), partition_seed, {}, true};
  DistributedIteration first;
  MeshPart<D>& part = start.part;
  partition_first(part, start.loads, partition_seed, first);
  start.loads = {};
  const WholeMeshResult whole_result = whole.run(part, start.home, first, on_iteration);
  const RootRuns<D> root{nullptr, geometry, settings};
  const RootRuns<D>* own_root = process_rank() == 0 ? &root : nullptr;
  DistributedIteration in_parts = last_runs_figures(kLastRunsInParts);
  const auto [parts_run, seams] = last_runs_in_parts(part, whole_result, own_root, whole, start.home, in_parts);
  if (process_rank() == 0 && on_iteration) on_iteration(in_parts);
  DistributedIteration last_figures = last_runs_figures(kLastRunsOnRoot);
  const AdaptationRun last = last_runs_on_root(part, seams, own_root, whole, start.home, last_figures);
  end_in_every_part(part, start.home, whole.recipe, end, last_figures);
  if (process_rank() == 0 && on_iteration) on_iteration(last_figures);
  return joined_runs(joined_runs(whole_result.run, parts_run), last);
}

template AdaptationRun adapt_distributed(Mesh<2>&, const AdaptationMetric<2>&, const BoundaryGeometry<2>*, const AdaptationSettings&,
                                         std::int64_t, const std::function<void(const DistributedIteration&)>&, const PartsEnd<2>&);
template AdaptationRun adapt_distributed(Mesh<3>&, const AdaptationMetric<3>&, const BoundaryGeometry<3>*, const AdaptationSettings&,
                                         std::int64_t, const std::function<void(const DistributedIteration&)>&, const PartsEnd<3>&);
template void serve_distributed_adaptation(const std::optional<AnalyticMetricSpec>&, const BoundaryGeometry<2>*, AdaptationSettings,
                                           const PartsEnd<2>&);
template void serve_distributed_adaptation(const std::optional<AnalyticMetricSpec>&, const BoundaryGeometry<3>*, AdaptationSettings,
                                           const PartsEnd<3>&);
template AdaptationRun adapt_distributed_from_pieces(PiecesStart<2>, const BoundaryGeometry<2>*, const AdaptationSettings&, std::int64_t,
                                                     const std::function<void(const DistributedIteration&)>&, const PartsEnd<2>&);
template AdaptationRun adapt_distributed_from_pieces(PiecesStart<3>, const BoundaryGeometry<3>*, const AdaptationSettings&, std::int64_t,
                                                     const std::function<void(const DistributedIteration&)>&, const PartsEnd<3>&);

}  // namespace hocav
