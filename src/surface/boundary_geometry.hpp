// The geometry of the domain boundary as the cavity operators see it (docs/method.md §9): project a point
// onto it, its normal there, and the P2 node proposed for a boundary edge. Implemented by the P3
// surrogate of the input boundary (p3_surrogate.hpp), by analytic shapes (analytic_boundary.hpp)
// and by a CAD model read through gmsh (cad_boundary_gmsh.hpp).
//
// Parts of the boundary are named by facet refs: a query may restrict a projection to one ref, so
// that a point between two surfaces (or near a ridge) lands on the surface its facet belongs to.
#pragma once

#include <array>
#include <optional>

#include "base/index.hpp"
#include "geom/vec.hpp"

namespace hocav {

struct ProjectionQuery {
  // Only the part of the boundary with this facet ref; every part when empty.
  std::optional<int> ref = std::nullopt;
  // The patch of an earlier projection near the point (BoundaryPoint::patch, from the same
  // geometry): a backend may search from there first. For the P3 surrogate, patch p is facet p of
  // the mesh it was built from.
  Index hint = kNoIndex;
};

template <int D>
struct BoundaryPoint {
  Vec<D> point{};
  double distance = 0;     // from the projected point
  Index patch = kNoIndex;  // the backend's piece of boundary that holds the point
  int ref = 0;             // the facet ref of that piece
};

// A boundary edge of a mesh, as a proposal needs it.
template <int D>
struct BoundaryEdge {
  Index a = kNoIndex, b = kNoIndex;  // its vertices
  Vec<D> node{};                     // its current P2 node, or its straight midpoint on a P1 mesh
  // The refs of the facets on either side; equal on a smooth part, and always in 2D, where the
  // edge is a facet.
  std::array<int, 2> refs{};
};

template <int D>
class BoundaryGeometry {
 public:
  virtual ~BoundaryGeometry() = default;

  // The closest point of the (queried part of the) boundary to x. Error when the query names a
  // ref the geometry does not have.
  virtual BoundaryPoint<D> project(const Vec<D>& x, const ProjectionQuery& query = {}) const = 0;

  // The unit normal of the boundary at the projection of x; its sign is the backend's.
  virtual Vec<D> normal(const Vec<D>& x, const ProjectionQuery& query = {}) const = 0;

  // The closest point to x where the parts with refs ref_a and ref_b meet (a ridge curve in 3D).
  // This default alternates projections onto the two parts, which converges for parts that meet
  // at an angle; a backend that knows the curve does better.
  virtual Vec<D> project_on_intersection(const Vec<D>& x, int ref_a, int ref_b) const;

  // The closest point to x on the feature curve of a ridge edge whose facets have refs ref_a and
  // ref_b: where a split puts the new vertex of a ridge edge, on the curve the mid nodes follow.
  // Two refs: this default is project_on_intersection; one ref (a ridge inside one part, from a
  // dihedral angle or a Ridges tag): the projection onto that part, which has no curve of its own
  // here. The P3 surrogate answers both from its shared cubic ridge curves (ridge_curves.hpp).
  virtual Vec<D> project_on_ridge(const Vec<D>& x, int ref_a, int ref_b) const;

  // The P2 node proposed for a boundary edge. This default projects the edge's node onto the part
  // of its ref, or onto the meeting curve when its two sides have different refs.
  virtual Vec<D> propose_edge_node(const BoundaryEdge<D>& edge) const;
};

extern template class BoundaryGeometry<2>;
extern template class BoundaryGeometry<3>;

}  // namespace hocav
