// Edge collapse (docs/adaptation.md §Collapse): the ball of the removed vertex re-starred from the
// kept one. A vertex collapses only onto one of its class or higher (a surface vertex along its
// surface, a ridge vertex along its line, corners never), its facets and lines re-starred with it.
#include <algorithm>
#include <array>
#include <limits>
#include <span>

#include "adapt/adaptation_operations.hpp"
#include "adapt/boundary_pieces.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

// The candidates whose tests before the plan run on the pool's threads at once, on the mesh as it
// is at the chunk's start.
constexpr std::size_t kCollapseChunk = 4096;

// The boundary pieces around `removed` (its ball: `ball`) that the collapse onto `kept` re-stars;
// false when the classes forbid it.
template <int D>
bool boundary_around(const AdaptationMesh<D>& am, std::span<const Index> ball, Index removed, Index kept, CollapseScratch<D>& s) {
  const VertexClass from = am.vertex_class(removed), to = am.vertex_class(kept);
  if (from == VertexClass::kCorner || from > to) return false;
  const Index center[1] = {removed};
  facets_through(am.mesh(), ball, center, s.facets);
  s.lines.clear();
  if (from == VertexClass::kInterior) return s.facets.empty();
  // Along the boundary only: (removed, kept) is a boundary edge, and on a ridge its line.
  const bool boundary_edge = std::any_of(s.facets.begin(), s.facets.end(), [&](Index f) {
    const auto& v = am.mesh().facet(f);
    return std::find(v.begin(), v.end(), kept) != v.end();
  });
  if (!boundary_edge) return false;
  if constexpr (D == 3)
    if (from == VertexClass::kRidge) {
      lines_through(am.mesh(), removed, s.lines);
      return s.lines.size() == 2 && std::any_of(s.lines.begin(), s.lines.end(),
                                                [&](Index l) { return am.mesh().line(l)[0] == kept || am.mesh().line(l)[1] == kept; });
    }
  return true;
}

// The elements the collapse makes: those of the ball without `kept`, `removed` moved onto it (the
// star of the ball from `kept`, which the cavity operator then plans): the length and quality tests
// run on them before the plan, which most refusals then skip.
template <int D>
void predicted_collapse(const Mesh<D>& mesh, std::span<const Index> ball, Index removed, Index kept,
                        std::vector<typename Mesh<D>::Element>& star) {
  star.clear();
  for (Index k : ball) {
    auto element = mesh.element(k);
    if (std::find(element.begin(), element.end(), kept) != element.end()) continue;
    std::replace(element.begin(), element.end(), removed, kept);
    star.push_back(element);
  }
}

template <int D>
double worst_of(const AdaptationMesh<D>& am, std::span<const typename Mesh<D>::Element> elements) {
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& element : elements) worst = std::min(worst, am.quality(element));
  return worst;
}

// The tests of a collapse before its plan (classes, lengths, qualities of the elements it would
// make), on `removed`'s ball; reads the mesh only.
template <int D>
Refusal collapse_pretest(const AdaptationMesh<D>& am, std::span<const Index> ball, Index removed, Index kept,
                         const AdaptationLimits& limits, CollapseScratch<D>& s) {
  if (!boundary_around(am, ball, removed, kept, s)) return Refusal::kClasses;
  predicted_collapse(am.mesh(), ball, removed, kept, s.star);
  if (!edges_from_within<D>(am, kept, s.star, limits.collapse_new_length)) return Refusal::kLength;
  if (!(worst_of<D>(am, s.star) >= std::min(0.3 * worst_quality<D>(am, ball), 0.1))) return Refusal::kQuality;
  return Refusal::kNone;
}

// The pretests of both directions of an edge, on the mesh as it is.
template <int D>
std::array<Refusal, 2> pretest_both_ways(const AdaptationMesh<D>& am, const EdgeCandidate& c, const AdaptationLimits& limits,
                                         CollapseScratch<D>& s) {
  if (am.mesh().vertex_removed(c.a) || am.mesh().vertex_removed(c.b)) return {Refusal::kNone, Refusal::kNone};  // not known
  collect_ball(am.mesh(), c.a, s.ball);
  const Refusal forward = collapse_pretest(am, s.ball, c.a, c.b, limits, s);
  collect_ball(am.mesh(), c.b, s.ball);
  return {forward, collapse_pretest(am, s.ball, c.b, c.a, limits, s)};
}

}  // namespace

