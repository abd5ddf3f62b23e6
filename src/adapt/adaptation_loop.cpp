#include "adapt/adaptation_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <utility>

#include "adapt/adaptation_mesh.hpp"
#include "adapt/boundary_settling.hpp"
#include "adapt/vertex_classes.hpp"
#include "base/error.hpp"
#include "mesh/spatial_order.hpp"

namespace hocav {
namespace {

// The loop's window (docs/adaptation.md §The loop): while it is open, a collapse may make edges up
// to kOpenCollapseLength, which the next split cuts; short edges that no collapse within √2 can
// remove then go. It closes for good when a pass after the busiest one changes more than
// kStalledChange of the pass before it, and not more than 1 / kStalledChange of it (a jump is new
// work, such as the end of the split's coarse phase): what is left is split/collapse ping-pong, and
// the loop then converges with the closed window's rule (no collapse makes work for the next split).
constexpr double kOpenCollapseLength = 2.0;
constexpr double kStalledChange = 0.9;
// A pass that changes more than kPingPongFall of the pass before but moves the vertex count by
// less than kPingPongShare of its splits plus collapses only moves vertices about: ping-pong too,
// which the rule above sees passes later (on the sphere shell, four passes of 19–26k splits and
// collapses, each 11% fewer than the one before, moved the vertex count by +7 to +288). A run whose
// changes fall faster (the UGAWG cube's by 25–35% a pass, its unit share rising) goes on, until
// kFlatPasses passes in a row have moved the vertex count by less than kPingPongShare of their
// changes (the linear-metric cube of 643k elements fell by 20–25% a pass with a flat vertex
// count from its tenth pass to the cap of 20).
constexpr double kPingPongFall = 0.8;
constexpr double kPingPongShare = 0.05;
constexpr std::size_t kFlatPasses = 3;

bool window_open(const AdaptationLimits& limits) { return limits.collapse_new_length > limits.split_length; }

Index changes(const AdaptationPass& pass) { return pass.splits.done + pass.collapses.done; }

// Whether the last pass's settling got further than the one before (docs/adaptation.md §Boundary
// settling, "Between passes"): a vertex reached the geometry, or fewer were left part of the way.
// While it does, the loop goes on though it changes little: each pass mends the elements that held
// the last moves back, and the next settling goes further.
bool settling_progressed(const std::vector<AdaptationPass>& passes) {
  const AdaptationPass& last = passes.back();
  const Index partly_before = passes.size() > 1 ? passes[passes.size() - 2].partly_settled : 0;
  return last.settled > 0 || last.partly_settled < partly_before;
}

// Whether pass `last` moved the vertex count by less than kPingPongShare of its changes.
bool flat(const AdaptationPass& before, const AdaptationPass& last) {
  return std::abs(static_cast<double>(last.vertices - before.vertices)) < kPingPongShare * static_cast<double>(changes(last));
}

// Whether a pass took the vertex and element counts back to those of the pass two before, from
// others: a few splits undone by collapses every other pass (a part's last run on the linear-metric
// cube: 5 splits of face diagonals exactly √2 long, their halves collapsed back, 36 passes to the
// cap), too few for `flat`.
bool back_where_it_was(const AdaptationPass& two_before, const AdaptationPass& before, const AdaptationPass& last) {
  const auto counts = [](const AdaptationPass& pass) { return std::pair(pass.vertices, pass.elements); };
  return counts(last) == counts(two_before) && counts(last) != counts(before);
}

bool ping_pong(const std::vector<AdaptationPass>& passes) {
  const std::size_t n = passes.size();
  if (n > 2 && back_where_it_was(passes[n - 3], passes[n - 2], passes[n - 1])) return true;
  const auto changed = static_cast<double>(changes(passes[n - 1]));
  if (changed > kPingPongFall * static_cast<double>(changes(passes[n - 2])) && flat(passes[n - 2], passes[n - 1])) return true;
  if (n <= kFlatPasses) return false;
  for (std::size_t i = n - kFlatPasses; i < n; ++i)
    if (!flat(passes[i - 1], passes[i])) return false;
  return true;
}

bool stalled(const std::vector<AdaptationPass>& passes) {
  if (passes.size() < 2) return false;
  if (!passes.back().coarse_phase && ping_pong(passes)) return true;
  Index busiest = 0;
  for (std::size_t i = 0; i + 1 < passes.size(); ++i) busiest = std::max(busiest, changes(passes[i]));
  const Index before = changes(passes[passes.size() - 2]);
  const bool past_the_busiest = before < busiest;
  const auto last = static_cast<double>(changes(passes.back()));
  return past_the_busiest && last > kStalledChange * static_cast<double>(before) && kStalledChange * last <= static_cast<double>(before);
}

// Runs `step` and adds its wall time to `seconds`.
template <typename Step>
auto timed(double& seconds, Step step) {
  const auto start = std::chrono::steady_clock::now();
  auto result = step();
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// A swap sweep tries only what changed since the previous sweep began (AdaptationMesh::start_sweep;
// everything in the first pass): a swap refused once is retried only when its cavity has changed.
template <int D>
AdaptationPass run_pass(AdaptationMesh<D>& am, const AdaptationLimits& limits, ThreadPool& pool) {
  AdaptationPass pass;
  am.start_pass();
  if (am.geometry()) {
    const BoundarySettling settling = timed(pass.seconds_settle, [&] { return settle_boundary_between_passes(am); });
    pass.settled = settling.settled;
    pass.partly_settled = settling.partly;
  }
  pass.collapses = timed(pass.seconds_collapse, [&] { return collapse_short_edges(am, limits, pool); });
  pass.collapses += timed(pass.seconds_collapse, [&] { return collapse_thin_vertices(am, limits); });
  pass.swaps = timed(pass.seconds_swap, [&] { return swap_for_quality(am, limits, am.start_sweep(), pool); });
  const SplitSweep split = timed(pass.seconds_split, [&] { return split_long_edges(am, limits, pool); });
  pass.splits = split.count;
  pass.coarse_phase = split.coarse_phase;
  pass.splits += timed(pass.seconds_split, [&] { return cut_boundary_only_elements(am, limits); });
  pass.swaps += timed(pass.seconds_swap, [&] { return swap_for_quality(am, limits, am.start_sweep(), pool); });
  pass.moves = timed(pass.seconds_smooth, [&] { return smooth_vertices(am, limits, pool); });
  // Compacted, then in spatial order: the pass appended its new vertices and elements in its
  // candidates' order, all over the domain (docs/mesh-model.md §Spatial order).
  timed(pass.seconds_compact, [&] {
    am.mesh().compact();
    sort_spatially(am.mesh());
    return 0;
  });
  pass.vertices = am.mesh().vertex_count();
  pass.elements = am.mesh().element_count();
  pass.seconds = pass.seconds_collapse + pass.seconds_swap + pass.seconds_split + pass.seconds_smooth + pass.seconds_compact +
                 pass.seconds_settle;
  return pass;
}

// AdaptationSettings::first_pass_vertices with the vertices of the poor elements, and with the ends
// of the edges outside the unit window when `unfinished_edges` (found as the split and the collapse
// find their candidates: every vertex counts as changed before the first pass).
template <int D>
std::vector<char> first_pass_region(const AdaptationMesh<D>& am, std::vector<char> region, bool unfinished_edges,
                                    const AdaptationLimits& limits, ThreadPool& pool) {
  const Mesh<D>& mesh = am.mesh();
  if (region.size() != static_cast<std::size_t>(mesh.vertex_count()))
    throw Error("adaptation: the first pass's vertices do not match the mesh");
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (am.quality(k) < kPoorQuality)
      for (Index v : mesh.element(k)) region[static_cast<std::size_t>(v)] = 1;
  if (unfinished_edges)
    for (const bool longer : {true, false})
      for (const EdgeCandidate& c : edges_beyond(am, longer ? limits.split_length : limits.collapse_length, longer, pool))
        region[static_cast<std::size_t>(c.a)] = region[static_cast<std::size_t>(c.b)] = 1;
  return region;
}

}  // namespace

bool changed_little(const AdaptationPass& pass) { return changes(pass) <= kConvergedChange * pass.vertices; }

template <int D>
AdaptationRun adapt_to_metric(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                              const AdaptationSettings& settings) {
  AdaptationMesh<D> am(mesh, metric, geometry, settings.ridges_from_shape ? settings.feature_angle_degrees : kRidgesFromTagsOnly);
  AdaptationLimits limits;
  ThreadPool pool(std::max(1, settings.threads));
  if (!settings.first_pass_vertices.empty())
    am.settle_outside(first_pass_region(am, settings.first_pass_vertices, settings.first_pass_unfinished_edges, limits, pool));
  limits.collapse_new_length = kOpenCollapseLength;
  limits.cos_feature_angle = std::cos(settings.feature_angle_degrees * std::numbers::pi / 180);
  limits.hausd = settings.hausd;
  limits.splits_at_required_vertices = settings.splits_at_required_vertices;
  AdaptationRun run;
  int closed_passes = 0;
  for (int pass = 1; pass <= settings.max_passes && !run.converged && closed_passes != settings.passes_after_window_closes; ++pass) {
    run.passes.push_back(run_pass(am, limits, pool));
    AdaptationPass& last = run.passes.back();
    last.window_open = window_open(limits);
    last.collapse_length_bound = limits.collapse_new_length;
    run.converged = changed_little(last) && !settling_progressed(run.passes);
    if (!window_open(limits)) ++closed_passes;
    if (stalled(run.passes)) limits.collapse_new_length = limits.split_length;
    if (settings.progress) settings.progress(pass, settings.max_passes);
  }
  run.stopped_with_window_open = window_open(limits);
  run.caps_removed = remove_boundary_caps(am, limits).done;
  mesh.compact();
  return run;
}

template AdaptationRun adapt_to_metric(Mesh<2>&, const AdaptationMetric<2>&, const BoundaryGeometry<2>*, const AdaptationSettings&);
template AdaptationRun adapt_to_metric(Mesh<3>&, const AdaptationMetric<3>&, const BoundaryGeometry<3>*, const AdaptationSettings&);

}  // namespace hocav
