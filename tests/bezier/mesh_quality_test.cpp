#include "bezier/mesh_quality.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "cases/structured.hpp"

namespace hocav {
namespace {

TEST(BezierMeshQuality, StraightMeshIsOneEverywhere) {
  const Mesh<3> mesh = generate_cube(3);
  const std::vector<JacobianQuality> qualities = mesh_jacobian_quality(mesh);
  ASSERT_EQ(Index(qualities.size()), mesh.element_count());
  for (const JacobianQuality& quality : qualities) {
    EXPECT_NEAR(quality.min_normalized_jacobian, 1.0, 1e-12);
    EXPECT_NEAR(quality.scaled_jacobian, 1.0, 1e-12);
  }
  const MeshJacobianSummary summary = summarize_jacobian_quality(qualities);
  EXPECT_EQ(summary.min_normalized_jacobian.count, mesh.element_count());
  EXPECT_NEAR(summary.min_normalized_jacobian.min, 1.0, 1e-12);
  EXPECT_NEAR(summary.min_normalized_jacobian.average, 1.0, 1e-12);
  EXPECT_EQ(summary.min_normalized_jacobian.invalid_count, 0);
  EXPECT_EQ(summary.scaled_jacobian.histogram.back() + summary.scaled_jacobian.above, mesh.element_count());
}

TEST(BezierMeshQuality, MovedNodeCurvesItsShellAndCanInvalidateIt) {
  Mesh<2> mesh = generate_square(2);
  mesh.make_p2();
  // An interior edge: both of its triangles change. A small move keeps them valid, a large one
  // folds at least one of them.
  Index interior = kNoIndex;
  for (Index e = 0; e < mesh.edge_count() && interior == kNoIndex; ++e) {
    const auto& ends = mesh.edge_vertices(e);
    const Vec2 middle = 0.5 * (mesh.vertex(ends[0]) + mesh.vertex(ends[1]));
    if (middle[0] > 0.1 && middle[0] < 0.9 && middle[1] > 0.1 && middle[1] < 0.9) interior = e;
  }
  ASSERT_NE(interior, kNoIndex);
  const Vec2 straight = mesh.edge_node(interior);

  mesh.edge_node(interior) = straight + Vec2{{0.02, 0.01}};
  std::vector<JacobianQuality> qualities = mesh_jacobian_quality(mesh);
  MeshJacobianSummary summary = summarize_jacobian_quality(qualities);
  EXPECT_EQ(summary.min_normalized_jacobian.invalid_count, 0);
  EXPECT_LT(summary.min_normalized_jacobian.min, 1.0);
  const auto curved = std::count_if(qualities.begin(), qualities.end(),
                                    [](const JacobianQuality& quality) { return quality.scaled_jacobian < 1.0 - 1e-9; });
  EXPECT_EQ(curved, 2);  // the two triangles of the edge, and only they

  mesh.edge_node(interior) = straight + Vec2{{0.3, 0.4}};
  summary = summarize_jacobian_quality(mesh_jacobian_quality(mesh));
  EXPECT_GE(summary.min_normalized_jacobian.invalid_count, 1);
  EXPECT_LT(summary.min_normalized_jacobian.min, 0.0);
  EXPECT_GE(summary.min_normalized_jacobian.below, 1);
}

TEST(BezierMeshQuality, SummaryOfValues) {
  const std::vector<double> values{-0.5, 0.0, 0.05, 0.5, 0.95, 1.0, 3.0};
  const ValueSummary summary = summarize_values(values, 10, 0.0, 1.0);
  EXPECT_EQ(summary.count, 7);
  EXPECT_DOUBLE_EQ(summary.min, -0.5);
  EXPECT_DOUBLE_EQ(summary.max, 3.0);
  EXPECT_DOUBLE_EQ(summary.average, 5.0 / 7.0);
  EXPECT_EQ(summary.invalid_count, 2);
  EXPECT_EQ(summary.below, 1);
  EXPECT_EQ(summary.above, 1);
  EXPECT_EQ(summary.histogram, (std::vector<Index>{2, 0, 0, 0, 0, 1, 0, 0, 0, 2}));
  EXPECT_EQ(summarize_values({}, 4, 0.0, 1.0).count, 0);
}

// Two sets summarized apart and merged: the summary of both (a distributed mesh's parts).
TEST(BezierMeshQuality, MergedSummariesAreTheSummaryOfBoth) {
  const std::vector<double> first{-0.5, 0.0, 0.05, 0.5}, second{0.95, 1.0, 3.0, 0.31, 0.32};
  std::vector<double> both = first;
  both.insert(both.end(), second.begin(), second.end());
  const ValueSummary whole = summarize_values(both, 10, 0.0, 1.0);
  const ValueSummary merged = merge_summaries(summarize_values(first, 10, 0.0, 1.0), summarize_values(second, 10, 0.0, 1.0));
  EXPECT_EQ(merged.count, whole.count);
  EXPECT_EQ(merged.min, whole.min);
  EXPECT_EQ(merged.max, whole.max);
  EXPECT_NEAR(merged.average, whole.average, 1e-15);
  EXPECT_EQ(merged.invalid_count, whole.invalid_count);
  EXPECT_EQ(merged.below, whole.below);
  EXPECT_EQ(merged.above, whole.above);
  EXPECT_EQ(merged.histogram, whole.histogram);
  // An empty side changes nothing, on either side.
  const ValueSummary none = summarize_values({}, 10, 0.0, 1.0);
  EXPECT_EQ(merge_summaries(none, whole).histogram, whole.histogram);
  EXPECT_EQ(merge_summaries(whole, none).min, whole.min);
  EXPECT_THROW(merge_summaries(whole, summarize_values(first, 4, 0.0, 1.0)), std::logic_error);
}

}  // namespace
}  // namespace hocav
