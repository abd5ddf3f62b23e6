// Vertex smoothing (docs/adaptation.md §Smoothing): an interior or surface vertex moves toward the
// mean of the points that would make each of its edges unit (w + (v − w)/l(v, w) for each neighbour
// w), by the whole step or half of it, when that raises the worst quality of its ball and keeps its
// edges in the length window; a ball with a poor element then also tries the point that makes that
// element regular (a surface vertex a hair from another surface may shorten its edges beyond the
// window there).
// A surface vertex stays on its surface (projected on the geometry, or kept in the plane of its
// facets without one) and its facets pass the boundary test of splits and collapses. The ball keeps
// its topology, so the move is checked by the quality itself: it is positive only for elements of
// positive measure.
#include <algorithm>
#include <array>
#include <cmath>

#include "adapt/adaptation_operations.hpp"
#include "adapt/boundary_pieces.hpp"
#include "adapt/conflict_batches.hpp"
#include "adapt/regular_apex.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

// A move must raise the ball's worst quality by this factor (mmg asks 1.02): no move undoes another.
constexpr double kSmoothingGain = 1.01;
// Smaller batches are tried on the calling thread alone.
constexpr std::size_t kSmallestSmoothingBatch = 32;

// The mean over the ball's elements of w + (v − w)/l(v, w) for each other vertex w (a neighbour
// counts once per element it shares with v), with `lengths` those of v's edges to its neighbours
// and `places` as neighbors_in gives them for `ball`.
template <int D>
Vec<D> unit_edge_target(const AdaptationMesh<D>& am, Index v, std::span<const Index> ball, std::span<const Index> places,
                        std::span<const double> lengths) {
  const Mesh<D>& mesh = am.mesh();
  Vec<D> sum{};
  int count = 0;
  std::size_t slot = 0;
  for (Index k : ball)
    for (Index w : mesh.element(k))
      if (w != v) {
        const double length = lengths[static_cast<std::size_t>(places[slot++])];
        if (!(length > 0)) continue;
        sum = sum + (mesh.vertex(w) + (1 / length) * (mesh.vertex(v) - mesh.vertex(w)));
        ++count;
      }
  return count ? (1.0 / count) * sum : mesh.vertex(v);
}

// The fractions of the way to its target a vertex tries.
constexpr std::array<double, 2> kSmoothingSteps{1, 0.5};
// A ball whose worst element is below this quality also tries the point that makes that element
// regular (refine's repair target), down to a small fraction of the way: a vertex a hair from a
// face gains much from a short move off it.
constexpr double kRepairQuality = 0.1;
constexpr std::array<double, 5> kRepairSteps{1, 0.5, 0.25, 0.125, 0.0625};

// Where v would make `element` (of its ball) regular in v's metric (regular_apex.hpp).
template <int D>
Vec<D> repair_target(const AdaptationMesh<D>& am, Index v, const typename Mesh<D>::Element& element) {
  std::array<Vec<D>, D> face;
  int n = 0;
  for (Index w : element)
    if (w != v) face[static_cast<std::size_t>(n++)] = am.mesh().vertex(w);
  return regular_apex<D>(face, am.mesh().vertex(v), am.metric(v));
}

// Whether element k of v's ball stands on a boundary facet of another ref than v's facet `own`, on
// its face opposite v.
template <int D>
bool over_another_surface(const Mesh<D>& mesh, Index v, Index k, Index own) {
  const Index f = mesh.element_face_facet(k, local_vertex(mesh, k, v));
  return f != kNoIndex && mesh.facet_ref(f) != mesh.facet_ref(own);
}

template <int D>
struct alignas(64) SmoothingScratch {  // a cache line of its own: each thread writes its own
  std::vector<Index> neighbors, places, facets;
  std::vector<double> lengths;
  std::vector<typename Mesh<D>::Element> elements;
  std::vector<Vec<D>> facet_normals;  // before the move
};

// Where surface vertex v may go near x: on the geometry of its facets' ref (searched from v's last
// projection), or (without one) in the plane through its start with the mean normal of its facets.
template <int D>
Vec<D> on_surface(AdaptationMesh<D>& am, Index v, const Vec<D>& x, const Vec<D>& start, const SmoothingScratch<D>& scratch) {
  if (am.geometry()) {
    const BoundaryPoint<D> projected = am.geometry()->project(x, {am.mesh().facet_ref(scratch.facets.front()), am.surface_hint(v)});
    am.set_surface_hint(v, projected.patch);
    return projected.point;
  }
  Vec<D> normal{};
  for (const Vec<D>& n : scratch.facet_normals) normal = normal + n;
  normal = (1 / norm(normal)) * normal;
  return x - dot(x - start, normal) * normal;
}

template <int D>
bool facets_stay_close(const AdaptationMesh<D>& am, const SmoothingScratch<D>& scratch, const AdaptationLimits& limits) {
  for (std::size_t i = 0; i < scratch.facets.size(); ++i)
    if (!facet_stays_close<D>(am, scratch.facets[i], scratch.facet_normals[i], limits.cos_feature_angle, limits.hausd)) return false;
  return true;
}

