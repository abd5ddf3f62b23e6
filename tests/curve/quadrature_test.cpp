#include "curve/quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "base/error.hpp"

namespace hocav {
namespace {

TEST(Quadrature, GaussLegendreIsExactUpToDegreeTwoNMinusOne) {
  for (int n : {1, 2, 3, 5, 8, 16, 33, 64}) {
    auto rule = gauss_legendre_rule(n);
    for (int degree = 0; degree <= 2 * n - 1; ++degree) {
      double integral = 0;
      for (int q = 0; q < n; ++q) integral += rule.weights[q] * std::pow(rule.nodes[q], degree);
      EXPECT_NEAR(integral, 1.0 / (degree + 1), 1e-14) << n << " points, degree " << degree;
    }
    // and not beyond: t^(2n) is integrated with an error (measurable for small n only).
    if (n > 8) continue;
    double integral = 0;
    for (int q = 0; q < n; ++q) integral += rule.weights[q] * std::pow(rule.nodes[q], 2 * n);
    EXPECT_GT(std::abs(integral - 1.0 / (2 * n + 1)), 1e-16);
  }
}

TEST(Quadrature, TrapezoidRuleIsTheThreePointRuleOfThePaper) {
  const auto& rule = trapezoid_rule();
  ASSERT_EQ(rule.nodes.size(), 3u);
  EXPECT_EQ(rule.nodes, (std::vector<double>{0, 0.5, 1}));
  EXPECT_EQ(rule.weights, (std::vector<double>{0.25, 0.5, 0.25}));
}

TEST(Quadrature, SimpsonIsExactForCubicsAndRulesAreFoundByName) {
  const auto& rule = simpson_rule();
  for (int degree = 0; degree <= 3; ++degree) {
    double integral = 0;
    for (std::size_t q = 0; q < rule.nodes.size(); ++q) integral += rule.weights[q] * std::pow(rule.nodes[q], degree);
    EXPECT_NEAR(integral, 1.0 / (degree + 1), 1e-15);
  }
  EXPECT_EQ(quadrature_rule_named("simpson").weights, rule.weights);
  EXPECT_EQ(quadrature_rule_named("trapezoid").weights, trapezoid_rule().weights);
  EXPECT_EQ(quadrature_rule_named("gauss-7").nodes.size(), 7u);
  EXPECT_EQ(&default_optimizer_rule(), &simpson_rule());
  for (const char* bad : {"gauss-", "gauss-x", "gauss-0", "gauss-999999999999", "midpoint"})
    EXPECT_THROW(quadrature_rule_named(bad), Error) << bad;
}

TEST(Quadrature, AdaptiveGaussKronrodIsExactToDegreeTwentyTwoOnOnePiece) {
  for (int degree = 0; degree <= 22; ++degree) {
    auto result = adaptive_integral([&](double t) { return (degree + 1) * std::pow(t, degree); }, 1e-300, 1, 1);
    EXPECT_NEAR(result.value, 1.0, 2e-15) << degree;
    EXPECT_EQ(result.evaluations, 15);
  }
  // The 7 embedded Gauss points are exact to degree 13 only: the estimate sees degree 14.
  EXPECT_LT(adaptive_integral([](double t) { return std::pow(t, 13); }, 1e-300, 1, 1).error_estimate, 1e-15);
  EXPECT_GT(adaptive_integral([](double t) { return std::pow(t, 14); }, 1e-300, 1, 1).error_estimate, 1e-9);
}

TEST(Quadrature, AdaptiveIntegralReachesItsToleranceOnSmoothAndKinkedIntegrands) {
  // Smooth: ∫ e^{10t} = (e^10 − 1)/10. Kinked (a jump of the derivative at an irrational point, as where an edge
  // crosses a back-mesh face): ∫ |t − 1/√3| + 1.
  const double kink = 1 / std::sqrt(3.0);
  const double smooth_exact = std::expm1(10.0) / 10, kinked_exact = 0.5 * (kink * kink + (1 - kink) * (1 - kink)) + 1;
  int smooth_previous = 0, kinked_previous = 0;
  for (double tolerance : {1e-3, 1e-6, 1e-9, 1e-12}) {
    auto smooth = adaptive_integral([](double t) { return std::exp(10 * t); }, tolerance);
    auto kinked = adaptive_integral([&](double t) { return std::abs(t - kink) + 1; }, tolerance);
    ASSERT_TRUE(smooth.converged && kinked.converged) << tolerance;
    EXPECT_LE(std::abs(smooth.value - smooth_exact), tolerance * smooth_exact) << tolerance;
    EXPECT_LE(std::abs(kinked.value - kinked_exact), tolerance * kinked_exact) << tolerance;
    // More evaluations for a tighter tolerance, but sensibly: a smooth integrand needs few more pieces, a kink
    // about one bisection (30 evaluations) per halving of the error.
    EXPECT_GE(smooth.evaluations, smooth_previous);
    EXPECT_GE(kinked.evaluations, kinked_previous);
    EXPECT_LE(smooth.evaluations, 150) << tolerance;
    EXPECT_LE(kinked.evaluations, 30 * std::log2(1 / tolerance) + 45) << tolerance;
    smooth_previous = smooth.evaluations;
    kinked_previous = kinked.evaluations;
  }
  EXPECT_GT(kinked_previous, 3 * smooth_previous / 2);
}

}  // namespace
}  // namespace hocav
