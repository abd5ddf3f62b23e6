#include "geom/sym_eigen.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <type_traits>

#include "geom/mat.hpp"
#include "geom/sym_mat.hpp"
#include "random_matrices.hpp"

namespace hocav {
namespace {

using namespace geom_test;

// ‖M − V Λ Vᵀ‖_F / ‖M‖_F, computed on M scaled by a power of two so that 1e±300 entries neither overflow nor
// underflow when squared.
template <int D>
double reconstruction_error(const SymMat<D>& m, const SymEigen<D>& eigen) {
  double largest = max_abs_entry(m);
  if (largest == 0.0) return max_abs_entry(SymMat<D>::from_eigen(eigen.vectors, eigen.values));
  int exponent = 0;
  std::frexp(largest, &exponent);
  double scale = std::ldexp(1.0, -exponent);
  SymMat<D> scaled = m * scale;
  return frobenius_norm(scaled - SymMat<D>::from_eigen(eigen.vectors, eigen.values * scale)) / frobenius_norm(scaled);
}

template <int D>
double orthonormality_error(const Mat<D>& v) {
  Mat<D> gram = transpose(v) * v;
  double worst = 0.0;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) worst = std::max(worst, std::abs(gram(i, j) - (i == j ? 1.0 : 0.0)));
  return worst;
}

template <int D>
void expect_sound(const SymMat<D>& m, const SymEigen<D>& eigen, double tolerance = 1e-14) {
  EXPECT_LE(reconstruction_error(m, eigen), tolerance);
  EXPECT_LE(orthonormality_error(eigen.vectors), tolerance);
  for (int k = 1; k < D; ++k) EXPECT_LE(eigen.values[k - 1], eigen.values[k]);
}

template <class Dimension>
class SymEigenTest : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(SymEigenTest, Dimensions);

TEST(SymMat, StorageFollowsTheGammaOrder) {
  SymMat3 s{{11, 12, 22, 13, 23, 33}};
  EXPECT_EQ(s(0, 0), 11);
  EXPECT_EQ(s(0, 1), 12);
  EXPECT_EQ(s(1, 0), 12);
  EXPECT_EQ(s(1, 1), 22);
  EXPECT_EQ(s(0, 2), 13);
  EXPECT_EQ(s(2, 0), 13);
  EXPECT_EQ(s(1, 2), 23);
  EXPECT_EQ(s(2, 1), 23);
  EXPECT_EQ(s(2, 2), 33);
  SymMat2 t{{11, 12, 22}};
  EXPECT_EQ(t(1, 0), 12);
  EXPECT_EQ(t(1, 1), 22);
}

TEST(SymMat, ArithmeticAndForms) {
  SymMat3 s{{4, 1, 3, 0.5, -1, 2}};  // m11 m12 m22 m13 m23 m33
  EXPECT_DOUBLE_EQ(trace(s), 9.0);
  // det = 4(3·2 − 1) − 1(1·2 − (−1)(0.5)) + 0.5(1·(−1) − 3·0.5) = 20 − 2.5 − 1.25
  EXPECT_DOUBLE_EQ(determinant(s), 16.25);
  EXPECT_DOUBLE_EQ(determinant(SymMat2{{2, 1, 3}}), 5.0);
  Vec3 v{{1, -2, 3}};
  Vec3 sv = s * v;
  EXPECT_EQ(sv, (Vec3{{4 - 2 + 1.5, 1 - 6 - 3, 0.5 + 2 + 6}}));
  EXPECT_DOUBLE_EQ(quadratic_form(s, v), dot(v, sv));
  EXPECT_EQ(SymMat3::identity() * v, v);
  EXPECT_EQ((s + s - 0.5 * s) * 2.0, 3.0 * s);
  EXPECT_EQ(SymMat3::from_diagonal(Vec3{{1, 2, 3}}), (SymMat3{{1, 0, 2, 0, 0, 3}}));
  EXPECT_DOUBLE_EQ(frobenius_dot(s, SymMat3::identity()), trace(s));
  EXPECT_DOUBLE_EQ(frobenius_dot(outer(v), SymMat3::identity()), dot(v, v));
  EXPECT_DOUBLE_EQ(frobenius_dot(s, outer(v)), quadratic_form(s, v));  // off-diagonal entries count twice
}

TYPED_TEST(SymEigenTest, CongruenceMatchesDenseProducts) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 100; ++trial) {
    Mat<D> a;
    for (double& x : a.entries) x = std::uniform_real_distribution<double>(-1, 1)(rng);
    SymMat<D> s;
    for (double& x : s.entries) x = std::uniform_real_distribution<double>(-1, 1)(rng);
    Mat<D> dense;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) dense(i, j) = s(i, j);
    Mat<D> expected = a * dense * transpose(a), expected_transposed = transpose(a) * dense * a;
    SymMat<D> got = congruence(a, s), got_transposed = congruence_transposed(a, s);
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) {
        EXPECT_NEAR(got(i, j), expected(i, j), 1e-14);
        EXPECT_NEAR(got_transposed(i, j), expected_transposed(i, j), 1e-14);
      }
    Mat<D> r = random_rotation<D>(rng);
    Vec<D> values = random_vec<D>(rng, -1, 1);
    EXPECT_LE(max_abs_entry(SymMat<D>::from_eigen(r, values) - congruence(r, SymMat<D>::from_diagonal(values))), 1e-15);
    EXPECT_LE(max_abs_entry(congruence_transposed(r, congruence(r, s)) - s), 1e-14);
  }
}

