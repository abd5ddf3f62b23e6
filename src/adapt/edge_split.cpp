// Edge split (docs/adaptation.md §Split): the shell of the edge re-starred from a new vertex at its
// middle; on a boundary edge the facets (and the 3D feature line) through it are re-starred too and
// the new vertex goes on the geometry, or on the straight middle if the geometry's point is refused.
#include <algorithm>

#include "adapt/adaptation_operations.hpp"
#include "adapt/boundary_pieces.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

// The share of the long edges longer than 2 above which a pass splits only those.
constexpr double kCoarsePhaseShare = 0.1;

template <int D>
struct SplitScratch {
  std::vector<Index> facets, lines, candidate_lines, shell;
  CollapseScratch<D> collapse;
};

// After a split: the new vertex v onto its nearest neighbour, when their edge is short.
template <int D>
void snap_to_nearest(AdaptationMesh<D>& am, Index v, const AdaptationLimits& limits, SplitScratch<D>& s) {
  auto& work = am.workspace();
  collect_ball(am.mesh(), v, work.cavity);
  Index nearest = kNoIndex;
  double shortest = limits.collapse_length;
  for (Index k : work.cavity)
    for (Index w : am.mesh().element(k))
      if (w != v)
        if (const double length = am.edge_length(v, w); length < shortest) {
          shortest = length;
          nearest = w;
        }
  if (nearest != kNoIndex) collapse_edge(am, v, nearest, limits, s.collapse);
}

// The boundary pieces through edge (a, b): its facets and, in 3D, the feature line on it.
template <int D>
void boundary_through_edge(AdaptationMesh<D>& am, Index a, Index b, SplitScratch<D>& s) {
  const Index ends[2] = {a, b};
  facets_through(am.mesh(), am.workspace().cavity, ends, s.facets);
  s.lines.clear();
  if constexpr (D == 3)
    if (!s.facets.empty() && am.vertex_class(a) >= VertexClass::kRidge && am.vertex_class(b) >= VertexClass::kRidge) {
      lines_through(am.mesh(), a, s.candidate_lines);
      for (Index l : s.candidate_lines)
        if (am.mesh().line(l)[0] == b || am.mesh().line(l)[1] == b) s.lines.push_back(l);
    }
}

// Whether the boundary pieces through the edge hold a required edge or triangle (then the edge is
// kept; both its ends are corners).
template <int D>
bool holds_required(const Mesh<D>& mesh, const SplitScratch<D>& s) {
  const auto listed = [](const std::vector<Index>& ids, Index id) { return std::find(ids.begin(), ids.end(), id) != ids.end(); };
  const std::vector<Index>& required_facets = D == 2 ? mesh.required_edges() : mesh.required_triangles();
  return std::any_of(s.facets.begin(), s.facets.end(), [&](Index f) { return listed(required_facets, f); }) ||
         std::any_of(s.lines.begin(), s.lines.end(), [&](Index l) { return listed(mesh.required_edges(), l); });
}

// Where the new vertex of a boundary edge goes: on the feature curve its two surfaces share, or
// on its surface (a ridge inside one surface: on its curve where the geometry has one); the
// straight middle without a geometry.
template <int D>
Vec<D> point_on_boundary(const AdaptationMesh<D>& am, const Vec<D>& middle, const SplitScratch<D>& s) {
  const BoundaryGeometry<D>* geometry = am.geometry();
  if (!geometry) return middle;
  const int ref_a = am.mesh().facet_ref(s.facets.front()), ref_b = am.mesh().facet_ref(s.facets.back());
  if (!s.lines.empty()) return geometry->project_on_ridge(middle, ref_a, ref_b);
  return geometry->project(middle, {ref_a}).point;
}

