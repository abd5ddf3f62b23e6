#include "parallel/curved_passes_in_parts.hpp"

#include <algorithm>
#include <chrono>
#include <type_traits>
#include <unordered_map>

#include "base/stopwatch.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/face_key.hpp"
#include "parallel/last_run_region.hpp"
#include "parallel/metrics_by_global_id.hpp"
#include "parallel/part_adaptation.hpp"
#include "parallel/part_curving.hpp"
#include "parallel/part_migration.hpp"
#include "parallel/peer_iteration.hpp"

namespace hocav {
namespace {

static_assert(std::is_trivially_copyable_v<CurvedPass>);

template <int D>
struct GlobalLogMetric {
  Index id;
  SymMat<D> log_metric;
};

int meeting_process_of(Index id) { return vertex_meeting_process(id, process_count()); }

// Collective: per vertex of `after`, the log-metric a process gave its global id before (`log_metrics`,
// per id of `before_ids`), the lowest rank's where several hold it: the holders tell it where the id
// hashes to, and the new holders ask there. Adds the bytes sent to others.
template <int D>
std::vector<SymMat<D>> log_metrics_by_global_id(const std::vector<Index>& before_ids, const std::vector<SymMat<D>>& log_metrics,
                                                const MeshPart<D>& after, long long& bytes_sent) {
  std::vector<std::vector<GlobalLogMetric<D>>> told(static_cast<std::size_t>(process_count()));
  for (std::size_t v = 0; v < before_ids.size(); ++v)
    told[static_cast<std::size_t>(meeting_process_of(before_ids[v]))].push_back({before_ids[v], log_metrics[v]});
  for (std::size_t p = 0; p < told.size(); ++p)
    if (p != static_cast<std::size_t>(process_rank())) bytes_sent += static_cast<long long>(told[p].size() * sizeof(GlobalLogMetric<D>));
  std::unordered_map<Index, SymMat<D>> known;
  for (const std::vector<GlobalLogMetric<D>>& from : exchange_values(told))
    for (const GlobalLogMetric<D>& each : from) known.emplace(each.id, each.log_metric);
  return values_asked_of<SymMat<D>>(
      after.global_ids, meeting_process_of, [&](Index id) { return known.at(id); }, bytes_sent);
}

// One part's passes in the field of its vertices' log-metrics, its global ids following its
// vertices; then its vertices' log-metrics sampled in that field, as the passes' operations sample them.
template <int D>
CurvedAdaptationRun passes_on_part(MeshPart<D>& part, std::vector<SymMat<D>>& log_metrics, const BoundaryGeometry<D>* geometry,
                                   const P2CavityOptions& options, const CurvedPassesSettings& settings, int threads) {
  if (part.mesh.element_count() == 0) return {};
  const MetricField<D> field = MetricField<D>::from_log_metrics(part.mesh, std::move(log_metrics));
  CurvedAdaptationRun run;
  change_keeping_global_ids<D>(part, [&](Mesh<D>& mesh) {
    run = adapt_curved(mesh, field, options, settings.max_passes, threads, {geometry, settings.feature_angle_degrees});
  });
  log_metrics.resize(static_cast<std::size_t>(part.mesh.vertex_count()));
  LocatorScratch scratch;
  Index hint = kNoIndex;
  for (Index v = 0; v < part.mesh.vertex_count(); ++v) {
    const auto sample = field.sample(part.mesh.vertex(v), hint, scratch);
    log_metrics[static_cast<std::size_t>(v)] = sample.log_metric;
    hint = sample.where.element;
  }
  return run;
}

// What a part's run says besides its passes.
struct RunSummary {
  P2CavityCounters counters;
  double seconds;
  bool ran, converged;
};

// Collective: the parts' runs as one, appended to `total`: pass i sums the parts' passes i (times:
// the slowest part's; sizes: a part's last when it stopped before); converged when every part that
// ran converged. Returns the most passes a part ran.
int append_combined(CurvedAdaptationRun& total, const CurvedAdaptationRun& own) {
  const std::vector<std::vector<CurvedPass>> passes = all_gather_values(own.passes);
  const std::vector<RunSummary> summaries = all_gather_value(RunSummary{own.counters, own.seconds, !own.passes.empty(), own.converged});
  std::size_t most = 0;
  for (const std::vector<CurvedPass>& each : passes) most = std::max(most, each.size());
  const std::size_t first = total.passes.size();
  total.passes.resize(first + most);
  for (const std::vector<CurvedPass>& each : passes)
    for (std::size_t i = 0; i < most && !each.empty(); ++i) {
      CurvedPass& sum = total.passes[first + i];
      const CurvedPass& pass = each[std::min(i, each.size() - 1)];
      sum.vertices += pass.vertices;
      sum.elements += pass.elements;
      if (i >= each.size()) continue;
      for (auto kind : {&CurvedPass::collapses, &CurvedPass::splits, &CurvedPass::swaps, &CurvedPass::moves}) sum.*kind += pass.*kind;
      sum.seconds = std::max(sum.seconds, pass.seconds);
    }
  double slowest = 0;
  total.converged = true;
  for (const RunSummary& each : summaries) {
    total.counters += each.counters;
    slowest = std::max(slowest, each.seconds);
    if (each.ran) total.converged = total.converged && each.converged;
  }
  total.seconds += slowest;
  return static_cast<int>(most);
}

// The rounds on every process: its part, its vertices' log-metrics, and what the rounds did.
template <int D>
struct PassRounds {
  MeshPart<D>& part;
  std::vector<SymMat<D>>& log_metrics;
  const BoundaryGeometry<D>* geometry;
  const P2CavityOptions& options;
  const CurvedPassesSettings& settings;
  int threads;
  Index next_global_id;  // the same on every process
  CurvedPassesInParts out{};

