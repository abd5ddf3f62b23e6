// The adaptation's mesh keeps each element's quality with it (adapt/adaptation_mesh.hpp): after
// vertices move outside the operators, every element holding one is measured again.
#include <gtest/gtest.h>

#include "../mesh/pinched_mesh.hpp"
#include "adapt/adaptation_mesh.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

TEST(AdaptationMesh, AMovedVertexRenewsTheQualityOfEveryElementItHoldsWhereTwoPartsMeet) {
  Mesh<3> mesh = mesh_test::pinched_tetrahedra();
  mesh.build_topology();
  const AdaptationMetric<3> metric(AnalyticMetricSpec{}, {});
  AdaptationMesh<3> am(mesh, metric, nullptr, 45);
  const double before[2] = {am.quality(0), am.quality(1)};
  mesh.vertex(0) = Vec3{{0.2, 0.1, -0.1}};
  ASSERT_GT(signed_measure(mesh.vertex(0), mesh.vertex(5), mesh.vertex(4), mesh.vertex(6)), 0);
  const Index moved[] = {0};
  am.vertices_moved(moved);
  for (Index k = 0; k < 2; ++k) {
    EXPECT_NE(am.quality(k), before[k]) << "element " << k;
    EXPECT_DOUBLE_EQ(am.quality(k), am.quality(mesh.element(k))) << "element " << k;
  }
}

}  // namespace
}  // namespace hocav
