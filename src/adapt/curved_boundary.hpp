// The boundary as the curved passes change it (docs/adaptation.md §Curved passes, on the boundary):
// which boundary edges a P2 split may cut and which boundary vertices a P2 collapse may remove, and
// where their new vertex and new boundary edges' nodes go (the closest points of the geometry the
// curving used). A split or a swap (3D: a flip of the edge on its surface) takes an edge of one
// smooth surface (not a feature line, no fold sharper than the feature angle between its two
// facets, no required facet); a collapse removes a surface vertex (not on a
// feature line, not a corner) along a boundary edge. Both keep every new facet within the feature
// angle of the facet it replaces, and a collapse keeps the surface's link condition. A move takes
// a surface vertex along its surface, each of its facets turning by less than the feature angle.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "cavity/p2_operations.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

template <int D>
class CurvedBoundary {
 public:
  // Classifies the vertices of `mesh` (on a copy: the mesh's tags do not change) as the P1 loop
  // does, with the feature angle, and keeps the classes as a vertex attribute of `mesh`, so that
  // they follow every operation and compaction. `geometry` outlives this object.
  CurvedBoundary(Mesh<D>& mesh, const BoundaryGeometry<D>& geometry, double feature_angle_degrees);

  // The placement of a split or swap of edge (a, b), whose shell is `shell`, when the edge is on
  // the boundary and may change there; none otherwise (an interior edge, or one the passes leave).
  std::optional<BoundaryPlacement<D>> edge_placement(std::span<const Index> shell, Index a, Index b);
  // The placement of the collapse of `removed`, whose ball is `ball`, onto `kept`, when `removed`
  // is on the boundary and may go; none otherwise.
  std::optional<BoundaryPlacement<D>> collapse_placement(std::span<const Index> ball, Index removed, Index kept);
  // The placement of a move of surface vertex v, whose ball is `ball`, along its surface; none when
  // v is not a surface vertex. Its facets may turn by less than the feature angle.
  std::optional<BoundaryPlacement<D>> move_placement(std::span<const Index> ball, Index v);
  // After a split placed on the boundary: its new vertex is a surface vertex.
  void add_surface_vertex(Index v);
  // On one smooth surface, not on a feature line, not a corner: it may move along it or vanish.
  bool surface_vertex(Index v) const;

 private:
  // Whether the facets found (facets_) are true boundary facets (no element beyond) of one ref.
  bool facets_on_one_surface() const;
  BoundaryPlacement<D> placement(int ref);

  Mesh<D>& mesh_;
  const BoundaryGeometry<D>& geometry_;
  double cos_feature_angle_;
  int class_attribute_;
  std::vector<Index> facets_, lines_, ball_, kept_facets_;
  std::vector<Vec<D>> facet_normals_;  // a move's facets' area normals before it
};

extern template class CurvedBoundary<2>;
extern template class CurvedBoundary<3>;

}  // namespace hocav
