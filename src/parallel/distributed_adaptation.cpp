#include "parallel/distributed_adaptation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include "adapt/vertex_classes.hpp"
#include "base/error.hpp"
#include "base/memory_budget.hpp"
#include "base/stopwatch.hpp"
#include "geom/sym_functions.hpp"
#include "metric/gradation.hpp"
#include "metric/implied_metric.hpp"
#include "parallel/back_mesh_share.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/part_adaptation.hpp"
#include "parallel/part_message.hpp"
#include "parallel/part_migration.hpp"
#include "parallel/peer_iteration.hpp"
#include "parallel/share_metric.hpp"
#include "parallel/spatial_cut.hpp"

namespace hocav {
namespace {

// A whole-mesh iteration asks for sizes at most this many times finer than the mesh it starts from
// (where the metric is finest against the input), if kDistributedIterations - 1 steps allow.
constexpr double kGradualRefinement = 5;

// The whole-mesh iterations that step from the input's own metric to the target: enough for the
// largest ratio of the input's sizes to the target's, at the input's vertices, to take steps of at
// most kGradualRefinement, and at most kDistributedIterations - 1.
template <int D>
int gradual_steps(const Mesh<D>& input, const MetricField<D>& input_metric, const AdaptationMetric<D>& metric) {
  double ratio = 1;
  Index hint = kNoIndex;
  for (Index v = 0; v < input.vertex_count(); ++v) {
    const SymMat<D> own = exp_sym(input_metric.vertex_log_metric(v));
    ratio = std::max(ratio, std::sqrt(largest_relative_eigenvalue(metric.metric_at(input.vertex(v), hint), own)));
  }
  const int steps = static_cast<int>(std::ceil(std::log(ratio) / std::log(kGradualRefinement) - 1e-9));
  return std::clamp(steps, 1, kDistributedIterations - 1);
}

// The input's own metric (docs/method.md §10), on the metric's back mesh when that is the input: rank
// 0 then holds one copy of the input and its point locator, not two.
template <int D>
MetricField<D> input_metric_of(const Mesh<D>& input, const AdaptationMetric<D>& metric) {
  const std::vector<SymMat<D>> implied = implied_metric_at_vertices(input);
  const MetricField<D>* field = metric.field();
  return field && field->is_on(input) ? field->with_metrics(implied) : MetricField<D>(input, implied);
}

// The share of the way from the input's own metric to the target that an iteration adapts to: the
// whole mesh's iterations step there evenly, so that each starts at most a few times coarser than
// it asks and its frozen interfaces stay near their metric; the band and the last run adapt to the
// target (docs/distributed.md §A gradual metric).
double gradual_fraction(int iteration, int steps) { return std::min(1.0, static_cast<double>(iteration) / steps); }

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

// The faces between two adapted parts (those below `adapted`) of a partition, and their vertices.
struct PartInterfaces {
  Index faces = 0;
  std::vector<char> vertex;  // per mesh vertex
};

template <int D>
PartInterfaces interfaces_between(const Mesh<D>& mesh, std::span<const int> part_of, int adapted) {
  PartInterfaces out{0, std::vector<char>(static_cast<std::size_t>(mesh.vertex_count()), 0)};
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face) {
      const Index other = mesh.neighbor(k, face);
      if (other == kNoIndex || other < k || part_of[other] == part_of[k] || part_of[k] >= adapted || part_of[other] >= adapted) continue;
      ++out.faces;
      for (int i = 0; i < D; ++i) out.vertex[mesh.element(k)[face_vertices<D>(face)[i]]] = 1;
    }
  return out;
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
  part = repartition(part, loads, {}, partition_seed, &bytes_sent);
  figures.bytes_sent += sum_over_processes(bytes_sent);
  figures.seconds_partition += seconds_since(start);
  figures.seconds += seconds_since(start);
}

// One iteration on rank 0: split along a partition, send, adapt part 0, receive, merge. Part r goes
// to rank r; the elements of part `process_count()` (the kept part) stay as they are.
template <int D>
struct RootIteration {
  Mesh<D>& mesh;
  AdaptationMetric<D> metric;  // the iteration's, on the whole back mesh
  const BoundaryGeometry<D>* geometry;
  AdaptationSettings settings;  // the parts' loop's (part_settings)
  std::int64_t partition_seed;
  std::vector<char> old_interface;  // per vertex of `mesh`: on the interfaces between adapted parts
  DistributedIteration figures;
  const BackMeshShare<D>* home;  // rank 0's share of the back mesh, which the other parts' metrics need

