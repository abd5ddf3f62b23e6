// The boundary as the curved passes change it (docs/adaptation.md §Curved passes, "The boundary"):
// which boundary edges a P2 split or flip may change, which boundary vertices a P2 collapse may
// remove, and where their new vertex and new boundary edges' nodes go (the closest points of the
// geometry the curving used). A split or a flip (3D: a swap of the edge on
// its surface) takes an edge of one smooth surface (no fold sharper than the feature angle between
// its two facets, no required facet), and a split also an edge of a feature line (3D), on its ridge
// curve; a collapse removes a surface vertex along a boundary edge, or a ridge vertex along its line
// (never a corner). Each keeps every new facet within the feature angle of the facet it replaces,
// and a collapse keeps the surface's link condition.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "adapt/adaptation_mesh.hpp"
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
  // With `along_lines` (a split), an edge of a feature line too: its new vertex and the line's new
  // edges go on the ridge curve.
  std::optional<BoundaryPlacement<D>> edge_placement(std::span<const Index> shell, Index a, Index b, bool along_lines);
  // The placement of the collapse of `removed`, whose ball is `ball`, onto `kept`, when `removed`
  // is on the boundary and may go: a surface vertex along a boundary edge, or a ridge vertex along
  // its line; none otherwise.
  std::optional<BoundaryPlacement<D>> collapse_placement(std::span<const Index> ball, Index removed, Index kept);
  // After a split placed on the boundary: the class of its new vertex (kSurface, or kRidge on a line).
  void add_boundary_vertex(Index v, VertexClass vertex_class);

 private:
  VertexClass vertex_class(Index v) const;
  // Whether the facets found (facets_) are on the domain's boundary (no element beyond), and of one ref.
  bool facets_on_domain_boundary() const;
  bool facets_of_one_ref() const;
  // 3D: whether ridge vertex `removed` has two line edges, one to `kept`; sets lines_ and the ridge
  // the collapse's new line edge follows.
  bool collapses_along_its_line(Index removed, Index kept);
  // A placement on facets_ and lines_: the vertex, and its edges to ridge_ends_, on the ridge curve
  // between ridge_refs_ when lines_ is not empty; any other edge on the surface of a facet through
  // its far vertex.
  BoundaryPlacement<D> placement();

  Mesh<D>& mesh_;
  const BoundaryGeometry<D>& geometry_;
  double cos_feature_angle_;
  int class_attribute_;
  std::vector<Index> facets_, lines_, ball_, kept_facets_;
  std::array<Index, 2> ridge_ends_{kNoIndex, kNoIndex};
  std::array<int, 2> ridge_refs_{};
};

extern template class CurvedBoundary<2>;
extern template class CurvedBoundary<3>;

}  // namespace hocav
