#include "io/gmsh_msh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <numeric>
#include <sstream>

#include "base/error.hpp"
#include "cases/structured.hpp"
#include "mesh/consistency.hpp"
#include "temporary_files.hpp"

namespace hocav {
namespace {

using testing_support::temporary_path;

std::string write_text(const std::string& name, const std::string& text) {
  std::string path = temporary_path(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The writer groups entities by ref (one Gmsh entity per ref), keeping mesh order within a ref.
template <typename RefOf>
std::vector<Index> order_by_ref(Index count, RefOf ref_of) {
  std::vector<Index> order(static_cast<std::size_t>(count));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return ref_of(a) < ref_of(b); });
  return order;
}

// Exact equality of everything .msh carries: coordinates, elements, facets, lines, corners, refs
// and P2 nodes (compared per element edge, since the edge table follows the element order).
template <int D>
void expect_msh_content(const Mesh<D>& original, const MeshFileContent& content) {
  ASSERT_TRUE(std::holds_alternative<Mesh<D>>(content.mesh));
  const Mesh<D>& read = std::get<Mesh<D>>(content.mesh);
  ASSERT_EQ(read.vertex_count(), original.vertex_count());
  for (Index v = 0; v < original.vertex_count(); ++v) {
    EXPECT_EQ(read.vertex(v), original.vertex(v)) << "vertex " << v;
    EXPECT_EQ(content.vertex_file_ids[v], v);
  }
  ASSERT_EQ(read.order(), original.order());
  ASSERT_EQ(read.element_count(), original.element_count());
  auto elements = order_by_ref(original.element_count(), [&](Index k) { return original.element_ref(k); });
  for (Index k = 0; k < read.element_count(); ++k) {
    Index source = elements[k];
    ASSERT_EQ(read.element(k), original.element(source)) << "element " << k;
    EXPECT_EQ(read.element_ref(k), original.element_ref(source));
    for (int e = 0; original.is_p2() && e < Simplex<D>::kEdges; ++e)
      EXPECT_EQ(read.edge_node(read.element_edge(k, e)), original.edge_node(original.element_edge(source, e)));
  }
  ASSERT_EQ(read.facet_count(), original.facet_count());
  auto facets = order_by_ref(original.facet_count(), [&](Index f) { return original.facet_ref(f); });
  for (Index f = 0; f < read.facet_count(); ++f) {
    EXPECT_EQ(read.facet(f), original.facet(facets[f])) << "facet " << f;
    EXPECT_EQ(read.facet_ref(f), original.facet_ref(facets[f]));
  }
  ASSERT_EQ(read.line_count(), original.line_count());
  auto lines = order_by_ref(original.line_count(), [&](Index l) { return original.line_ref(l); });
  for (Index l = 0; l < read.line_count(); ++l) {
    EXPECT_EQ(read.line(l), original.line(lines[l])) << "line " << l;
    EXPECT_EQ(read.line_ref(l), original.line_ref(lines[l]));
  }
  EXPECT_EQ(read.corners(), original.corners());
  if (original.is_p2()) {
    // The file numbers edge nodes after the vertices, in the written mesh's edge order.
    ASSERT_EQ(content.file_node_count, original.vertex_count() + original.edge_count());
    for (Index e = 0; e < read.edge_count(); ++e)
      EXPECT_EQ(read.edge_node(e), original.edge_node(content.edge_node_file_ids[e] - original.vertex_count()));
  }
  EXPECT_EQ(check_consistency(read, {.require_positive_orientation = !read.is_p2()}), std::vector<std::string>{});
}

// Moves every P2 node off its straight midpoint by a small, edge-dependent amount.
template <int D>
void curve(Mesh<D>& mesh) {
  mesh.make_p2();
  for (Index e = 0; e < mesh.edge_count(); ++e)
    for (int c = 0; c < D; ++c) mesh.edge_node(e)[c] += 0.01 * std::sin(1.7 * e + c) / 3.0;
}

template <int D>
void expect_round_trip(const Mesh<D>& mesh, const std::string& name) {
  std::string path = temporary_path(name + ".msh");
  write_gmsh_msh(path, mesh);
  MeshFileContent content = read_gmsh_msh(path);
  expect_msh_content(mesh, content);
  EXPECT_EQ(gmsh_msh_dimension(path), D);
  // Once grouped by ref (as any mesh read from .msh is), a mesh goes through .msh byte for byte.
  std::string again = temporary_path(name + "_again.msh"), third = temporary_path(name + "_third.msh");
  write_gmsh_msh(again, std::get<Mesh<D>>(content.mesh));
  write_gmsh_msh(third, std::get<Mesh<D>>(read_gmsh_msh(again).mesh));
  EXPECT_EQ(read_text(third), read_text(again));
}

TEST(GmshMsh, RoundTripsStraightCube) { expect_round_trip(generate_cube(2), "cube_p1"); }

TEST(GmshMsh, RoundTripsCurvedCube) {
  Mesh<3> mesh = generate_cube(3);
  curve(mesh);
  expect_round_trip(mesh, "cube_p2");
}

TEST(GmshMsh, RoundTripsStraightSquare) { expect_round_trip(generate_square(3), "square_p1"); }

TEST(GmshMsh, RoundTripsCurvedSquare) {
  Mesh<2> mesh = generate_square(4);
  curve(mesh);
  expect_round_trip(mesh, "square_p2");
}

// Interleaved, zero and negative refs, and coordinates that need all 17 digits.
TEST(GmshMsh, RoundTripsMixedRefsAndUglyReals) {
  Mesh<3> cube = generate_cube(2);
  Mesh<3> mesh;
  for (Index v = 0; v < cube.vertex_count(); ++v)
    mesh.add_vertex(cube.vertex(v) * (1.0 / 3.0) + Vec3{{1e-3 / 7, std::numbers::pi, -2e5 / 3}});
  for (Index k = 0; k < cube.element_count(); ++k) mesh.add_element(cube.element(k), static_cast<int>(k % 3) - 1);
  for (Index f = 0; f < cube.facet_count(); ++f) mesh.add_facet(cube.facet(f), cube.facet_ref(f) * (f % 2 == 0 ? 1 : -100));
  for (Index l = 0; l < cube.line_count(); ++l) mesh.add_line(cube.line(l), static_cast<int>(l % 4));
  mesh.corners() = cube.corners();
  mesh.build_topology();
  curve(mesh);
  expect_round_trip(mesh, "mixed_refs");
}

// Node tags sparse and out of order, a parametric node block, physical tags from $Entities (the
// volume's second physical tag is ignored; the curve has none, so its tag is the ref), quoted
// physical names with spaces, and sections hocav does not use.
const char* const kHandWrittenTet10 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Comments
anything at all $Nodes 1 2 3
$EndComments
$PhysicalNames
2
3 70 "the ball"
2 30 "outer skin"
$EndPhysicalNames
$Entities
1 1 1 1
4 0 0 0 1 5
8 0 0 0 1 0 0 0 0
6 0 0 0 1 1 1 1 30 0
9 0 0 0 1 1 1 2 70 71 1 6
$EndEntities
$Nodes
2 10 3 1000
3 9 0 7
1000
40
7
3
500
60
61
0 0 0
1 0 0
0 1 0
0 0 1
0.5 0 0.1
0.5 0.5 0.1
0 0.5 0.1
2 6 1 3
62
63
64
0 0 0.5 0.1 0.2
0.5 0 0.5 0.3 0.4
0 0.5 0.5 0.5 0.6
$EndNodes
$Elements
4 4 1 4
0 4 15 1
1 1000
1 8 8 1
2 1000 40 500
2 6 9 1
3 1000 7 40 61 60 500
3 9 11 1
4 1000 40 7 3 500 60 61 62 64 63
$EndElements
$NodeData
1
"unused"
$EndNodeData
)";

TEST(GmshMsh, ReadsSparseTagsEntitiesAndSkipsUnknownSections) {
  std::string path = write_text("hand.msh", kHandWrittenTet10);
  testing::internal::CaptureStderr();
  MeshFileContent content = read_gmsh_msh(path);
  std::string warnings = testing::internal::GetCapturedStderr();
  EXPECT_NE(warnings.find("$Comments"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("$NodeData"), std::string::npos) << warnings;
  EXPECT_EQ(warnings.find("$PhysicalNames"), std::string::npos) << warnings;

  const Mesh<3>& mesh = std::get<Mesh<3>>(content.mesh);
  ASSERT_EQ(mesh.vertex_count(), 4);
  EXPECT_EQ(mesh.vertex(1), (Vec3{{1, 0, 0}}));
  EXPECT_EQ(content.vertex_file_ids, (std::vector<Index>{0, 1, 2, 3}));
  ASSERT_EQ(mesh.element_count(), 1);
  EXPECT_EQ(mesh.element(0), (Mesh<3>::Element{0, 1, 2, 3}));
  EXPECT_EQ(mesh.element_ref(0), 70);
  ASSERT_TRUE(mesh.is_p2());
  // Gmsh lists m23 (tag 64) before m13 (tag 63).
  EXPECT_EQ(mesh.edge_node(mesh.find_edge(1, 3)), (Vec3{{0.5, 0, 0.5}}));
  EXPECT_EQ(mesh.edge_node(mesh.find_edge(2, 3)), (Vec3{{0, 0.5, 0.5}}));
  EXPECT_EQ(mesh.edge_node(mesh.find_edge(0, 1)), (Vec3{{0.5, 0, 0.1}}));
  EXPECT_EQ(content.file_node_count, 10);
  EXPECT_EQ(content.edge_node_file_ids[mesh.find_edge(2, 3)], 9);
  ASSERT_EQ(mesh.facet_count(), 1);
  EXPECT_EQ(mesh.facet(0), (Mesh<3>::Facet{0, 2, 1}));
  EXPECT_EQ(mesh.facet_ref(0), 30);
  ASSERT_EQ(mesh.line_count(), 1);
  EXPECT_EQ(mesh.line_ref(0), 8);
  EXPECT_EQ(mesh.corners(), std::vector<Index>{0});
  EXPECT_EQ(mesh.vertex_ref(0), 5);
  EXPECT_EQ(gmsh_msh_dimension(path), 3);
}

// Without $Entities the ref of an element is its entity tag; nodes at z = 0 make a 2D mesh.
TEST(GmshMsh, ReadsMinimalTwoDimensionalFile) {
  std::string path = write_text("minimal2d.msh", R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Nodes
1 4 1 4
2 1 0 4
1
2
3
4
0 0 0
1 0 0
1 1 0
0 1 0
$EndNodes
$Elements
2 3 1 3
2 5 2 2
1 1 2 3
2 1 3 4
1 3 1 1
3 1 2
$EndElements
)");
  MeshFileContent content = read_gmsh_msh(path);
  const Mesh<2>& mesh = std::get<Mesh<2>>(content.mesh);
  EXPECT_EQ(mesh.vertex_count(), 4);
  EXPECT_EQ(mesh.element_count(), 2);
  EXPECT_EQ(mesh.element_ref(1), 5);
  ASSERT_EQ(mesh.facet_count(), 1);
  EXPECT_EQ(mesh.facet_ref(0), 3);
  EXPECT_FALSE(mesh.is_p2());
  EXPECT_EQ(gmsh_msh_dimension(path), 2);
}

// A 3D file around `elements` (an $Elements body) with four nodes of the unit tetrahedron and
// six mid nodes (tags 5-10).
std::string tet_file(const std::string& elements, const std::string& nodes_header = "1 10 1 10\n3 1 0 10") {
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n" + nodes_header +
         "\n1\n2\n3\n4\n5\n6\n7\n8\n9\n10\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
         ".5 0 0\n.5 .5 0\n0 .5 0\n0 0 .5\n.5 0 .5\n0 .5 .5\n$EndNodes\n$Elements\n" +
         elements + "\n$EndElements\n";
}

struct BadInput {
  const char* name;
  std::string text;
  std::vector<std::string> expected;  // parts of the message besides the file name
};

TEST(GmshMsh, RefusesBadInputWithClearMessages) {
  const std::string tet4 = "1 1 1 1\n3 1 4 1\n1 1 2 3 4";
  const std::vector<BadInput> cases = {
      {"empty", "", {"$MeshFormat", "not a Gmsh .msh file"}},
      {"not_msh", "MeshVersionFormatted 2\nDimension 3\n", {"$MeshFormat", "not a Gmsh .msh file", "line 1"}},
      {"version22", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", {"$MeshFormat", "version '2.2' is not supported", "msh41"}},
      {"binary",
       "$MeshFormat\n4.1 1 8\n\x01\x00\x00\x00\n$EndMeshFormat\n",
       {"$MeshFormat", "binary .msh is not supported", "-format msh41"}},
      {"truncated_nodes", tet_file(tet4).substr(0, 90), {"$Nodes", "unexpected end of file"}},
      {"truncated_elements", tet_file(tet4).substr(0, tet_file(tet4).size() - 25), {"$Elements", "unexpected end of file"}},
      {"no_end_nodes",
       "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1 1 1\n0 1 0 1\n1\n0 0 0\n$Elements\n",
       {"$Nodes", "expected $EndNodes, found '$Elements'", "line 9"}},
      {"node_count", tet_file(tet4, "1 11 1 10\n3 1 0 10"), {"$Nodes", "announces 11 nodes, the blocks hold 10"}},
      {"duplicate_tag",
       tet_file(tet4, "1 10 1 10\n3 1 0 10").replace(tet_file(tet4).find("\n2\n"), 3, "\n1\n"),
       {"$Nodes", "node tag 1 is defined twice", "line 8"}},
      {"undefined_tag", tet_file("1 1 1 1\n3 1 4 1\n1 1 2 3 99"), {"$Elements", "node tag 99 is not defined", "line 31"}},
      {"zero_tag", tet_file("1 1 1 1\n3 1 4 1\n1 1 2 3 0"), {"$Elements", "node tag 0 is not defined"}},
      {"element_count", tet_file("1 2 1 1\n3 1 4 1\n1 1 2 3 4"), {"$Elements", "announces 2 elements, the blocks hold 1"}},
      {"negative_count", tet_file("1 1 1 1\n3 1 4 -1"), {"$Elements", "negative count -1"}},
      {"quadrangle", tet_file("1 1 1 1\n2 1 3 1\n1 1 2 3 4"), {"$Elements", "element type 3 (quadrangle) is not supported", "11 tet10"}},
      {"unknown_type", tet_file("1 1 1 1\n2 1 777 1\n1 1 2 3 4"), {"$Elements", "element type 777 (unknown)"}},
      {"type_dimension", tet_file("1 1 1 1\n2 1 4 1\n1 1 2 3 4"), {"$Elements", "tet4 elements in a block of dimension 2"}},
      {"mixed_orders", tet_file("2 2 1 2\n3 1 4 1\n1 1 2 3 4\n3 2 11 1\n2 1 2 3 4 5 6 7 8 10 9"), {"$Elements", "mixes tet4 and tet10"}},
      {"p2_facet_in_p1",
       tet_file("2 2 1 2\n3 1 4 1\n1 1 2 3 4\n2 1 9 1\n2 1 3 2 7 6 5"),
       {"$Elements (tri6)", "P2 elements of lower dimension in a P1 mesh"}},
      {"facet_not_a_face", tet_file("2 2 1 2\n3 1 4 1\n1 1 2 3 4\n2 1 2 1\n2 1 2 5"), {"not a face"}},
      {"mid_node_conflict",
       tet_file("2 2 1 2\n3 1 11 1\n1 1 2 3 4 5 6 7 8 10 9\n1 1 8 1\n2 1 2 9"),
       {"$Elements (line3)", "another mid node"}},
      {"only_lines", tet_file("1 1 1 1\n1 1 1 1\n1 1 2"), {"$Elements", "no triangles or tetrahedra"}},
      {"surface_mesh", tet_file("1 1 1 1\n2 1 2 1\n1 1 2 4"), {"$Nodes", "surface mesh", "not support", "line 20"}},
      {"elements_first", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Elements\n0 0 0 0\n$EndElements\n", {"$Elements", "comes before $Nodes"}},
      {"no_elements", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n0 0 0 0\n$EndNodes\n", {"no $Elements section"}},
      {"unterminated_section", tet_file(tet4) + "$Periodic\n1 2 3\n", {"$Periodic", "no $EndPeriodic"}},
      {"stray_token", tet_file(tet4) + "garbage\n", {"expected a section such as $Nodes, found 'garbage'"}},
      {"not_a_real", tet_file(tet4).replace(tet_file(tet4).find(".5 .5 0"), 7, ".5 x 0"), {"$Nodes", "expected a real, found 'x'"}},
      {"nan", tet_file(tet4).replace(tet_file(tet4).find(".5 .5 0"), 7, ".5 nan 0"), {"$Nodes", "not finite"}},
      {"entities_counts", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n1 0 0 0\n1 0 0\n", {"$Entities", "unexpected end of file"}},
      {"huge_node_count",
       "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4000000000000000000 1 1\n0 1 0 4000000000000000000\n1\n",
       {"$Nodes", "unexpected end of file"}},
      {"huge_element_count",
       tet_file("1 1 1 1\n3 1 11 4000000000000000000\n1 1 2 3 4"),
       {"$Elements", "expected an integer, found '$EndElements'"}},
      {"parametric_flag", tet_file(tet4, "1 10 1 10\n3 1 7 10"), {"$Nodes", "parametric flag"}},
  };
  testing::internal::CaptureStderr();
  for (const BadInput& bad : cases) {
    std::string path = write_text(std::string(bad.name) + ".msh", bad.text);
    try {
      read_gmsh_msh(path);
      ADD_FAILURE() << bad.name << ": no error";
    } catch (const Error& error) {
      std::string message = error.what();
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << bad.name << ": " << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << bad.name << ": " << message;
      for (const std::string& part : bad.expected) EXPECT_NE(message.find(part), std::string::npos) << bad.name << ": " << message;
    }
  }
  testing::internal::GetCapturedStderr();
}

TEST(GmshMsh, DimensionOfASurfaceMeshIsAnError) {
  std::string path = write_text("surface.msh", tet_file("1 1 1 1\n2 1 2 1\n1 1 2 4"));
  EXPECT_THROW(gmsh_msh_dimension(path), Error);
  EXPECT_THROW(gmsh_msh_dimension(temporary_path("does_not_exist.msh")), Error);
}

TEST(GmshMsh, FailedWriteLeavesNoFile) {
  std::string path = temporary_path("no_such_directory/out.msh");
  EXPECT_THROW(write_gmsh_msh(path, generate_square(1)), Error);
  EXPECT_FALSE(std::ifstream(path).good());
}

}  // namespace
}  // namespace hocav
