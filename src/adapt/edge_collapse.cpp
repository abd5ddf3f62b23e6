// Edge collapse (docs/adaptation.md §Collapse): the ball of the removed vertex re-starred from the
// kept one. A vertex collapses only onto one of its class or higher (a surface vertex along its
// surface, a ridge vertex along its line, corners never), its facets and lines re-starred with it.
#include <algorithm>

#include "adapt/adaptation_operations.hpp"
#include "adapt/boundary_pieces.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

// The boundary pieces around `removed` that the collapse onto `kept` re-stars; false when the
// classes forbid it.
template <int D>
bool boundary_around(AdaptationMesh<D>& am, Index removed, Index kept, CollapseScratch& s) {
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

// No edge from the kept vertex longer than the split threshold: a collapse must not make work for
// the next split.
template <int D>
bool new_edges_short(const AdaptationMesh<D>& am, Index kept, const CavityOperator<D>& plan, double longest) {
  for (const auto& element : plan.new_elements())
    for (Index w : element)
      if (w != kept && am.edge_length(kept, w) > longest) return false;
  return true;
}

}  // namespace

template <int D>
Refusal collapse_edge(AdaptationMesh<D>& am, Index removed, Index kept, const AdaptationLimits& limits, CollapseScratch& s) {
  Mesh<D>& mesh = am.mesh();
  auto& work = am.workspace();
  collect_ball(mesh, removed, work.cavity);
  if (!boundary_around(am, removed, kept, s)) return Refusal::kClasses;
  CavityOptions options;
  options.removable_vertex = removed;
  options.removed_facets = s.facets;
  options.removed_lines = s.lines;
  if (work.cavity_operator.plan(mesh, work.cavity, kept, options) != CavityStatus::kAccepted) return Refusal::kTopology;
  if (!(worst_planned_quality(am, work.cavity_operator) >= std::min(0.3 * worst_quality<D>(am, work.cavity), 0.1))) return Refusal::kQuality;
  if (!new_edges_short(am, kept, work.cavity_operator, limits.split_length)) return Refusal::kLength;
  if (!s.facets.empty() && !boundary_change_acceptable(am, work.cavity_operator, limits.cos_feature_angle, limits.hausd))
    return Refusal::kGeometry;
  am.commit(work.cavity_operator);
  return Refusal::kNone;
}


template <int D>
OperationCount collapse_short_edges(AdaptationMesh<D>& am, const AdaptationLimits& limits) {
  const std::vector<EdgeCandidate> candidates = edges_beyond(am, limits.collapse_length, false);
  OperationCount count;
  CollapseScratch scratch;
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

template Refusal collapse_edge(AdaptationMesh<2>&, Index, Index, const AdaptationLimits&, CollapseScratch&);
template Refusal collapse_edge(AdaptationMesh<3>&, Index, Index, const AdaptationLimits&, CollapseScratch&);
template OperationCount collapse_short_edges(AdaptationMesh<2>&, const AdaptationLimits&);
template OperationCount collapse_short_edges(AdaptationMesh<3>&, const AdaptationLimits&);

}  // namespace hocav
