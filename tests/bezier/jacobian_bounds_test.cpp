#include "bezier/jacobian_bounds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <type_traits>

#include "mesh/measure.hpp"
#include "reference_jacobian.hpp"

namespace hocav {
namespace {

using namespace bezier_test;

template <class Dimension>
class JacobianBoundsTest : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(JacobianBoundsTest, Dimensions);

template <int D>
int sampling_resolution() {
  return D == 2 ? 200 : 40;
}

// The unit reference simplex with its edge nodes at the midpoints, then `moves` added to edge nodes.
template <int D>
P2Element<D> reference_element(std::initializer_list<std::pair<int, Vec<D>>> moves) {
  P2Element<D> element;
  for (int i = 1; i <= D; ++i) element.nodes[i][i - 1] = 1.0;
  for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
    const auto& ends = edge_vertices<D>(edge);
    element.nodes[D + 1 + edge] = 0.5 * (element.vertex(ends[0]) + element.vertex(ends[1]));
  }
  for (const auto& [edge, offset] : moves) element.nodes[D + 1 + edge] += offset;
  return element;
}

template <int D>
double min_coefficient(const P2Element<D>& element) {
  const JacobianCoefficients<D> coefficients = jacobian_coefficients(element);
  return *std::min_element(coefficients.begin(), coefficients.end());
}

// The paper's Fig. 9 in 2D: the vertices are clockwise (straight area < 0), yet the curved element is
// valid. A crescent: edge 01 bulges far below, edges 12 and 20 sag toward it, so at every corner
// the two edge tangents are counter-clockwise although the three vertices are not.
P2Element<2> fig9_triangle() {
  P2Element<2> element;
  element.nodes = {Vec2{{0.0, 0.0}}, Vec2{{1.0, 0.0}}, Vec2{{0.5, -0.05}}, Vec2{{0.5, -0.8}}, Vec2{{0.75, -0.225}}, Vec2{{0.25, -0.225}}};
  return element;
}

// The same in 3D: the crescent as base, an apex above it, and the apex's edge to vertex 2 leaving
// on the other side of the plane through the apex and vertices 0, 1 so that the three edge
// tangents at the apex are positively oriented too.
P2Element<3> fig9_tetrahedron() {
  P2Element<3> element;
  const Vec3 v0{{0.0, 0.0, 0.0}}, v1{{1.0, 0.0, 0.0}}, v2{{0.5, -0.05, 0.0}}, v3{{0.5, -0.3, 1.0}};
  element.nodes = {v0,
                   v1,
                   v2,
                   v3,
                   Vec3{{0.5, -0.8, 0.0}},
                   Vec3{{0.75, -0.225, 0.0}},
                   Vec3{{0.25, -0.225, 0.0}},
                   0.5 * (v0 + v3),
                   0.5 * (v1 + v3),
                   0.5 * (v2 + v3) + Vec3{{0.0, 0.3, 0.0}}};
  return element;
}

// Valid, but some coefficients are negative: a false negative at depth 0. True min J ≈ 0.027
// (2D) and ≈ 0.021 (3D) against corner values 0.24 to 3.4.
P2Element<2> false_negative_triangle() {
  return reference_element<2>({{0, Vec2{{0.0, -0.5}}}, {1, Vec2{{0.05, 0.05}}}, {2, Vec2{{0.3, 0.0}}}});
}
P2Element<3> false_negative_tetrahedron() { return reference_element<3>({{1, Vec3{{0.45, 0.0, 0.0}}}, {0, Vec3{{0.0, 0.45, 0.0}}}}); }

// Invalid in a small region only: corners positive, sampled min J ≈ −0.005 (2D), −0.016 (3D).
P2Element<2> slightly_invalid_triangle() {
  return reference_element<2>({{0, Vec2{{0.0, -0.25}}}, {1, Vec2{{0.1, 0.1}}}, {2, Vec2{{0.45, 0.0}}}});
}
P2Element<3> slightly_invalid_tetrahedron() { return reference_element<3>({{3, Vec3{{0.0, 0.45, 0.0}}}, {4, Vec3{{-0.35, 0.0, 0.0}}}}); }

template <int D>
P2Element<D> false_negative_element() {
  if constexpr (D == 2)
    return false_negative_triangle();
  else
    return false_negative_tetrahedron();
}

template <int D>
P2Element<D> slightly_invalid_element() {
  if constexpr (D == 2)
    return slightly_invalid_triangle();
  else
    return slightly_invalid_tetrahedron();
}

template <int D>
P2Element<D> fig9_element() {
  if constexpr (D == 2)
    return fig9_triangle();
  else
    return fig9_tetrahedron();
}

TYPED_TEST(JacobianBoundsTest, MildlyCurvedElementsAreCertifiedOnTheFastPath) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(21);
  for (int trial = 0; trial < 200; ++trial) {
    const P2Element<D> element = random_curved_element<D>(0.05, random);
    const JacobianCertificate certificate = certify_min_normalized_jacobian(element, 0.01);
    EXPECT_TRUE(certificate.certified);
    EXPECT_EQ(certificate.subdivisions, 0);
  }
}

