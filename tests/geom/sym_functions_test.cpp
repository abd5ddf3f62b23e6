#include "geom/sym_functions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <type_traits>

#include "base/error.hpp"
#include "random_matrices.hpp"

namespace hocav {
namespace {

using namespace geom_test;

template <class Dimension>
class SymFunctionsTest : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(SymFunctionsTest, Dimensions);

template <int D>
SymMat<D> random_direction(std::mt19937_64& rng) {
  SymMat<D> h;
  for (double& x : h.entries) x = std::uniform_real_distribution<double>(-1, 1)(rng);
  return h;
}

template <int D>
Mat<D> dense(const SymMat<D>& s) {
  Mat<D> a;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) a(i, j) = s(i, j);
  return a;
}

// Fourth-order central difference (f(−2h) − 8f(−h) + 8f(h) − f(2h))/12h: with h = 1e-3 its truncation error
// (~h⁴/30 f⁽⁵⁾) and rounding error (~eps·|θ|/h) both stay near 1e-11 of the scale of f.
template <class Function>
auto central_difference(Function f) {
  constexpr double kStep = 1e-3;
  return (8.0 * (f(kStep) - f(-kStep)) - (f(2 * kStep) - f(-2 * kStep))) * (1.0 / (12 * kStep));
}

TYPED_TEST(SymFunctionsTest, DiagonalMatricesWithHugeRatios) {
  constexpr int D = TypeParam::value;
  Vec<D> theta, lambda;
  for (int i = 0; i < D; ++i) theta[i] = kLogEigenvalueBound * (1.0 - 2.0 * i / (D - 1)), lambda[i] = std::exp(theta[i]);
  SymMat<D> m = SymMat<D>::from_diagonal(lambda), t = SymMat<D>::from_diagonal(theta);
  for (int i = 0; i < D; ++i) {
    EXPECT_NEAR(log_spd(m)(i, i), theta[i], 4 * kEpsilon * kLogEigenvalueBound);
    EXPECT_NEAR(exp_sym(t)(i, i) / lambda[i], 1.0, 8 * kEpsilon * kLogEigenvalueBound);
    EXPECT_NEAR(sqrt_spd(m)(i, i) / std::sqrt(lambda[i]), 1.0, 2 * kEpsilon);
    EXPECT_NEAR(pow_spd(m, -0.5)(i, i) * std::sqrt(lambda[i]), 1.0, 4 * kEpsilon);
  }
  EXPECT_LE(max_abs_entry(log_spd(exp_sym(t)) - t), 1e-14);
}

// log(exp(T)) = T up to the conditioning of the explicit metric exp(T): its entries are rounded relative to
// λmax, so the small eigenvalues carry a relative error up to eps·κ, and so does their logarithm. A result that
// rounding has made indefinite (only possible at κ ≈ 1/eps) must be refused.
TYPED_TEST(SymFunctionsTest, LogOfExpIsTheIdentityUpToConditioning) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(5);
  int refused = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    Vec<D> theta = log_eigenvalues_case<D>(rng, trial);
    SymMat<D> t = random_with_eigenvalues<D>(rng, theta);
    SymMat<D> m = exp_sym(t);
    double kappa = condition_number(theta);
    if (!is_spd(m)) {
      EXPECT_GT(kappa, 1e14);
      EXPECT_THROW(log_spd(m), Error);
      ++refused;
      continue;
    }
    double error = max_abs_entry(log_spd(m) - t);
    EXPECT_LE(error, 16 * kEpsilon * (kappa + kLogEigenvalueBound));
    if (kappa < 1e3) {
      EXPECT_LE(error, 1e-12);
    }
  }
  EXPECT_LT(refused, 400);
}

TYPED_TEST(SymFunctionsTest, ExpOfLogAndSquareRootsReturnTheMetric) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(6);
  for (int trial = 0; trial < 4000; ++trial) {
    Vec<D> theta = log_eigenvalues_case<D>(rng, trial);
    SymMat<D> m = exp_sym(random_with_eigenvalues<D>(rng, theta));
    if (!is_spd(m)) continue;  // see LogOfExpIsTheIdentityUpToConditioning
    double scale = max_abs_entry(m);
    EXPECT_LE(max_abs_entry(exp_sym(log_spd(m)) - m), 1e-13 * scale);
    SymMat<D> root = sqrt_spd(m);
    SymMat<D> square = congruence(dense(root), SymMat<D>::identity());  // root rootᵀ = root²
    EXPECT_LE(max_abs_entry(square - m), 1e-14 * scale);
    EXPECT_LE(max_abs_entry(pow_spd(m, 0.5) - root), 1e-14 * max_abs_entry(root));
    EXPECT_LE(max_abs_entry(pow_spd(m, 1.0) - m), 1e-14 * scale);
    // M^{-1/2} M M^{-1/2} = I, to the conditioning of M (past κ ≈ 1e12 the rounded M no longer pins λmin).
    double kappa = condition_number(theta);
    if (kappa < 1e12) {
      SymMat<D> whitened = congruence(dense(pow_spd(m, -0.5)), m);
      EXPECT_LE(max_abs_entry(whitened - SymMat<D>::identity()), 1e-14 + 32 * kEpsilon * kappa);
    }
  }
}

