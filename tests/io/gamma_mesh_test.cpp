#include "io/gamma_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <filesystem>
#include <limits>

#include "base/error.hpp"
#include "cases/structured.hpp"
#include "gamma_test_support.hpp"
#include "shared_data.hpp"

namespace hocav {
namespace {

using testing_support::GammaBinaryBuilder;
using testing_support::read_file;
using testing_support::temporary_path;
using testing_support::write_file;

// ---- meshes to write ----

// A copy with refs that differ from entity to entity (a negative one too), required vertices and
// (in 2D) ridges, so a round trip that drops or shuffles any of them fails.
template <int D>
Mesh<D> with_varied_tags(const Mesh<D>& mesh) {
  Mesh<D> copy;
  for (Index v = 0; v < mesh.vertex_count(); ++v) copy.add_vertex(mesh.vertex(v), v == 3 ? -7 : v % 5);
  for (Index k = 0; k < mesh.element_count(); ++k) copy.add_element(mesh.element(k), k % 3 + 1);
  for (Index f = 0; f < mesh.facet_count(); ++f) copy.add_facet(mesh.facet(f), mesh.facet_ref(f) * 10 + f % 2);
  if constexpr (D == 3)
    for (Index l = 0; l < mesh.line_count(); ++l) copy.add_line(mesh.line(l), l % 4);
  copy.corners() = mesh.corners();
  copy.ridges() = D == 2 ? std::vector<Index>{0, 2, 5} : mesh.ridges();
  copy.required_vertices() = {1, 4, 2};
  copy.required_edges() = D == 2 ? std::vector<Index>{3, 1} : std::vector<Index>{mesh.line_count() - 1, 0};
  if constexpr (D == 3) copy.required_triangles() = {2, 7, 0};
  copy.build_topology();
  return copy;
}

// P2 with every edge node moved off its midpoint by an amount that needs all 17 digits.
template <int D>
Mesh<D> curved(Mesh<D> mesh) {
  mesh.make_p2();
  for (Index e = 0; e < mesh.edge_count(); ++e)
    for (int i = 0; i < D; ++i) mesh.edge_node(e)[i] += 0.01 * std::sin(1.7 * e + i + 0.3);
  return mesh;
}

// ---- comparison ----

std::uint64_t bits(double value) { return std::bit_cast<std::uint64_t>(value); }

// Bit-exact equality of everything a Gamma file carries; `single_precision`: coordinates as the
// float32 reals of version 1 hold them. Edge nodes must carry the file ids of `expected_file`'s
// nodes when it is given (two files listing the same nodes), else hocav's writer numbering
// (vertices, then edge nodes in edge order).
template <int D>
void expect_same_mesh(const Mesh<D>& expected, const MeshFileContent& content, bool single_precision = false,
                      const MeshFileContent* expected_file = nullptr) {
  ASSERT_TRUE(std::holds_alternative<Mesh<D>>(content.mesh));
  const Mesh<D>& actual = std::get<Mesh<D>>(content.mesh);
  auto expect_same_point = [&](const Vec<D>& want, const Vec<D>& got, const char* what, Index id) {
    for (int i = 0; i < D; ++i) {
      double wanted = single_precision ? static_cast<double>(static_cast<float>(want[i])) : want[i];
      EXPECT_EQ(bits(got[i]), bits(wanted)) << what << " " << id << " coordinate " << i << ": " << got[i] << " vs " << wanted;
    }
  };
  ASSERT_EQ(actual.vertex_count(), expected.vertex_count());
  for (Index v = 0; v < expected.vertex_count(); ++v) {
    expect_same_point(expected.vertex(v), actual.vertex(v), "vertex", v);
    EXPECT_EQ(actual.vertex_ref(v), expected.vertex_ref(v)) << "vertex " << v;
    EXPECT_EQ(content.vertex_file_ids[v], v);
  }
  ASSERT_EQ(actual.element_count(), expected.element_count());
  for (Index k = 0; k < expected.element_count(); ++k) {
    EXPECT_EQ(actual.element(k), expected.element(k)) << "element " << k;
    EXPECT_EQ(actual.element_ref(k), expected.element_ref(k)) << "element " << k;
  }
  ASSERT_EQ(actual.facet_count(), expected.facet_count());
  for (Index f = 0; f < expected.facet_count(); ++f) {
    EXPECT_EQ(actual.facet(f), expected.facet(f)) << "facet " << f;
    EXPECT_EQ(actual.facet_ref(f), expected.facet_ref(f)) << "facet " << f;
  }
  ASSERT_EQ(actual.line_count(), expected.line_count());
  for (Index l = 0; l < expected.line_count(); ++l) {
    EXPECT_EQ(actual.line(l), expected.line(l)) << "line " << l;
    EXPECT_EQ(actual.line_ref(l), expected.line_ref(l)) << "line " << l;
  }
  EXPECT_EQ(actual.corners(), expected.corners());
  EXPECT_EQ(actual.ridges(), expected.ridges());
  EXPECT_EQ(actual.required_vertices(), expected.required_vertices());
  EXPECT_EQ(actual.required_edges(), expected.required_edges());
  EXPECT_EQ(actual.required_triangles(), expected.required_triangles());
  ASSERT_EQ(actual.order(), expected.order());
  if (!expected.is_p2()) {
    EXPECT_TRUE(content.edge_node_file_ids.empty());
    EXPECT_EQ(content.file_node_count, expected.vertex_count());
    return;
  }
  ASSERT_EQ(actual.edge_count(), expected.edge_count());
  EXPECT_EQ(content.file_node_count, expected.vertex_count() + expected.edge_count());
  // Per element edge, so the test does not depend on how the edge table is numbered.
  for (Index k = 0; k < expected.element_count(); ++k)
    for (int e = 0; e < Mesh<D>::kElementEdges; ++e) {
      Index edge = actual.element_edge(k, e);
      expect_same_point(expected.edge_node(expected.element_edge(k, e)), actual.edge_node(edge), "element edge", k);
      Index expected_edge = expected.element_edge(k, e);
      EXPECT_EQ(content.edge_node_file_ids[edge],
                expected_file ? expected_file->edge_node_file_ids[expected_edge] : expected.vertex_count() + expected_edge);
    }
}

struct Format {
  const char* extension;
  bool binary;
  int version;
};

constexpr Format kFormats[] = {{".mesh", false, 0}, {".meshb", true, 1}, {".meshb", true, 2}, {".meshb", true, 3}, {".meshb", true, 4}};

template <int D>
void expect_round_trips(const Mesh<D>& mesh, const std::string& name) {
  for (const Format& format : kFormats) {
    SCOPED_TRACE(std::string(format.extension) + " version " + std::to_string(format.version));
    std::string path = temporary_path(name + "_v" + std::to_string(format.version) + format.extension);
    write_gamma_mesh(path, mesh, format.binary, format.version);
    EXPECT_EQ(gamma_mesh_dimension(path), D);
    expect_same_mesh(mesh, read_gamma_mesh(path), format.version == 1);
  }
}

TEST(GammaMesh, RoundTripsSquareP1) { expect_round_trips(with_varied_tags(generate_square(3)), "square_p1"); }

TEST(GammaMesh, RoundTripsCurvedSquareP2) { expect_round_trips(curved(with_varied_tags(generate_square(3))), "square_p2"); }

TEST(GammaMesh, RoundTripsCubeP1) { expect_round_trips(with_varied_tags(generate_cube(2)), "cube_p1"); }

TEST(GammaMesh, RoundTripsCurvedCubeP2) { expect_round_trips(curved(with_varied_tags(generate_cube(2))), "cube_p2"); }

// ---- reading in slices ----

// Slices 0..count-1 of every format, put end to end, are the whole file: the same points, elements,
// facets and refs in file order, each slice starting where slice_start says; lines and tags whole.
template <int D>
void expect_slices_make_the_file(const Mesh<D>& mesh, const std::string& name) {
  for (const Format& format : kFormats) {
    const std::string path = temporary_path(name + "_slices_v" + std::to_string(format.version) + format.extension);
    write_gamma_mesh(path, mesh, format.binary, format.version);
    const Mesh<D> whole = std::get<Mesh<D>>(read_gamma_mesh(path).mesh);
    for (int count : {1, 3, 7}) {
      SCOPED_TRACE(std::string(format.extension) + " version " + std::to_string(format.version) + ", " + std::to_string(count) + " slices");
      std::vector<Vec<D>> points;
      std::vector<typename Mesh<D>::Element> elements;
      std::vector<typename Mesh<D>::Facet> facets;
      std::vector<int> refs;
      for (int index = 0; index < count; ++index) {
        const GammaMeshSlice<D> slice = read_gamma_mesh_slice<D>(path, index, count);
        EXPECT_EQ(slice.vertex_count, whole.vertex_count());
        EXPECT_EQ(slice.first_vertex, static_cast<Index>(points.size()));
        EXPECT_EQ(slice.first_element, slice_start(whole.element_count(), index, count));
        EXPECT_EQ(slice.first_facet, static_cast<Index>(facets.size()));
        points.insert(points.end(), slice.points.begin(), slice.points.end());
        elements.insert(elements.end(), slice.elements.begin(), slice.elements.end());
        facets.insert(facets.end(), slice.facets.begin(), slice.facets.end());
        refs.insert(refs.end(), slice.element_refs.begin(), slice.element_refs.end());
        EXPECT_EQ(static_cast<Index>(slice.lines.size()), whole.line_count());
        EXPECT_EQ(slice.required_vertices, whole.required_vertices());
        EXPECT_EQ(slice.ridges, whole.ridges());
      }
      ASSERT_EQ(points.size(), static_cast<std::size_t>(whole.vertex_count()));
      for (Index v = 0; v < whole.vertex_count(); ++v) EXPECT_EQ(points[v], whole.vertex(v)) << "vertex " << v;
      ASSERT_EQ(elements.size(), static_cast<std::size_t>(whole.element_count()));
      for (Index k = 0; k < whole.element_count(); ++k) {
        EXPECT_EQ(elements[k], whole.element(k)) << "element " << k;
        EXPECT_EQ(refs[k], whole.element_ref(k)) << "element " << k;
      }
      ASSERT_EQ(facets.size(), static_cast<std::size_t>(whole.facet_count()));
      for (Index f = 0; f < whole.facet_count(); ++f) EXPECT_EQ(facets[f], whole.facet(f)) << "facet " << f;
    }
  }
}

TEST(GammaMeshSlice, SlicesOfASquarePutEndToEndAreTheFile) { expect_slices_make_the_file(with_varied_tags(generate_square(4)), "square"); }

TEST(GammaMeshSlice, SlicesOfACubePutEndToEndAreTheFile) { expect_slices_make_the_file(with_varied_tags(generate_cube(3)), "cube"); }

TEST(GammaMeshSlice, EachEntityIsInTheSliceThatHoldsIt) {
  for (Index total : {0, 1, 2, 5, 100, 1001})
    for (int count : {1, 2, 3, 7})
      for (Index id = 0; id < total; ++id) {
        const int slice = slice_holding(id, total, count);
        EXPECT_LE(slice_start(total, slice, count), id) << total << " in " << count;
        EXPECT_LT(id, slice_start(total, slice + 1, count)) << total << " in " << count;
      }
}

// What a distributed curving asks before it reads a file in pieces: whether read_gamma_mesh_slice
// would refuse it for its P2 entities.
TEST(GammaMeshSlice, TellsAP2FileFromAP1File) {
  for (bool binary : {true, false}) {
    const std::string extension = binary ? ".meshb" : ".mesh";
    const std::string p1 = temporary_path("order_p1" + extension), p2 = temporary_path("order_p2" + extension),
                      square = temporary_path("order_square_p2" + extension);
    write_gamma_mesh(p1, with_varied_tags(generate_cube(2)), binary);
    write_gamma_mesh(p2, curved(generate_cube(1)), binary);
    write_gamma_mesh(square, curved(generate_square(2)), binary);
    EXPECT_FALSE(gamma_mesh_has_p2_keyword(p1)) << extension;
    EXPECT_TRUE(gamma_mesh_has_p2_keyword(p2)) << extension;
    EXPECT_TRUE(gamma_mesh_has_p2_keyword(square)) << extension;
  }
}

TEST(GammaMeshSlice, RefusesP2OutOfRangeAndOtherDimensions) {
  const std::string p2 = temporary_path("slice_p2.meshb");
  write_gamma_mesh(p2, curved(generate_cube(1)), true);
  EXPECT_THROW(
      {
        try {
          read_gamma_mesh_slice<3>(p2, 0, 2);
        } catch (const Error& error) {
          EXPECT_NE(std::string(error.what()).find("P2: a distributed run reads P1 meshes in pieces"), std::string::npos) << error.what();
          throw;
        }
      },
      Error);
  const std::string square = temporary_path("slice_square.mesh");
  write_gamma_mesh(square, generate_square(2), false);
  EXPECT_THROW(read_gamma_mesh_slice<3>(square, 0, 1), Error);
  const std::string bad = write_file("slice_bad.mesh",
                                     "MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\n"
                                     "Triangles\n2\n1 2 3 0\n1 2 4 0\nEnd\n");
  for (int index : {0, 1}) try {
      read_gamma_mesh_slice<2>(bad, index, 2);
      EXPECT_EQ(index, 0) << "slice 1 holds the triangle with vertex 4";
    } catch (const Error& error) {
      EXPECT_EQ(index, 1);
      EXPECT_EQ(std::string(error.what()), bad + ": Triangles: vertex 4 out of range, entity 2");
    }
}

// An element that repeats a vertex: refused by the slice that holds it in the whole file reader's
// words, and by no other.
TEST(GammaMeshSlice, RefusesAnElementThatRepeatsAVertexAsTheWholeFileReaderDoes) {
  const std::string bad = write_file("slice_repeats.mesh",
                                     "MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
                                     "Triangles\n3\n1 2 3 0\n2 4 3 0\n2 4 2 0\nEnd\n");
  std::string whole;
  try {
    read_gamma_mesh(bad);
  } catch (const Error& error) {
    whole = error.what();
  }
  EXPECT_EQ(whole, bad + ": Triangles: repeats a vertex in element 3");
  for (int index : {0, 1, 2}) try {
      read_gamma_mesh_slice<2>(bad, index, 3);
      EXPECT_NE(index, 2) << "slice 2 holds triangle 3";
    } catch (const Error& error) {
      EXPECT_EQ(index, 2);
      EXPECT_EQ(std::string(error.what()), whole);
    }
}

TEST(GammaMesh, VersionOneKeepsOnlyFloatPrecision) {
  // The reason version 1 is compared to float precision above: a coordinate that needs a double
  // does not survive it, while it survives every later version.
  Mesh<2> mesh = generate_square(1);
  mesh.vertex(3)[0] = 0.1;
  std::string path = temporary_path("float.meshb");
  write_gamma_mesh(path, mesh, true, 1);
  MeshFileContent content = read_gamma_mesh(path);
  const auto& read = std::get<Mesh<2>>(content.mesh);
  EXPECT_NE(read.vertex(3)[0], 0.1);
  EXPECT_EQ(read.vertex(3)[0], static_cast<double>(0.1f));
}

// ---- third-party files ----

const std::string kTorus = testing_support::shared_data_path("mmg-torus/torus.mesh");
const std::string kLinear = testing_support::shared_data_path("ugawg-linear/linear.mesh");

TEST(GammaMesh, ReadsMmgTorusAndSkipsItsNormalsOnceEach) {
  if (auto missing = testing_support::missing_shared_data({kTorus}); !missing.empty()) GTEST_SKIP() << missing;
  ::testing::internal::CaptureStderr();
  MeshFileContent content = read_gamma_mesh(kTorus);
  std::string warnings = ::testing::internal::GetCapturedStderr();
  const auto& mesh = std::get<Mesh<3>>(content.mesh);
  EXPECT_EQ(mesh.vertex_count(), 4351);
  EXPECT_EQ(mesh.element_count(), 20067);
  EXPECT_EQ(mesh.facet_count(), 2954);
  EXPECT_EQ(mesh.line_count(), 94);
  EXPECT_EQ(mesh.ridges().size(), 94u);
  EXPECT_FALSE(mesh.is_p2());
  EXPECT_EQ(content.file_node_count, 4351);
  for (const char* skipped : {"Normals", "NormalAtVertices", "Tangents", "TangentAtVertices"}) {
    std::string line = std::string("skipping keyword ") + skipped + " ";
    auto first = warnings.find(line);
    EXPECT_NE(first, std::string::npos) << skipped;
    EXPECT_EQ(warnings.find(line, first + 1), std::string::npos) << skipped;
  }
  EXPECT_EQ(gamma_mesh_dimension(kTorus), 3);
}

TEST(GammaMesh, ReadsUgawgLinearAndRoundTripsIt) {
  if (auto missing = testing_support::missing_shared_data({kLinear}); !missing.empty()) GTEST_SKIP() << missing;
  ::testing::internal::CaptureStderr();
  MeshFileContent content = read_gamma_mesh(kLinear);
  ::testing::internal::GetCapturedStderr();
  const auto& mesh = std::get<Mesh<3>>(content.mesh);
  EXPECT_EQ(mesh.vertex_count(), 9476);
  EXPECT_EQ(mesh.element_count(), 48720);
  EXPECT_EQ(mesh.facet_count(), 5112);
  EXPECT_EQ(mesh.line_count(), 261);
  EXPECT_EQ(mesh.corners().size(), 8u);
  EXPECT_EQ(mesh.ridges().size(), 261u);
  EXPECT_EQ(mesh.vertex(1)[0], 0.210322003134042);  // the second line of Vertices, to the last digit
  for (const Format& format : {kFormats[0], kFormats[3]}) {
    std::string path = temporary_path(std::string("linear") + format.extension);
    write_gamma_mesh(path, mesh, format.binary, format.version);
    expect_same_mesh(mesh, read_gamma_mesh(path));
  }
}

// ---- P2 node orderings ----

const std::string kTriangleVertices =
    "MeshVersionFormatted 2\nDimension 2\nVertices\n6\n0 0 1\n1 0 2\n0 1 3\n0.5 -0.1 0\n0.6 0.6 0\n-0.1 0.5 0\n";

TEST(GammaMesh, HonoursTriangleAndEdgeOrderings) {
  std::string in_local_order = kTriangleVertices + "TrianglesP2\n1\n1 2 3 4 5 6 9\nEdgesP2\n1\n1 2 4 5\nEnd\n";
  // File order: m01 v2 v0 m12 v1 m20 for the triangle, mid v1 v0 for the edge (one integer per
  // edge node, the weight of the first vertex, as libMeshb defines EdgesP2Ordering).
  std::string permuted = kTriangleVertices +
                         "TrianglesP2Ordering\n6\n1 1 0\n0 0 2\n2 0 0\n0 1 1\n0 2 0\n1 0 1\n"
                         "TrianglesP2\n1\n4 3 1 5 2 6 9\n"
                         "EdgesP2Ordering\n3\n1\n0\n2\nEdgesP2\n1\n4 2 1 5\nEnd\n";
  MeshFileContent expected = read_gamma_mesh(write_file("triangle_local.mesh", in_local_order));
  MeshFileContent actual = read_gamma_mesh(write_file("triangle_permuted.mesh", permuted));
  const auto& mesh = std::get<Mesh<2>>(expected.mesh);
  ASSERT_TRUE(mesh.is_p2());
  EXPECT_EQ(mesh.edge_node(mesh.find_edge(0, 1)), (Vec2{{0.5, -0.1}}));
  EXPECT_EQ(mesh.edge_node(mesh.find_edge(1, 2)), (Vec2{{0.6, 0.6}}));
  expect_same_mesh(mesh, actual, false, &expected);
}

TEST(GammaMesh, HonoursTetrahedronOrderingGivenAfterTheElements) {
  std::string vertices =
      "MeshVersionFormatted 2\nDimension 3\nVertices\n10\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
      "0.5 -0.1 0 0\n0.5 0.6 0 0\n-0.1 0.5 0 0\n0 0.1 0.5 0\n0.6 0 0.5 0\n0 0.5 0.6 0\n";
  std::string in_local_order = vertices + "TetrahedraP2\n1\n1 2 3 4 5 6 7 8 9 10 3\nEnd\n";
  // Every node listed in reverse: m23 m13 m03 m20 m12 m01 v3 v2 v1 v0.
  std::string permuted = vertices +
                         "TetrahedraP2\n1\n10 9 8 7 6 5 4 3 2 1 3\n"
                         "TetrahedraP2Ordering\n10\n0 0 1 1\n0 1 0 1\n1 0 0 1\n1 0 1 0\n0 1 1 0\n1 1 0 0\n"
                         "0 0 0 2\n0 0 2 0\n0 2 0 0\n2 0 0 0\nEnd\n";
  MeshFileContent expected = read_gamma_mesh(write_file("tet_local.mesh", in_local_order));
  const auto& mesh = std::get<Mesh<3>>(expected.mesh);
  EXPECT_EQ(mesh.edge_node(mesh.find_edge(0, 3)), (Vec3{{0, 0.1, 0.5}}));
  expect_same_mesh(mesh, read_gamma_mesh(write_file("tet_permuted.mesh", permuted)), false, &expected);
}

// ---- malformed input ----

// Reading `text` as <name> fails with a message naming the file and containing every `part`.
void expect_read_error(const std::string& name, const std::string& text, std::initializer_list<std::string> parts) {
  std::string path = write_file(name, text);
  try {
    ::testing::internal::CaptureStderr();
    read_gamma_mesh(path);
    ::testing::internal::GetCapturedStderr();
    ADD_FAILURE() << name << ": no error";
  } catch (const Error& error) {
    ::testing::internal::GetCapturedStderr();
    std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
}

const std::string kHeader3 = "MeshVersionFormatted 2\nDimension 3\n";
const std::string kTetVertices = kHeader3 + "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";

TEST(GammaMesh, RefusesMalformedAsciiFiles) {
  expect_read_error("truncated.mesh", kHeader3 + "Vertices\n3\n0 0 0 0\n1 0 0 0\n", {"Vertices: ", "end of file"});
  expect_read_error("negative.mesh", kHeader3 + "Vertices\n-4\n", {"Vertices: ", "negative count -4"});
  expect_read_error("huge_count.mesh", kHeader3 + "Vertices\n99999999999\n", {"Vertices: ", "too large"});
  expect_read_error("absurd_count.mesh", kHeader3 + "Vertices\n2000000000\n0 0 0 0\n", {"Vertices: ", "end of file"});
  expect_read_error("more_data.mesh", kHeader3 + "Vertices\n1\n0 0 0 0\n1 0 0 0\n", {"Vertices: ", "found the number 1"});
  expect_read_error("not_a_number.mesh", kHeader3 + "Vertices\n1\n0 x 0 0\n", {"Vertices: ", "expected a real", "line 5"});
  expect_read_error("nan.mesh", kHeader3 + "Vertices\n1\n0 nan 0 0\n", {"Vertices: ", "not finite"});
  expect_read_error("vertex_zero.mesh", kTetVertices + "Tetrahedra\n1\n1 2 0 4 1\n", {"Tetrahedra: ", "vertex 0 out of range", "entity 1"});
  expect_read_error("vertex_99.mesh", kTetVertices + "Tetrahedra\n2\n1 2 3 4 1\n1 2 99 4 1\n",
                    {"Tetrahedra: ", "99 out of range", "entity 2"});
  expect_read_error("corner_50.mesh", kTetVertices + "Tetrahedra\n1\n1 2 3 4 1\nCorners\n1\n50\n", {"Corners: ", "50 out of range"});
  expect_read_error("ridge.mesh", kTetVertices + "Tetrahedra\n1\n1 2 3 4 1\nRidges\n1\n1\n", {"Ridges: ", "names no edge"});
  expect_read_error("required_edge.mesh", kTetVertices + "Tetrahedra\n1\n1 2 3 4 1\nRequiredEdges\n1\n1\n",
                    {"RequiredEdges: ", "names no edge"});
  expect_read_error("required_triangle.mesh", kTetVertices + "Tetrahedra\n1\n1 2 3 4 1\nTriangles\n1\n1 2 3 1\nRequiredTriangles\n1\n2\n",
                    {"RequiredTriangles: ", "names no triangle in required triangle 1"});
  expect_read_error("required_2d.mesh", "Dimension 2\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\nTriangles\n1\n1 2 3 1\nRequiredTriangles\n1\n1\n",
                    {"RequiredTriangles: ", "not supported in a 2D mesh"});
  expect_read_error("no_dimension.mesh", "MeshVersionFormatted 2\nVertices\n1\n0 0 0 0\n", {"Vertices: ", "no Dimension"});
  expect_read_error("empty.mesh", "", {"Dimension: missing"});
  expect_read_error("dimension_4.mesh", "MeshVersionFormatted 2\nDimension 4\n", {"Dimension: ", "2 or 3, found 4"});
  expect_read_error("two_dimensions.mesh", kHeader3 + "Dimension 2\n", {"Dimension: ", "disagrees"});
  expect_read_error("version_9.mesh", "MeshVersionFormatted 9\nDimension 3\n", {"MeshVersionFormatted: ", "version 9"});
  expect_read_error("tets_in_2d.mesh", "Dimension 2\nVertices\n4\n0 0 0\n1 0 0\n0 1 0\n1 1 0\nTetrahedra\n1\n1 2 3 4 1\n",
                    {"Tetrahedra: ", "Dimension 2"});
  expect_read_error("mixed.mesh", kTetVertices + "Tetrahedra\n1\n1 2 3 4 1\nTriangles\n1\n1 2 3 1\nTrianglesP2\n1\n1 2 3 1 2 3 1\n",
                    {"Triangles and TrianglesP2", "mixing P1 and P2"});
  expect_read_error("surface.mesh", kTetVertices + "Triangles\n1\n1 2 3 1\n", {"Triangles: ", "surface meshes", "Dimension 2", ".msh"});
  expect_read_error("nothing.mesh", kTetVertices, {"no Tetrahedra or TetrahedraP2"});
  expect_read_error("p2_boundary.mesh", kTetVertices + "Tetrahedra\n1\n1 2 3 4 1\nEdgesP2\n1\n1 2 3 1\n", {"EdgesP2: ", "P1 mesh"});
  expect_read_error("twice.mesh", kTetVertices + "Vertices\n0\n", {"Vertices: ", "appears twice"});
  expect_read_error("quads.mesh", kTetVertices + "Quadrilaterals\n1\n1 2 3 4 1\n", {"Quadrilaterals: ", "not supported"});
  expect_read_error("ordering_count.mesh", kHeader3 + "TetrahedraP2Ordering\n4\n", {"TetrahedraP2Ordering: ", "lists 4 nodes"});
  expect_read_error("ordering_index.mesh", kHeader3 + "EdgesP2Ordering\n3\n2\n0\n3\n", {"EdgesP2Ordering: ", "Bézier index 3"});
  expect_read_error("ordering_repeat.mesh",
                    kTriangleVertices +
                        "TrianglesP2Ordering\n6\n2 0 0\n2 0 0\n0 0 2\n1 1 0\n0 1 1\n1 0 1\n"
                        "TrianglesP2\n1\n1 2 3 4 5 6 1\n",
                    {"TrianglesP2Ordering: ", "not a permutation"});
}

TEST(GammaMesh, SkipsUnknownAsciiKeywordsWithOneWarningEach) {
  std::string text = kHeader3 + "# a comment line\nIdentifier\n\"a name with spaces\"\nGeometry\n\"cube.egads\"\n" +
                     "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nNormals\n2\n0 0 1\n0 0 -1\nAcmeExtension 3 1.5 2 3\n" +
                     "Tetrahedra\n1\n1 2 3 4 5\nNormals\n1\n1 0 0\nEnd\nThis is ignored\n";
  ::testing::internal::CaptureStderr();
  MeshFileContent content = read_gamma_mesh(write_file("unknown_keywords.mesh", text));
  std::string warnings = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(std::get<Mesh<3>>(content.mesh).element_ref(0), 5);
  EXPECT_EQ(std::count(warnings.begin(), warnings.end(), '\n'), 4) << warnings;
  for (const char* keyword : {"Identifier", "Geometry", "Normals", "AcmeExtension"})
    EXPECT_NE(warnings.find(std::string("skipping keyword ") + keyword), std::string::npos) << warnings;
}

// A binary 3D file: header, Dimension, then Vertices of a unit tetrahedron unless told otherwise.
GammaBinaryBuilder binary_tet_vertices(int version, bool swap = false) {
  GammaBinaryBuilder file(version, swap);
  file.dimension(3);
  file.begin_keyword(4);
  file.count(4);
  const double points[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& point : points) {
    for (double x : point) file.real(x);
    file.integer(0);
  }
  file.end_keyword();
  return file;
}

void add_tetrahedron(GammaBinaryBuilder& file, std::int64_t last_vertex = 4) {
  file.begin_keyword(8);
  file.count(1);
  for (std::int64_t id : {std::int64_t{1}, std::int64_t{2}, std::int64_t{3}, last_vertex}) file.integer(id);
  file.integer(2);
  file.end_keyword();
}

TEST(GammaMesh, ReadsByteSwappedBinaryFiles) {
  for (int version = 1; version <= 4; ++version) {
    GammaBinaryBuilder file = binary_tet_vertices(version, true);
    add_tetrahedron(file);
    file.end();
    MeshFileContent content = read_gamma_mesh(write_file("swapped.meshb", file.bytes()));
    const auto& mesh = std::get<Mesh<3>>(content.mesh);
    EXPECT_EQ(mesh.vertex(3), (Vec3{{0, 0, 1}})) << version;
    EXPECT_EQ(mesh.element(0), (Mesh<3>::Element{0, 1, 2, 3})) << version;
    EXPECT_EQ(mesh.element_ref(0), 2) << version;
  }
}

TEST(GammaMesh, SkipsUnknownBinaryKeywordsByNextPos) {
  GammaBinaryBuilder file = binary_tet_vertices(3);
  for (int code : {60, 200}) {  // Normals, then a code no table knows, each with data to jump over
    file.begin_keyword(code);
    file.count(2);
    for (int i = 0; i < 6; ++i) file.real(0.25);
    file.end_keyword();
  }
  add_tetrahedron(file);
  file.end();
  ::testing::internal::CaptureStderr();
  MeshFileContent content = read_gamma_mesh(write_file("unknown_keywords.meshb", file.bytes()));
  std::string warnings = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(std::get<Mesh<3>>(content.mesh).element_count(), 1);
  EXPECT_NE(warnings.find("skipping keyword Normals "), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("skipping keyword code 200 "), std::string::npos) << warnings;
}

TEST(GammaMesh, RefusesMalformedBinaryFiles) {
  auto finished = [](GammaBinaryBuilder file) {
    file.end();
    return file.bytes();
  };
  GammaBinaryBuilder valid = binary_tet_vertices(3);
  add_tetrahedron(valid);
  ASSERT_NO_THROW(read_gamma_mesh(write_file("valid.meshb", finished(valid))));

  expect_read_error("short.meshb", std::string("\1\0\0\0\3\0", 6), {"truncated file"});
  GammaBinaryBuilder version5(5);
  expect_read_error("version5.meshb", version5.bytes(), {"unsupported version 5"});

  GammaBinaryBuilder out_of_range = binary_tet_vertices(4);
  add_tetrahedron(out_of_range, std::int64_t{1} << 40);
  expect_read_error("id64.meshb", finished(out_of_range), {"Tetrahedra: ", "1099511627776 out of range", "entity 1"});
  GammaBinaryBuilder missing_vertex = binary_tet_vertices(2);
  add_tetrahedron(missing_vertex, 9);
  expect_read_error("id9.meshb", finished(missing_vertex), {"Tetrahedra: ", "9 out of range"});

  // NextPos chains that go backward or leave the file.
  GammaBinaryBuilder backward = binary_tet_vertices(3);
  backward.patch_position(backward.next_position_at(), 8);
  expect_read_error("backward.meshb", finished(backward), {"Vertices: ", "NextPos 8 points backward"});
  GammaBinaryBuilder outside = binary_tet_vertices(2);
  outside.patch_position(outside.next_position_at(), 1 << 30);
  expect_read_error("outside.meshb", finished(outside), {"Vertices: ", "past the end of the file"});

  // Counts beyond the data: to the end of the file, or past NextPos.
  GammaBinaryBuilder truncated(3);
  truncated.dimension(3);
  truncated.begin_keyword(4);
  truncated.count(1000);
  for (double x : {0.0, 0.0, 0.0}) truncated.real(x);
  truncated.integer(0);
  truncated.real(1.0);
  expect_read_error("truncated.meshb", truncated.bytes(), {"Vertices: truncated file, entity 2"});
  GammaBinaryBuilder past_next(4);
  past_next.dimension(3);
  past_next.begin_keyword(4);
  past_next.count(5);
  for (int i = 0; i < 4; ++i) past_next.real(0.5);
  past_next.end_keyword();
  expect_read_error("past_next.meshb", finished(past_next), {"Vertices: ", "past the next keyword", "entity 2"});
  GammaBinaryBuilder negative(1);
  negative.dimension(3);
  negative.begin_keyword(4);
  negative.count(-3);
  negative.end_keyword();
  expect_read_error("negative.meshb", finished(negative), {"Vertices: ", "negative count -3"});

  GammaBinaryBuilder not_finite(2);
  not_finite.dimension(3);
  not_finite.begin_keyword(4);
  not_finite.count(2);
  for (double x : {0.0, 0.0, 0.0}) not_finite.real(x);
  not_finite.integer(0);
  for (double x : {1.0, std::numeric_limits<double>::infinity(), 0.0}) not_finite.real(x);
  not_finite.integer(0);
  not_finite.end_keyword();
  expect_read_error("not_finite.meshb", finished(not_finite), {"Vertices: ", "not finite", "entity 2"});

  GammaBinaryBuilder no_dimension(3);
  no_dimension.begin_keyword(4);
  no_dimension.count(0);
  no_dimension.end_keyword();
  expect_read_error("no_dimension.meshb", finished(no_dimension), {"Vertices: ", "no Dimension"});
  GammaBinaryBuilder bad_dimension(3);
  bad_dimension.dimension(7);
  expect_read_error("bad_dimension.meshb", finished(bad_dimension), {"Dimension: ", "found 7"});
}

// ---- the binary layout, byte by byte ----

// One P2 triangle with its three boundary edges and a corner; edge ids follow the element edges.
Mesh<2> single_curved_triangle() {
  Mesh<2> mesh;
  mesh.add_vertex({{0, 0}}, 1);
  mesh.add_vertex({{1, 0}}, 2);
  mesh.add_vertex({{0, 1}}, 3);
  mesh.add_element({0, 1, 2}, 7);
  mesh.add_facet({0, 1}, 4);
  mesh.add_facet({1, 2}, 5);
  mesh.add_facet({2, 0}, 6);
  mesh.corners() = {0};
  mesh.build_topology();
  mesh.make_p2();
  mesh.edge_node(mesh.find_edge(1, 2)) = {{0.6, 0.6}};
  return mesh;
}

TEST(GammaMesh, WritesTheBinaryLayoutOfFormatsMd) {
  const Mesh<2> mesh = single_curved_triangle();
  for (int version = 1; version <= 4; ++version) {
    SCOPED_TRACE(version);
    GammaBinaryBuilder expected(version);
    expected.dimension(2);
    expected.begin_keyword(4);
    expected.count(6);
    // Edge nodes in edge order: edges by their smaller vertex, then their larger one.
    const double nodes[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0, 0.5}, {0.6, 0.6}};
    const int refs[6] = {1, 2, 3, 0, 0, 0};
    for (int n = 0; n < 6; ++n) {
      expected.real(nodes[n][0]);
      expected.real(nodes[n][1]);
      expected.integer(refs[n]);
    }
    expected.end_keyword();
    expected.begin_keyword(25);  // EdgesP2: v0 v1 mid ref
    expected.count(3);
    const std::array<std::array<int, 4>, 3> edges{{{1, 2, 4, 4}, {2, 3, 6, 5}, {3, 1, 5, 6}}};
    for (const auto& edge : edges)
      for (int value : edge) expected.integer(value);
    expected.end_keyword();
    expected.begin_keyword(24);  // TrianglesP2
    expected.count(1);
    for (int value : {1, 2, 3, 4, 6, 5, 7}) expected.integer(value);
    expected.end_keyword();
    expected.begin_keyword(13);  // Corners
    expected.count(1);
    expected.integer(1);
    expected.end_keyword();
    expected.end();

    std::string path = temporary_path("layout.meshb");
    write_gamma_mesh(path, mesh, true, version);
    EXPECT_EQ(read_file(path), expected.bytes());
  }
}

TEST(GammaMesh, WritesAsciiThatGammaReadersExpect) {
  std::string path = temporary_path("layout.mesh");
  write_gamma_mesh(path, single_curved_triangle(), false);
  EXPECT_EQ(read_file(path),
            "MeshVersionFormatted 2\n\nDimension 2\n\nVertices\n6\n0 0 1\n1 0 2\n0 1 3\n0.5 0 0\n0 0.5 0\n0.6 0.6 0\n"
            "\nEdgesP2\n3\n1 2 4 4\n2 3 6 5\n3 1 5 6\n\nTrianglesP2\n1\n1 2 3 4 6 5 7\n\nCorners\n1\n1\n\nEnd\n");
}

// ---- writing errors leave nothing behind ----

TEST(GammaMesh, FailedWritesLeaveNoFile) {
  const std::string directory = temporary_path("write_failures");
  std::filesystem::remove_all(directory);
  std::filesystem::create_directory(directory);
  Mesh<2> mesh = generate_square(2);
  EXPECT_THROW(write_gamma_mesh(directory + "/missing/out.meshb", mesh, true), Error);
  EXPECT_THROW(write_gamma_mesh(directory + "/bad_version.meshb", mesh, true, 7), Error);
  mesh.vertex(4)[0] = 1e300;  // beyond float32: version 1 fails in the middle of Vertices
  try {
    write_gamma_mesh(directory + "/overflow.meshb", mesh, true, 1);
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("overflow.meshb"), std::string::npos) << error.what();
  }
  EXPECT_TRUE(std::filesystem::is_empty(directory));
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace hocav
