#include "curve/curved_quality.hpp"

#include <gtest/gtest.h>

#include <random>

#include "geom/sym_functions.hpp"
#include "metric/metric_quality.hpp"

namespace hocav {
namespace {

// A P2 element with straight edges (mid nodes at the middles) on these vertices.
template <int D>
P2Element<D> straight(const std::array<Vec<D>, D + 1>& vertices) {
  P2Element<D> element;
  for (int i = 0; i <= D; ++i) element.nodes[static_cast<std::size_t>(i)] = vertices[static_cast<std::size_t>(i)];
  for (int e = 0; e < Simplex<D>::kEdges; ++e) {
    const auto& ends = edge_vertices<D>(e);
    element.nodes[static_cast<std::size_t>(D + 1 + e)] = 0.5 * (vertices[ends[0]] + vertices[ends[1]]);
  }
  return element;
}

template <int D>
std::array<Vec<D>, D + 1> skewed_vertices() {
  if constexpr (D == 2)
    return {Vec2{{0.1, 0.2}}, Vec2{{1.3, 0.1}}, Vec2{{0.4, 0.9}}};
  else
    return {Vec3{{0.1, 0.2, 0.0}}, Vec3{{1.3, 0.1, 0.2}}, Vec3{{0.4, 0.9, 0.1}}, Vec3{{0.5, 0.3, 1.1}}};
}

template <int D>
SymMat<D> anisotropic_metric() {
  SymMat<D> m = SymMat<D>::identity();
  m(0, 0) = 4.0;
  m(1, 0) = 0.7;
  if constexpr (D == 3) m(2, 1) = -0.3;
  return m;
}

template <int D>
void expect_p1_quality_on_straight_elements() {
  const auto vertices = skewed_vertices<D>();
  const SymMat<D> metric = anisotropic_metric<D>();
  std::array<SymMat<D>, D + 1> logs;
  logs.fill(log_spd(metric));
  SimplexPoints<D> points;
  for (int i = 0; i <= D; ++i) points[static_cast<std::size_t>(i)] = vertices[static_cast<std::size_t>(i)];
  EXPECT_NEAR(curved_mean_ratio<D>(straight<D>(vertices), logs).value, metric_mean_ratio<D>(points, metric), 1e-13);
}

TEST(CurvedQuality, EqualsTheP1QualityOnStraightElementsInAConstantMetric) {
  expect_p1_quality_on_straight_elements<2>();
  expect_p1_quality_on_straight_elements<3>();
}

template <int D>
void expect_one_on_the_regular_element_and_less_when_curved() {
  std::array<Vec<D>, D + 1> regular;
  regular[1][0] = 1;
  regular[2][0] = 0.5, regular[2][1] = std::sqrt(3.0) / 2;
  if constexpr (D == 3) regular[3][0] = 0.5, regular[3][1] = std::sqrt(3.0) / 6, regular[3][2] = std::sqrt(2.0 / 3.0);
  std::array<SymMat<D>, D + 1> identity_logs{};
  P2Element<D> element = straight<D>(regular);
  EXPECT_NEAR(curved_mean_ratio<D>(element, identity_logs).value, 1.0, 1e-13);
  element.nodes[D + 1][1] -= 0.1;  // edge 0 bent outward
  const double bent = curved_mean_ratio<D>(element, identity_logs).value;
  EXPECT_LT(bent, 0.99);
  EXPECT_GT(bent, 0.5);
  element.nodes[D + 1][1] += 1.5;  // far inward: the Jacobian changes sign near the edge's middle
  EXPECT_LT(curved_mean_ratio<D>(element, identity_logs).value, bent);
}

TEST(CurvedQuality, IsOneOnTheRegularElementAndLowerWhenAnEdgeBends) {
  expect_one_on_the_regular_element_and_less_when_curved<2>();
  expect_one_on_the_regular_element_and_less_when_curved<3>();
}

template <int D>
void expect_gradient_matches_finite_differences(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.08, 0.08);
  P2Element<D> element = straight<D>(skewed_vertices<D>());
  for (auto& node : element.nodes)
    for (int a = 0; a < D; ++a) node[a] += jitter(random);
  std::array<SymMat<D>, D + 1> logs;
  for (int i = 0; i <= D; ++i) logs[static_cast<std::size_t>(i)] = log_spd((1.0 + 0.5 * i) * anisotropic_metric<D>());
  const CurvedQuality<D> q = curved_mean_ratio<D>(element, logs);
  const double step = 1e-6;
  for (std::size_t n = 0; n < element.nodes.size(); ++n)
    for (int a = 0; a < D; ++a) {
      P2Element<D> plus = element, minus = element;
      plus.nodes[n][a] += step;
      minus.nodes[n][a] -= step;
      const double fd = (curved_mean_ratio<D>(plus, logs).value - curved_mean_ratio<D>(minus, logs).value) / (2 * step);
      EXPECT_NEAR(q.gradient[n][a], fd, 1e-7 * (1 + std::abs(fd))) << "node " << n << " coordinate " << a;
    }
}

TEST(CurvedQuality, GradientMatchesFiniteDifferences) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    expect_gradient_matches_finite_differences<2>(seed);
    expect_gradient_matches_finite_differences<3>(seed);
  }
}

}  // namespace
}  // namespace hocav