// Whether v moved to x (metric there: metric_x) raises every element of its ball above `bar` and
// keeps its edges in the length window of `old_lengths`; evaluated without moving it, and
// stopped at the first element at or below the bar (most trials are refused).
template <int D>
bool move_passes(const AdaptationMesh<D>& am, Index v, const Vec<D>& x, const SymMat<D>& metric_x, const SmoothingScratch<D>& scratch,
                 double bar, std::pair<double, double> old_lengths, const AdaptationLimits& limits) {
  for (const auto& element : scratch.elements)
    if (!(am.quality(element, v, x, metric_x) > bar)) return false;
  return lengths_stay_in_window(old_lengths, length_range_from<D>(am, x, metric_x, scratch.neighbors), limits);
}

// One vertex's smoothing: what every trial position is judged against, read before any move.
template <int D>
struct SmoothingTrial {
  Index v;
  std::span<const Index> ball;
  Vec<D> start;
  bool on_boundary;
  double old_worst;
  std::pair<double, double> old_lengths;
};

// Moves the trial's vertex to the first of `fractions` of the way to `target` that passes, its
// edges judged against `window` (the shortest and longest lengths the window then allows, as
// lengths_stay_in_window reads them); false (nothing moved) when none does.
template <int D>
bool move_toward(AdaptationMesh<D>& am, const SmoothingTrial<D>& trial, const Vec<D>& target, std::span<const double> fractions,
                 std::pair<double, double> window, SmoothingScratch<D>& scratch, const AdaptationLimits& limits) {
  const Index v = trial.v;
  for (double fraction : fractions) {
    const Vec<D> along = trial.start + fraction * (target - trial.start);
    const Vec<D> x = trial.on_boundary ? on_surface(am, v, along, trial.start, scratch) : along;
    if (!move_passes(am, v, x, am.metric_near(x, v), scratch, kSmoothingGain * trial.old_worst, window, limits)) continue;
    const SymMat<D> start_metric = am.metric(v);
    am.move_vertex(v, x, trial.ball);
    if (trial.on_boundary && !facets_stay_close(am, scratch, limits)) {  // read on the moved mesh
      am.restore_vertex(v, trial.start, start_metric, trial.ball);
      continue;
    }
    return true;
  }
  return false;
}

// Tries to move v (its ball: `ball`); changes only v, its metric, geometry hint and its ball's kept qualities, so
// vertices whose balls share no element may be tried at the same time.
template <int D>
bool smooth_vertex(AdaptationMesh<D>& am, Index v, std::span<const Index> ball, SmoothingScratch<D>& scratch,
                   const AdaptationLimits& limits) {
  if (ball.empty()) return false;
  scratch.elements.clear();
  for (Index k : ball) scratch.elements.push_back(am.mesh().element(k));
  neighbors_in<D>(scratch.elements, v, scratch.neighbors, &scratch.places);
  // Most trials are refused by the element that was the worst: judged first.
  const auto worst = std::min_element(ball.begin(), ball.end(), [&](Index x, Index y) { return am.quality(x) < am.quality(y); });
  std::swap(scratch.elements.front(), scratch.elements[static_cast<std::size_t>(worst - ball.begin())]);
  scratch.lengths.clear();
  for (Index w : scratch.neighbors) scratch.lengths.push_back(am.edge_length(v, w));
  const auto [shortest, longest] = std::minmax_element(scratch.lengths.begin(), scratch.lengths.end());
  const SmoothingTrial<D> trial{
      v, ball, am.mesh().vertex(v), am.vertex_class(v) == VertexClass::kSurface, am.quality(*worst), {*shortest, *longest}};
  if (trial.on_boundary) {
    const Index center[1] = {v};
    facets_through<D>(am.mesh(), ball, center, scratch.facets);
    if (scratch.facets.empty()) return false;
    scratch.facet_normals.clear();
    for (Index f : scratch.facets) scratch.facet_normals.push_back(area_normal<D>(am.mesh(), am.mesh().facet(f)));
  }
  if (move_toward(am, trial, unit_edge_target(am, v, ball, scratch.places, scratch.lengths), kSmoothingSteps, trial.old_lengths, scratch,
                  limits))
    return true;
  if (!(trial.old_worst < kRepairQuality)) return false;
  // A surface vertex a hair from another surface may make an edge shorter than its ball's shortest
  // (the next collapse's): nothing else takes it off the feature line between them (inner vertices
  // over a facet have the thin vertices' collapse and sink).
  std::pair<double, double> repair_window = trial.old_lengths;
  if (trial.on_boundary && over_another_surface(am.mesh(), v, *worst, scratch.facets.front())) repair_window.first = 0;
  return move_toward(am, trial, repair_target(am, v, scratch.elements.front()), kRepairSteps, repair_window, scratch, limits);
}

