// Meshes whose parts meet without a face (docs/adaptation.md §Vertex classes and the boundary): a
// walk around such a place sees one part, so the loop keeps it as it is, and every part stays
// joined to the others there.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "../mesh/pinched_mesh.hpp"
#include "adapt/adaptation_loop.hpp"
#include "adapt/vertex_classes.hpp"
#include "adapt_test_support.hpp"
#include "mesh/measure.hpp"
#include "mesh/mesh_defects.hpp"

namespace hocav {
namespace {

using Segment = std::pair<std::array<double, 3>, std::array<double, 3>>;

// The non-manifold edges of a mesh with topology, by their ends' coordinates (ids change).
std::set<Segment> non_manifold_segments(const Mesh<3>& mesh) {
  std::set<Segment> segments;
  for (const std::uint64_t key : non_manifold_places(mesh).edges) {
    const Vec3 a = mesh.vertex(static_cast<Index>(key >> 32)), b = mesh.vertex(static_cast<Index>(key & 0xffffffffu));
    segments.insert(std::minmax(std::array<double, 3>{a[0], a[1], a[2]}, std::array<double, 3>{b[0], b[1], b[2]}));
  }
  return segments;
}

TEST(NonManifoldMesh, APinchedVertexIsACorner) {
  Mesh<3> mesh = mesh_test::pinched_tetrahedra();
  for (const auto& element : std::vector<Mesh<3>::Element>(mesh.elements().begin(), mesh.elements().end()))
    for (int face = 0; face < 4; ++face) {
      Mesh<3>::Facet facet;
      for (int i = 0; i < 3; ++i) facet[i] = element[face_vertices<3>(face)[i]];
      mesh.add_facet(facet, 1);
    }
  mesh.build_topology();
  // The facets around vertex 0 meet at 90 degrees: with a feature angle of 179 degrees nothing
  // else makes it a corner.
  const std::vector<VertexClass> classes = classify_vertices(mesh, 179);
  EXPECT_EQ(classes[0], VertexClass::kCorner);
  EXPECT_NE(std::find(mesh.corners().begin(), mesh.corners().end(), 0), mesh.corners().end());
  for (Index v = 1; v < mesh.vertex_count(); ++v) EXPECT_EQ(classes[v], VertexClass::kSurface) << v;
}

TEST(NonManifoldMesh, TwoCubesSharingAnEdgeStayJoinedAlongItAndValid) {
  Mesh<3> mesh = mesh_test::cubes_sharing_an_edge(2);
  mesh.build_topology();
  const std::set<Segment> shared = non_manifold_segments(mesh);
  ASSERT_EQ(shared.size(), 2u);
  const Index elements_before = mesh.element_count();
  AnalyticMetricSpec spec;
  spec.name = "uniform";
  spec.h = 0.15;
  const AdaptationMetric<3> metric(spec, {});
  adapt_to_metric<3>(mesh, metric, nullptr, {});
  ASSERT_GT(mesh.element_count(), 10 * elements_before);
  adapt_test::expect_closed_and_consistent(mesh);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const auto& e = mesh.element(k);
    ASSERT_GT(signed_measure(mesh.vertex(e[0]), mesh.vertex(e[1]), mesh.vertex(e[2]), mesh.vertex(e[3])), 0) << "element " << k;
  }
  // Split on one side only, the edge would leave the other side's elements on a line the first no
  // longer has as an edge: the two cubes would touch at points, no longer along an edge.
  EXPECT_EQ(non_manifold_segments(mesh), shared);
  EXPECT_EQ(non_manifold_places(mesh).vertices.size(), 3u);
}

// In 2D (where the shared corner is a corner by its angle as well): the squares still meet there.
TEST(NonManifoldMesh, TwoSquaresSharingACornerKeepItAndStayValid) {
  Mesh<2> mesh = mesh_test::squares_sharing_a_corner(2);
  mesh.build_topology();
  ASSERT_EQ(non_manifold_places(mesh).vertices.size(), 1u);
  AnalyticMetricSpec spec;
  spec.name = "uniform";
  spec.h = 0.1;
  const AdaptationMetric<2> metric(spec, {});
  adapt_to_metric<2>(mesh, metric, nullptr, {});
  ASSERT_GT(mesh.element_count(), 100);
  adapt_test::expect_closed_and_consistent(mesh);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const auto& e = mesh.element(k);
    ASSERT_GT(signed_measure(mesh.vertex(e[0]), mesh.vertex(e[1]), mesh.vertex(e[2])), 0) << "element " << k;
  }
  const std::vector<Index> pinched = non_manifold_places(mesh).vertices;
  ASSERT_EQ(pinched.size(), 1u);
  EXPECT_EQ(mesh.vertex(pinched[0]), (Vec2{{1, 1}}));
}

}  // namespace
}  // namespace hocav
