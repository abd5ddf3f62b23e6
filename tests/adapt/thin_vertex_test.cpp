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

// The structured cube in a metric 10,000 times finer along the side z = 0 than across it: the elements
// on that side are needles in the metric (quality far below 0.01), but their inner vertices lie a
// quarter of the size across above it.
TEST(ThinVertices, APoorElementsVertexWellAboveASideStays) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(4);
  mesh.build_topology();
  SymMat<3> needles;
  needles(0, 0) = needles(1, 1) = 1e8;  // sizes 1e-4 along the side
  needles(2, 2) = 1;                    // size 1 across it
  const MetricField<3> field(mesh, std::vector<SymMat<3>>(static_cast<std::size_t>(mesh.vertex_count()), needles));
  const AdaptationMetric<3> metric(field, SizeBounds{});
  AdaptationMesh<3> am(mesh, metric, nullptr, 45);
  Index poor = 0;
  for (Index k = 0; k < mesh.element_count(); ++k) poor += am.quality(k) < 1e-2;
  ASSERT_GT(poor, 0);
  const OperationCount count = collapse_thin_vertices(am, AdaptationLimits{});
  EXPECT_EQ(count.done + count.refused_total(), 0);
}

}  // namespace
}  // namespace hocav
