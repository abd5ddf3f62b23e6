// Edge split (docs/adaptation.md §Split): the shell of the edge re-starred from a new vertex at its
// middle; on a boundary edge the facets (and the 3D feature line) through it are re-starred too and
// the new vertex goes on the geometry, or on the straight middle if the geometry's point is refused.
#include <algorithm>
#include <array>
#include <span>
#include <tuple>

#include "adapt/adaptation_operations.hpp"
#include "adapt/boundary_pieces.hpp"
#include "base/small_set.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/element_snapshot.hpp"

namespace hocav {
namespace {

// A required facet's edge longer than this (its halves longer than the unit) bars splits at its ends
// (SplitsAtRequiredVertices::kNextToFineRequiredFacets): toward a frozen surface coarser than the
// metric the splits would not end (docs/distributed.md).
constexpr double kCoarseRequiredEdge = 2;
// The share of the long edges longer than 2 above which a pass splits only those.
constexpr double kCoarsePhaseShare = 0.1;
// With more than one thread, the candidates previewed at once (docs/adaptation.md §Threads): small
// enough that few previews go stale before their turn, large enough to feed the threads.
constexpr std::size_t kPreviewChunk = 64;
// A boundary-only element's cut (cut_boundary_only_elements) must raise the worst quality of its
// cavity by this factor.
constexpr double kCutGain = 1.05;
// A split of an edge shorter than this, away from the boundary, whose point lies next to a vertex and
// whose snap cannot be made in one, is not made (docs/adaptation.md §Split).
constexpr double kFilteredBelow = 2;
// The quality every element of a split and snap in one must reach (reconnect_to): the snap's
// collapse asks at most this.
constexpr double kReconnectQuality = 0.1;

template <int D>
struct alignas(64) SplitScratch {  // a cache line of its own: each thread writes its own
  std::vector<Index> lines, line_shell;
  CollapseScratch<D> collapse;
};

// The surfaces a boundary edge's new point goes on: the refs of its first and last facets, and
// whether a feature line runs along it (nothing inside the domain).
struct EdgeSurfaces {
  bool boundary = false, line = false;
  int ref_a = 0, ref_b = 0;

  bool operator==(const EdgeSurfaces&) const = default;
};

// What splitting an edge needs, found by reading the mesh (docs/adaptation.md §Threads): its shell
// (sorted, so that nothing depends on where the shell's walk began) and boundary pieces, where the
// new vertex goes and the metric there and, inside the domain, its Delaunay cavity. Previews of a
// chunk of candidates are made on the pool's threads at once; a split uses its preview while every
// element the preview read still holds the same vertices and its boundary pieces are the same (a
// new preview would then find the same), and makes it again otherwise.
template <int D>
struct SplitPreview {
  bool made = false;  // false when (a, b) was no edge
  // Never split: both ends are corners and a required facet or line holds the edge, or a line lies
  // on it with no facet (its new vertex would have no surface to go on), or both ends are
  // non-manifold places.
  bool kept = false;
  std::vector<Index> shell, facets, lines, cavity;
  EdgeSurfaces surfaces;
  Vec<D> point;
  Index patch = kNoIndex;  // the geometry's patch of the point, if projected onto a surface
  typename AdaptationMesh<D>::PointMetric metric;
  std::vector<Index> read;  // the shell and every element the Delaunay growth tested
  std::vector<typename Mesh<D>::Element> read_vertices;
  // Inside the domain, for a long edge: the cavity's vertex other than the edge's ends nearest the
  // point when closer than a collapse's bound in the metric (split_edge), or kNoIndex.
  Index nearest = kNoIndex;