// Log-metrics: random rotations, log-eigenvalues in ±18.42 with repeated and nearly repeated ones. Both
// solvers must find θ to absolute accuracy.
TYPED_TEST(SymEigenTest, LogMetricsWithRepeatedEigenvalues) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(1);
  for (int trial = 0; trial < 4000; ++trial) {
    Vec<D> theta = log_eigenvalues_case<D>(rng, trial);
    SymMat<D> t = random_with_eigenvalues<D>(rng, theta);
    std::sort(theta.c.begin(), theta.c.end());
    for (SymEigen<D> eigen : {sym_eigen(t), spd_eigen(t)}) {
      expect_sound(t, eigen);
      for (int k = 0; k < D; ++k) EXPECT_NEAR(eigen.values[k], theta[k], 16 * kEpsilon * kLogEigenvalueBound);
    }
  }
}

// Metrics: eigenvalues e^θ, up to 1e16 apart.
TYPED_TEST(SymEigenTest, MetricsWithHugeEigenvalueRatios) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(2);
  for (int trial = 0; trial < 4000; ++trial) {
    Vec<D> theta = log_eigenvalues_case<D>(rng, trial);
    Vec<D> lambda;
    for (int k = 0; k < D; ++k) lambda[k] = std::exp(theta[k]);
    SymMat<D> m = random_with_eigenvalues<D>(rng, lambda);
    expect_sound(m, sym_eigen(m));
    expect_sound(m, spd_eigen(m));
  }
}

// Multiples of the identity, perturbed by 0 to 1e-8 relative, and distinct diagonals with tiny off-diagonal
// entries, at every scale from 1e-300 to 1e300.
TYPED_TEST(SymEigenTest, NearlyDiagonalAtEveryScale) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(3);
  for (double scale : {1e-300, 1e-150, 1e-8, 1.0, 1e8, 1e150, 1e300})
    for (double perturbation : {0.0, 1e-300, 1e-200, 1e-100, 1e-90, 1e-80, 1e-40, 1e-20, 1e-17, 1e-16, 1e-15, 1e-8})
      for (int trial = 0; trial < 20; ++trial) {
        SymMat<D> noise;
        for (double& x : noise.entries) x = std::uniform_real_distribution<double>(-1, 1)(rng);
        SymMat<D> near_identity = (SymMat<D>::identity() + perturbation * noise) * scale;
        SymMat<D> near_diagonal = SymMat<D>::from_diagonal(random_vec<D>(rng, -1, 1));
        for (int i = 0; i < D; ++i)
          for (int j = 0; j < i; ++j) near_diagonal(i, j) = perturbation * noise(i, j);
        near_diagonal *= scale;
        for (const SymMat<D>& m : {near_identity, near_diagonal}) {
          expect_sound(m, sym_eigen(m));
          expect_sound(m, spd_eigen(m));
        }
      }
}

