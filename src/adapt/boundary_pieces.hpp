// The boundary pieces an adaptation operation replaces, found around its cavity, and the geometric
// test of the boundary it makes (docs/adaptation.md §Boundary).
#pragma once

#include <span>
#include <vector>

#include "adapt/adaptation_mesh.hpp"

namespace hocav {

// Whether `point` (a boundary point the geometry gives for edge (a, b)) is the edge's straight
// middle, within 1e-9 of the edge's length: the boundary is flat there. A distributed part splits a
// side's edges only where it is (edge_split.cpp, parallel/interface_refinement.cpp), so that both
// sides of an interface hold the new vertex at one point, on the geometry.
template <int D>
bool at_straight_middle(const Vec<D>& point, const Vec<D>& a, const Vec<D>& b) {
  return norm(point - 0.5 * (a + b)) <= 1e-9 * norm(b - a);
}

// The boundary facets on faces of `elements` that contain every vertex of `through`.
template <int D>
void facets_through(const Mesh<D>& mesh, std::span<const Index> elements, std::span<const Index> through, std::vector<Index>& out);

// Whether one of these facets is required (RequiredTriangles in 3D; RequiredEdges, the facets, in 2D).
template <int D>
bool holds_required_facet(const Mesh<D>& mesh, std::span<const Index> facets);

// 3D: the feature lines through v (a scan of the lines: they are few, and only ridge and corner
// vertices ask).
void lines_through(const Mesh<3>& mesh, Index v, std::vector<Index>& out);

// 3D: the feature lines along edge (a, b) (a scan of the lines, as lines_through).
void lines_along(const Mesh<3>& mesh, Index a, Index b, std::vector<Index>& out);

// Whether the facets a planned boundary operation creates stay close to the boundary they replace:
// no new facet turns by more than the feature angle from the facet it replaces, and (with a
// geometry and hausd > 0) each new facet's centroid lies within hausd of the geometry.
template <int D>
bool boundary_change_acceptable(const AdaptationMesh<D>& mesh, const CavityOperator<D>& plan, double cos_feature_angle, double hausd);

// Whether a facet with these vertices turns by less than the feature angle from a facet of area
// normal `old_normal`; and whether every new facet of a plan does from the facet it replaces.
template <int D>
bool turns_less(const Mesh<D>& mesh, const typename Mesh<D>::Facet& vertices, const Vec<D>& old_normal, double cos_feature_angle);
template <int D>
bool new_facets_turn_less(const Mesh<D>& mesh, const CavityOperator<D>& plan, double cos_feature_angle);

// Whether the planned collapse of `removed` (its facets: `removed_facets`) onto `kept` folds the
// surface: the link condition on the surface. The ends of a surface edge may share no surface
// neighbour besides the far vertices of the edge's facets (else the collapse leaves an edge with four
// facets, pinching the domain there), and no facet the plan creates may be one around `kept` already
// (two facets on one face, each the boundary of elements on both sides of it: a boundary-layer
// shell's inner wall did). `ball` and `kept_facets` are scratch.
template <int D>
bool collapse_folds_surface(const Mesh<D>& mesh, const CavityOperator<D>& plan, Index removed, Index kept,
                            std::span<const Index> removed_facets, std::vector<Index>& ball, std::vector<Index>& kept_facets);

// The same test for a facet of the mesh whose vertices moved: its normal against the one it had.
template <int D>
bool facet_stays_close(const AdaptationMesh<D>& mesh, Index facet, const Vec<D>& old_area_normal, double cos_feature_angle, double hausd);

// The facet's normal scaled by its measure, outward.
template <int D>
Vec<D> area_normal(const Mesh<D>& mesh, const typename Mesh<D>::Facet& facet);

}  // namespace hocav
