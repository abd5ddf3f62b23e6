#include "picture/planar_cut.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "cases/structured.hpp"

namespace hocav {
namespace {

CutPlane horizontal_plane(double z) { return {{{0, 0, z}}, {{1, 0, 0}}, {{0, 1, 0}}}; }

double polygon_area(const std::vector<Vec2>& outline) {
  double twice = 0;
  for (std::size_t i = 0; i < outline.size(); ++i) twice += determinant(outline[i], outline[(i + 1) % outline.size()]);
  return std::abs(0.5 * twice);
}

std::array<Vec3, 6> straight_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return {a, b, c, 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)};
}

TEST(PlanarCut, StraightTriangleGivesTheExactSegment) {
  // Rising from z = −1 at (0, 0) to z = 1 at (2, 0) and (0, 2): z = 0 on the segment x + y = 1.
  const auto nodes = straight_triangle({{0, 0, -1}}, {{2, 0, 1}}, {{0, 2, 1}});
  const std::vector<CutCurve> curves = cut_p2_triangle(nodes, horizontal_plane(0), 8);
  ASSERT_EQ(curves.size(), 1u);
  const CutCurve& cut = curves.front();
  EXPECT_FALSE(cut.closed);
  ASSERT_GE(cut.points.size(), 2u);
  for (const Vec3& p : cut.points) {
    EXPECT_NEAR(p[0] + p[1], 1, 1e-12);
    EXPECT_NEAR(p[2], 0, 1e-12);
  }
  // From edge to edge: the ends are (1, 0, 0) and (0, 1, 0), in some order.
  const Vec3 &first = cut.points.front(), &last = cut.points.back();
  EXPECT_NEAR(std::min(first[0], last[0]), 0, 1e-12);
  EXPECT_NEAR(std::max(first[0], last[0]), 1, 1e-12);
}

TEST(PlanarCut, CurvedTriangleGivesPointsOnTheTrueCurve) {
  // The P2 map (u, v) -> (u, u², v), exact for these nodes: the plane z = 0.3 cuts it along the
  // parabola y = x², x in [0, 0.7].
  auto map = [](double u, double v) { return Vec3{{u, u * u, v}}; };
  const std::array<Vec3, 6> nodes{map(0, 0), map(1, 0), map(0, 1), map(0.5, 0), map(0.5, 0.5), map(0, 0.5)};
  for (int subdivisions : {4, 16}) {
    const std::vector<CutCurve> curves = cut_p2_triangle(nodes, horizontal_plane(0.3), subdivisions);
    ASSERT_EQ(curves.size(), 1u);
    const std::vector<Vec3>& points = curves.front().points;
    // Between samples the cut is a chord of the surface: off the parabola by at most Δu²/4.
    const double chord_error = 0.25 / (subdivisions * subdivisions);
    double below_end_chord = 0;
    for (const Vec3& p : points) {
      EXPECT_NEAR(p[1], p[0] * p[0], chord_error + 1e-12);
      EXPECT_GE(p[0], -1e-12);
      EXPECT_LE(p[0], 0.7 + 1e-12);
      below_end_chord = std::max(below_end_chord, 0.7 * p[0] - p[1]);  // under the chord y = 0.7 x
    }
    EXPECT_NEAR(std::min(points.front()[0], points.back()[0]), 0, 1e-12);
    EXPECT_NEAR(std::max(points.front()[0], points.back()[0]), 0.7, 1e-12);
    EXPECT_GT(below_end_chord, 0.1);  // curved: the true sag is 0.35² = 0.1225
  }
}

TEST(PlanarCut, StraightTetrahedronGivesItsClosedSection) {
  P2Element<3> element;
  element.nodes[0] = {{0, 0, 0}};
  element.nodes[1] = {{1, 0, 0}};
  element.nodes[2] = {{0, 1, 0}};
  element.nodes[3] = {{0, 0, 1}};
  for (int edge = 0; edge < 6; ++edge) {
    const auto& ends = edge_vertices<3>(edge);
    element.nodes[4 + edge] = 0.5 * (element.nodes[ends[0]] + element.nodes[ends[1]]);
  }
  const CutPlane plane = horizontal_plane(0.5);
  const std::vector<CutCurve> curves = cut_p2_tetrahedron(element, plane, 8);
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_TRUE(curves.front().closed);
  std::vector<Vec2> outline;
  for (const Vec3& p : curves.front().points) outline.push_back(plane.coordinates(p));
  EXPECT_NEAR(polygon_area(outline), 0.125, 1e-12);  // the triangle (0, 0), (0.5, 0), (0, 0.5)
}

TEST(PlanarCut, SectionsOfACubeTileTheSquare) {
  // z = 0.5 passes through vertices and faces of the mesh: each face lying in the plane is drawn
  // once, so the sections still add up to the unit square.
  Mesh<3> mesh = generate_cube(4);
  mesh.make_p2();
  for (double z : {0.3, 0.5}) {
    double area = 0;
    for (const CutCell& cell : cut_p2_mesh(mesh, horizontal_plane(z), 4)) {
      ASSERT_LT(cell.element, mesh.element_count());
      area += polygon_area(cell.outline);
    }
    EXPECT_NEAR(area, 1, 1e-12) << "z = " << z;
  }
}

TEST(PlanarCut, PlaneMissingTheMeshGivesNothing) {
  Mesh<3> mesh = generate_cube(2);
  EXPECT_TRUE(cut_p2_mesh(mesh, horizontal_plane(1.5), 4).empty());
}

}  // namespace
}  // namespace hocav
