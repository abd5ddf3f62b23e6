#include "surface/boundary_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "surface/analytic_boundary.hpp"
#include "surface/boundary_proposals.hpp"
#include "surface_test_meshes.hpp"

namespace hocav {
namespace {

TEST(SurfaceBoundaryDistance, StraightAndCurvedCircle) {
  Mesh<2> mesh = testing::circle_polygon(10, 2.0);
  const AnalyticBoundary<2> circle = concentric_shell_boundary<2>(2.0, 3.0);
  // The sagitta of a chord, r (1 − cos(π / n)), sampled at the chord's middle (n even).
  const double sagitta = 2.0 * (1 - std::cos(std::numbers::pi / 10));
  EXPECT_NEAR(max_boundary_distance(mesh, circle, 8), sagitta, 1e-15);
  BoundaryProposals<2> proposals(mesh, circle);
  apply_boundary_proposals(mesh, proposals);
  const double curved = max_boundary_distance(mesh, circle, 40);
  EXPECT_LT(curved, sagitta / 50);
  EXPECT_GT(curved, 0);
}

TEST(SurfaceBoundaryDistance, SphereFacetsSampledInside) {
  const Mesh<3> mesh = testing::icosphere(1);
  AnalyticBoundary<3> sphere;
  sphere.add(1, AnalyticSurface<3>::sphere({}, 1.0));
  // The deepest point of a flat facet is near its centre, deeper than any edge midpoint.
  double deepest_midpoint = 0;
  for (const auto& facet : mesh.facets())
    deepest_midpoint = std::max(deepest_midpoint, 1 - norm(0.5 * (mesh.vertex(facet[0]) + mesh.vertex(facet[1]))));
  EXPECT_GT(max_boundary_distance(mesh, sphere, 12), deepest_midpoint);
}

}  // namespace
}  // namespace hocav