// The vertices a sweep tries, with their balls: smoothing keeps the topology, so the balls
// gathered at the start hold to the end.
struct SmoothingCandidates {
  std::vector<Index> vertices, ball_start, balls;  // ball i: balls[ball_start[i] .. ball_start[i + 1])

  std::span<const Index> ball(std::size_t i) const {
    return std::span<const Index>(balls).subspan(static_cast<std::size_t>(ball_start[i]),
                                                 static_cast<std::size_t>(ball_start[i + 1] - ball_start[i]));
  }
};

// The recently changed interior and surface vertices, with their balls, but those refused last
// time whose balls have not changed since; gathered in chunks of vertices on the pool's threads,
// then joined in order.
template <int D>
SmoothingCandidates smoothing_candidates(const AdaptationMesh<D>& am, ThreadPool& pool) {
  constexpr std::size_t kChunk = 4096;
  const std::vector<SmoothingCandidates> found = results_by_chunk<SmoothingCandidates>(
      pool, static_cast<std::size_t>(am.mesh().vertex_count()), kChunk, [&](std::size_t begin, std::size_t end, SmoothingCandidates& part) {
        std::vector<Index> ball;
        part.ball_start.push_back(0);
        for (auto v = static_cast<Index>(begin); v < static_cast<Index>(end); ++v) {
          if (am.mesh().vertex_removed(v) || am.vertex_class(v) > VertexClass::kSurface || !am.changed_recently(v) ||
              am.smoothing_refused_as_is(v))
            continue;
          collect_ball(am.mesh(), v, ball);
          part.vertices.push_back(v);
          part.balls.insert(part.balls.end(), ball.begin(), ball.end());
          part.ball_start.push_back(static_cast<Index>(part.balls.size()));
        }
      });
  SmoothingCandidates candidates;
  candidates.ball_start.push_back(0);
  for (const SmoothingCandidates& part : found) {
    const auto offset = static_cast<Index>(candidates.balls.size());
    candidates.vertices.insert(candidates.vertices.end(), part.vertices.begin(), part.vertices.end());
    candidates.balls.insert(candidates.balls.end(), part.balls.begin(), part.balls.end());
    for (std::size_t i = 1; i < part.ball_start.size(); ++i) candidates.ball_start.push_back(offset + part.ball_start[i]);
  }
  return candidates;
}

// Tries the candidates at these positions in batches whose balls share no element
// (docs/adaptation.md §Threads); returns the positions that found no batch, for the next round.
template <int D>
std::vector<Index> smooth_round(AdaptationMesh<D>& am, const SmoothingCandidates& candidates, std::span<const Index> positions,
                                ConflictBatches& batches, std::vector<SmoothingScratch<D>>& scratch, const AdaptationLimits& limits,
                                ThreadPool& pool, OperationCount& count) {
  batches.clear();
  for (Index i : positions) batches.place(i, candidates.ball(static_cast<std::size_t>(i)));
  std::vector<char> moved;
  for (const std::vector<Index>& batch : batches.batches()) {
    am.tick();  // a refusal in this batch comes after the moves of the earlier ones
    moved.assign(batch.size(), 0);
    run_in_blocks(pool, batch.size(), kSmallestSmoothingBatch, [&](std::size_t worker, std::size_t n) {
      const auto i = static_cast<std::size_t>(batch[n]);
      moved[n] = smooth_vertex(am, candidates.vertices[i], candidates.ball(i), scratch[worker], limits);
    });
    for (std::size_t n = 0; n < batch.size(); ++n) {
      count.add(moved[n] ? Refusal::kNone : Refusal::kQuality);
      if (!moved[n]) am.note_smoothing_refused(candidates.vertices[static_cast<std::size_t>(batch[n])]);
      if (moved[n])
        for (Index k : candidates.ball(static_cast<std::size_t>(batch[n])))
          for (Index w : am.mesh().element(k)) am.mark_changed(w);
    }
  }
  return batches.overflow();
}

}  // namespace

template <int D>
OperationCount smooth_vertices(AdaptationMesh<D>& am, const AdaptationLimits& limits, ThreadPool& pool) {
  std::vector<SmoothingScratch<D>> scratch(static_cast<std::size_t>(pool.thread_count()));
  OperationCount count;
  const SmoothingCandidates candidates = smoothing_candidates(am, pool);
  std::vector<Index> positions(candidates.vertices.size());
  for (std::size_t i = 0; i < positions.size(); ++i) positions[i] = static_cast<Index>(i);
  ConflictBatches batches(am.mesh().element_count());  // keys: elements
  while (!positions.empty()) positions = smooth_round(am, candidates, positions, batches, scratch, limits, pool, count);
  return count;
}

template OperationCount smooth_vertices(AdaptationMesh<2>&, const AdaptationLimits&, ThreadPool&);
template OperationCount smooth_vertices(AdaptationMesh<3>&, const AdaptationLimits&, ThreadPool&);

}  // namespace hocav