  // Element k goes to process destination[k] before round r, with its vertices' log-metrics.
  void migrate(std::span<const int> destination, int r) {
    CurvedPassRound& round = out.rounds[static_cast<std::size_t>(r)];
    Index moved = 0;
    for (int to : destination) moved += to != process_rank();
    round.moved_elements = sum_over_processes(moved);
    long long bytes_sent = 0;
    const std::vector<Index> before_ids = part.global_ids;
    part = migrate_part(std::move(part), destination, &bytes_sent);
    log_metrics = log_metrics_by_global_id(before_ids, log_metrics, part, bytes_sent);
    round.bytes_sent = sum_over_processes(bytes_sent);
  }

  // Round r: the passes on every part (here when `runs_here`), then the new vertices numbered.
  void run(int r, bool runs_here, std::chrono::steady_clock::time_point start) {
    CurvedPassRound& round = out.rounds[static_cast<std::size_t>(r)];
    round.elements = sum_over_processes(part.mesh.element_count());
    const CurvedAdaptationRun own = runs_here ? passes_on_part(part, log_metrics, geometry, options, settings, threads)
                                              : CurvedAdaptationRun{};
    round.passes = append_combined(out.run, own);
    number_new_vertices(part, next_global_id);
    round.seconds = max_over_processes(seconds_since(start));
  }
};

// Per element of `part`: rank 0 for those within kBandRings rings of the vertices `seams` names,
// this process for the others.
template <int D>
std::vector<int> seams_to_rank_0(const MeshPart<D>& part, const std::vector<Index>& seams) {
  const std::vector<char> near = elements_near(part.mesh, flags_of_global_ids(part, seams), kBandRings);
  std::vector<int> destination(near.size(), process_rank());
  for (std::size_t k = 0; k < near.size(); ++k)
    if (near[k]) destination[k] = 0;
  return destination;
}

}  // namespace

template <int D>
CurvedPassesInParts adapt_curved_in_parts(MeshPart<D>& part, std::vector<SymMat<D>>& log_metrics, const BoundaryGeometry<D>* geometry,
                                          const P2CavityOptions& options, const CurvedPassesSettings& settings, int threads) {
  const Index largest = part.global_ids.empty() ? -1 : *std::max_element(part.global_ids.begin(), part.global_ids.end());
  PassRounds<D> rounds{part, log_metrics, geometry, options, settings, threads, max_over_processes(largest) + 1};
  rounds.run(0, true, std::chrono::steady_clock::now());  // every part, its interfaces frozen
  // Each interface's region with one of its two processes: the interface inside a part.
  auto start = std::chrono::steady_clock::now();
  // (Each region to the lighter of its two processes: the loop's last runs left them unbalanced.)
  const RegionCut cut = cut_last_run_region(part, kBandRings, all_gather_value(part.mesh.element_count()));
  const std::vector<Index> seams = all_gather_values_joined(cut.seams);
  rounds.migrate(cut.destination, 1);
  rounds.run(1, true, start);
  // The regions' seams (none with two processes), on rank 0.
  if (seams.empty()) return std::move(rounds.out);
  start = std::chrono::steady_clock::now();
  rounds.migrate(seams_to_rank_0(part, seams), 2);
  rounds.run(2, process_rank() == 0, start);
  return std::move(rounds.out);
}

template CurvedPassesInParts adapt_curved_in_parts(MeshPart<2>&, std::vector<SymMat<2>>&, const BoundaryGeometry<2>*,
                                                   const P2CavityOptions&, const CurvedPassesSettings&, int);
template CurvedPassesInParts adapt_curved_in_parts(MeshPart<3>&, std::vector<SymMat<3>>&, const BoundaryGeometry<3>*,
                                                   const P2CavityOptions&, const CurvedPassesSettings&, int);

}  // namespace hocav
