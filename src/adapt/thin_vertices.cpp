// Inner vertices a hair above the boundary (docs/adaptation.md §Collapse, "Thin vertices"): an
// element of quality below kThinQuality with a boundary facet whose opposite vertex is inner and lies
// less than kThinHeight above the facet's plane, measured in that vertex's metric. The loop's other
// operators do not see such a vertex: its edges along the boundary are long (so split, which puts
// their middles closer still) and its smoothing target stays near the boundary. It is collapsed
// onto the facet's vertex nearest it in the metric, else onto another of them; a vertex that stands
// over several facets, so that no collapse removes it, sinks onto the boundary instead.
#include <algorithm>
#include <cmath>
#include <limits>

#include "adapt/adaptation_operations.hpp"
#include "adapt/boundary_pieces.hpp"
#include "base/small_set.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

constexpr double kThinQuality = 1e-2;
constexpr double kThinHeight = 1e-2;

template <int D>
struct ThinVertex {
  Index vertex;
  Index facet_id;                 // the boundary facet it is a hair above
  typename Mesh<D>::Facet facet;  // that facet's vertices
};

// The height of point x above the plane of `facet` in `metric`: its distance to the plane along the
// unit normal n, times the metric length of n.
template <int D>
double height_in_metric(const Mesh<D>& mesh, const typename Mesh<D>::Facet& facet, const Vec<D>& x, const SymMat<D>& metric) {
  const Vec<D> normal = area_normal<D>(mesh, facet);
  const double area = norm(normal);
  if (!(area > 0)) return 0;
  return std::abs(dot(normal, x - mesh.vertex(facet[0]))) / area * std::sqrt(quadratic_form(metric, normal)) / area;
}

// The thin vertices of the poor elements, each once (the first facet found), by vertex id.
template <int D>
std::vector<ThinVertex<D>> thin_vertices(const AdaptationMesh<D>& am) {
  const Mesh<D>& mesh = am.mesh();
  std::vector<ThinVertex<D>> thin;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    if (am.quality(k) >= kThinQuality) continue;
    for (int face = 0; face <= D; ++face) {
      const Index apex = mesh.element(k)[face], facet = mesh.element_face_facet(k, face);
      if (facet == kNoIndex || am.vertex_class(apex) != VertexClass::kInterior) continue;
      if (height_in_metric<D>(mesh, mesh.facet(facet), mesh.vertex(apex), am.metric(apex)) < kThinHeight)
        thin.push_back({apex, facet, mesh.facet(facet)});
    }
  }
  std::stable_sort(thin.begin(), thin.end(), [](const ThinVertex<D>& x, const ThinVertex<D>& y) { return x.vertex < y.vertex; });
  thin.erase(std::unique(thin.begin(), thin.end(), [](const ThinVertex<D>& x, const ThinVertex<D>& y) { return x.vertex == y.vertex; }),
             thin.end());
  return thin;
}

// 3D: whether a feature line runs along an edge that two of these facets share.
template <int D>
bool line_between(const AdaptationMesh<D>& am, std::span<const Index> facets) {
  if constexpr (D == 3) {
    const Mesh<D>& mesh = am.mesh();
    std::vector<Index> lines;
    for (std::size_t i = 0; i < facets.size(); ++i)
      for (int e = 0; e < 3; ++e) {
        const Index a = mesh.facet(facets[i])[e], b = mesh.facet(facets[i])[(e + 1) % 3];
        if (am.vertex_class(a) < VertexClass::kRidge || am.vertex_class(b) < VertexClass::kRidge) continue;
        const bool shared = std::any_of(facets.begin(), facets.begin() + static_cast<std::ptrdiff_t>(i),
                                        [&](Index f) { return small_set_holds(mesh.facet(f), a) && small_set_holds(mesh.facet(f), b); });
        if (!shared) continue;
        lines_along(mesh, a, b, lines);
        if (!lines.empty()) return true;
      }
  }
  return false;
}

// The facets of ref `ref` on the faces of v's ball (all opposite v, an inner vertex): the part of the
// boundary under v. False when one of them is required, or when a feature line runs between two of
// them: the sink's surface star would remove it.
template <int D>
bool facets_below(const AdaptationMesh<D>& am, std::span<const Index> ball, int ref, std::vector<Index>& out) {
  const Mesh<D>& mesh = am.mesh();
  facets_through(mesh, ball, {}, out);
  std::erase_if(out, [&](Index f) { return mesh.facet_ref(f) != ref; });
  const std::vector<Index>& required = D == 2 ? mesh.required_edges() : mesh.required_triangles();
  const auto is_required = [&](Index f) { return std::find(required.begin(), required.end(), f) != required.end(); };
  return std::none_of(out.begin(), out.end(), is_required) && !line_between(am, out);
}

