// Defects a consistent mesh may still have, which curving works around but a user should hear of:
// element faces on the domain boundary without a boundary facet (an open or missing boundary),
// non-manifold vertices (parts of the mesh that meet only there) and edges (3D: more than two
// boundary faces around them), and overlapping elements (an inner vertex around which its elements
// turn more than once). Needs Mesh::build_topology().
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

struct MeshDefects {
  Index open_faces = 0, non_manifold_vertices = 0, non_manifold_edges = 0, overlap_vertices = 0;
  std::vector<std::string> examples;  // the first few defects found, one line each, 1-based ids

  bool none() const { return open_faces + non_manifold_vertices + non_manifold_edges + overlap_vertices == 0; }
  // "12 open boundary faces, 1 non-manifold vertex (first: face 2 of element 5 has no boundary
  // facet; ...)"; empty when there is none.
  std::string summary() const;
};

template <int D>
MeshDefects find_mesh_defects(const Mesh<D>& mesh, std::size_t max_examples = 3);

// Where parts of a mesh meet without sharing a face: the vertices that a walk through the faces
// around them does not take all around (ascending ids: two parts touching at a point, or along an
// edge), and in 3D the edges with more than two boundary faces around them (ascending
// Mesh::edge_key values). Every operator that walks a ball or a shell sees one side of such a
// place. Needs Mesh::build_topology() (none are found without it).
struct NonManifoldPlaces {
  std::vector<Index> vertices;
  std::vector<std::uint64_t> edges;

  // The vertices and the edges' ends, ascending, once each.
  std::vector<Index> every_vertex() const;
};

template <int D>
NonManifoldPlaces non_manifold_places(const Mesh<D>& mesh);

}  // namespace hocav
