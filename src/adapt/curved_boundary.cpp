#include "adapt/curved_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "adapt/boundary_pieces.hpp"
#include "adapt/vertex_classes.hpp"
#include "base/small_set.hpp"

namespace hocav {

template <int D>
CurvedBoundary<D>::CurvedBoundary(Mesh<D>& mesh, const BoundaryGeometry<D>& geometry, double feature_angle_degrees)
    : mesh_(mesh),
      geometry_(geometry),
      cos_feature_angle_(std::cos(feature_angle_degrees * std::numbers::pi / 180)),
      class_attribute_(mesh.add_vertex_attribute(1)) {
  Mesh<D> copy = mesh;  // the classification tags the feature lines and corners it finds
  const std::vector<VertexClass> classes = classify_vertices(copy, feature_angle_degrees);
  for (Index v = 0; v < mesh.vertex_count(); ++v) mesh.vertex_attribute(class_attribute_, v)[0] = static_cast<double>(classes[v]);
}

template <int D>
bool CurvedBoundary<D>::surface_vertex(Index v) const {
  return static_cast<VertexClass>(mesh_.vertex_attribute(class_attribute_, v)[0]) == VertexClass::kSurface;
}

template <int D>
void CurvedBoundary<D>::add_surface_vertex(Index v) {
  mesh_.vertex_attribute(class_attribute_, v)[0] = static_cast<double>(VertexClass::kSurface);
}

template <int D>
bool CurvedBoundary<D>::facets_on_one_surface() const {
  if (facets_.empty()) return false;
  return std::all_of(facets_.begin(), facets_.end(), [&](Index f) {
    const Index element_face = mesh_.facet_element_face(f);
    const bool outer = mesh_.neighbor(element_face / (D + 1), static_cast<int>(element_face % (D + 1))) == kNoIndex;
    return outer && mesh_.facet_ref(f) == mesh_.facet_ref(facets_.front());
  });
}

template <int D>
BoundaryPlacement<D> CurvedBoundary<D>::placement(int ref) {
  BoundaryPlacement<D> placement;
  placement.facets = facets_;
  placement.onto_surface = [this, ref](const Vec<D>& x) { return geometry_.project(x, {ref}).point; };
  return placement;
}

template <int D>
std::optional<BoundaryPlacement<D>> CurvedBoundary<D>::edge_placement(std::span<const Index> shell, Index a, Index b) {
  const Index ends[2] = {a, b};
  facets_through<D>(mesh_, shell, ends, facets_);
  if (!facets_on_one_surface() || holds_required_facet<D>(mesh_, facets_)) return std::nullopt;
  if constexpr (D == 3) {
    lines_along(mesh_, a, b, lines_);
    if (!lines_.empty() || facets_.size() != 2) return std::nullopt;
    const Vec<3> other = area_normal<3>(mesh_, mesh_.facet(facets_[1]));
    if (!turns_less<3>(mesh_, mesh_.facet(facets_[0]), other, cos_feature_angle_)) return std::nullopt;  // a fold: a ridge
  }
  BoundaryPlacement<D> split = placement(mesh_.facet_ref(facets_.front()));
  split.check = [this](const CavityOperator<D>& plan) { return new_facets_turn_less<D>(mesh_, plan, cos_feature_angle_); };
  return split;
}

template <int D>
std::optional<BoundaryPlacement<D>> CurvedBoundary<D>::collapse_placement(std::span<const Index> ball, Index removed, Index kept) {
  const Index center[1] = {removed};
  facets_through<D>(mesh_, ball, center, facets_);
  if (facets_.empty() || !surface_vertex(removed) || !facets_on_one_surface()) return std::nullopt;
  const bool along_boundary = std::any_of(facets_.begin(), facets_.end(), [&](Index f) { return small_set_holds(mesh_.facet(f), kept); });
  if (!along_boundary) return std::nullopt;
  BoundaryPlacement<D> collapse = placement(mesh_.facet_ref(facets_.front()));
  collapse.check = [this, removed, kept](const CavityOperator<D>& plan) {
    return new_facets_turn_less<D>(mesh_, plan, cos_feature_angle_) &&
           !collapse_folds_surface<D>(mesh_, plan, removed, kept, facets_, ball_, kept_facets_);
  };
  return collapse;
}

template <int D>
std::optional<BoundaryPlacement<D>> CurvedBoundary<D>::move_placement(std::span<const Index> ball, Index v) {
  const Index center[1] = {v};
  facets_through<D>(mesh_, ball, center, facets_);
  if (!surface_vertex(v) || !facets_on_one_surface()) return std::nullopt;
  facet_normals_.clear();
  for (Index f : facets_) facet_normals_.push_back(area_normal<D>(mesh_, mesh_.facet(f)));
  BoundaryPlacement<D> move = placement(mesh_.facet_ref(facets_.front()));
  move.check = [this](const CavityOperator<D>&) {  // the vertex is where the move puts it
    for (std::size_t i = 0; i < facets_.size(); ++i)
      if (!turns_less<D>(mesh_, mesh_.facet(facets_[i]), facet_normals_[i], cos_feature_angle_)) return false;
    return true;
  };
  return move;
}

template class CurvedBoundary<2>;
template class CurvedBoundary<3>;

}  // namespace hocav