// Whether the thin vertex's facet is still in the mesh: earlier operations of the sweep re-star
// facets, and may give a removed facet's id to another.
template <int D>
bool still_below(const Mesh<D>& mesh, const ThinVertex<D>& thin) {
  if (thin.facet_id >= mesh.facet_count() || mesh.facet_removed(thin.facet_id)) return false;
  auto now = mesh.facet(thin.facet_id), then = thin.facet;
  std::sort(now.begin(), now.end());
  std::sort(then.begin(), then.end());
  return now == then;
}

// Where a thin vertex sinks to: its closest point on the geometry's part of the facet's ref, or
// without a geometry its foot on the facet's plane.
template <int D>
BoundaryPoint<D> sink_point(const AdaptationMesh<D>& am, const ThinVertex<D>& thin) {
  const Mesh<D>& mesh = am.mesh();
  const Vec<D>& x = mesh.vertex(thin.vertex);
  const int ref = mesh.facet_ref(thin.facet_id);
  if (am.geometry()) return am.geometry()->project(x, {ref, am.surface_hint(thin.facet[0])});
  const Vec<D> normal = area_normal<D>(mesh, thin.facet);
  return {x - dot(normal, x - mesh.vertex(thin.facet[0])) / dot(normal, normal) * normal};
}

// Replaces a thin vertex by a new boundary vertex at its sink point: its ball re-starred from there,
// the facets under it re-starred with it. Refused as a collapse would be (the floor on the new
// elements' quality, the boundary's turn and distance).
template <int D>
Refusal sink_thin_vertex(AdaptationMesh<D>& am, const ThinVertex<D>& thin, const AdaptationLimits& limits, std::vector<Index>& below) {
  Mesh<D>& mesh = am.mesh();
  auto& work = am.workspace();
  collect_ball(mesh, thin.vertex, work.cavity);
  if (!facets_below(am, work.cavity, mesh.facet_ref(thin.facet_id), below)) return Refusal::kClasses;
  const BoundaryPoint<D> sink = sink_point(am, thin);
  const double floor = std::min(0.3 * worst_quality<D>(am, work.cavity), 0.1);
  const Index w = am.add_vertex(sink.point, VertexClass::kSurface, thin.vertex);
  am.set_surface_hint(w, sink.patch);
  CavityOptions options;
  options.removable_vertex = thin.vertex;
  options.removed_facets = below;
  CavityOperator<D>& plan = work.cavity_operator;
  Refusal refusal = Refusal::kNone;
  if (plan.plan(mesh, work.cavity, w, options) != CavityStatus::kAccepted)
    refusal = Refusal::kTopology;
  else if (!(worst_planned_quality(am, plan) >= floor))
    refusal = Refusal::kQuality;
  else if (!boundary_change_acceptable(am, plan, limits.cos_feature_angle, limits.hausd))
    refusal = Refusal::kGeometry;
  if (refusal != Refusal::kNone) {
    mesh.pop_vertex();
    return refusal;
  }
  am.commit(plan);
  return Refusal::kNone;
}

}  // namespace

template <int D>
OperationCount collapse_thin_vertices(AdaptationMesh<D>& am, const AdaptationLimits& limits) {
  OperationCount count;
  // The vertex's edges along the boundary are long, so a collapse makes long edges: the next split
  // cuts them, away from the boundary's plane.
  AdaptationLimits any_length = limits;
  any_length.collapse_new_length = std::numeric_limits<double>::infinity();
  CollapseScratch<D> scratch;
  std::vector<Index> below;
  for (ThinVertex<D> thin : thin_vertices(am)) {
    if (am.mesh().vertex_removed(thin.vertex)) continue;
    std::sort(thin.facet.begin(), thin.facet.end(),
              [&](Index a, Index b) { return am.edge_length(thin.vertex, a) < am.edge_length(thin.vertex, b); });
    Refusal first = Refusal::kNone;
    for (std::size_t i = 0; i < thin.facet.size(); ++i) {
      const Refusal refusal = collapse_edge(am, thin.vertex, thin.facet[i], any_length, scratch);
      if (i == 0) first = refusal;
      if (refusal == Refusal::kNone) {
        first = Refusal::kNone;
        break;
      }
    }
    if (first != Refusal::kNone && still_below(am.mesh(), thin) && sink_thin_vertex(am, thin, limits, below) == Refusal::kNone)
      first = Refusal::kNone;
    count.add(first);
  }
  return count;
}

template OperationCount collapse_thin_vertices(AdaptationMesh<2>&, const AdaptationLimits&);
template OperationCount collapse_thin_vertices(AdaptationMesh<3>&, const AdaptationLimits&);

}  // namespace hocav