  bool current(const Mesh<D>& mesh) const { return made && elements_unchanged<D>(mesh, read, read_vertices); }
};

// The vertex of these elements, other than the two skipped, nearest the point x (metric m there)
// when closer than `shortest` in the metric; kNoIndex otherwise.
template <int D>
Index nearest_vertex(const AdaptationMesh<D>& am, std::span<const Index> elements, const Vec<D>& x, const SymMat<D>& m,
                     std::array<Index, 2> skipped, double shortest) {
  Index nearest = kNoIndex;
  for (Index k : elements)
    for (Index w : am.mesh().element(k))
      if (w != skipped[0] && w != skipped[1])
        if (const double length = metric_edge_length<D>(x, am.mesh().vertex(w), m, am.metric(w)); length < shortest) {
          shortest = length;
          nearest = w;
        }
  return nearest;
}

// After a split: the new vertex v onto its nearest neighbour, when their edge is short.
template <int D>
void snap_to_nearest(AdaptationMesh<D>& am, Index v, const AdaptationLimits& limits, SplitScratch<D>& s) {
  auto& work = am.workspace();
  collect_ball(am.mesh(), v, work.cavity);
  const Index nearest = nearest_vertex(am, work.cavity, am.mesh().vertex(v), am.metric(v), {v, v}, limits.collapse_length);
  if (nearest != kNoIndex) collapse_edge(am, v, nearest, limits, s.collapse);
}

// The split and its snap in one (docs/adaptation.md §Split): the preview's cavity re-starred from
// its vertex `nearest`, which the split's star with the snap's collapse would make, when its new
// edges are no longer than a collapse may make and its elements reach kReconnectQuality. False
// (nothing changed) otherwise.
template <int D>
bool reconnect_to(AdaptationMesh<D>& am, Index nearest, const SplitPreview<D>& p, const AdaptationLimits& limits) {
  CavityOperator<D>& plan = am.workspace().cavity_operator;
  if (plan.plan(am.mesh(), p.cavity, nearest, {}) != CavityStatus::kAccepted) return false;
  if (!edges_from_within<D>(am, nearest, plan.new_elements(), limits.collapse_new_length)) return false;
  if (!(worst_planned_quality(am, plan) >= kReconnectQuality)) return false;
  am.commit(plan);
  return true;
}

// The boundary pieces through edge (a, b) (from its shell): its facets and, in 3D, the feature line
// on it (looked for off the facets too: an input's Edges may lie inside the volume); and the
// surfaces they name.
template <int D>
EdgeSurfaces boundary_through_edge(const AdaptationMesh<D>& am, Index a, Index b, SplitPreview<D>& p) {
  const Index ends[2] = {a, b};
  facets_through(am.mesh(), p.shell, ends, p.facets);
  p.lines.clear();
  if constexpr (D == 3)
    if (am.vertex_class(a) >= VertexClass::kRidge && am.vertex_class(b) >= VertexClass::kRidge) lines_along(am.mesh(), a, b, p.lines);
  if (p.facets.empty()) return {};
  return {true, !p.lines.empty(), am.mesh().facet_ref(p.facets.front()), am.mesh().facet_ref(p.facets.back())};
}

// Whether the boundary pieces through the edge hold a required edge or triangle (then the edge is
// kept; both its ends are corners).
template <int D>
bool holds_required(const Mesh<D>& mesh, const SplitPreview<D>& p) {
  const auto listed = [](const std::vector<Index>& ids, Index id) { return std::find(ids.begin(), ids.end(), id) != ids.end(); };
  return holds_required_facet(mesh, p.facets) ||
         std::any_of(p.lines.begin(), p.lines.end(), [&](Index l) { return listed(mesh.required_edges(), l); });
}

// Where the new vertex of an edge goes: inside the domain its middle; on the boundary, on the
// feature curve its two surfaces share, or on its surface (a ridge inside one surface: on its curve
// where the geometry has one); the straight middle without a geometry.
template <int D>
BoundaryPoint<D> split_point(const AdaptationMesh<D>& am, const Vec<D>& middle, const EdgeSurfaces& surfaces) {
  const BoundaryGeometry<D>* geometry = am.geometry();
  if (!surfaces.boundary || !geometry) return {middle};
  if (surfaces.line) return {geometry->project_on_ridge(middle, surfaces.ref_a, surfaces.ref_b)};
  return geometry->project(middle, {surfaces.ref_a});
}

// Whether the preview's boundary pieces are still the edge's: facet and line ids can change while
// every element the preview read keeps its vertices (a split nearby re-stars them). `fresh` is
// scratch.
template <int D>
bool same_boundary(const AdaptationMesh<D>& am, Index a, Index b, const SplitPreview<D>& p, SplitPreview<D>& fresh) {
  fresh.shell.assign(p.shell.begin(), p.shell.end());
  return boundary_through_edge(am, a, b, fresh) == p.surfaces && fresh.facets == p.facets && fresh.lines == p.lines;
}

// Whether the Delaunay cavity's elements past the shell go all around a feature line's edge, which
// the star would then remove. A line on facets never is (the growth stops at facets); one with no
// facet along it (an input's Edges inside the volume) may be.
template <int D>
bool buries_a_line(const AdaptationMesh<D>& am, const SplitPreview<D>& p, SplitScratch<D>& s) {
  if constexpr (D == 3) {
    const Mesh<D>& mesh = am.mesh();
    for (std::size_t i = p.shell.size(); i < p.cavity.size(); ++i)
      for (int e = 0; e < Simplex<D>::kEdges; ++e) {
        const Index x = mesh.element(p.cavity[i])[edge_vertices<D>(e)[0]], y = mesh.element(p.cavity[i])[edge_vertices<D>(e)[1]];
        if (am.vertex_class(x) < VertexClass::kRidge || am.vertex_class(y) < VertexClass::kRidge) continue;  // no line's ends
        collect_shell(mesh, x, y, s.line_shell);
        if (!shell_is_closed(mesh, s.line_shell, x, y) ||
            !std::all_of(s.line_shell.begin(), s.line_shell.end(), [&](Index k) { return small_set_holds(p.cavity, k); }))
          continue;
        lines_along(mesh, x, y, s.lines);
        if (!s.lines.empty()) return true;
      }
  }
  return false;
}

// Why an edge is split: it is long (then a new element may be as poor as refine's floor, and the
// new vertex is snapped), or it cuts a poor boundary-only element (then the split must raise the
// worst quality of its cavity, and the new vertex stays).
enum class SplitPurpose { kLength, kCut };

// The preview of splitting edge (a, b) on the mesh as it is; reads the mesh only.
template <int D>
void preview_split(const AdaptationMesh<D>& am, Index a, Index b, const AdaptationLimits& limits, SplitPurpose purpose, SplitPreview<D>& p,
                   SplitScratch<D>& s) {
  const Mesh<D>& mesh = am.mesh();
  p.made = false;
  p.nearest = kNoIndex;
  if (mesh.vertex_removed(a) || mesh.vertex_removed(b)) return;
  collect_shell(mesh, a, b, p.shell);
  if (p.shell.empty()) return;
  p.made = true;
  std::sort(p.shell.begin(), p.shell.end());
  p.surfaces = boundary_through_edge(am, a, b, p);
  // A kept edge is never split (split_edge refuses it): its straight middle, not a projection onto
  // a surface the geometry may not have (a distributed part's interface: docs/distributed.md).
  const Vec<D> middle = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
  // An edge between two non-manifold places may be shared by parts that its shell (one part's) does
  // not see: kept, so that every part keeps it.
  p.kept = (am.vertex_class(a) == VertexClass::kCorner && am.vertex_class(b) == VertexClass::kCorner && holds_required(mesh, p)) ||
           (p.facets.empty() && !p.lines.empty()) || (am.non_manifold(a) && am.non_manifold(b));
  const BoundaryPoint<D> on_geometry = p.kept ? BoundaryPoint<D>{middle} : split_point(am, middle, p.surfaces);
  p.point = on_geometry.point;
  p.patch = on_geometry.patch;
  p.metric = am.metric_at_point(p.point, a);
  p.cavity.assign(p.shell.begin(), p.shell.end());
  p.read.clear();
  if (!p.surfaces.boundary) {
    grow_delaunay_cavity(mesh, p.cavity, p.read, p.point, p.metric.metric);
    make_star_shaped(mesh, p.cavity, p.shell.size(), p.read, p.point);
    if (buries_a_line(am, p, s)) {  // then the shell alone; what the growth took stays read
      p.read.insert(p.read.end(), p.cavity.begin() + static_cast<std::ptrdiff_t>(p.shell.size()), p.cavity.end());
      p.cavity.resize(p.shell.size());
    }
    if (purpose == SplitPurpose::kLength)
      p.nearest = nearest_vertex(am, p.cavity, p.point, p.metric.metric, {a, b}, limits.collapse_length);
  }
  p.read.insert(p.read.end(), p.cavity.begin(), p.cavity.end());
  p.read_vertices.clear();
  for (Index k : p.read) p.read_vertices.push_back(mesh.element(k));
}

// The points a split tries, from the geometry's to the straight middle (split_edge).
constexpr std::size_t kSplitPoints = 4;

// Plans the star of the new vertex v at the preview's point: inside the domain on its Delaunay
// cavity of v in v's metric grown from the edge's shell (mmg's insertion: the new vertex joins
// vertices farther than the shell's, so fewer short edges for the collapses to undo), else (or
// when the operator refuses that star) on the shell alone.
template <int D>
bool plan_split(AdaptationMesh<D>& am, Index v, bool at_preview_point, const SplitPreview<D>& p, const CavityOptions& options) {
  CavityOperator<D>& plan = am.workspace().cavity_operator;
  if (at_preview_point && p.cavity.size() > p.shell.size() && plan.plan(am.mesh(), p.cavity, v, options) == CavityStatus::kAccepted)
    return true;
  return plan.plan(am.mesh(), p.shell, v, options) == CavityStatus::kAccepted;
}

// The quality every element a split makes must reach.
template <int D>
double split_quality_floor(const AdaptationMesh<D>& am, const SplitPreview<D>& p, const CavityOperator<D>& plan, SplitPurpose purpose) {
  if (purpose == SplitPurpose::kLength) return std::min(1e-3, 0.1 * worst_quality<D>(am, p.shell));
  return kCutGain * worst_quality<D>(am, plan.cavity());
}

// Splits edge (a, b) as its current preview `p` says.
template <int D>
Refusal split_edge(AdaptationMesh<D>& am, Index a, Index b, const SplitPreview<D>& p, const AdaptationLimits& limits, SplitPurpose purpose,
                   SplitScratch<D>& s) {
  Mesh<D>& mesh = am.mesh();
  auto& work = am.workspace();
  if (p.kept) return Refusal::kClasses;
  // Inside the domain, a new point next to a vertex already there (docs/adaptation.md §Split).
  if (purpose == SplitPurpose::kLength && p.nearest != kNoIndex) {
    if (reconnect_to(am, p.nearest, p, limits)) return Refusal::kNone;
    const auto interior = [&](Index v) { return am.vertex_class(v) == VertexClass::kInterior; };
    if (interior(a) && interior(b) && interior(p.nearest) && am.edge_length(a, b) < kFilteredBelow) return Refusal::kLength;
  }
  const Vec<D> middle = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
  const VertexClass new_class = !p.surfaces.boundary ? VertexClass::kInterior
                                : p.lines.empty()    ? VertexClass::kSurface
                                                     : VertexClass::kRidge;
  CavityOptions options;
  options.removed_facets = p.facets;
  options.removed_lines = p.lines;
  // The point on the geometry first, then halfway and a quarter of the way to it from the straight
  // middle (mmg bisects between the two), then the middle: a boundary vertex as close to the
  // geometry as its cavity allows (the boundary settling moves it the rest of the way if it can).
  const Vec<D> toward = p.point - middle;
  const std::array<Vec<D>, kSplitPoints> points{p.point, middle + 0.5 * toward, middle + 0.25 * toward, middle};
  Refusal refusal = Refusal::kTopology;
  for (std::size_t attempt = 0; attempt < (p.point == middle ? 1 : kSplitPoints); ++attempt) {
    const Index v = am.add_vertex(points[attempt], new_class, attempt == 0 ? p.metric : am.metric_at_point(points[attempt], a));
    if (attempt + 1 < kSplitPoints) am.set_surface_hint(v, p.patch);
    if (!plan_split(am, v, attempt == 0, p, options))
      refusal = Refusal::kTopology;
    else if (!(worst_planned_quality(am, work.cavity_operator) >= split_quality_floor(am, p, work.cavity_operator, purpose)))
      refusal = Refusal::kQuality;
    else if (p.surfaces.boundary && !boundary_change_acceptable(am, work.cavity_operator, limits.cos_feature_angle, 0))
      refusal = Refusal::kGeometry;
    else {
      am.commit(work.cavity_operator);
      if (purpose == SplitPurpose::kLength) snap_to_nearest(am, v, limits, s);
      return Refusal::kNone;
    }
    mesh.pop_vertex();
  }
  return refusal;
}

// Per vertex, as `splits` bars edges at it: kBarredEnd for a required vertex (kNextToFineRequiredFacets:
// one on a required facet's edge longer than 2), kBoundaryEnd for a required vertex on the domain's
// boundary (a facet that is not required), kRequiredEnd for another required vertex, 0 otherwise.
constexpr char kRequiredEnd = 1, kBoundaryEnd = 2, kBarredEnd = 3;
template <int D>
std::vector<char> barred_split_ends(const AdaptationMesh<D>& am, SplitsAtRequiredVertices splits) {
  const Mesh<D>& mesh = am.mesh();
  std::vector<char> ends(static_cast<std::size_t>(mesh.vertex_count()), 0);
  for (Index v : mesh.required_vertices()) ends[v] = splits == SplitsAtRequiredVertices::kNone ? kBarredEnd : kRequiredEnd;
  const std::vector<Index>& listed = D == 3 ? mesh.required_triangles() : mesh.required_edges();
  std::vector<char> required_facet(static_cast<std::size_t>(mesh.facet_count()), 0);
  for (Index f : listed) required_facet[f] = 1;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_removed(f)) continue;
    const auto& facet = mesh.facet(f);
    for (int i = 0; i < D; ++i) {
      const Index a = facet[i], b = facet[(i + 1) % D];
      const char end = !required_facet[f] ? kBoundaryEnd : am.edge_length(a, b) > kCoarseRequiredEdge ? kBarredEnd : kRequiredEnd;
      for (Index v : {a, b})
        if (ends[v] != 0) ends[v] = std::max(ends[v], end);
    }
  }
  return ends;
}

