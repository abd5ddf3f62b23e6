#include "io/mesh_assembly.hpp"

#include <gtest/gtest.h>

#include "base/error.hpp"

namespace hocav {
namespace {

// Two P2 triangles on the unit square, sharing the diagonal (file nodes 1 and 2):
//   corners 0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1); mid nodes 4..8, one per edge, listed after them.
RawMesh<2> two_curved_triangles() {
  RawMesh<2> raw;
  raw.nodes = {{{0, 0}}, {{1, 0}}, {{0, 1}}, {{1, 1}}, {{0.5, -0.1}}, {{0.5, 0.5}}, {{0, 0.5}}, {{1, 0.5}}, {{0.5, 1}}};
  raw.node_refs = {1, 2, 3, 4, 0, 0, 0, 0, 0};
  raw.order = 2;
  // v0 v1 v2 m01 m12 m20
  raw.element_nodes = {0, 1, 2, 4, 5, 6, /**/ 1, 3, 2, 7, 8, 5};
  raw.element_refs = {10, 20};
  raw.element_keyword = "TrianglesP2";
  raw.facet_keyword = "EdgesP2";
  return raw;
}

void expect_error(RawMesh<2> raw, const std::string& keyword, const std::string& what) {
  try {
    assemble_mesh(std::move(raw), "in.mesh");
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    std::string message = error.what();
    EXPECT_EQ(message.rfind("in.mesh: " + keyword + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(what), std::string::npos) << "'" << what << "' not in: " << message;
  }
}

TEST(MeshAssembly, PutsMidNodesOnEdgesAndKeepsTheFileNumbering) {
  RawMesh<2> raw = two_curved_triangles();
  raw.facet_order = 2;
  raw.facet_nodes = {0, 1, 4, /**/ 1, 3, 7};
  raw.facet_refs = {5, 6};
  raw.corners = {3};
  raw.ridges = {1};
  MeshFileContent content = assemble_mesh(std::move(raw), "in.mesh");
  const auto& mesh = std::get<Mesh<2>>(content.mesh);
  ASSERT_EQ(mesh.vertex_count(), 4);
  EXPECT_EQ(content.vertex_file_ids, (std::vector<Index>{0, 1, 2, 3}));
  EXPECT_EQ(content.file_node_count, 9);
  EXPECT_EQ(mesh.vertex_ref(3), 4);
  EXPECT_EQ(mesh.element(1), (Mesh<2>::Element{1, 3, 2}));
  EXPECT_EQ(mesh.element_ref(1), 20);
  EXPECT_EQ(mesh.facet_ref(1), 6);
  EXPECT_EQ(mesh.corners(), std::vector<Index>{3});
  EXPECT_EQ(mesh.ridges(), std::vector<Index>{1});
  ASSERT_TRUE(mesh.is_p2());
  ASSERT_EQ(mesh.edge_count(), 5);
  const std::pair<std::array<Index, 2>, Index> edges[] = {{{0, 1}, 4}, {{1, 2}, 5}, {{2, 0}, 6}, {{1, 3}, 7}, {{3, 2}, 8}};
  for (const auto& [ends, node] : edges) {
    Index edge = mesh.find_edge(ends[0], ends[1]);
    ASSERT_NE(edge, kNoIndex);
    EXPECT_EQ(content.edge_node_file_ids[edge], node);
    EXPECT_EQ(mesh.edge_node(edge), two_curved_triangles().nodes[node]);
  }
  EXPECT_TRUE(mesh.has_topology());
  EXPECT_EQ(mesh.neighbor(0, 0), 1);  // across the shared diagonal, opposite vertex 0
}

TEST(MeshAssembly, KeepsUnusedNodesOfP1FilesAsVertices) {
  RawMesh<2> raw;
  raw.nodes = {{{0, 0}}, {{5, 5}}, {{1, 0}}, {{0, 1}}};
  raw.element_nodes = {0, 2, 3};
  raw.element_refs = {1};
  MeshFileContent content = assemble_mesh(std::move(raw), "in.mesh");
  const auto& mesh = std::get<Mesh<2>>(content.mesh);
  EXPECT_EQ(mesh.vertex_count(), 4);
  EXPECT_EQ(mesh.element(0), (Mesh<2>::Element{0, 2, 3}));
  EXPECT_EQ(mesh.vertex_ref(1), 0);  // missing node refs default to 0
  EXPECT_FALSE(mesh.is_p2());
}

TEST(MeshAssembly, AcceptsP1FacetsInAP2Mesh) {
  RawMesh<2> raw = two_curved_triangles();
  raw.facet_nodes = {0, 1, /**/ 3, 2};
  raw.facet_refs = {1, 2};
  MeshFileContent content = assemble_mesh(std::move(raw), "in.mesh");
  const auto& mesh = std::get<Mesh<2>>(content.mesh);
  EXPECT_EQ(mesh.facet_count(), 2);
  EXPECT_EQ(mesh.edge_node(mesh.find_edge(0, 1)), (Vec2{{0.5, -0.1}}));  // the element's mid node
}

TEST(MeshAssembly, RefusesConflictingMidNodes) {
  RawMesh<2> raw = two_curved_triangles();
  raw.element_nodes[11] = 6;  // the second triangle's m20 is the diagonal: 6 instead of 5
  expect_error(std::move(raw), "TrianglesP2", "another mid node");
}

TEST(MeshAssembly, RefusesAFacetMidNodeOtherThanTheElements) {
  RawMesh<2> raw = two_curved_triangles();
  raw.facet_order = 2;
  raw.facet_nodes = {0, 1, 7};
  raw.facet_refs = {1};
  expect_error(std::move(raw), "EdgesP2", "another mid node");
}

TEST(MeshAssembly, RefusesANodeThatIsBothCornerAndMidNode) {
  RawMesh<2> raw = two_curved_triangles();
  raw.element_nodes[9] = 3;  // the second triangle's m01 is its own corner 3
  expect_error(std::move(raw), "TrianglesP2", "both a corner and a mid-edge node");
}

TEST(MeshAssembly, RefusesTaggingAMidNodeAsCorner) {
  RawMesh<2> raw = two_curved_triangles();
  raw.corners = {5};
  expect_error(std::move(raw), "Corners", "both a corner and a mid-edge node");
}

TEST(MeshAssembly, RefusesNodesOutOfRange) {
  RawMesh<2> raw = two_curved_triangles();
  raw.element_nodes[7] = 9;
  expect_error(std::move(raw), "TrianglesP2", "node 10 out of range in entity 2");
  RawMesh<2> negative = two_curved_triangles();
  negative.element_nodes[0] = -1;
  expect_error(std::move(negative), "TrianglesP2", "out of range in entity 1");
  RawMesh<2> required = two_curved_triangles();
  required.required_vertices = {42};
  expect_error(std::move(required), "RequiredVertices", "vertex 43 out of range");
}

TEST(MeshAssembly, RefusesIncompleteNodeLists) {
  RawMesh<2> raw = two_curved_triangles();
  raw.element_nodes.pop_back();
  expect_error(std::move(raw), "TrianglesP2", "incomplete node list");
}

TEST(MeshAssembly, RefusesRepeatedVerticesAndFacetsOffTheElements) {
  RawMesh<2> repeated = two_curved_triangles();
  repeated.element_nodes[2] = 1;
  expect_error(std::move(repeated), "TrianglesP2", "repeats a vertex");

  RawMesh<2> raw;
  raw.nodes = {{{0, 0}}, {{1, 0}}, {{0, 1}}, {{1, 1}}};
  raw.element_nodes = {0, 1, 2};
  raw.element_refs = {1};
  raw.facet_nodes = {1, 3};  // an edge no triangle has
  raw.facet_refs = {1};
  try {
    assemble_mesh(std::move(raw), "in.mesh");
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("in.mesh: "), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("not a face"), std::string::npos) << error.what();
  }
}

TEST(MeshAssembly, RefusesNonManifoldMeshes) {
  // Three triangles on one edge (0, 1).
  RawMesh<2> raw;
  raw.nodes = {{{0, 0}}, {{1, 0}}, {{0, 1}}, {{0, -1}}, {{1, 1}}};
  raw.element_nodes = {0, 1, 2, /**/ 1, 0, 3, /**/ 0, 1, 4};
  raw.element_refs = {1, 1, 1};
  try {
    assemble_mesh(std::move(raw), "in.mesh");
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(std::string(error.what()).rfind("in.mesh: non-manifold", 0), 0u) << error.what();
  }
}

TEST(MeshAssembly, RefusesRidgesNamingNoEdge) {
  RawMesh<2> raw = two_curved_triangles();
  raw.ridges = {0};  // there are no facets to name
  expect_error(std::move(raw), "Ridges", "names no edge");
}

TEST(MeshAssembly, RefusesAnEdgeWithoutMidNodeInAP2Mesh) {
  // Two P2 tetrahedra sharing face (0, 1, 2), and a P1 feature line (3, 4) that no element has.
  RawMesh<3> raw;
  raw.nodes = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}, {{0, 0, -1}}};
  for (int i = 0; i < 9; ++i) raw.nodes.push_back({{0.1 * i, 0.5, 0.5}});
  raw.order = 2;
  // v0 v1 v2 v3 m01 m12 m20 m03 m13 m23
  raw.element_nodes = {0, 1, 2, 3, 5, 6, 7, 8, 9, 10, /**/ 0, 2, 1, 4, 7, 6, 5, 11, 12, 13};
  raw.element_refs = {1, 1};
  raw.line_nodes = {3, 4};
  raw.line_refs = {1};
  raw.element_keyword = "TetrahedraP2";
  try {
    assemble_mesh(std::move(raw), "in.meshb");
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(std::string(error.what()).rfind("in.meshb: TetrahedraP2: no mid node given for edge", 0), 0u) << error.what();
  }
}

}  // namespace
}  // namespace hocav
