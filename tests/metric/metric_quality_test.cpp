#include "metric/metric_quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../geom/random_matrices.hpp"
#include "geom/sym_functions.hpp"

namespace hocav {
namespace {

SimplexPoints<2> regular_triangle() { return {{Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{0.5, std::sqrt(3.0) / 2}}}}; }

// Alternate corners of a cube of side 1/√2: six edges of length 1, positively ordered.
SimplexPoints<3> regular_tetrahedron() {
  const double s = 0.5 / std::sqrt(2.0);
  return {{Vec3{{s, s, s}}, Vec3{{-s, s, -s}}, Vec3{{s, -s, -s}}, Vec3{{-s, -s, s}}}};
}

template <int D>
SimplexPoints<D> mapped(const SimplexPoints<D>& points, const Mat<D>& a, const Vec<D>& b) {
  SimplexPoints<D> out;
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = a * points[i] + b;
  return out;
}

// A random map with singular values in [1/3, 3] (the quality does not see their spread, but the
// rounding of a nearly flat image does).
template <int D>
Mat<D> random_map(std::mt19937_64& rng) {
  Vec<D> stretch = geom_test::random_vec<D>(rng, -std::log(3.0), std::log(3.0));
  for (int i = 0; i < D; ++i) stretch[i] = std::exp(stretch[i]);
  Mat<D> scaled = geom_test::random_rotation<D>(rng);
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) scaled(i, j) *= stretch[j];
  return scaled * geom_test::random_rotation<D>(rng);
}

template <int D>
SymMat<D> random_metric(std::mt19937_64& rng) {
  return exp_sym(geom_test::random_with_eigenvalues<D>(rng, geom_test::random_vec<D>(rng, -3, 3)));
}

TEST(MetricMeanRatio, RegularUnitSimplexIsOne) {
  EXPECT_NEAR(metric_mean_ratio<2>(regular_triangle(), SymMat2::identity()), 1, 1e-14);
  EXPECT_NEAR(metric_mean_ratio<3>(regular_tetrahedron(), SymMat3::identity()), 1, 1e-14);
}

// The corner simplex of the unit square / cube: 4√3 (1/2) / 4 and 36 / 3^(1/3) (1/6)^(2/3) / 9.
TEST(MetricMeanRatio, CornerSimplexHasItsClosedFormValue) {
  SimplexPoints<2> triangle{{Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{0, 1}}}};
  EXPECT_NEAR(metric_mean_ratio<2>(triangle, SymMat2::identity()), std::sqrt(3.0) / 2, 1e-14);
  SimplexPoints<3> tetrahedron{{Vec3{{0, 0, 0}}, Vec3{{1, 0, 0}}, Vec3{{0, 1, 0}}, Vec3{{0, 0, 1}}}};
  EXPECT_NEAR(metric_mean_ratio<3>(tetrahedron, SymMat3::identity()), 4 / (3 * std::cbrt(4.0)), 1e-14);
}

// Q(A p + b, M) = Q(p, Aᵀ M A): the metric carried by the map, i.e. M at the image is A⁻ᵀ (Aᵀ M A) A⁻¹.
template <int D>
void expect_affine_invariance(const SimplexPoints<D>& regular) {
  std::mt19937_64 rng(7 + D);
  for (int trial = 0; trial < 200; ++trial) {
    const Mat<D> a = random_map<D>(rng);
    const SimplexPoints<D> points = mapped(regular, random_map<D>(rng), geom_test::random_vec<D>(rng, -1, 1));
    const SymMat<D> metric = random_metric<D>(rng);
    const double quality = metric_mean_ratio<D>(points, congruence_transposed(a, metric));
    const double image_quality = metric_mean_ratio<D>(mapped(points, a, geom_test::random_vec<D>(rng, -5, 5)), metric);
    EXPECT_NEAR(image_quality, quality, 1e-10 * std::abs(quality));
  }
}

TEST(MetricMeanRatio, InvariantUnderAffineMapsCarryingTheMetric) {
  expect_affine_invariance<2>(regular_triangle());
  expect_affine_invariance<3>(regular_tetrahedron());
}

// A simplex mapped by A is regular in the metric (A Aᵀ)⁻¹ = A⁻ᵀ A⁻¹, whatever A.
template <int D>
void expect_regular_in_its_map_metric(const SimplexPoints<D>& regular) {
  std::mt19937_64 rng(11 + D);
  for (int trial = 0; trial < 100; ++trial) {
    const Mat<D> a = random_map<D>(rng);
    const SymMat<D> metric = pow_spd(congruence(a, SymMat<D>::identity()), -1.0);
    EXPECT_NEAR(metric_mean_ratio<D>(mapped(regular, a, Vec<D>{}), metric), 1, 1e-9);
  }
}

TEST(MetricMeanRatio, MappedRegularSimplexIsOneInTheMetricOfItsMap) {
  expect_regular_in_its_map_metric<2>(regular_triangle());
  expect_regular_in_its_map_metric<3>(regular_tetrahedron());
}

TEST(MetricMeanRatio, ScaleInvariantInTheElementAndTheMetric) {
  SimplexPoints<3> tetrahedron{{Vec3{{0, 0, 0}}, Vec3{{2, 0, 0}}, Vec3{{0.3, 1, 0}}, Vec3{{0.5, 0.2, 0.7}}}};
  const SymMat3 metric{{4, 1, 3, 0.5, 0.2, 2}};
  const double quality = metric_mean_ratio<3>(tetrahedron, metric);
  EXPECT_GT(quality, 0);
  EXPECT_LT(quality, 1);
  EXPECT_NEAR(metric_mean_ratio<3>(tetrahedron, 1e6 * metric), quality, 1e-12);
  EXPECT_NEAR(metric_mean_ratio<3>(mapped(tetrahedron, Mat<3>{{1e-3, 0, 0, 0, 1e-3, 0, 0, 0, 1e-3}}, Vec3{}), metric), quality, 1e-12);
}

TEST(MetricMeanRatio, FlatSimplexIsZeroAndInvertedIsNegative) {
  SimplexPoints<2> flat_triangle{{Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{3, 0}}}};
  EXPECT_EQ(metric_mean_ratio<2>(flat_triangle, SymMat2::identity()), 0);
  SimplexPoints<3> flat_tetrahedron{{Vec3{{0, 0, 0}}, Vec3{{1, 0, 0}}, Vec3{{0, 1, 0}}, Vec3{{0.4, 0.3, 0}}}};
  EXPECT_EQ(metric_mean_ratio<3>(flat_tetrahedron, SymMat3::identity()), 0);
  SimplexPoints<3> inverted = regular_tetrahedron();
  std::swap(inverted[0], inverted[1]);
  EXPECT_NEAR(metric_mean_ratio<3>(inverted, SymMat3::identity()), -1, 1e-14);
}

}  // namespace
}  // namespace hocav
