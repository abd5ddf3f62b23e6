#include "curve/edge_length.hpp"

#include <gtest/gtest.h>

#include <random>

#include "geom/sym_functions.hpp"

namespace hocav {
namespace {

template <int D>
SymMat<D> random_log_metric(std::mt19937& random, double spread) {
  // A random rotation of random log-eigenvalues in [−spread, spread].
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> eigenvalue(-spread, spread);
  SymMat<D> s;
  for (double& e : s.entries) e = gauss(random);
  auto eigen = sym_eigen(s);
  Vec<D> values;
  for (int i = 0; i < D; ++i) values[i] = eigenvalue(random);
  return SymMat<D>::from_eigen(eigen.vectors, values);
}

// ℓ(X) with L^L affine in X, as it is inside one back element.
template <int D>
struct AffineCase {
  Vec<D> a, b, node;
  SymMat<D> log_a, log_b, log_at_node;
  std::array<SymMat<D>, D> slope;
  SymMat<D> log_node(const Vec<D>& x) const {
    SymMat<D> value = log_at_node;
    for (int i = 0; i < D; ++i) value += (x[i] - node[i]) * slope[i];
    return value;
  }
};

template <int D>
AffineCase<D> random_case(std::mt19937& random, double spread) {
  std::uniform_real_distribution<double> unit(0, 1), offset(-0.3, 0.3);
  AffineCase<D> c;
  for (int i = 0; i < D; ++i) c.a[i] = unit(random), c.b[i] = unit(random);
  double size = norm(c.b - c.a);
  c.node = 0.5 * (c.a + c.b);
  for (int i = 0; i < D; ++i) c.node[i] += offset(random) * size;
  c.log_a = random_log_metric<D>(random, spread);
  c.log_b = random_log_metric<D>(random, spread);
  c.log_at_node = random_log_metric<D>(random, spread);
  for (auto& s : c.slope) s = (1 / size) * random_log_metric<D>(random, 1.0);
  return c;
}

template <int D>
void check_derivatives_against_finite_differences(const QuadratureRule& rule, double spread, std::uint32_t seed) {
  using Order = typename EdgeLengthFunction<D>::Order;
  std::mt19937 random(seed);
  double worst_gradient = 0, worst_hessian = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    auto c = random_case<D>(random, spread);
    EdgeLengthFunction<D> f(c.a, c.b, c.log_a, c.log_b, rule);
    auto value = f.evaluate(c.node, c.log_node(c.node), c.slope, Order::kHessian);
    EXPECT_NEAR(f.length(c.node, c.log_node(c.node)), value.length, 1e-14 * value.length);
    const double step = 1e-6 * norm(c.b - c.a);
    Vec<D> fd_gradient;
    std::array<Vec<D>, D> fd_hessian;
    for (int i = 0; i < D; ++i) {
      Vec<D> plus = c.node, minus = c.node;
      plus[i] += step;
      minus[i] -= step;
      fd_gradient[i] = (f.length(plus, c.log_node(plus)) - f.length(minus, c.log_node(minus))) / (2 * step);
      auto g_plus = f.evaluate(plus, c.log_node(plus), c.slope, Order::kGradient).gradient;
      auto g_minus = f.evaluate(minus, c.log_node(minus), c.slope, Order::kGradient).gradient;
      fd_hessian[i] = (1 / (2 * step)) * (g_plus - g_minus);
    }
    double gradient_scale = norm(value.gradient) + 1e-3 * value.length / norm(c.b - c.a);
    worst_gradient = std::max(worst_gradient, norm(fd_gradient - value.gradient) / gradient_scale);
    double hessian_scale = frobenius_norm(value.hessian) + 1e-3 * value.length / std::pow(norm(c.b - c.a), 2);
    double hessian_error = 0;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) hessian_error += std::pow(fd_hessian[i][j] - value.hessian(i, j), 2);
    worst_hessian = std::max(worst_hessian, std::sqrt(hessian_error) / hessian_scale);
  }
  EXPECT_LT(worst_gradient, 1e-6) << rule.name;
  EXPECT_LT(worst_hessian, 1e-5) << rule.name;
}

TEST(EdgeLength, GradientAndHessianMatchFiniteDifferences2D) {
  check_derivatives_against_finite_differences<2>(trapezoid_rule(), 4.6, 1);  // sizes up to 1e2 apart
  check_derivatives_against_finite_differences<2>(gauss_legendre_rule(5), 4.6, 2);
}

TEST(EdgeLength, GradientAndHessianMatchFiniteDifferences3D) {
  check_derivatives_against_finite_differences<3>(trapezoid_rule(), 4.6, 3);
  check_derivatives_against_finite_differences<3>(gauss_legendre_rule(5), 4.6, 4);
}

// The curvature along one direction d is dᵀHd, H the full Hessian, for rules with and without the middle node
// and with nodes where both the tangent and the metric move (Gauss), at anisotropy up to 1e4: the two agree to
// rounding (~1e-12 of the Hessian there), where a wrong term would be of its order.
template <int D>
void check_curvature_is_the_hessian_along_a_direction(const QuadratureRule& rule, std::uint32_t seed) {
  using Order = typename EdgeLengthFunction<D>::Order;
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss;
  for (int trial = 0; trial < 500; ++trial) {
    auto c = random_case<D>(random, 9.2);
    EdgeLengthFunction<D> f(c.a, c.b, c.log_a, c.log_b, rule);
    const auto value = f.evaluate(c.node, c.log_node(c.node), c.slope, Order::kHessian);
    Vec<D> d;
    for (int i = 0; i < D; ++i) d[i] = gauss(random);
    SymMat<D> log_derivative;
    for (int i = 0; i < D; ++i) log_derivative += d[i] * c.slope[i];
    const double scale = (frobenius_norm(value.hessian) + 1e-3 * value.length / std::pow(norm(c.b - c.a), 2)) * dot(d, d);
    EXPECT_NEAR(f.curvature(c.node, c.log_node(c.node), d, log_derivative), dot(d, value.hessian * d), 1e-10 * scale)
        << rule.name << " trial " << trial;
  }
}

TEST(EdgeLength, CurvatureIsTheHessianAlongADirection) {
  const QuadratureRule gauss = gauss_legendre_rule(5);
  for (const QuadratureRule* rule : {&default_optimizer_rule(), &trapezoid_rule(), &gauss}) {
    check_curvature_is_the_hessian_along_a_direction<2>(*rule, 6);
    check_curvature_is_the_hessian_along_a_direction<3>(*rule, 7);
  }
}

TEST(EdgeLength, DerivativesHoldAtAnisotropyTenThousand) {
  check_derivatives_against_finite_differences<3>(trapezoid_rule(), 9.2, 5);  // log(1e4) = 9.2
}

TEST(EdgeLength, StraightEdgeInAUniformMetricHasItsMetricLength) {
  const double h = 0.2;
  SymMat<3> log_metric = std::log(1 / (h * h)) * SymMat<3>::identity();
  Vec3 a{{0, 0, 0}}, b{{0.3, 0.4, 1.2}};
  for (const auto* rule : {&trapezoid_rule(), &high_precision_rule()}) {
    EdgeLengthFunction<3> f(a, b, log_metric, log_metric, *rule);
    EXPECT_NEAR(f.length(0.5 * (a + b), log_metric), norm(b - a) / h, 1e-12);
  }
}

}  // namespace
}  // namespace hocav