// Whether the split of boundary edge (a, b) puts its point at the edge's straight middle: the
// boundary there is flat.
template <int D>
bool splits_flat_boundary(const Mesh<D>& mesh, Index a, Index b, const SplitPreview<D>& p) {
  return p.surfaces.boundary && at_straight_middle<D>(p.point, mesh.vertex(a), mesh.vertex(b));
}

}  // namespace

template <int D>
SplitSweep split_long_edges(AdaptationMesh<D>& am, const AdaptationLimits& limits, ThreadPool& pool) {
  std::vector<EdgeCandidate> candidates = edges_beyond(am, limits.split_length, true, pool);
  // 3D coarse phase: while many long edges are longer than 2, only those are split. Their halves
  // are longer than 1, so the mesh never gets denser than the metric asks; halves of edges in
  // (√2, 2) would be, while the coarse edges around them are still to be cut. (In 2D, where a
  // split triangle makes 4 and not 8 children, it lowered the annulus's mean quality.)
  SplitSweep sweep;
  OperationCount& count = sweep.count;
  // At a required vertex on the domain's boundary, only boundary edges where it is flat: on a
  // curved wall the points put on the geometry beside the frozen edges there made creases, and the
  // inner edges' splits left vertices off the geometry (docs/distributed.md §Interfaces refined first).
  std::vector<char> barred;
  const auto flat_boundary_only = [&](const EdgeCandidate& c) {
    return !barred.empty() && (barred[c.a] == kBoundaryEnd || barred[c.b] == kBoundaryEnd);
  };
  // (Before the coarse phase is judged: a distributed part's frozen interface edges, long and many
  // next to a coarse interface, would keep it in its coarse phase.)
  if (limits.splits_at_required_vertices != SplitsAtRequiredVertices::kEvery) {
    barred = barred_split_ends(am, limits.splits_at_required_vertices);
    std::erase_if(candidates, [&](const EdgeCandidate& c) {
      const bool barred_edge = barred[c.a] == kBarredEnd || barred[c.b] == kBarredEnd;
      if (barred_edge) count.add(Refusal::kClasses);
      return barred_edge;
    });
  }
  const auto beyond_two = std::partition_point(candidates.begin(), candidates.end(), [](const EdgeCandidate& c) { return c.length > 2; });
  sweep.coarse_phase = D == 3 &&
                       static_cast<double>(beyond_two - candidates.begin()) > kCoarsePhaseShare * static_cast<double>(candidates.size());
  if (sweep.coarse_phase) candidates.erase(beyond_two, candidates.end());
  std::vector<SplitScratch<D>> scratch(static_cast<std::size_t>(pool.thread_count()));
  std::vector<SplitPreview<D>> previews;
  SplitPreview<D> fresh;
  // One thread previews each candidate at its turn (never stale); more preview a chunk at once.
  const std::size_t chunk_size = pool.thread_count() > 1 ? kPreviewChunk : 1;
  for (std::size_t start = 0; start < candidates.size(); start += chunk_size) {
    const std::span<const EdgeCandidate> chunk = std::span(candidates).subspan(start, std::min(chunk_size, candidates.size() - start));
    previews.resize(chunk.size());
    run_in_blocks(pool, chunk.size(), 2, [&](std::size_t worker, std::size_t i) {
      preview_split(am, chunk[i].a, chunk[i].b, limits, SplitPurpose::kLength, previews[i], scratch[worker]);
    });
    for (std::size_t i = 0; i < chunk.size(); ++i) {
      const EdgeCandidate& c = chunk[i];
      // (On one thread each preview was made just now.)
      if (chunk_size > 1 && (!previews[i].current(am.mesh()) || !same_boundary(am, c.a, c.b, previews[i], fresh)))
        preview_split(am, c.a, c.b, limits, SplitPurpose::kLength, previews[i], scratch.front());
      if (!previews[i].made || am.edge_length(c.a, c.b) <= limits.split_length) continue;  // gone, or no longer long
      if (flat_boundary_only(c) && !splits_flat_boundary(am.mesh(), c.a, c.b, previews[i])) {
        count.add(Refusal::kClasses);
        continue;
      }
      count.add(split_edge(am, c.a, c.b, previews[i], limits, SplitPurpose::kLength, scratch.front()));
    }
  }
  return sweep;
}

