#include "metric/straight_edge_length.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace hocav {
namespace {

TEST(StraightEdgeLength, MetricNormReadsTheLowerTriangleInSolOrder) {
  std::array<double, 3> identity2{1, 0, 1};
  EXPECT_DOUBLE_EQ(metric_norm(Vec2{{3, 4}}, identity2), 5);
  std::array<double, 3> m2{2, 1, 3};  // [[2 1] [1 3]]
  EXPECT_DOUBLE_EQ(metric_norm(Vec2{{1, -1}}, m2), std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(metric_norm(Vec2{{1, 1}}, m2), std::sqrt(7.0));
  // 3D order m11 m12 m22 m13 m23 m33: each off-diagonal term on its own.
  EXPECT_DOUBLE_EQ(metric_norm(Vec3{{1, 0, 1}}, std::array<double, 6>{1, 0, 1, 0.5, 0, 1}), std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(metric_norm(Vec3{{0, 1, 1}}, std::array<double, 6>{1, 0, 1, 0, 0.25, 1}), std::sqrt(2.5));
  EXPECT_DOUBLE_EQ(metric_norm(Vec3{{1, 1, 0}}, std::array<double, 6>{1, 0.5, 1, 0, 0, 1}), std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(metric_norm(Vec3{{0, 0, 2}}, std::array<double, 6>{1, 0, 1, 0, 0, 9}), 6);
}

TEST(StraightEdgeLength, LogarithmicMeanIsTheIntegralOfTheGeometricInterpolation) {
  // Length of an edge whose metric length varies as la^(1 - t) lb^t along it.
  auto integral = [](double la, double lb) {
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += std::pow(la, 1 - (i + 0.5) / n) * std::pow(lb, (i + 0.5) / n);
    return sum / n;
  };
  for (auto [la, lb] : {std::pair{0.3, 5.0}, std::pair{2.0, 1.0}, std::pair{1.0, 1.1}}) {
    EXPECT_NEAR(logarithmic_mean(la, lb), integral(la, lb), 1e-9) << la << " " << lb;
    EXPECT_DOUBLE_EQ(logarithmic_mean(la, lb), logarithmic_mean(lb, la));
  }
  EXPECT_DOUBLE_EQ(logarithmic_mean(2.0, 1.0), 1 / std::log(2.0));
}

TEST(StraightEdgeLength, LogarithmicMeanIsAccurateForCloseAndEqualEnds) {
  EXPECT_EQ(logarithmic_mean(0.7, 0.7), 0.7);
  EXPECT_EQ(logarithmic_mean(0.0, 0.0), 0.0);
  // la x / log(1 + x) = la (1 + x / 2 - x^2 / 12 + O(x^3)): the naive formula would lose half the digits.
  for (double x : {1e-10, 1e-6, -1e-5}) EXPECT_NEAR(logarithmic_mean(3.0, 3.0 * (1 + x)), 3.0 * (1 + x / 2 - x * x / 12), 1e-15);
}

TEST(StraightEdgeLength, UniformMetricGivesTheEuclideanLengthOverTheSize) {
  double h = 0.25;
  std::array<double, 6> metric{1 / (h * h), 0, 1 / (h * h), 0, 0, 1 / (h * h)};
  Vec3 a{{0.1, 0.2, 0.3}}, b{{0.4, -0.2, 0.3}};
  EXPECT_NEAR(straight_edge_length(a, b, metric, metric), norm(b - a) / h, 1e-14);
  // Ends with metrics h = 0.25 and h = 0.5 along the edge: between the two lengths.
  std::array<double, 6> coarse{4, 0, 4, 0, 0, 4};
  double length = straight_edge_length(a, b, metric, coarse);
  EXPECT_GT(length, norm(b - a) / 0.5);
  EXPECT_LT(length, norm(b - a) / 0.25);
  EXPECT_NEAR(length, logarithmic_mean(norm(b - a) / 0.25, norm(b - a) / 0.5), 1e-14);
}

}  // namespace
}  // namespace hocav
