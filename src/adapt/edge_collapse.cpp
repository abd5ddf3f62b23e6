// Edge collapse (docs/adaptation.md §Collapse): the ball of the removed vertex re-starred from the
// kept one. A vertex collapses only onto one of its class or higher (a surface vertex along its
// surface, a ridge vertex along its line, corners never), its facets and lines re-starred with it.
#include <algorithm>
#include <limits>
#include <span>

#include "adapt/adaptation_operations.hpp"
#include "adapt/boundary_pieces.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

// The boundary pieces around `removed` that the collapse onto `kept` re-stars; false when the
// classes forbid it.
template <int D>
bool boundary_around(AdaptationMesh<D>& am, Index removed, Index kept, CollapseScratch<D>& s) {
  const VertexClass from = am.vertex_class(removed), to = am.vertex_class(kept);
  if (from == VertexClass::kCorner || from > to) return false;
  const Index center[1] = {removed};
  facets_through(am.mesh(), am.workspace().cavity, center, s.facets);
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
      return s.lines.size() == 2 && std::any_of(s.lines.begin(), s.lines.end(), [&](Index l) {
               return am.mesh().line(l)[0] == kept || am.mesh().line(l)[1] == kept;
             });
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

// No edge from the kept vertex longer than the split threshold: a collapse must not make work for
// the next split.
template <int D>
bool new_edges_short(const AdaptationMesh<D>& am, Index kept, std::span<const typename Mesh<D>::Element> star, double longest) {
  for (const auto& element : star)
    for (Index w : element)
      if (w != kept && am.edge_length(kept, w) > longest) return false;
  return true;
}

template <int D>
double worst_of(const AdaptationMesh<D>& am, std::span<const typename Mesh<D>::Element> elements) {
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& element : elements) worst = std::min(worst, am.quality(element));
  return worst;
}

}  // namespace

template <int D>
Refusal collapse_edge(AdaptationMesh<D>& am, Index removed, Index kept, const AdaptationLimits& limits, CollapseScratch<D>& s) {
  Mesh<D>& mesh = am.mesh();
  auto& work = am.workspace();
  collect_ball(mesh, removed, work.cavity);
  if (!boundary_around(am, removed, kept, s)) return Refusal::kClasses;
  predicted_collapse(mesh, work.cavity, removed, kept, s.star);
  if (!new_edges_short<D>(am, kept, s.star, limits.split_length)) return Refusal::kLength;
  if (!(worst_of<D>(am, s.star) >= std::min(0.3 * worst_quality<D>(am, work.cavity), 0.1))) return Refusal::kQuality;
  CavityOptions options;
  options.removable_vertex = removed;
  options.removed_facets = s.facets;
  options.removed_lines = s.lines;
  if (work.cavity_operator.plan(mesh, work.cavity, kept, options) != CavityStatus::kAccepted) return Refusal::kTopology;
  if (!s.facets.empty() && !boundary_change_acceptable(am, work.cavity_operator, limits.cos_feature_angle, limits.hausd))
    return Refusal::kGeometry;
  am.commit(work.cavity_operator);
  return Refusal::kNone;
}


template <int D>
OperationCount collapse_short_edges(AdaptationMesh<D>& am, const AdaptationLimits& limits) {
  const std::vector<EdgeCandidate> candidates = edges_beyond(am, limits.collapse_length, false);
  OperationCount count;
  CollapseScratch<D> scratch;
  const Mesh<D>& mesh = am.mesh();
  for (const EdgeCandidate& c : candidates) {
    if (mesh.vertex_removed(c.a) || mesh.vertex_removed(c.b) || am.edge_length(c.a, c.b) >= limits.collapse_length) continue;
    collect_shell(mesh, c.a, c.b, am.workspace().cavity);
    if (am.workspace().cavity.empty()) continue;  // no longer an edge
    // One end onto the other, else the other way; the first refusal's reason is the one counted.
    const Refusal first = collapse_edge(am, c.a, c.b, limits, scratch);
    count.add(first == Refusal::kNone ? first : collapse_edge(am, c.b, c.a, limits, scratch) == Refusal::kNone ? Refusal::kNone : first);
  }
  return count;
}

template Refusal collapse_edge(AdaptationMesh<2>&, Index, Index, const AdaptationLimits&, CollapseScratch<2>&);
template Refusal collapse_edge(AdaptationMesh<3>&, Index, Index, const AdaptationLimits&, CollapseScratch<3>&);
template OperationCount collapse_short_edges(AdaptationMesh<2>&, const AdaptationLimits&);
template OperationCount collapse_short_edges(AdaptationMesh<3>&, const AdaptationLimits&);

}  // namespace hocav
