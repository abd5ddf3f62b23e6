// The boundary pieces an adaptation operation replaces, found around its cavity, and the geometric
// test of the boundary it makes (docs/adaptation.md §Boundary).
#pragma once

#include <span>
#include <vector>

#include "adapt/adaptation_mesh.hpp"

namespace hocav {

// The boundary facets on faces of `elements` that contain every vertex of `through`.
template <int D>
void facets_through(const Mesh<D>& mesh, std::span<const Index> elements, std::span<const Index> through, std::vector<Index>& out);

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

// The same test for a facet of the mesh whose vertices moved: its normal against the one it had.
template <int D>
bool facet_stays_close(const AdaptationMesh<D>& mesh, Index facet, const Vec<D>& old_area_normal, double cos_feature_angle, double hausd);

// The facet's normal scaled by its measure, outward.
template <int D>
Vec<D> area_normal(const Mesh<D>& mesh, const typename Mesh<D>::Facet& facet);

}  // namespace hocav
