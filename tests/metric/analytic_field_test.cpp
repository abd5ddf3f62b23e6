#include "metric/analytic_field.hpp"

#include <gtest/gtest.h>

#include <random>

#include "base/error.hpp"

namespace hocav {
namespace {

// Central second differences of u against the closed-form Hessian.
template <int D>
void expect_hessian_matches_finite_differences(const AnalyticFieldSpec& spec, const Vec<D>& x) {
  const double step = 1e-4;
  SymMat<D> exact = analytic_field_hessian<D>(spec, x);
  double scale = std::max(1.0, frobenius_norm(exact));
  for (int i = 0; i < D; ++i)
    for (int j = 0; j <= i; ++j) {
      Vec<D> di{}, dj{};
      di[i] = step;
      dj[j] = step;
      double difference = (analytic_field<D>(spec, x + di + dj) - analytic_field<D>(spec, x + di - dj) -
                           analytic_field<D>(spec, x - di + dj) + analytic_field<D>(spec, x - di - dj)) /
                          (4 * step * step);
      EXPECT_NEAR(difference, exact(i, j), 1e-5 * scale) << spec.name << " (" << i << ", " << j << ")";
    }
}

template <int D>
void expect_hessians_match(const AnalyticFieldSpec& spec) {
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for (int trial = 0; trial < 50; ++trial) {
    Vec<D> x;
    for (int i = 0; i < D; ++i) x[i] = coordinate(random);
    expect_hessian_matches_finite_differences<D>(spec, x);
  }
}

TEST(AnalyticField, HessiansAreTheSecondDerivativesOfTheFields) {
  for (const std::string& name : analytic_field_names()) {
    AnalyticFieldSpec spec{name, 0.6, 0.2, {0.1, -0.2, 0.05}};
    expect_hessians_match<2>(spec);
    expect_hessians_match<3>(spec);
  }
}

TEST(AnalyticField, ShockIsAStepAcrossTheCircle) {
  AnalyticFieldSpec shock{"tanh-shock", 0.5, 0.01, {1, 1, 0}};
  EXPECT_NEAR(analytic_field<2>(shock, Vec2{{1.5, 1}}), 0, 1e-15);
  EXPECT_NEAR(analytic_field<2>(shock, Vec2{{1.2, 1}}), -1, 1e-12);
  EXPECT_NEAR(analytic_field<2>(shock, Vec2{{1, 1.8}}), 1, 1e-12);
  // At the centre of the layer f'' = 0 across it, and f'/r = 1/(width · radius) along it.
  SymMat2 at_centre = analytic_field_hessian<2>(shock, Vec2{{1.5, 1}});
  EXPECT_NEAR(at_centre(0, 0), 0, 1e-9);
  EXPECT_NEAR(at_centre(1, 1), (1 / shock.width) / shock.radius, 1e-9);
  // At the origin, where e_r is undefined: f''(0) I.
  AnalyticFieldSpec wide{"tanh-shock", 0.5, 1, {0, 0, 0}};
  double t = std::tanh(-0.5);
  EXPECT_EQ(analytic_field_hessian<3>(wide, Vec3{}), -2 * t * (1 - t * t) * SymMat3::identity());
}

TEST(AnalyticField, RefusesUnknownNamesAndBadWidths) {
  EXPECT_THROW(analytic_field<2>(AnalyticFieldSpec{"sine"}, Vec2{}), Error);
  EXPECT_THROW(analytic_field_hessian<3>(AnalyticFieldSpec{"sine"}, Vec3{}), Error);
  EXPECT_THROW(analytic_field<2>(AnalyticFieldSpec{"tanh-shock", 1, 0}, Vec2{}), Error);
}

}  // namespace
}  // namespace hocav
