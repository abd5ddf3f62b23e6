#include "bezier/bernstein_subdivision.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <type_traits>

#include "reference_jacobian.hpp"

namespace hocav {
namespace {

using namespace bezier_test;

template <class Dimension>
class BezierSubdivisionTest : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(BezierSubdivisionTest, Dimensions);

// Signed measure of a child in barycentric space, relative to the parent's.
template <int D>
double child_measure_ratio(int child) {
  Barycentrics<D> q[D + 1];
  for (int v = 0; v <= D; ++v) q[v] = subdivision_child_vertex<D>(child, v);
  // Barycentric coordinates 1..D of the vertices are Cartesian coordinates in the reference simplex.
  double m[D][D];
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) m[r][c] = q[c + 1][r + 1] - q[0][r + 1];
  if constexpr (D == 2)
    return m[0][0] * m[1][1] - m[0][1] * m[1][0];
  else
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

TYPED_TEST(BezierSubdivisionTest, ChildrenTileTheParent) {
  constexpr int D = TypeParam::value;
  double total = 0.0;
  for (int child = 0; child < kSubdivisionChildCount<D>; ++child) {
    const double ratio = std::abs(child_measure_ratio<D>(child));
    EXPECT_DOUBLE_EQ(ratio, 1.0 / kSubdivisionChildCount<D>);  // regular refinement: equal volumes
    total += ratio;
  }
  EXPECT_DOUBLE_EQ(total, 1.0);
}

TYPED_TEST(BezierSubdivisionTest, ChildCoefficientsRepresentTheSamePolynomial) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    JacobianCoefficients<D> parent;
    for (double& c : parent) c = value(random);
    SubdivisionChildren<D> children;
    subdivide_bernstein(parent, children);
    for (int child = 0; child < kSubdivisionChildCount<D>; ++child)
      for (int point = 0; point < 10; ++point) {
        const Barycentrics<D> mu = random_barycentrics<D>(random);  // in the child
        Barycentrics<D> lambda{};                                   // the same point in the parent
        for (int v = 0; v <= D; ++v) {
          const Barycentrics<D> corner = subdivision_child_vertex<D>(child, v);
          for (int i = 0; i <= D; ++i) lambda[i] += mu[v] * corner[i];
        }
        EXPECT_NEAR(evaluate_bernstein(children[child], mu), evaluate_bernstein(parent, lambda), 1e-13);
      }
  }
}

TYPED_TEST(BezierSubdivisionTest, CornerCoefficientsOfChildrenAreValuesOfThePolynomial) {
  constexpr int D = TypeParam::value;
  std::mt19937 random(12);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  JacobianCoefficients<D> parent;
  for (double& c : parent) c = value(random);
  SubdivisionChildren<D> children;
  subdivide_bernstein(parent, children);
  for (int child = 0; child < kSubdivisionChildCount<D>; ++child)
    for (int v = 0; v <= D; ++v) EXPECT_NEAR(children[child][v], evaluate_bernstein(parent, subdivision_child_vertex<D>(child, v)), 1e-14);
}

}  // namespace
}  // namespace hocav
