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
VertexClass CurvedBoundary<D>::vertex_class(Index v) const {
  return static_cast<VertexClass>(mesh_.vertex_attribute(class_attribute_, v)[0]);
}

template <int D>
void CurvedBoundary<D>::add_boundary_vertex(Index v, VertexClass vertex_class) {
  mesh_.vertex_attribute(class_attribute_, v)[0] = static_cast<double>(vertex_class);
}

template <int D>
bool CurvedBoundary<D>::facets_on_domain_boundary() const {
  return !facets_.empty() && std::all_of(facets_.begin(), facets_.end(), [&](Index f) {
    const Index element_face = mesh_.facet_element_face(f);
    return mesh_.neighbor(element_face / (D + 1), static_cast<int>(element_face % (D + 1))) == kNoIndex;
  });
}

template <int D>
bool CurvedBoundary<D>::facets_of_one_ref() const {
  return std::all_of(facets_.begin(), facets_.end(), [&](Index f) { return mesh_.facet_ref(f) == mesh_.facet_ref(facets_.front()); });
}

template <int D>
BoundaryPlacement<D> CurvedBoundary<D>::placement() {
  BoundaryPlacement<D> placement;
  placement.facets = facets_;
  placement.lines = lines_;
  placement.place = [this](const Vec<D>& x, Index w) {
    const bool on_ridge = !lines_.empty() && (w == kNoIndex || w == ridge_ends_[0] || w == ridge_ends_[1]);
    if (on_ridge) return geometry_.project_on_ridge(x, ridge_refs_[0], ridge_refs_[1]);
    // Otherwise on the surface of a facet through w (the operation's vertex: any of them, one ref).
    const auto through = std::find_if(facets_.begin(), facets_.end(), [&](Index f) { return small_set_holds(mesh_.facet(f), w); });
    return geometry_.project(x, {mesh_.facet_ref(through != facets_.end() ? *through : facets_.front())}).point;
  };
  return placement;
}

template <int D>
std::optional<BoundaryPlacement<D>> CurvedBoundary<D>::edge_placement(std::span<const Index> shell, Index a, Index b, bool along_lines) {
  const Index ends[2] = {a, b};
  facets_through<D>(mesh_, shell, ends, facets_);
  lines_.clear();
  ridge_ends_ = {kNoIndex, kNoIndex};
  if (!facets_on_domain_boundary() || holds_required_facet<D>(mesh_, facets_)) return std::nullopt;
  if constexpr (D == 3) {
    if (facets_.size() != 2) return std::nullopt;
    lines_along(mesh_, a, b, lines_);
    if (!lines_.empty()) {  // a feature line: split along its curve, never flipped
      const bool required = std::find(mesh_.required_edges().begin(), mesh_.required_edges().end(), lines_.front()) !=
                            mesh_.required_edges().end();
      if (!along_lines || lines_.size() != 1 || required) return std::nullopt;
      ridge_ends_ = {a, b};
      ridge_refs_ = {mesh_.facet_ref(facets_[0]), mesh_.facet_ref(facets_[1])};
    } else {
      const Vec<3> other = area_normal<3>(mesh_, mesh_.facet(facets_[1]));
      if (!facets_of_one_ref() || !turns_less<3>(mesh_, mesh_.facet(facets_[0]), other, cos_feature_angle_)) return std::nullopt;
    }
  }
  BoundaryPlacement<D> edge = placement();
  edge.check = [this](const CavityOperator<D>& plan) { return new_facets_turn_less<D>(mesh_, plan, cos_feature_angle_); };
  return edge;
}

template <int D>
bool CurvedBoundary<D>::collapses_along_its_line(Index removed, Index kept) {
  if constexpr (D == 3) {
    lines_through(mesh_, removed, lines_);
    if (lines_.size() != 2) return false;
    const auto other_end = [&](Index l) { return mesh_.line(l)[0] == removed ? mesh_.line(l)[1] : mesh_.line(l)[0]; };
    const Index first = other_end(lines_[0]), second = other_end(lines_[1]);
    if (first != kept && second != kept) return false;
    ridge_ends_ = {first == kept ? second : first, kNoIndex};  // the line edge the collapse makes ends there
    // The line's two sides: the refs of the facets along the collapsed line edge.
    std::array<int, 2> refs{};
    int found = 0;
    for (Index f : facets_)
      if (small_set_holds(mesh_.facet(f), kept) && found < 2) refs[static_cast<std::size_t>(found++)] = mesh_.facet_ref(f);
    ridge_refs_ = {refs[0], found == 2 ? refs[1] : refs[0]};
    return found == 2;
  }
  return false;
}

template <int D>
std::optional<BoundaryPlacement<D>> CurvedBoundary<D>::collapse_placement(std::span<const Index> ball, Index removed, Index kept) {
  const Index center[1] = {removed};
  facets_through<D>(mesh_, ball, center, facets_);
  lines_.clear();
  ridge_ends_ = {kNoIndex, kNoIndex};
  if (!facets_on_domain_boundary()) return std::nullopt;
  const bool along_boundary = std::any_of(facets_.begin(), facets_.end(), [&](Index f) { return small_set_holds(mesh_.facet(f), kept); });
  if (!along_boundary) return std::nullopt;
  const VertexClass from = vertex_class(removed);
  const bool on_surface = from == VertexClass::kSurface && facets_of_one_ref();
  if (!on_surface && !(from == VertexClass::kRidge && collapses_along_its_line(removed, kept))) return std::nullopt;
  BoundaryPlacement<D> collapse = placement();
  collapse.check = [this, removed, kept](const CavityOperator<D>& plan) {
    return new_facets_turn_less<D>(mesh_, plan, cos_feature_angle_) &&
           !collapse_folds_surface<D>(mesh_, plan, removed, kept, facets_, ball_, kept_facets_);
  };
  return collapse;
}

template class CurvedBoundary<2>;
template class CurvedBoundary<3>;

}  // namespace hocav