TYPED_TEST(JacobianBoundsTest, StraightElementsHaveQualityOne) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(22);
  const P2Element<D> element = random_curved_element<D>(0.0, random);
  const JacobianQuality quality = jacobian_quality(element);
  EXPECT_NEAR(quality.min_normalized_jacobian, 1.0, 1e-12);
  EXPECT_NEAR(quality.scaled_jacobian, 1.0, 1e-12);
  EXPECT_TRUE(certify_min_normalized_jacobian_above(element, 0.999));
  const JacobianCertificate above_one = certify_min_normalized_jacobian(element, 1.001);
  EXPECT_FALSE(above_one.certified);
  EXPECT_TRUE(above_one.decided);  // the corners are J itself: decided without doubt

  P2Element<D> inverted = element;
  std::swap(inverted.nodes[0], inverted.nodes[1]);  // vertex swap; edge nodes are midpoints either way
  for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
    const auto& ends = edge_vertices<D>(edge);
    inverted.nodes[D + 1 + edge] = 0.5 * (inverted.vertex(ends[0]) + inverted.vertex(ends[1]));
  }
  const JacobianQuality inverted_quality = jacobian_quality(inverted);
  EXPECT_NEAR(inverted_quality.min_normalized_jacobian, -1.0, 1e-12);
  EXPECT_NEAR(inverted_quality.scaled_jacobian, -1.0, 1e-12);
  EXPECT_FALSE(certify_min_normalized_jacobian_above(inverted, 0.0));
}

TYPED_TEST(JacobianBoundsTest, RefinedBoundsBracketTheDenselySampledMinimumAndMaximum) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(23);
  const RefinementOptions options{1e-6, {16, 100000}};
  for (int trial = 0; trial < 20; ++trial) {
    const P2Element<D> element = random_curved_element<D>(0.5, random);
    const double scale = std::abs(straight_jacobian(element));
    const SampledRange sampled = sample_jacobian(element, sampling_resolution<D>());
    const JacobianRange range = normalized_jacobian_range(element, options);
    ASSERT_TRUE(range.converged);
    const double sampled_min = sampled.min / scale, sampled_max = sampled.max / scale;
    const double slack = 1e-9 * std::max({1.0, std::abs(sampled_min), std::abs(sampled_max)});
    // lower ≤ true min ≤ sampled min, and upper is within the tolerance of the true min.
    EXPECT_LE(range.min_lower, sampled_min + slack);
    EXPECT_LE(range.min_lower, range.min_upper);
    EXPECT_LE(range.min_upper, sampled_min + 1e-6 * (std::abs(range.max_upper) + std::abs(range.min_lower)) + slack);
    EXPECT_GE(range.max_upper, sampled_max - slack);
    EXPECT_GE(range.max_upper, range.max_lower);
    EXPECT_GE(range.max_lower, sampled_max - 1e-6 * (std::abs(range.max_upper) + std::abs(range.min_lower)) - slack);
    // The lattice misses the true extremes by O(spacing²) only.
    EXPECT_NEAR(range.min_upper, sampled_min, 2e-3 * std::max(1.0, sampled_max - sampled_min));
    EXPECT_NEAR(range.max_lower, sampled_max, 2e-3 * std::max(1.0, sampled_max - sampled_min));
  }
}

TYPED_TEST(JacobianBoundsTest, BoundsConvergeAsTheDepthGrows) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(24);
  int tested = 0;
  for (int trial = 0; trial < 1000 && tested < 10; ++trial) {
    const JacobianCoefficients<D> coefficients = jacobian_coefficients(random_curved_element<D>(0.5, random));
    const MinimumBounds initial = bound_bernstein_minimum(coefficients, 0.0, {0, 0});
    const double gap_at_depth_0 = initial.upper - initial.lower;
    if (gap_at_depth_0 < 1e-3) continue;  // the coefficients alone already give the minimum
    ++tested;
    double previous_lower = initial.lower, gap = gap_at_depth_0;
    for (int depth = 1; depth <= 8; ++depth) {
      const MinimumBounds bounds = bound_bernstein_minimum(coefficients, 0.0, {depth, 1000000});
      gap = bounds.upper - bounds.lower;
      EXPECT_GE(bounds.lower, previous_lower - 1e-13);  // deeper leaves never lower the bound
      previous_lower = bounds.lower;
    }
    // Quadratic convergence: about 4^-8 of the initial gap after 8 levels.
    EXPECT_LE(gap, 1e-3 * gap_at_depth_0);
  }
  EXPECT_EQ(tested, 10);
}

