// Boundary-node proposals (docs/method.md §9, surface curvature recovery): for every boundary edge, the
// P2 node the geometry proposes for it, kept in a table keyed by the edge's vertex pair until a
// cavity consumes it.
//
// Boundary edges are the edges of the boundary facets (3D) or the facets themselves (2D). The
// proposal is the geometry's BoundaryGeometry::propose_edge_node: on the P3 surrogate the midpoint
// of the edge's cubic curve (exact on the surrogate, ridges included); on an analytic or CAD
// geometry the projection of the edge's straight midpoint — or of its current node on a P2 mesh —
// onto the surface of its facets' ref, or onto the curve where two refs meet.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "base/index_hash_map.hpp"
#include "mesh/mesh.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

// Which boundary edges get a proposal, and how the geometry knows their vertices (by default: every
// edge, by the mesh's ids). A part of a distributed curving (docs/distributed.md §Curving) proposes
// none on its frozen interfaces, its second round only near the first round's interfaces, and its
// vertices have the ids of the whole mesh the geometry was made from.
struct ProposalScope {
  std::optional<int> frozen_facet_ref;  // the edges of the facets with this ref get none
  std::span<const char> region;         // per vertex, when not empty: only edges with both ends in it get one
  std::span<const Index> geometry_ids;  // per vertex, when not empty: its id in the geometry's mesh
};

template <int D>
class BoundaryProposals {
 public:
  BoundaryProposals(const Mesh<D>& mesh, const BoundaryGeometry<D>& geometry, const ProposalScope& scope = {});

  // Proposals not consumed yet.
  std::size_t size() const { return slot_of_edge_.size(); }
  // The proposal for edge (a, b), in either order; std::nullopt when there is none (any more).
  std::optional<Vec<D>> find(Index a, Index b) const;
  // Returns the proposal for edge (a, b) and removes it from the table.
  std::optional<Vec<D>> take(Index a, Index b);

  // A proposal not consumed yet.
  struct Left {
    Index a, b;
    Vec<D> node;
  };
  // The proposals not consumed yet, in the order of the mesh's facets when the table was made.
  std::vector<Left> left() const;

 private:
  IndexHashMap slot_of_edge_;
  std::vector<std::array<Index, 2>> ends_;
  std::vector<Vec<D>> nodes_;
};

// Curves the boundary edges of a mesh with the proposals: every boundary edge that has one gets it
// as its P2 node, and the proposal is consumed. A P1 mesh is made P2 first (mid nodes at the
// straight midpoints). Returns the number of edges curved. For measurements and tests: the
// adaptation consumes proposals edge by edge in the P2 cavity operator instead.
template <int D>
Index apply_boundary_proposals(Mesh<D>& mesh, BoundaryProposals<D>& proposals);

extern template class BoundaryProposals<2>;
extern template class BoundaryProposals<3>;

}  // namespace hocav