template <int D>
Refusal collapse_edge(AdaptationMesh<D>& am, Index removed, Index kept, const AdaptationLimits& limits, CollapseScratch<D>& s) {
  Mesh<D>& mesh = am.mesh();
  auto& work = am.workspace();
  collect_ball(mesh, removed, work.cavity);
  if (const Refusal refusal = collapse_pretest(am, work.cavity, removed, kept, limits, s); refusal != Refusal::kNone) return refusal;
  CavityOptions options;
  options.removable_vertex = removed;
  options.removed_facets = s.facets;
  options.removed_lines = s.lines;
  if (work.cavity_operator.plan(mesh, work.cavity, kept, options) != CavityStatus::kAccepted) return Refusal::kTopology;
  if (!s.facets.empty() && collapse_folds_surface(mesh, work.cavity_operator, removed, kept, s.facets, s.ball, s.kept_facets))
    return Refusal::kTopology;
  if (!s.facets.empty() && !boundary_change_acceptable(am, work.cavity_operator, limits.cos_feature_angle, limits.hausd))
    return Refusal::kGeometry;
  am.commit(work.cavity_operator);
  return Refusal::kNone;
}

// Chunk by chunk, the pretests of every candidate run on the pool's threads on the mesh as it is
// at the chunk's start (a clock tick); a candidate's verdict is used while neither end has changed
// since (docs/adaptation.md §Threads), so the result is the serial one.
template <int D>
OperationCount collapse_short_edges(AdaptationMesh<D>& am, const AdaptationLimits& limits, ThreadPool& pool) {
  const std::vector<EdgeCandidate> candidates = edges_beyond(am, limits.collapse_length, false, pool);
  OperationCount count;
  std::vector<CollapseScratch<D>> scratch(static_cast<std::size_t>(pool.thread_count()));
  std::vector<std::array<Refusal, 2>> pretests;
  const Mesh<D>& mesh = am.mesh();
  for (std::size_t start = 0; start < candidates.size(); start += kCollapseChunk) {
    const std::span<const EdgeCandidate> chunk = std::span(candidates).subspan(start, std::min(kCollapseChunk, candidates.size() - start));
    const int chunk_clock = am.tick();
    pretests.resize(chunk.size());
    run_in_blocks(pool, chunk.size(), 1,
                  [&](std::size_t worker, std::size_t i) { pretests[i] = pretest_both_ways(am, chunk[i], limits, scratch[worker]); });
    for (std::size_t i = 0; i < chunk.size(); ++i) {
      const EdgeCandidate& c = chunk[i];
      if (mesh.vertex_removed(c.a) || mesh.vertex_removed(c.b) || am.edge_length(c.a, c.b) >= limits.collapse_length) continue;
      collect_shell(mesh, c.a, c.b, am.workspace().cavity);
      if (am.workspace().cavity.empty()) continue;  // no longer an edge
      // A refusal known from the pretest stands while neither end changed.
      const bool known = !am.changed_since(c.a, chunk_clock) && !am.changed_since(c.b, chunk_clock);
      const auto try_collapse = [&](int way, Index removed, Index kept) {
        return known && pretests[i][way] != Refusal::kNone ? pretests[i][way] : collapse_edge(am, removed, kept, limits, scratch.front());
      };
      // One end onto the other, else the other way; the first refusal's reason is the one counted.
      const Refusal first = try_collapse(0, c.a, c.b);
      count.add(first == Refusal::kNone ? first : try_collapse(1, c.b, c.a) == Refusal::kNone ? Refusal::kNone : first);
    }
  }
  return count;
}

template Refusal collapse_edge(AdaptationMesh<2>&, Index, Index, const AdaptationLimits&, CollapseScratch<2>&);
template Refusal collapse_edge(AdaptationMesh<3>&, Index, Index, const AdaptationLimits&, CollapseScratch<3>&);
template OperationCount collapse_short_edges(AdaptationMesh<2>&, const AdaptationLimits&, ThreadPool&);
template OperationCount collapse_short_edges(AdaptationMesh<3>&, const AdaptationLimits&, ThreadPool&);

}  // namespace hocav