// Plans the star of the new vertex v: inside the domain on the Delaunay cavity of v in its metric
// grown from the edge's shell (mmg's insertion: the new vertex joins vertices farther than the
// shell's, so fewer short edges for the collapses to undo), else on the shell alone.
template <int D>
bool plan_split(AdaptationMesh<D>& am, Index v, bool inside, const CavityOptions& options, SplitScratch<D>& s) {
  auto& work = am.workspace();
  if (inside) {
    s.shell.assign(work.cavity.begin(), work.cavity.end());
    grow_delaunay_cavity(am.mesh(), work, am.mesh().vertex(v), am.metric(v));
    if (work.cavity.size() > s.shell.size()) {
      if (work.cavity_operator.plan(am.mesh(), work.cavity, v, options) == CavityStatus::kAccepted) return true;
      work.cavity.assign(s.shell.begin(), s.shell.end());
    }
  }
  return work.cavity_operator.plan(am.mesh(), work.cavity, v, options) == CavityStatus::kAccepted;
}

template <int D>
Refusal split_edge(AdaptationMesh<D>& am, Index a, Index b, const AdaptationLimits& limits, SplitScratch<D>& s) {
  Mesh<D>& mesh = am.mesh();
  auto& work = am.workspace();
  boundary_through_edge(am, a, b, s);
  if (am.vertex_class(a) == VertexClass::kCorner && am.vertex_class(b) == VertexClass::kCorner && holds_required(mesh, s))
    return Refusal::kClasses;
  const Vec<D> middle = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
  const VertexClass new_class = s.facets.empty() ? VertexClass::kInterior : s.lines.empty() ? VertexClass::kSurface : VertexClass::kRidge;
  const double old_worst = worst_quality<D>(am, work.cavity);
  CavityOptions options;
  options.removed_facets = s.facets;
  options.removed_lines = s.lines;
  // The point on the geometry first, then the straight middle (mmg bisects between the two).
  const std::array<Vec<D>, 2> points{s.facets.empty() ? middle : point_on_boundary(am, middle, s), middle};
  Refusal refusal = Refusal::kTopology;
  for (int attempt = 0; attempt < (points[0] == points[1] ? 1 : 2); ++attempt) {
    const Index v = am.add_vertex(points[attempt], new_class, a);
    if (!plan_split(am, v, s.facets.empty(), options, s))
      refusal = Refusal::kTopology;
    else if (!(worst_planned_quality(am, work.cavity_operator) >= std::min(1e-3, 0.1 * old_worst)))
      refusal = Refusal::kQuality;
    else if (!s.facets.empty() && !boundary_change_acceptable(am, work.cavity_operator, limits.cos_feature_angle, 0))
      refusal = Refusal::kGeometry;
    else {
      am.commit(work.cavity_operator);
      snap_to_nearest(am, v, limits, s);
      return Refusal::kNone;
    }
    mesh.pop_vertex();
  }
  return refusal;
}

}  // namespace

template <int D>
OperationCount split_long_edges(AdaptationMesh<D>& am, const AdaptationLimits& limits, ThreadPool& pool) {
  std::vector<EdgeCandidate> candidates = edges_beyond(am, limits.split_length, true, pool);
  // 3D coarse phase: while many long edges are longer than 2, only those are split. Their halves
  // are longer than 1, so the mesh never gets denser than the metric asks; halves of edges in
  // (√2, 2) would be, while the coarse edges around them are still to be cut. (In 2D, where a
  // split triangle makes 4 and not 8 children, it lowered the annulus's mean quality.)
  const auto beyond_two = std::partition_point(candidates.begin(), candidates.end(), [](const EdgeCandidate& c) { return c.length > 2; });
  if (D == 3 && static_cast<double>(beyond_two - candidates.begin()) > kCoarsePhaseShare * static_cast<double>(candidates.size()))
    candidates.erase(beyond_two, candidates.end());
  OperationCount count;
  SplitScratch<D> scratch;
  for (const EdgeCandidate& c : candidates) {
    collect_shell(am.mesh(), c.a, c.b, am.workspace().cavity);
    if (am.workspace().cavity.empty() || am.edge_length(c.a, c.b) <= limits.split_length) continue;  // gone, or no longer long
    count.add(split_edge(am, c.a, c.b, limits, scratch));
  }
  return count;
}

template OperationCount split_long_edges(AdaptationMesh<2>&, const AdaptationLimits&, ThreadPool&);
template OperationCount split_long_edges(AdaptationMesh<3>&, const AdaptationLimits&, ThreadPool&);

}  // namespace hocav
