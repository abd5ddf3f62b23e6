// The surrogate's ridge curves (docs/surface.md, "Ridge curves"): the closest point on a cubic
// curve, and the points project_on_ridge / project_on_intersection give on the curves the mid nodes
// follow, between two refs or on a ridge inside one.
#include "surface/ridge_curves.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cases/structured.hpp"
#include "surface/analytic_boundary.hpp"
#include "surface/p3_surrogate.hpp"
#include "surface_test_meshes.hpp"

namespace hocav {
namespace {

TEST(RidgeCurves, ClosestPointOnAStraightCubicIsTheProjectionClampedToItsEnds) {
  const Vec3 a{{0, 0, 0}}, b{{3, 0, 0}};
  const CubicCurve line{a, Vec3{{1, 0, 0}}, Vec3{{2, 0, 0}}, b};
  EXPECT_NEAR(norm(closest_point_on_curve(line, Vec3{{1.3, 0.4, -0.2}}) - Vec3{{1.3, 0, 0}}), 0, 1e-14);
  EXPECT_EQ(closest_point_on_curve(line, Vec3{{-1, 1, 0}}), a);
  EXPECT_EQ(closest_point_on_curve(line, Vec3{{5, 0, 1}}), b);
}

TEST(RidgeCurves, ClosestPointOnACurvedCubicIsOrthogonalToIt) {
  const CubicCurve arc{Vec3{{1, 0, 0}}, Vec3{{1, 0.5, 0}}, Vec3{{0.5, 1, 0.2}}, Vec3{{0, 1, 0}}};
  const Vec3 x{{0.9, 0.9, 0.3}};
  const Vec3 point = closest_point_on_curve(arc, x);
  // No sample of the curve is closer, and the offset is orthogonal to the curve there.
  for (int k = 0; k <= 1000; ++k) EXPECT_GE(norm(evaluate_curve(arc, k / 1000.0) - x), norm(point - x) - 1e-15);
  const double step = 1e-6;
  double t = 0;
  for (int k = 0; k <= 1000; ++k)
    if (norm(evaluate_curve(arc, k / 1000.0) - point) < norm(evaluate_curve(arc, t) - point)) t = k / 1000.0;
  const Vec3 tangent = evaluate_curve(arc, t + step) - evaluate_curve(arc, t - step);
  EXPECT_NEAR(dot(point - x, tangent) / (norm(point - x) * norm(tangent)), 0, 1e-3);
}

TEST(RidgeCurves, SurrogateRimPointsBetweenTheRightRefs) {
  const Mesh<3> mesh = testing::capped_cylinder(16);  // refs 1 side, 2 bottom cap, 3 top cap
  const P3Surrogate<3> surrogate(mesh);
  for (int k = 0; k < 7; ++k) {
    const double angle = 0.37 + k * 0.9;
    const Vec3 near_bottom{{1.02 * std::cos(angle), 1.02 * std::sin(angle), 0.01}};
    const Vec3 on_bottom = surrogate.project_on_ridge(near_bottom, 1, 2);
    EXPECT_EQ(on_bottom[2], 0.0);  // the rim curves lie in the cap's plane
    EXPECT_NEAR(std::hypot(on_bottom[0], on_bottom[1]), 1, 1e-4);
    EXPECT_EQ(surrogate.project_on_ridge(near_bottom, 2, 1), on_bottom);
    EXPECT_EQ(surrogate.project_on_intersection(near_bottom, 1, 2), on_bottom);
    // Between the side and the top cap: on the top rim, however far.
    EXPECT_NEAR(surrogate.project_on_ridge(near_bottom, 1, 3)[2], 1.0, 1e-15);
  }
  // A rim edge's midpoint is on the curve the proposed mid node follows.
  const Vec3 middle = *surrogate.edge_midpoint(0, 1);
  EXPECT_LT(norm(surrogate.project_on_ridge(middle, 1, 2) - middle), 1e-15);
}

TEST(RidgeCurves, RidgeInsideOneRefFromTheDihedralAngle) {
  const Mesh<3> cube = generate_cube(3);
  Mesh<3> one_ref;
  for (const Vec3& point : cube.vertices()) one_ref.add_vertex(point);
  for (const auto& facet : cube.facets()) one_ref.add_facet(facet, 1);
  const P3Surrogate<3> surrogate(one_ref);
  const Vec3 on_edge = surrogate.project_on_ridge(Vec3{{1.05, 0.98, 0.3}}, 1, 1);
  EXPECT_NEAR(norm(on_edge - Vec3{{1, 1, 0.3}}), 0, 1e-15);
}

TEST(RidgeCurves, DefaultOfAGeometryWithoutCurvesIsItsProjection) {
  const AnalyticBoundary<3> spheres = concentric_shell_boundary<3>(0.5, 1.0);
  const Vec3 x{{0.3, 0.8, 0.1}};
  EXPECT_EQ(spheres.project_on_ridge(x, 2, 2), spheres.project(x, {.ref = 2}).point);
}

}  // namespace
}  // namespace hocav