  // The parts' metric is `metric`, figures.metric_fraction of the way (sent to the other ranks).
  AdaptationRun run(const std::vector<int>& part_of, std::chrono::steady_clock::time_point start) {
    const int count = process_count();
    std::vector<MeshPart<D>> parts = split_mesh(mesh, part_of, count + 1);
    const PartInterfaces interfaces = interfaces_between(mesh, part_of, count);
    figures.seconds_partition = seconds_since(start);
    figures.interface_faces = interfaces.faces;
    for (int p = 1; p < count; ++p) {
      send(p, bytes_of_values(std::vector<double>{figures.metric_fraction}));
      send(p, pack_part(parts[p].mesh, std::span<const Index>(parts[p].global_ids)));
    }
    gathered_metric(*home, {}, Mesh<D>{}, figures);  // rank 0 has the whole back mesh: it asks for none
    auto [run0, figures0] = adapt_part_measured(parts[0], metric, geometry, settings);
    std::vector<AdaptationRun> runs{std::move(run0)};
    note(figures0);
    for (int p = 1; p < count; ++p) {
      parts[p] = unpack_part<D>(receive(p));
      runs.push_back(unpack_run(receive(p)));
      const std::vector<PartFigures> figures_of_part = values_of_bytes<PartFigures>(receive(p));
      if (figures_of_part.size() != 1) throw Error("a distributed adaptation message has the wrong size");
      note(figures_of_part[0]);
    }
    MergedMesh<D> merged = merge_parts(mesh, parts);
    mesh = std::move(merged.mesh);
    mesh.build_topology();
    old_interface.assign(static_cast<std::size_t>(mesh.vertex_count()), 0);
    for (std::size_t v = 0; v < interfaces.vertex.size(); ++v)
      if (interfaces.vertex[v]) old_interface[merged.old_vertex_ids[v]] = 1;
    figures.interface_vertices = static_cast<Index>(std::count(old_interface.begin(), old_interface.end(), 1));
    figures.vertices = mesh.vertex_count();
    figures.elements = mesh.element_count();
    figures.seconds = seconds_since(start);
    return combined(runs);
  }

  // The elements within kInterfaceBandRings rings of the last interfaces in the processes' parts, of
  // balanced predicted output; the others in the kept part.
  std::vector<int> band_partition() const {
    std::vector<int> part_of(static_cast<std::size_t>(mesh.element_count()), process_count());
    std::vector<Index> band;
    const WeightedGraph graph = member_graph(mesh, elements_near(mesh, old_interface, kInterfaceBandRings),
                                             expected_element_counts(mesh, metric), band);
    if (band.empty()) return part_of;
    const std::vector<int> part_of_band = partition_graph(graph, process_count(), partition_seed);
    for (std::size_t i = 0; i < band.size(); ++i) part_of[band[i]] = part_of_band[i];
    return part_of;
  }

  void note(const PartFigures& part) {
    figures.part_seconds.push_back(part.seconds);
    figures.peak_memory_bytes.push_back(part.peak_memory_bytes);
  }
  void send(int to, const std::vector<std::byte>& bytes) { send_bytes(to, bytes, figures.bytes_sent); }
  std::vector<std::byte> receive(int from) { return receive_bytes(from, figures.bytes_sent); }
};

// The whole-mesh iterations, 1 to kDistributedIterations - 1, on every process at once and peer to
// peer (peer_iteration.hpp), from the processes' parts of the first partition; the last gathers the
// mesh on rank 0. Each adapts to the metric its share of the way from the input's own.
template <int D>
struct WholeMeshIterations {
  MetricRecipe recipe;  // the target's
  int steps;            // gradual_steps, rank 0's
  const BoundaryGeometry<D>* geometry;
  AdaptationSettings settings;  // the parts' loop's (part_settings)
  std::int64_t partition_seed;
  // Rank 0's: the metric on the whole back mesh, a fraction of the way from the input's own (rank 0
  // asks for no share: it holds the whole); empty on the other processes.
  std::function<AdaptationMetric<D>(double)> whole_metric;

