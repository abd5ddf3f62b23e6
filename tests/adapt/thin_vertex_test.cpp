// Inner vertices a hair above the boundary (docs/adaptation.md §Collapse, "Thin vertices"): the
// collapse removes them, which no other operator of the loop does.
#include <gtest/gtest.h>

#include "adapt/adaptation_operations.hpp"
#include "adapt_test_support.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

template <int D>
bool every_element_positive(const Mesh<D>& mesh) {
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (!(element_measure(mesh, k) > 0)) return false;
  return true;
}

// The structured cube's inner vertex at (1/4, 1/4, 1/4) lowered to `height` above the side z = 0.
Index lower_an_inner_vertex(Mesh<3>& mesh, double height) {
  Index v = 0;
  while (mesh.vertex(v) != Vec3{{0.25, 0.25, 0.25}}) ++v;
  mesh.vertex(v)[2] = height;
  return v;
}

TEST(ThinVertices, AnInnerVertexAHairAboveASideIsCollapsedOntoIt) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(4);
  const Index v = lower_an_inner_vertex(mesh, 1e-6);
  ASSERT_TRUE(every_element_positive(mesh));
  const AdaptationMetric<3> metric = adapt_test::uniform_metric<3>(0.25);  // 1e-6 is 4e-6 of the size across
  AdaptationMesh<3> am(mesh, metric, nullptr, 45);
  const OperationCount count = collapse_thin_vertices(am, AdaptationLimits{});
  EXPECT_EQ(count.done, 1);
  EXPECT_TRUE(mesh.vertex_removed(v));
  mesh.compact();
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_TRUE(every_element_positive(mesh));
}

TEST(ThinVertices, AVertexWellAboveASideStays) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(4);
  lower_an_inner_vertex(mesh, 0.05);
  const AdaptationMetric<3> metric = adapt_test::uniform_metric<3>(0.25);  // a fifth of the size across
  AdaptationMesh<3> am(mesh, metric, nullptr, 45);
  const OperationCount count = collapse_thin_vertices(am, AdaptationLimits{});
  EXPECT_EQ(count.done + count.refused_total(), 0);
}

}  // namespace
}  // namespace hocav