namespace {

// An element by its vertices, with its quality when listed.
template <int D>
struct ListedElement {
  double quality;
  typename Mesh<D>::Element vertices;
  bool operator<(const ListedElement& other) const { return std::tie(quality, vertices) < std::tie(other.quality, other.vertices); }
};

// The elements below kBoundaryOnlyQuality whose vertices all lie on the boundary, worst first.
template <int D>
std::vector<ListedElement<D>> poor_boundary_only_elements(const AdaptationMesh<D>& am) {
  std::vector<ListedElement<D>> listed;
  for (Index k = 0; k < am.mesh().element_count(); ++k) {
    const auto& e = am.mesh().element(k);
    if (am.quality(k) < kBoundaryOnlyQuality &&
        std::none_of(e.begin(), e.end(), [&](Index v) { return am.vertex_class(v) == VertexClass::kInterior; }))
      listed.push_back({am.quality(k), e});
  }
  std::sort(listed.begin(), listed.end());
  return listed;
}

// Whether the shell of the preview still holds an element with these vertices.
template <int D>
bool shell_holds(const Mesh<D>& mesh, const SplitPreview<D>& p, const typename Mesh<D>::Element& vertices) {
  auto sorted = vertices;
  std::sort(sorted.begin(), sorted.end());
  return std::any_of(p.shell.begin(), p.shell.end(), [&](Index k) {
    auto element = mesh.element(k);
    std::sort(element.begin(), element.end());
    return element == sorted;
  });
}

}  // namespace

