#include "surface/analytic_boundary.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "base/error.hpp"

namespace hocav {
namespace {

TEST(SurfaceAnalytic, SphereCylinderAndPlaneProjections) {
  const auto sphere = AnalyticSurface<3>::sphere(Vec3{{1, 0, 0}}, 2);
  EXPECT_LT(norm(sphere.project(Vec3{{1, 0, 5}}) - Vec3{{1, 0, 2}}), 1e-15);
  EXPECT_LT(norm(sphere.normal(Vec3{{1, 0, 5}}) - Vec3{{0, 0, 1}}), 1e-15);
  EXPECT_NEAR(norm(sphere.project(Vec3{{1, 0, 0}}) - Vec3{{1, 0, 0}}), 2.0, 1e-15);  // the centre: any point

  const auto cylinder = AnalyticSurface<3>::cylinder(Vec3{{0, 0, 0}}, Vec3{{0, 0, 3}}, 0.5);
  EXPECT_LT(norm(cylinder.project(Vec3{{2, 0, 7}}) - Vec3{{0.5, 0, 7}}), 1e-15);
  EXPECT_LT(norm(cylinder.normal(Vec3{{0, -0.1, 7}}) - Vec3{{0, -1, 0}}), 1e-15);
  EXPECT_NEAR(norm(cylinder.project(Vec3{{0, 0, 4}}) - Vec3{{0, 0, 4}}), 0.5, 1e-15);  // on the axis

  const auto plane = AnalyticSurface<2>::plane(Vec2{{0, 1}}, Vec2{{0, 2}});
  EXPECT_LT(norm(plane.project(Vec2{{3, 4}}) - Vec2{{3, 1}}), 1e-15);
  EXPECT_LT(norm(plane.normal(Vec2{{3, 4}}) - Vec2{{0, 1}}), 1e-15);
}

TEST(SurfaceAnalytic, RefsSelectTheSurface) {
  const AnalyticBoundary<3> shell = concentric_shell_boundary<3>(0.5, 1.0);
  const Vec3 x{{0, 0.6, 0}};
  const BoundaryPoint<3> closest = shell.project(x);
  EXPECT_EQ(closest.ref, 1);
  EXPECT_NEAR(closest.distance, 0.1, 1e-15);
  const BoundaryPoint<3> outer = shell.project(x, {.ref = 2});
  EXPECT_EQ(outer.ref, 2);
  EXPECT_LT(norm(outer.point - Vec3{{0, 1, 0}}), 1e-15);
  EXPECT_THROW(shell.project(x, {.ref = 3}), Error);
  EXPECT_THROW(AnalyticBoundary<2>().project(Vec2{}), Error);
}

// The default ridge projection (alternating projections) lands on both surfaces.
TEST(SurfaceAnalytic, IntersectionOfTwoSurfaces) {
  AnalyticBoundary<3> boundary;
  boundary.add(1, AnalyticSurface<3>::cylinder(Vec3{}, Vec3{{0, 0, 1}}, 1));
  boundary.add(2, AnalyticSurface<3>::plane(Vec3{{0, 0, 1}}, Vec3{{0, 0, 1}}));
  boundary.add(3, AnalyticSurface<3>::sphere(Vec3{{0, 0, 0}}, std::sqrt(2.0)));
  for (int other : {2, 3}) {
    const Vec3 rim = boundary.project_on_intersection(Vec3{{0.9, 0.3, 1.2}}, 1, other);
    EXPECT_NEAR(std::hypot(rim[0], rim[1]), 1.0, 1e-12);
    EXPECT_NEAR(rim[2], 1.0, 1e-12);
    EXPECT_NEAR(std::atan2(rim[1], rim[0]), std::atan2(0.3, 0.9), 1e-12);
  }
  // A proposal across two refs uses that curve; within one ref, the surface.
  const BoundaryEdge<3> rim_edge{0, 1, Vec3{{0.9, 0.3, 1.0}}, {1, 2}};
  EXPECT_NEAR(boundary.propose_edge_node(rim_edge)[2], 1.0, 1e-12);
  const BoundaryEdge<3> side_edge{0, 1, Vec3{{0.9, 0.3, 0.5}}, {1, 1}};
  const double r = std::hypot(0.9, 0.3);
  EXPECT_LT(norm(boundary.propose_edge_node(side_edge) - Vec3{{0.9 / r, 0.3 / r, 0.5}}), 1e-15);
}

}  // namespace
}  // namespace hocav
