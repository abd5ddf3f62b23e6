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

}  // namespace
}  // namespace hocav