TYPED_TEST(JacobianBoundsTest, Fig9ValidCurvedElementWhoseStraightElementIsInverted) {
  constexpr int D = TypeParam::value;
  const P2Element<D> element = fig9_element<D>();
  EXPECT_LT(straight_jacobian(element), 0.0);
  if constexpr (D == 2)
    EXPECT_LT(signed_measure(element.vertex(0), element.vertex(1), element.vertex(2)), 0.0);
  else
    EXPECT_LT(signed_measure(element.vertex(0), element.vertex(1), element.vertex(2), element.vertex(3)), 0.0);
  const SampledRange sampled = sample_jacobian(element, sampling_resolution<D>());
  EXPECT_GT(sampled.min, 0.5);  // J ≥ 0.75 everywhere: a comfortably valid curved element
  EXPECT_TRUE(certify_min_normalized_jacobian_above(element, 1.0));
  const JacobianQuality quality = jacobian_quality(element);
  EXPECT_GT(quality.min_normalized_jacobian, 1.0);  // normalized by |J_straight|, which is small here
  EXPECT_GT(quality.scaled_jacobian, 0.0);
}

TYPED_TEST(JacobianBoundsTest, FalseNegativeOfTheCoefficientsIsCertifiedAfterSubdivision) {
  constexpr int D = TypeParam::value;
  const P2Element<D> element = false_negative_element<D>();
  EXPECT_LT(min_coefficient(element), 0.0);
  EXPECT_GT(sample_jacobian(element, sampling_resolution<D>()).min, 0.0);
  const JacobianCertificate certificate = certify_min_normalized_jacobian(element, 0.0);
  EXPECT_TRUE(certificate.certified);
  EXPECT_TRUE(certificate.decided);
  EXPECT_GT(certificate.subdivisions, 0);
  EXPECT_GT(jacobian_quality(element).min_normalized_jacobian, 0.0);

  // Out of depth (or budget) before the sign is settled: undecided, and so not certified.
  for (const SubdivisionLimits limits : {SubdivisionLimits{0, 256}, SubdivisionLimits{8, 0}}) {
    const JacobianCertificate early = certify_min_normalized_jacobian(element, 0.0, limits);
    EXPECT_FALSE(early.certified);
    EXPECT_FALSE(early.decided);
  }
}

TYPED_TEST(JacobianBoundsTest, SmallNegativeRegionIsRejected) {
  constexpr int D = TypeParam::value;
  const P2Element<D> element = slightly_invalid_element<D>();
  const JacobianCoefficients<D> coefficients = jacobian_coefficients(element);
  for (int i = 0; i <= D; ++i) EXPECT_GT(coefficients[i], 0.1);  // all corners comfortably positive
  const SampledRange sampled = sample_jacobian(element, sampling_resolution<D>());
  EXPECT_LT(sampled.min, 0.0);
  EXPECT_GT(sampled.min, -0.03 * sampled.max);
  const JacobianCertificate certificate = certify_min_normalized_jacobian(element, 0.0, {kMaxSubdivisionDepth, 100000});
  EXPECT_FALSE(certificate.certified);
  EXPECT_TRUE(certificate.decided);  // a sub-simplex corner with J < 0 was found
  EXPECT_LT(jacobian_quality(element).min_normalized_jacobian, 0.0);
}

// J of this triangle vanishes on edge 20 at λ = (1/4, 0, 3/4) and is positive elsewhere. No rounding
// of its coefficients may certify J > 0 there.
TEST(JacobianBounds, JacobianTouchingZeroIsNotCertifiedAboveZero) {
  const P2Element<2> element = reference_element<2>({{0, Vec2{{0.0, -0.1}}}, {1, Vec2{{0.1, 0.1}}}, {2, Vec2{{0.5, 0.0}}}});
  EXPECT_NEAR(reference_jacobian(element, {0.25, 0.0, 0.75}), 0.0, 1e-15);
  EXPECT_GT(sample_jacobian(element, 200).min, -1e-15);
  EXPECT_FALSE(certify_min_normalized_jacobian_above(element, 0.0, {kMaxSubdivisionDepth, 100000}));
}

TEST(JacobianBounds, NonFiniteNodesAreNotCertified) {
  P2Element<3> element = reference_element<3>({});
  element.nodes[5][1] = std::numeric_limits<double>::quiet_NaN();
  const JacobianCertificate certificate = certify_min_normalized_jacobian(element, 0.0);
  EXPECT_FALSE(certificate.certified);
  EXPECT_TRUE(certificate.decided);
}

TEST(JacobianBounds, ScaledJacobianOfBounds) {
  EXPECT_DOUBLE_EQ(scaled_jacobian(0.5, 2.0), 0.25);
  EXPECT_DOUBLE_EQ(scaled_jacobian(-1.0, 2.0), -0.5);
  EXPECT_DOUBLE_EQ(scaled_jacobian(-2.0, -1.0), -2.0);
  EXPECT_DOUBLE_EQ(scaled_jacobian(0.0, 0.0), 0.0);
  EXPECT_EQ(scaled_jacobian(-1.0, 0.0), -std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace hocav
