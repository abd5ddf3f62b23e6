#include "mesh/boundary_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "adapt/vertex_classes.hpp"
#include "cases/structured.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

// A cube bent by a smooth map (its faces curved), its corners and feature lines classified, some
// vertices required inside and on the boundary.
Mesh<3> bent_cube() {
  Mesh<3> mesh = generate_cube(5);
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    Vec3& x = mesh.vertex(v);
    x = Vec3{x[0] + 0.05 * std::sin(3 * x[1]), x[1] + 0.05 * std::sin(2 * x[2]), x[2] + 0.04 * std::sin(3 * x[0])};
  }
  mesh.build_topology();
  classify_vertices(mesh, 45);
  mesh.required_vertices() = {0, 31, 100};
  return mesh;
}

TEST(BoundaryMesh, KeepsTheVerticesAndBoundaryEntitiesAndNoElement) {
  const Mesh<3> mesh = bent_cube();
  const Mesh<3> boundary = boundary_mesh_of(mesh);
  EXPECT_EQ(boundary.element_count(), 0);
  ASSERT_EQ(boundary.vertex_count(), mesh.vertex_count());
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    EXPECT_EQ(boundary.vertex(v), mesh.vertex(v));
    EXPECT_EQ(boundary.vertex_ref(v), mesh.vertex_ref(v));
  }
  ASSERT_EQ(boundary.facet_count(), mesh.facet_count());
  ASSERT_GT(mesh.line_count(), 0);
  ASSERT_EQ(boundary.line_count(), mesh.line_count());
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    EXPECT_EQ(boundary.facet(f), mesh.facet(f));
    EXPECT_EQ(boundary.facet_ref(f), mesh.facet_ref(f));
  }
  for (Index l = 0; l < mesh.line_count(); ++l) EXPECT_EQ(boundary.line(l), mesh.line(l));
  EXPECT_EQ(boundary.corners(), mesh.corners());
  EXPECT_EQ(boundary.required_vertices(), mesh.required_vertices());
  EXPECT_EQ(boundary.ridges(), mesh.ridges());
}

TEST(BoundaryMesh, ItsSurrogateAnswersAsTheWholeMeshs) {
  const Mesh<3> mesh = bent_cube();
  const P3Surrogate<3> whole(mesh), from_boundary(boundary_mesh_of(mesh));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-0.2, 1.2);
  for (int i = 0; i < 300; ++i) {
    const Vec3 x{coordinate(random), coordinate(random), coordinate(random)};
    const BoundaryPoint<3> a = whole.project(x), b = from_boundary.project(x);
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.distance, b.distance);
    EXPECT_EQ(a.patch, b.patch);
    EXPECT_EQ(a.ref, b.ref);
    EXPECT_EQ(whole.normal(x), from_boundary.normal(x));
  }
  // The edge curves, asked by the mesh's vertex ids (as the distributed curving's parts ask them).
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (int i = 0; i < 3; ++i) {
      BoundaryEdge<3> edge{mesh.facet(f)[i], mesh.facet(f)[(i + 1) % 3]};
      edge.node = 0.5 * (mesh.vertex(edge.a) + mesh.vertex(edge.b));
      edge.refs = {mesh.facet_ref(f), mesh.facet_ref(f)};
      EXPECT_EQ(whole.propose_edge_node(edge), from_boundary.propose_edge_node(edge));
    }
}

}  // namespace
}  // namespace hocav
