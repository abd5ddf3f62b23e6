// Turns what a mesh reader found in a file (nodes and node lists, with file numbering) into a
// Mesh<D>: corners become vertices, P2 mid nodes go onto edges, and every cross-reference is
// checked. Shared by the Gamma and Gmsh readers so both enforce the same rules.
#pragma once

#include <string>
#include <vector>

#include "io/mesh_file.hpp"

namespace hocav {

template <int D>
struct RawMesh {
  std::vector<Vec<D>> nodes;  // every node of the file, in file order
  std::vector<int> node_refs;
  int order = 1;  // 2 when elements carry mid-edge nodes
  // Node lists, 0-based file ids, in hocav's local order (simplex.hpp): corners, then (P2) the
  // nodes of the local edges. Elements have D + 1 (+ edges) ids; facets D (+ facet edges);
  // lines 2 (+ 1). Facets and lines may be P1 in a P2 mesh.
  std::vector<Index> element_nodes;
  std::vector<int> element_refs;
  std::vector<Index> facet_nodes;
  std::vector<int> facet_refs;
  int facet_order = 1;
  std::vector<Index> line_nodes;
  std::vector<int> line_refs;
  int line_order = 1;
  // Corners and RequiredVertices: file node ids. Ridges and RequiredEdges: ids of Edges entities
  // (facets in 2D, lines in 3D); RequiredTriangles: ids of 3D Triangles (facets); all 0-based.
  std::vector<Index> corners, required_vertices, ridges, required_edges, required_triangles;
  // Names for error messages: the file, and the keywords or element types the lists came from.
  std::string element_keyword = "elements", facet_keyword = "facets", line_keyword = "edges";
};

// Builds the mesh and its file-node maps. Throws Error "<path>: <keyword>: <what> N" when a node
// is used both as a corner and as a mid node, two elements give one edge different mid nodes, a
// facet or line disagrees with the elements, a facet is no element face, or the topology is not
// manifold.
template <int D>
MeshFileContent assemble_mesh(RawMesh<D>&& raw, const std::string& path);

}  // namespace hocav
