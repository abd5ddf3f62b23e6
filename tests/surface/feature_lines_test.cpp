// Feature lines and the input's corners (docs/surface.md, "Feature lines"): a line passes through
// its vertices with one tangent, and stops at a vertex listed in Corners or RequiredVertices, where
// each ridge edge leaves along its own branch.
#include "surface/feature_lines.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "surface/p3_surrogate.hpp"
#include "surface_test_meshes.hpp"
#include "surrogate_checks.hpp"

namespace hocav {
namespace {

using testing::capped_cylinder;
using testing::edge_curve;
using testing::expect_no_cracks;

constexpr int kSegments = 16;
// Rim vertices of the bottom rim (capped_cylinder: layer 0 holds vertices 0 .. kSegments − 1).
constexpr Index kKinked = 3, kBefore = 2, kAfter = 4;

// The bottom rim of a capped cylinder with one rim vertex lifted: the rim kinks there.
Mesh<3> kinked_cylinder() {
  Mesh<3> mesh = capped_cylinder(kSegments);
  mesh.vertex(kKinked)[2] += 0.05;
  return mesh;
}

// The sine of the angle between the rim's two edge curves at the kinked vertex (0 when they leave
// it along one tangent).
double turn_at_kink(const Mesh<3>& mesh, const P3Surrogate<3>& surrogate) {
  auto leaving = [&](Index other) {
    for (Index f = 0; f < mesh.facet_count(); ++f)
      if (facet_local_vertex(mesh, f, kKinked) >= 0 && facet_local_vertex(mesh, f, other) >= 0) {
        const auto curve = edge_curve(mesh, surrogate, f, kKinked, other);
        return (curve[1] - curve[0]) * (1 / norm(curve[1] - curve[0]));
      }
    ADD_FAILURE() << "no facet with edge " << kKinked << "-" << other;
    return Vec3{};
  };
  return norm(cross(leaving(kBefore), leaving(kAfter)));
}

TEST(FeatureLines, TheRimPassesThroughItsVerticesWithOneTangent) {
  const Mesh<3> mesh = kinked_cylinder();
  P3Surrogate<3> surrogate(mesh);
  expect_no_cracks(mesh, surrogate);
  EXPECT_LT(turn_at_kink(mesh, surrogate), 1e-12);
}

TEST(FeatureLines, InputCornersEndTheLines) {
  for (const bool required : {false, true}) {
    Mesh<3> mesh = kinked_cylinder();
    (required ? mesh.required_vertices() : mesh.corners()) = {kKinked};
    const P3Surrogate<3> surrogate(mesh);
    expect_no_cracks(mesh, surrogate);  // each branch's curve is still shared by both its patches
    // Each rim edge leaves the corner along its own branch: the circle through the corner and the
    // next two rim vertices, which turns there by about the kink.
    const double turn = turn_at_kink(mesh, surrogate);
    EXPECT_GT(turn, 0.1) << (required ? "RequiredVertices" : "Corners");
    VertexNormals<3> normals = surrogate.vertex_normals();
    const FeatureLines<3> lines = find_feature_lines(mesh, surrogate.topology(), normals);
    EXPECT_EQ(norm(lines.tangents[kKinked]), 0.0);
    EXPECT_GT(norm(lines.tangents[kBefore]), 0.0);
    EXPECT_TRUE(lines.input_corners[kKinked]);
  }
}

TEST(FeatureLines, BranchTangentFollowsTheLineBeyond) {
  // On the unkinked rim a branch tangent is the rim circle's tangent: one-sided, yet exact.
  Mesh<3> mesh = capped_cylinder(kSegments);
  mesh.corners() = {kKinked};
  const P3Surrogate<3> surrogate(mesh);
  VertexNormals<3> normals = surrogate.vertex_normals();
  const FeatureLines<3> lines = find_feature_lines(mesh, surrogate.topology(), normals);
  const Vec3 tangent = branch_tangent(mesh, lines, kKinked, kAfter);
  const Vec3& point = mesh.vertex(kKinked);
  const Vec3 circle_tangent = Vec3{{-point[1], point[0], 0}};  // counter-clockwise, toward kAfter
  EXPECT_NEAR(dot(tangent, circle_tangent), 1.0, 1e-14);
  // A listed vertex with no ridge through it (the bottom cap's centre) changes nothing.
  Mesh<3> centre_listed = capped_cylinder(kSegments);
  const P3Surrogate<3> plain(centre_listed);
  Index centre = kNoIndex;
  for (Index v = 0; v < centre_listed.vertex_count(); ++v)
    if (centre_listed.vertex(v) == Vec3{{0, 0, 0}}) centre = v;
  ASSERT_NE(centre, kNoIndex);
  centre_listed.corners() = {centre};
  const P3Surrogate<3> listed(centre_listed);
  for (Index f = 0; f < centre_listed.facet_count(); ++f) EXPECT_EQ(listed.patch(f).control, plain.patch(f).control);
}

}  // namespace
}  // namespace hocav
