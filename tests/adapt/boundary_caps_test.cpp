// Caps after the loop (docs/adaptation.md §Operators, "Caps"): a poor tetrahedron with two facets
// on one smooth surface is removed, its inner faces becoming the boundary; a good one, one with a
// required facet, and one whose removal would turn the boundary by more than the feature angle stay.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "adapt/adaptation_operations.hpp"
#include "adapt_test_support.hpp"
#include "cavity/roof_mesh.hpp"

namespace hocav {
namespace {

using cap_test::Roof;

TEST(BoundaryCaps, APoorCapIsRemovedAndItsInnerFacesBecomeTheBoundary) {
  Roof roof(0.02);
  const AdaptationMetric<3> metric = adapt_test::uniform_metric<3>(1);
  AdaptationMesh<3> am(roof.mesh, metric, nullptr, 45);
  ASSERT_LT(am.quality(roof.cap), kBoundaryOnlyQuality);
  const OperationCount count = remove_boundary_caps(am, AdaptationLimits{});
  EXPECT_EQ(count.done, 1);
  roof.mesh.compact();
  EXPECT_EQ(roof.mesh.element_count(), 2);
  EXPECT_EQ(roof.mesh.facet_count(), 6);
  adapt_test::expect_closed_and_consistent(roof.mesh);
  for (Index k = 0; k < roof.mesh.element_count(); ++k) EXPECT_GT(am.quality(k), kBoundaryOnlyQuality);
}

TEST(BoundaryCaps, GoodRequiredOrSharplyTurningCapsStay) {
  const AdaptationMetric<3> metric = adapt_test::uniform_metric<3>(1);
  {
    Roof roof(0.6);  // a fat cap
    AdaptationMesh<3> am(roof.mesh, metric, nullptr, 45);
    ASSERT_GT(am.quality(roof.cap), kBoundaryOnlyQuality);
    EXPECT_EQ(remove_boundary_caps(am, AdaptationLimits{}).done, 0);
    EXPECT_EQ(roof.mesh.element_count(), 3);
  }
  {
    Roof roof(0.02);
    roof.mesh.required_triangles().push_back(roof.roof[0]);
    AdaptationMesh<3> am(roof.mesh, metric, nullptr, 45);
    const OperationCount count = remove_boundary_caps(am, AdaptationLimits{});
    EXPECT_EQ(count.done, 0);
    EXPECT_EQ(count.refused[static_cast<std::size_t>(Refusal::kClasses)], 1);
  }
  {
    // The valley's facets turn by about 2h = 2.3° from the roof's: more than a feature angle of 1°.
    Roof roof(0.02);
    AdaptationMesh<3> am(roof.mesh, metric, nullptr, 45);
    AdaptationLimits limits;
    limits.cos_feature_angle = std::cos(1 * std::numbers::pi / 180);
    const OperationCount count = remove_boundary_caps(am, limits);
    EXPECT_EQ(count.done, 0);
    EXPECT_EQ(count.refused[static_cast<std::size_t>(Refusal::kGeometry)], 1);
    EXPECT_EQ(roof.mesh.element_count(), 3);
  }
}

}  // namespace
}  // namespace hocav