  // Rank 0 gets the runs, the last iteration's interface vertices and (in `part`) every element;
  // `first` holds the figures of the first cut's scatter.
  PeerIterationResult run(MeshPart<D>& part, const BackMeshShare<D>& home, DistributedIteration first,
                          const std::function<void(const DistributedIteration&)>& on_iteration) const {
    Index next_global_id = 0;
    for (Index most :
         all_gather_value(part.global_ids.empty() ? Index{0} : *std::max_element(part.global_ids.begin(), part.global_ids.end()) + 1))
      next_global_id = std::max(next_global_id, most);
    PeerIterationResult all;
    for (int iteration = 1; iteration < kDistributedIterations; ++iteration) {
      const double fraction = gradual_fraction(iteration, steps);
      DistributedIteration figures = iteration == 1 ? first : DistributedIteration{};
      figures.iteration = iteration;
      figures.metric_fraction = fraction;
      const std::unique_ptr<ShareMetric<D>> near = gathered_metric(home, recipe, whole_metric ? Mesh<D>{} : part.mesh, figures);
      const auto partway = [&](double to) { return whole_metric ? whole_metric(to) : near->partway(to); };
      const AdaptationMetric<D> iteration_metric = partway(fraction);
      std::optional<AdaptationMetric<D>> next;
      if (iteration + 1 < kDistributedIterations) next = partway(gradual_fraction(iteration + 1, steps));
      const PeerIteration<D> step{iteration_metric, geometry, settings, partition_seed, next ? &*next : nullptr};
      PeerIterationResult result = run_peer_iteration(part, next_global_id, step, figures);
      all.run.passes.insert(all.run.passes.end(), result.run.passes.begin(), result.run.passes.end());
      all.run.caps_removed += result.run.caps_removed;
      all.interface_vertices = std::move(result.interface_vertices);
      if (process_rank() == 0 && on_iteration) on_iteration(figures);
    }
    return all;
  }
};

// Per vertex of the gathered `part`: whether its global id is listed in `ids`.
template <int D>
std::vector<char> flags_of_global_ids(const MeshPart<D>& part, const std::vector<Index>& ids) {
  std::vector<char> flags(part.global_ids.size(), 0);
  for (Index id : ids)
    if (const auto at = std::lower_bound(part.global_ids.begin(), part.global_ids.end(), id); at != part.global_ids.end() && *at == id)
      flags[static_cast<std::size_t>(at - part.global_ids.begin())] = 1;
  return flags;
}

// The last runs, serial on rank 0's merged mesh after the band. The band's parts kept their own
// interfaces (`old_interface`) frozen where they cross the band: the first run tries first only
// the region around them, the poor elements and the edges outside the unit window that the parts,
// stopped early, left elsewhere. The second starts from what that run left (its poor elements and
// edges outside the unit window) with its window open again: a run that closed its window early
// cannot collapse what it made later. Their passes, in order; the second's flags.
template <int D>
AdaptationRun last_serial_runs(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                               const AdaptationSettings& settings, const std::vector<char>& old_interface) {
  AdaptationSettings last = settings;
  last.first_pass_vertices = around_interfaces(mesh, old_interface);
  last.first_pass_unfinished_edges = true;
  AdaptationRun run = adapt_to_metric(mesh, metric, geometry, last);
  last.first_pass_vertices.assign(static_cast<std::size_t>(mesh.vertex_count()), 0);
  const AdaptationRun again = adapt_to_metric(mesh, metric, geometry, last);
  run.passes.insert(run.passes.end(), again.passes.begin(), again.passes.end());
  run.converged = again.converged;
  run.stopped_with_window_open = again.stopped_with_window_open;
  run.caps_removed += again.caps_removed;
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
                                const std::function<void(const DistributedIteration&)>& on_iteration) {
  // The whole mesh's corners and feature lines first, as the serial loop finds them: a part sees
  // only its share of the boundary (docs/distributed.md §Parts).
  classify_vertices(mesh, settings.feature_angle_degrees);
  // The input's own metric, where the gradual metric starts.
  const MetricField<D> input_metric = input_metric_of(mesh, metric);
  const MetricRecipe recipe = recipe_of(metric);
  std::vector<RunShape> shape{{recipe.bounds, recipe.hausdorff, settings.hausd, gradual_steps(mesh, input_metric, metric), partition_seed}};
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
  const PeerIterationResult peer = whole.run(part, home, first, on_iteration);
  AdaptationRun run = peer.run;
  std::vector<char> old_interface = flags_of_global_ids(part, peer.interface_vertices);
  mesh = whole_mesh_of(std::move(part));
  mesh.build_topology();
  // The band, from rank 0.
  const double band_fraction = gradual_fraction(kDistributedIterations, steps);
  RootIteration<D> root{
      mesh, metric.partway_from(input_metric, band_fraction), geometry, whole.settings, partition_seed, std::move(old_interface), {},
      &home};
  root.figures.iteration = kDistributedIterations;
  root.figures.metric_fraction = band_fraction;
  const AdaptationRun band = root.run(root.band_partition(), std::chrono::steady_clock::now());
  run.passes.insert(run.passes.end(), band.passes.begin(), band.passes.end());
  run.caps_removed += band.caps_removed;
  if (on_iteration) on_iteration(root.figures);
  for (int p = 1; p < process_count(); ++p) send_bytes(p, {});  // stop
  const AdaptationRun last = last_serial_runs(mesh, metric, geometry, settings, root.old_interface);
  run.passes.insert(run.passes.end(), last.passes.begin(), last.passes.end());
  run.converged = last.converged;
  run.stopped_with_window_open = last.stopped_with_window_open;
  run.caps_removed += last.caps_removed;
  return run;
}

template <int D>
void serve_distributed_adaptation(const std::optional<AnalyticMetricSpec>& analytic, const BoundaryGeometry<D>* geometry,
                                  AdaptationSettings settings) {
  std::vector<RunShape> shape;  // rank 0's
  broadcast_values(shape);
  settings.hausd = shape.at(0).hausd;
  const MetricRecipe recipe{analytic, shape[0].bounds, shape[0].hausdorff};
  const WholeMeshIterations<D> whole{recipe, shape[0].steps, geometry, part_settings(settings), shape[0].partition_seed, {}};
  const BackMeshShare<D> home = scatter_back_mesh(Mesh<D>{}, {}, {});
  MeshPart<D> part = migrate_part(MeshPart<D>{}, {});
  DistributedIteration unused;  // (rank 0 keeps the figures)
  partition_first(part, scattered_by_part({}, {}), whole.partition_seed, unused);
  whole.run(part, home, {}, {});
  // The band: the part rank 0 sends, until it says stop.
  for (;;) {
    const std::vector<double> fraction = receive_values<double>(0);
    if (fraction.size() != 1) return;  // stop
    part = unpack_part<D>(receive_bytes(0));
    const std::unique_ptr<ShareMetric<D>> near = gathered_metric(home, recipe, part.mesh, unused);
    const auto [run, figures] = adapt_part_measured(part, near->partway(fraction[0]), geometry, whole.settings);
    send_bytes(0, pack_part(part.mesh, std::span<const Index>(part.global_ids)));
    send_bytes(0, pack_run(run));
    send_values(0, std::vector<PartFigures>{figures});
  }
}

template AdaptationRun adapt_distributed(Mesh<2>&, const AdaptationMetric<2>&, const BoundaryGeometry<2>*, const AdaptationSettings&,
                                         std::int64_t, const std::function<void(const DistributedIteration&)>&);
template AdaptationRun adapt_distributed(Mesh<3>&, const AdaptationMetric<3>&, const BoundaryGeometry<3>*, const AdaptationSettings&,
                                         std::int64_t, const std::function<void(const DistributedIteration&)>&);
template void serve_distributed_adaptation(const std::optional<AnalyticMetricSpec>&, const BoundaryGeometry<2>*, AdaptationSettings);
template void serve_distributed_adaptation(const std::optional<AnalyticMetricSpec>&, const BoundaryGeometry<3>*, AdaptationSettings);

}  // namespace hocav