template <int D>
OperationCount cut_boundary_only_elements(AdaptationMesh<D>& am, const AdaptationLimits& limits) {
  OperationCount count;
  SplitScratch<D> scratch;
  SplitPreview<D> preview;
  std::vector<std::pair<double, std::array<Index, 2>>> edges;
  for (const ListedElement<D>& element : poor_boundary_only_elements(am)) {
    edges.clear();
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j < i; ++j) {
        const Index a = element.vertices[i], b = element.vertices[j];
        edges.push_back({-am.edge_length(a, b), {std::min(a, b), std::max(a, b)}});
      }
    std::sort(edges.begin(), edges.end());  // longest first
    for (const auto& [minus_length, edge] : edges) {
      preview_split(am, edge[0], edge[1], limits, SplitPurpose::kCut, preview, scratch);
      if (!preview.made || preview.surfaces.boundary || !shell_holds(am.mesh(), preview, element.vertices)) continue;
      const Refusal outcome = split_edge(am, edge[0], edge[1], preview, limits, SplitPurpose::kCut, scratch);
      count.add(outcome);
      if (outcome == Refusal::kNone) break;
    }
  }
  return count;
}

template OperationCount cut_boundary_only_elements(AdaptationMesh<2>&, const AdaptationLimits&);
template OperationCount cut_boundary_only_elements(AdaptationMesh<3>&, const AdaptationLimits&);
template SplitSweep split_long_edges(AdaptationMesh<2>&, const AdaptationLimits&, ThreadPool&);
template SplitSweep split_long_edges(AdaptationMesh<3>&, const AdaptationLimits&, ThreadPool&);

}  // namespace hocav