TYPED_TEST(SymFunctionsTest, PositiveDefinitenessCriterion) {
  constexpr int D = TypeParam::value;
  SymMat<D> identity = SymMat<D>::identity();
  EXPECT_TRUE(is_spd(identity));
  EXPECT_TRUE(is_spd(1e-300 * identity));
  EXPECT_TRUE(is_spd(1e300 * identity));
  EXPECT_FALSE(is_spd(SymMat<D>{}));
  SymMat<D> indefinite = identity;
  indefinite(0, 1) = 2.0;
  EXPECT_FALSE(is_spd(indefinite));
  SymMat<D> singular = identity;
  singular(0, 0) = singular(1, 1) = singular(0, 1) = 1.0;
  EXPECT_FALSE(is_spd(singular));
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    SymMat<D> m = identity;
    m(D - 1, 0) = bad;
    EXPECT_FALSE(is_spd(m));
    m = identity;
    m(1, 1) = bad;
    EXPECT_FALSE(is_spd(m));
  }
  EXPECT_THROW(log_spd(indefinite), Error);
  EXPECT_THROW(sqrt_spd(-identity), Error);
  EXPECT_THROW(pow_spd(singular, 2.0), Error);
}

TEST(SymFunctions, ExpDividedDifferences) {
  // Confluent values: exp[a, a] = e^a, exp[a, a, a] = e^a/2, exp[a, a, b] = (e^b − e^a − (b − a)e^a)/(b − a)².
  for (double a : {-80.0, -3.0, 0.0, 0.7, 60.0}) {
    EXPECT_NEAR(exp_divided_difference(a, a) / std::exp(a), 1.0, 2 * kEpsilon);
    EXPECT_NEAR(exp_divided_difference(a, a, a) / std::exp(a), 0.5, 2 * kEpsilon);
    double b = a + 3.0;
    EXPECT_NEAR(exp_divided_difference(a, b, a) / ((std::exp(b) - std::exp(a) - 3.0 * std::exp(a)) / 9.0), 1.0, 1e-14);
  }
  // Against long double quotients wherever their cancellation stays below 1e-16 (spreads ≥ 0.1), on both sides
  // of the switch between the series and the quotients.
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 20000; ++trial) {
    double a = std::uniform_real_distribution<double>(-20, 20)(rng);
    double spread = std::pow(10.0, std::uniform_real_distribution<double>(-1.0, 1.3)(rng));
    double b = a + spread * std::uniform_real_distribution<double>(0.3, 0.7)(rng), c = a + spread;
    auto quotient = [](long double x, long double y) { return (std::exp(x) - std::exp(y)) / (x - y); };
    long double first = quotient(a, c);
    long double second = (quotient(a, b) - quotient(b, c)) / (static_cast<long double>(a) - c);
    EXPECT_NEAR(exp_divided_difference(a, c) / static_cast<double>(first), 1.0, 1e-15);
    EXPECT_NEAR(exp_divided_difference(c, b, a) / static_cast<double>(second), 1.0, 4e-15);
  }
  // Nearly confluent arguments, against the Taylor expansion about the mean.
  for (double delta : {1e-3, 1e-6, 1e-10, 1e-15}) {
    double a = 0.4, mean = a + delta / 2;
    double expected = std::exp(mean) * (1.0 + delta * delta / 24.0);
    EXPECT_NEAR(exp_divided_difference(a, a + delta) / expected, 1.0, 4 * kEpsilon);
  }
}

// Dexp and D²exp against fourth-order central differences of exp and of Dexp, for log-metrics with
// eigenvalues up to 1e16 apart, repeated and nearly repeated ones included. Errors are measured against the
// scale of exp(T), since the directions H are of unit size.
TYPED_TEST(SymFunctionsTest, FrechetDerivativesMatchFiniteDifferences) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(8);
  for (int trial = 0; trial < 2000; ++trial) {
    SymMat<D> t = random_with_eigenvalues<D>(rng, log_eigenvalues_case<D>(rng, trial));
    SymMat<D> h1 = random_direction<D>(rng), h2 = random_direction<D>(rng);
    ExpFrechet<D> at_t(t);
    double scale = max_abs_entry(at_t.value());
    EXPECT_LE(max_abs_entry(at_t.value() - exp_sym(t)), 1e-15 * scale);
    SymMat<D> first = at_t.derivative(h1);
    SymMat<D> first_expected = central_difference([&](double s) { return exp_sym(t + s * h1); });
    EXPECT_LE(max_abs_entry(first - first_expected), 1e-9 * scale);
    SymMat<D> second = at_t.second_derivative(h1, h2);
    SymMat<D> second_expected = central_difference([&](double s) { return dexp(t + s * h2, h1); });
    EXPECT_LE(max_abs_entry(second - second_expected), 1e-9 * scale);
    EXPECT_LE(max_abs_entry(second - at_t.second_derivative(h2, h1)), 1e-14 * scale);
    EXPECT_EQ(dexp(t, h1), first);
    EXPECT_EQ(d2exp(t, h1, h2), second);
  }
}

