// AdaptationMetric::partway_from: the metric of a distributed run's early iterations, the
// log-Euclidean way from a start field (the input's own metric) to the target.
#include "adapt/adaptation_metric.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "adapt_test_support.hpp"
#include "base/error.hpp"

namespace hocav {
namespace {

using adapt_test::unit_mesh;

MetricField<3> constant_field(const Mesh<3>& mesh, const Vec<3>& diagonal) {
  return MetricField<3>(mesh, std::vector<SymMat<3>>(static_cast<std::size_t>(mesh.vertex_count()), SymMat<3>::from_diagonal(diagonal)));
}

void expect_diagonal_near(const SymMat<3>& m, const Vec<3>& diagonal) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(m(i, i), diagonal[i], 1e-11 * diagonal[i]) << "entry " << i;
    for (int j = 0; j < i; ++j) EXPECT_NEAR(m(i, j), 0, 1e-11 * diagonal[0]) << "entry " << i << ", " << j;
  }
}

// Commuting metrics: the sizes at fraction t are h_start^(1-t) h_target^t in each direction.
TEST(GradualMetric, StepsFromTheStartToTheTargetByGeometricMeansOfTheSizes) {
  const Mesh<3> mesh = unit_mesh<3>(4);
  const MetricField<3> start = constant_field(mesh, {100, 100, 100});        // sizes 0.1
  const MetricField<3> target_field = constant_field(mesh, {1e6, 1e4, 25});  // sizes 0.001, 0.01, 0.2
  const AdaptationMetric<3> target(target_field, SizeBounds{});
  for (double t : {0.0, 1.0 / 3, 0.5, 1.0}) {
    Index hint = kNoIndex;
    const SymMat<3> m = target.partway_from(start, t).metric_at({0.3, 0.6, 0.2}, hint);
    expect_diagonal_near(
        m, {std::pow(100, 1 - t) * std::pow(1e6, t), std::pow(100, 1 - t) * std::pow(1e4, t), std::pow(100, 1 - t) * std::pow(25, t)});
    EXPECT_NE(hint, kNoIndex);
  }
}

// An analytic target, which needs no back mesh: the start is located all the same, and the
// bounds clamp the target before the blend.
TEST(GradualMetric, BlendsAnAnalyticTargetClampedByItsBounds) {
  const Mesh<3> mesh = unit_mesh<3>(3);
  const MetricField<3> start = constant_field(mesh, {100, 100, 100});
  AnalyticMetricSpec uniform;
  uniform.h = 0.001;
  const AdaptationMetric<3> target(uniform, SizeBounds{0.01, 1});  // clamped to 0.01
  Index hint = kNoIndex;
  expect_diagonal_near(target.partway_from(start, 0.5).metric_at({0.9, 0.1, 0.5}, hint), {1000, 1000, 1000});
  hint = kNoIndex;
  expect_diagonal_near(target.partway_from(start, 0).metric_at({0.9, 0.1, 0.5}, hint), {100, 100, 100});
}

TEST(GradualMetric, RefusesAStartOffTheTargetsBackMesh) {
  const MetricField<3> target_field = constant_field(unit_mesh<3>(4), {100, 100, 100});
  const MetricField<3> start = constant_field(unit_mesh<3>(3), {100, 100, 100});
  const AdaptationMetric<3> target(target_field, SizeBounds{});
  EXPECT_THROW(static_cast<void>(target.partway_from(start, 0.5)), Error);
}

}  // namespace
}  // namespace hocav
