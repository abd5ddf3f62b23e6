// Inner vertices a hair above the boundary (docs/adaptation.md §Collapse, "Thin vertices"): an
// element of quality below kThinQuality with a boundary facet whose opposite vertex is inner and lies
// less than kThinHeight above the facet's plane, measured in that vertex's metric. The loop's other
// operators do not see such a vertex: its edges along the boundary are long (so split, which puts
// their middles closer still) and its smoothing target stays near the boundary. It is collapsed
// onto the facet's vertex nearest it in the metric, else onto another of them.
#include <algorithm>
#include <cmath>
#include <limits>

#include "adapt/adaptation_operations.hpp"
#include "adapt/boundary_pieces.hpp"

namespace hocav {
namespace {

constexpr double kThinQuality = 1e-2;
constexpr double kThinHeight = 1e-2;

template <int D>
struct ThinVertex {
  Index vertex;
  typename Mesh<D>::Facet facet;  // the boundary facet it is a hair above
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
        thin.push_back({apex, mesh.facet(facet)});
    }
  }
  std::stable_sort(thin.begin(), thin.end(), [](const ThinVertex<D>& x, const ThinVertex<D>& y) { return x.vertex < y.vertex; });
  thin.erase(std::unique(thin.begin(), thin.end(), [](const ThinVertex<D>& x, const ThinVertex<D>& y) { return x.vertex == y.vertex; }),
             thin.end());
  return thin;
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
    count.add(first);
  }
  return count;
}

template OperationCount collapse_thin_vertices(AdaptationMesh<2>&, const AdaptationLimits&);
template OperationCount collapse_thin_vertices(AdaptationMesh<3>&, const AdaptationLimits&);

}  // namespace hocav