// At T = θI every divided difference is e^θ (first order) or e^θ/2 (second order).
TYPED_TEST(SymFunctionsTest, FrechetDerivativesAtAMultipleOfTheIdentity) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(9);
  for (double theta : {-18.0, 0.0, 0.3, 18.0}) {
    SymMat<D> t = theta * SymMat<D>::identity();
    SymMat<D> h1 = random_direction<D>(rng), h2 = random_direction<D>(rng);
    ExpFrechet<D> at_t(t);
    double e = std::exp(theta);
    EXPECT_LE(max_abs_entry(at_t.derivative(h1) - e * h1), 4 * kEpsilon * e);
    // D²exp(θI)[H1, H2] = e^θ (H1 H2 + H2 H1)/2.
    Mat<D> product = dense(h1) * dense(h2);
    SymMat<D> expected;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j <= i; ++j) expected(i, j) = 0.5 * e * (product(i, j) + product(j, i));
    EXPECT_LE(max_abs_entry(at_t.second_derivative(h1, h2) - expected), 8 * kEpsilon * e);
  }
}

// Dexp(T) is self-adjoint, so the derivative of the squared length uᵀexp(T)u along any H is
// frobenius_dot(Dexp(T)[u uᵀ], H): what the edge optimizer uses to get a gradient from one derivative; the same
// symmetry holds for the second derivative.
TYPED_TEST(SymFunctionsTest, SquaredLengthAndItsGradient) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(10);
  for (int trial = 0; trial < 1000; ++trial) {
    SymMat<D> t = random_with_eigenvalues<D>(rng, log_eigenvalues_case<D>(rng, trial));
    ExpFrechet<D> at_t(t);
    double scale = max_abs_entry(at_t.value());
    Vec<D> u = random_vec<D>(rng, -1, 1);
    EXPECT_NEAR(at_t.squared_length(u), quadratic_form(at_t.value(), u), 1e-14 * scale);
    SymMat<D> gradient = at_t.squared_length_gradient(u);
    EXPECT_LE(max_abs_entry(gradient - at_t.derivative(outer(u))), 1e-14 * scale);
    SymMat<D> h = random_direction<D>(rng);
    EXPECT_NEAR(frobenius_dot(gradient, h), quadratic_form(at_t.derivative(h), u), 1e-13 * scale);
    double difference = central_difference([&](double s) { return ExpFrechet<D>(t + s * h).squared_length(u); });
    EXPECT_NEAR(frobenius_dot(gradient, h), difference, 1e-9 * scale);
    SymMat<D> other = random_direction<D>(rng);
    EXPECT_NEAR(frobenius_dot(at_t.second_derivative(h, outer(u)), other), quadratic_form(at_t.second_derivative(h, other), u),
                1e-13 * scale);
    // The Hessian along D directions at once, in the eigenbasis: entry (i, j) is uᵀ D²exp[Hi, Hj] u.
    std::array<SymMat<D>, D> directions;
    for (auto& direction : directions) direction = random_direction<D>(rng);
    SymMat<D> hessian = at_t.squared_length_hessian(directions, u);
    for (int i = 0; i < D; ++i)
      for (int j = 0; j <= i; ++j)
        EXPECT_NEAR(hessian(i, j), quadratic_form(at_t.second_derivative(directions[i], directions[j]), u), 1e-13 * scale);
  }
}

// Along the eigenvector of the smallest eigenvalue (sizes 1e8 times larger than along the largest), the
// squared length keeps its relative accuracy: it is e^θmin to rounding.
TYPED_TEST(SymFunctionsTest, SquaredLengthIsRelativelyAccurateAtAnyAnisotropy) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 1000; ++trial) {
    Vec<D> theta = random_vec<D>(rng, -kLogEigenvalueBound, kLogEigenvalueBound);
    theta[0] = -kLogEigenvalueBound, theta[D - 1] = kLogEigenvalueBound;
    Mat<D> rotation = random_rotation<D>(rng);
    ExpFrechet<D> at_t(SymMat<D>::from_eigen(rotation, theta));
    for (int k = 0; k < D; ++k) EXPECT_NEAR(at_t.squared_length(rotation.column(k)) / std::exp(theta[k]), 1.0, 1e-13);
  }
}

}  // namespace
}  // namespace hocav
