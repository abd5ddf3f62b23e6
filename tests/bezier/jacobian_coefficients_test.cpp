#include "bezier/jacobian_coefficients.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <type_traits>

#include "bezier/p2_element.hpp"
#include "cases/structured.hpp"
#include "reference_jacobian.hpp"

namespace hocav {
namespace {

using namespace bezier_test;

template <class Dimension>
class JacobianCoefficientsTest : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(JacobianCoefficientsTest, Dimensions);

template <int D>
double max_magnitude(const JacobianCoefficients<D>& coefficients) {
  double magnitude = 0.0;
  for (double c : coefficients) magnitude = std::max(magnitude, std::abs(c));
  return magnitude;
}

TEST(JacobianCoefficients, OrderIsCornersThenEdgesThenFaces) {
  EXPECT_EQ(kJacobianMultiIndices<2>[0], (BernsteinMultiIndex<2>{2, 0, 0}));
  EXPECT_EQ(kJacobianMultiIndices<2>[3], (BernsteinMultiIndex<2>{1, 1, 0}));  // edge 01
  EXPECT_EQ(kJacobianMultiIndices<2>[4], (BernsteinMultiIndex<2>{0, 1, 1}));  // edge 12
  EXPECT_EQ(kJacobianMultiIndices<2>[5], (BernsteinMultiIndex<2>{1, 0, 1}));  // edge 20
  EXPECT_EQ(kJacobianMultiIndices<3>[3], (BernsteinMultiIndex<3>{0, 0, 0, 3}));
  EXPECT_EQ(kJacobianMultiIndices<3>[4], (BernsteinMultiIndex<3>{2, 1, 0, 0}));  // edge 01
  EXPECT_EQ(kJacobianMultiIndices<3>[5], (BernsteinMultiIndex<3>{1, 2, 0, 0}));
  EXPECT_EQ(kJacobianMultiIndices<3>[8], (BernsteinMultiIndex<3>{1, 0, 2, 0}));   // edge 20: 2e_2 + e_0
  EXPECT_EQ(kJacobianMultiIndices<3>[15], (BernsteinMultiIndex<3>{0, 0, 1, 2}));  // edge 23
  EXPECT_EQ(kJacobianMultiIndices<3>[16], (BernsteinMultiIndex<3>{0, 1, 1, 1}));  // face opposite 0
  EXPECT_EQ(kJacobianMultiIndices<3>[19], (BernsteinMultiIndex<3>{1, 1, 1, 0}));  // face opposite 3
}

TYPED_TEST(JacobianCoefficientsTest, MultiIndicesAreTheDistinctOnesOfDegreeD) {
  constexpr int D = TypeParam::value;
  std::set<BernsteinMultiIndex<D>> seen;
  for (int position = 0; position < kJacobianCoefficientCount<D>; ++position) {
    const auto& gamma = kJacobianMultiIndices<D>[position];
    int degree = 0;
    for (int count : gamma) degree += count;
    EXPECT_EQ(degree, D);
    EXPECT_EQ(jacobian_coefficient_index<D>(gamma), position);
    seen.insert(gamma);
  }
  EXPECT_EQ(int(seen.size()), kJacobianCoefficientCount<D>);
}

TYPED_TEST(JacobianCoefficientsTest, ControlNodeOfAnEdgeIsTwiceItsNodeMinusTheMeanOfItsVertices) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(1);
  const P2Element<D> element = curve_randomly(random_straight_element<D>(random), 0.5, random);
  const BezierControlNet<D> net = control_net(element);
  for (int i = 0; i <= D; ++i) EXPECT_EQ(net.of_pair(i, i), element.vertex(i));
  for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
    const auto& ends = edge_vertices<D>(edge);
    // The quadratic curve through the control node passes through the Lagrange node at t = 1/2.
    const Vec<D> at_half = 0.25 * element.vertex(ends[0]) + 0.5 * net.of_pair(ends[0], ends[1]) + 0.25 * element.vertex(ends[1]);
    EXPECT_LT(norm(at_half - element.edge_node(edge)), 1e-14);
    EXPECT_EQ(net.of_pair(ends[1], ends[0]), net.of_pair(ends[0], ends[1]));
  }
}

TYPED_TEST(JacobianCoefficientsTest, StraightElementsHaveAllNormalizedCoefficientsOne) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(2);
  for (int trial = 0; trial < 200; ++trial) {
    const P2Element<D> element = random_straight_element<D>(random);
    const double straight = straight_jacobian(element);
    if (std::abs(straight) < 1e-3) continue;
    const double sign = straight > 0 ? 1.0 : -1.0;  // an inverted straight element is −1 everywhere
    for (double c : normalized_jacobian_coefficients(element)) EXPECT_NEAR(c, sign, 1e-12);
    for (double c : jacobian_coefficients(element)) EXPECT_NEAR(c, straight, 1e-12);
  }
}