// c·I with diagonal entries moved by a few ulps: the rounded shift c leaves a trace as large as the deviation.
TYPED_TEST(SymEigenTest, MultiplesOfTheIdentityOffByAFewUlps) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 2000; ++trial) {
    double c = std::uniform_real_distribution<double>(-kLogEigenvalueBound, kLogEigenvalueBound)(rng);
    SymMat<D> m = c * SymMat<D>::identity();
    for (int i = 0; i < D; ++i) {
      int ulps = std::uniform_int_distribution<int>(-3, 3)(rng);
      for (int k = 0; k < std::abs(ulps); ++k) m(i, i) = std::nextafter(m(i, i), ulps > 0 ? 1e300 : -1e300);
    }
    expect_sound(m, sym_eigen(m));
    expect_sound(m, spd_eigen(m));
  }
}

TYPED_TEST(SymEigenTest, ZeroAndDiagonalMatricesAreExact) {
  constexpr int D = TypeParam::value;
  for (SymEigen<D> eigen : {sym_eigen(SymMat<D>{}), spd_eigen(SymMat<D>{})}) {
    EXPECT_EQ(eigen.values, Vec<D>{});
    EXPECT_EQ(eigen.vectors, Mat<D>::identity());
  }
  // A diagonal metric with sizes 1e-8 … 1: Jacobi does no rotation, so every eigenvalue is exact.
  Vec<D> diagonal;
  for (int i = 0; i < D; ++i) diagonal[i] = std::pow(10.0, 16.0 - 8.0 * i);
  SymEigen<D> eigen = spd_eigen(SymMat<D>::from_diagonal(diagonal));
  for (int k = 0; k < D; ++k) {
    EXPECT_EQ(eigen.values[k], diagonal[D - 1 - k]);
    EXPECT_EQ(std::abs(eigen.vectors(D - 1 - k, k)), 1.0);
  }
}

// The elementary symmetric functions of the eigenvalues of Δ A Δ (Δ diagonal, A SPD), from its principal
// minors, which are products of Δ² and the minors of A, all positive terms: relatively accurate references.
template <int D>
Vec<D> graded_symmetric_functions(const Vec<D>& delta, const SymMat<D>& a) {
  Vec<D> e;
  double product = 1.0;
  for (int i = 0; i < D; ++i) {
    e[0] += delta[i] * delta[i] * a(i, i);
    product *= delta[i] * delta[i];
  }
  if constexpr (D == 3)
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j) e[1] += delta[i] * delta[i] * delta[j] * delta[j] * (a(i, i) * a(j, j) - a(i, j) * a(i, j));
  e[D - 1] = product * determinant(a);
  return e;
}

template <int D>
Vec<D> symmetric_functions(const Vec<D>& lambda) {
  if constexpr (D == 2) {
    return {{lambda[0] + lambda[1], lambda[0] * lambda[1]}};
  } else {
    return {{lambda[0] + lambda[1] + lambda[2], lambda[0] * lambda[1] + lambda[0] * lambda[2] + lambda[1] * lambda[2],
             lambda[0] * lambda[1] * lambda[2]}};
  }
}

// Graded metrics Δ A Δ (A well conditioned, Δ spanning 1e-8 … 1e8) determine every eigenvalue, the smallest
// included, to high relative accuracy; spd_eigen must deliver it (a closed form loses the small ones entirely).
TYPED_TEST(SymEigenTest, SpdEigenIsRelativelyAccurateOnGradedMetrics) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(4);
  for (int trial = 0; trial < 4000; ++trial) {
    SymMat<D> a = random_with_eigenvalues<D>(rng, random_vec<D>(rng, 1, 10));
    Vec<D> delta = random_vec<D>(rng, -8, 8);
    for (int i = 0; i < D; ++i) delta[i] = std::pow(10.0, delta[i]);
    SymMat<D> graded;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j <= i; ++j) graded(i, j) = delta[i] * a(i, j) * delta[j];
    SymEigen<D> eigen = spd_eigen(graded);
    expect_sound(graded, eigen);
    Vec<D> expected = graded_symmetric_functions(delta, a), got = symmetric_functions(eigen.values);
    for (int k = 0; k < D; ++k) EXPECT_NEAR(got[k] / expected[k], 1.0, 1e-13);
  }
}

}  // namespace
}  // namespace hocav
