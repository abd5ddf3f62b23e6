// The geometric class of every vertex at the start of an adaptation (docs/adaptation.md §Boundary):
// corners and ridges from the mesh's own tags (Corners, RequiredVertices, Ridges/Edges) and from
// the boundary's shape (sides whose facets differ in ref or meet at more than the feature angle).
#pragma once

#include <vector>

#include "adapt/adaptation_mesh.hpp"
#include "mesh/mesh_defects.hpp"

namespace hocav {

// A feature angle no two facets' normals exceed: classify_vertices then takes its ridges from the
// mesh's tags, its ref changes and its open or non-manifold sides only.
constexpr double kRidgesFromTagsOnly = 180;

// Classifies the vertices of a mesh with topology. Ridges found from the shape are added to the
// mesh as tagged feature lines (3D) or corners (2D ridge vertices), and vertices where the feature
// lines do not continue (3D: ends and junctions) as corners, so the output carries them. So are the
// vertices of the mesh's non-manifold places (`places`, non_manifold_places of the mesh): a walk
// around them sees one of the parts that meet there, so no operator may move or remove them.
template <int D>
std::vector<VertexClass> classify_vertices(Mesh<D>& mesh, double feature_angle_degrees, const NonManifoldPlaces& places);
// The same with the mesh's own non-manifold places.
template <int D>
std::vector<VertexClass> classify_vertices(Mesh<D>& mesh, double feature_angle_degrees);

}  // namespace hocav