TYPED_TEST(JacobianCoefficientsTest, CornerCoefficientsAreTheJacobianAtTheVertices) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(3);
  for (int trial = 0; trial < 200; ++trial) {
    const P2Element<D> element = curve_randomly(random_straight_element<D>(random), 0.4, random);
    const JacobianCoefficients<D> coefficients = jacobian_coefficients(element);
    for (int i = 0; i <= D; ++i) {
      Barycentrics<D> vertex{};
      vertex[i] = 1.0;
      EXPECT_NEAR(coefficients[i], reference_jacobian(element, vertex), 1e-12 * max_magnitude(coefficients));
    }
  }
}

TYPED_TEST(JacobianCoefficientsTest, BernsteinFormIsTheJacobianEverywhere) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(4);
  for (int trial = 0; trial < 200; ++trial) {
    const P2Element<D> element = curve_randomly(random_straight_element<D>(random), 0.4, random);
    const JacobianCoefficients<D> coefficients = jacobian_coefficients(element);
    for (int point = 0; point < 20; ++point) {
      const Barycentrics<D> lambda = random_barycentrics<D>(random);
      EXPECT_NEAR(evaluate_bernstein(coefficients, lambda), reference_jacobian(element, lambda), 1e-12 * max_magnitude(coefficients));
    }
  }
}

TYPED_TEST(JacobianCoefficientsTest, CoefficientsBoundTheDenselySampledJacobian) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(5);
  for (int trial = 0; trial < 40; ++trial) {
    const P2Element<D> element = curve_randomly(random_straight_element<D>(random), 0.6, random);
    const JacobianCoefficients<D> coefficients = jacobian_coefficients(element);
    const SampledRange sampled = sample_jacobian(element, D == 2 ? 100 : 24);
    const double rounding = 1e-13 * max_magnitude(coefficients);
    EXPECT_LE(*std::min_element(coefficients.begin(), coefficients.end()), sampled.min + rounding);
    EXPECT_GE(*std::max_element(coefficients.begin(), coefficients.end()), sampled.max - rounding);
  }
}

// With nodes on a 2^-20 grid, a shift by 1024 is exact: the same element far from the origin. Its
// coefficients may differ only by rounding, which the margin must cover.
TYPED_TEST(JacobianCoefficientsTest, RoundingMarginCoversTheErrorFarFromTheOrigin) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(6);
  double worst_ratio = 0.0;
  for (int trial = 0; trial < 2000; ++trial) {
    P2Element<D> element = curve_randomly(random_straight_element<D>(random), 0.5, random);
    for (Vec<D>& node : element.nodes)
      for (int r = 0; r < D; ++r) node[r] = std::ldexp(std::round(std::ldexp(node[r], 20)), -20);
    P2Element<D> shifted = element;
    for (Vec<D>& node : shifted.nodes)
      for (int r = 0; r < D; ++r) node[r] += 1024.0;
    const ElementJacobian<D> near = element_jacobian(element), far = element_jacobian(shifted);
    for (int i = 0; i < kJacobianCoefficientCount<D>; ++i)
      worst_ratio = std::max(worst_ratio, std::abs(near.coefficients[i] - far.coefficients[i]) / near.rounding_margin);
    EXPECT_EQ(near.straight_jacobian, far.straight_jacobian);  // offsets are exact here
  }
  EXPECT_LT(worst_ratio, 0.1);
}

TEST(JacobianCoefficients, GathersTheNodesOfAMeshElementInLocalOrder) {
  Mesh<3> mesh = generate_cube(1);
  const P2Element<3> straight = gather_p2_element(mesh, 0);  // P1 mesh: straight midpoints
  for (int edge = 0; edge < 6; ++edge) {
    const auto& ends = edge_vertices<3>(edge);
    EXPECT_EQ(straight.edge_node(edge), 0.5 * (straight.vertex(ends[0]) + straight.vertex(ends[1])));
  }
  mesh.make_p2();
  const Index moved_edge = mesh.element_edge(0, 4);  // edge (1, 3)
  mesh.edge_node(moved_edge) += Vec3{{0.01, 0.02, 0.03}};
  const P2Element<3> curved = gather_p2_element(mesh, 0);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(curved.vertex(i), mesh.vertex(mesh.element(0)[i]));
  for (int edge = 0; edge < 6; ++edge) EXPECT_EQ(curved.edge_node(edge), mesh.edge_node(mesh.element_edge(0, edge)));
  EXPECT_NE(curved.edge_node(4), straight.edge_node(4));
}

}  // namespace
}  // namespace hocav
