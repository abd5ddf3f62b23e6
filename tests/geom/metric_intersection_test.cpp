#include "geom/metric_intersection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <type_traits>

#include "base/error.hpp"
#include "geom/sym_eigen.hpp"
#include "geom/sym_functions.hpp"
#include "random_matrices.hpp"

namespace hocav {
namespace {

using namespace geom_test;

template <class Dimension>
class MetricIntersectionTest : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(MetricIntersectionTest, Dimensions);

// A random metric with sizes spread over up to 1e8 (the k-th case of log_eigenvalues_case), kept explicit:
// returns its log-eigenvalues too, for the condition number.
template <int D>
SymMat<D> random_metric(std::mt19937_64& rng, int k, Vec<D>& theta) {
  theta = log_eigenvalues_case<D>(rng, k);
  Vec<D> lambda;
  for (int i = 0; i < D; ++i) lambda[i] = std::exp(theta[i]);
  return random_with_eigenvalues<D>(rng, lambda);
}

TYPED_TEST(MetricIntersectionTest, DiagonalMetricsGiveTheEntrywiseMaximum) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(20);
  for (int trial = 0; trial < 1000; ++trial) {
    Vec<D> a = random_vec<D>(rng, -kLogEigenvalueBound, kLogEigenvalueBound);
    Vec<D> b = random_vec<D>(rng, -kLogEigenvalueBound, kLogEigenvalueBound);
    if (trial % 4 == 0) b[0] = a[0];
    Vec<D> larger;
    for (int i = 0; i < D; ++i) a[i] = std::exp(a[i]), b[i] = std::exp(b[i]), larger[i] = std::max(a[i], b[i]);
    SymMat<D> result = intersect_metrics(SymMat<D>::from_diagonal(a), SymMat<D>::from_diagonal(b));
    for (int i = 0; i < D; ++i) {
      EXPECT_NEAR(result(i, i) / larger[i], 1.0, 4 * kEpsilon);
      for (int j = 0; j < i; ++j) EXPECT_EQ(result(i, j), 0.0);
    }
  }
}

// M1∩M2 ≥ M1 and ≥ M2 to rounding, whatever the conditioning: the smallest eigenvalue of the difference is
// above −(a few tens of) eps·‖M1∩M2‖. Also |v|_{M1∩M2} ≥ max(|v|_M1, |v|_M2) for random v.
TYPED_TEST(MetricIntersectionTest, ContainsBothMetrics) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(21);
  for (int trial = 0; trial < 4000; ++trial) {
    Vec<D> theta1, theta2;
    SymMat<D> m1 = random_metric<D>(rng, trial, theta1), m2 = random_metric<D>(rng, trial / 8, theta2);
    if (!is_spd(m1) || !is_spd(m2)) continue;  // rounded to indefinite at κ ≈ 1/eps
    SymMat<D> result = intersect_metrics(m1, m2);
    double scale = max_abs_entry(result);
    EXPECT_GE(spd_eigen(result - m1).values[0], -32 * kEpsilon * scale);
    EXPECT_GE(spd_eigen(result - m2).values[0], -32 * kEpsilon * scale);
    for (int k = 0; k < 4; ++k) {
      Vec<D> v = random_vec<D>(rng, -1, 1);
      double larger = std::max(quadratic_form(m1, v), quadratic_form(m2, v));
      EXPECT_GE(quadratic_form(result, v), larger - 32 * kEpsilon * scale * dot(v, v));
    }
  }
}

// M∩M = M and M1∩M2 = M2∩M1, to about eps·sqrt(κ)·‖M1∩M2‖ (κ the larger condition number of the inputs).
TYPED_TEST(MetricIntersectionTest, IdempotentAndCommutative) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(22);
  for (int trial = 0; trial < 4000; ++trial) {
    Vec<D> theta1, theta2;
    SymMat<D> m1 = random_metric<D>(rng, trial, theta1), m2 = random_metric<D>(rng, trial / 8, theta2);
    if (!is_spd(m1) || !is_spd(m2)) continue;
    double kappa = std::max(condition_number(theta1), condition_number(theta2));
    double tolerance = 32 * kEpsilon * (1.0 + std::sqrt(kappa));
    EXPECT_LE(max_abs_entry(intersect_metrics(m1, m1) - m1), tolerance * max_abs_entry(m1));
    SymMat<D> result = intersect_metrics(m1, m2);
    EXPECT_LE(max_abs_entry(intersect_metrics(m2, m1) - result), tolerance * max_abs_entry(result));
  }
}

// Nested metrics: the larger one is the intersection. Also covariance under a change of basis,
// (A M1 Aᵀ)∩(A M2 Aᵀ) = A (M1∩M2) Aᵀ, on moderately anisotropic metrics.
TYPED_TEST(MetricIntersectionTest, NestedMetricsAndChangeOfBasis) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(23);
  for (int trial = 0; trial < 1000; ++trial) {
    SymMat<D> m = random_with_eigenvalues<D>(rng, random_vec<D>(rng, 0.01, 100));
    Vec<D> u = random_vec<D>(rng, -1, 1);
    SymMat<D> larger = m + outer(u);
    double scale = max_abs_entry(larger);
    EXPECT_LE(max_abs_entry(intersect_metrics(m, larger) - larger), 1e-12 * scale);
    EXPECT_LE(max_abs_entry(intersect_metrics(larger, m) - larger), 1e-12 * scale);
    EXPECT_LE(max_abs_entry(intersect_metrics(m, 0.5 * m) - m), 1e-14 * max_abs_entry(m));

    SymMat<D> other = random_with_eigenvalues<D>(rng, random_vec<D>(rng, 0.01, 100));
    Mat<D> a = random_rotation<D>(rng);
    for (int j = 0; j < D; ++j) a.set_column(j, a.column(j) * std::uniform_real_distribution<double>(0.5, 2)(rng));
    SymMat<D> expected = congruence(a, intersect_metrics(m, other));
    SymMat<D> got = intersect_metrics(congruence(a, m), congruence(a, other));
    EXPECT_LE(max_abs_entry(got - expected), 1e-11 * max_abs_entry(expected));
  }
}

TYPED_TEST(MetricIntersectionTest, RefusesMatricesThatAreNotMetrics) {
  constexpr int D = TypeParam::value;
  SymMat<D> identity = SymMat<D>::identity(), indefinite = identity;
  indefinite(0, 0) = -1.0;
  EXPECT_THROW(intersect_metrics(indefinite, identity), Error);
  EXPECT_THROW(intersect_metrics(identity, indefinite), Error);
  EXPECT_THROW(intersect_metrics(identity, SymMat<D>{}), Error);
}

}  // namespace
}  // namespace hocav
