#include "metric/point_locator.hpp"

#include <gtest/gtest.h>

#include <random>

#include "cases/structured.hpp"
#include "geom/closest_point.hpp"

namespace hocav {
namespace {

template <int D>
Vec<D> combination(const SimplexPoints<D>& points, const Barycentrics<D>& lambda) {
  Vec<D> x{};
  for (int i = 0; i <= D; ++i) x += lambda[i] * points[i];
  return x;
}

template <int D>
double distance_to_boundary(const Mesh<D>& mesh, Index k, const Vec<D>& x) {
  double best = 1e300;
  for (int face = 0; face <= D; ++face) {
    if (mesh.neighbor(k, face) != kNoIndex) continue;
    std::array<Vec<D>, D> c;
    for (int i = 0; i < D; ++i) c[i] = mesh.vertex(mesh.element(k)[face_vertices<D>(face)[i]]);
    Vec<D> closest;
    if constexpr (D == 2) {
      auto w = closest_on_segment<2>(c[0], c[1], x);
      closest = w[0] * c[0] + w[1] * c[1];
    } else {
      auto w = closest_on_triangle(c[0], c[1], c[2], x);
      closest = w[0] * c[0] + w[1] * c[1] + w[2] * c[2];
    }
    best = std::min(best, norm(closest - x));
  }
  return best;
}

template <int D>
void expect_localizes_inside_points(const Mesh<D>& mesh, std::uint32_t seed) {
  PointLocator<D> locator(mesh);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<Index> element(0, mesh.element_count() - 1);
  for (int trial = 0; trial < 2000; ++trial) {
    // A random point of a random element, found from a random hint and from a cold start.
    Index target = element(random);
    Barycentrics<D> weights;
    double sum = 0;
    for (auto& w : weights) sum += (w = -std::log(unit(random) + 1e-300));
    for (auto& w : weights) w /= sum;
    Vec<D> x = combination<D>(locator.element_points(target), weights);
    for (Index hint : {element(random), kNoIndex}) {
      auto found = locator.localize(x, hint);
      ASSERT_TRUE(found.inside);
      ASSERT_NE(found.element, kNoIndex);
      for (double lambda : found.barycentrics) EXPECT_GE(lambda, -1e-12);
      Vec<D> back = combination<D>(locator.element_points(found.element), found.barycentrics);
      EXPECT_LT(norm(back - x), 1e-12);
    }
  }
}

TEST(PointLocator, FindsPointsInsideTheCube) { expect_localizes_inside_points(generate_cube(6), 1); }
TEST(PointLocator, FindsPointsInsideTheSquare) { expect_localizes_inside_points(generate_square(12), 2); }

TEST(PointLocator, FindsPointsAcrossTheNotchOfANonConvexDomain) {
  // An L-shaped domain: the square without its upper-right quarter.
  Mesh<2> square = generate_square(8);
  Mesh<2> l_shape;
  for (const auto& p : square.vertices()) l_shape.add_vertex(p);
  for (Index k = 0; k < square.element_count(); ++k) {
    Vec2 centroid{};
    for (Index v : square.element(k)) centroid += square.vertex(v) * (1.0 / 3);
    if (!(centroid[0] > 0.5 && centroid[1] > 0.5)) l_shape.add_element(square.element(k));
  }
  l_shape.build_topology();
  expect_localizes_inside_points(l_shape, 3);
}

TEST(PointLocator, OutsidePointsGoToTheClosestBoundaryElement) {
  Mesh<3> mesh = generate_cube(5);
  PointLocator<3> locator(mesh);
  std::mt19937 random(4);
  std::uniform_real_distribution<double> coordinate(-0.02, 1.02);
  int outside = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Vec3 x{{coordinate(random), coordinate(random), coordinate(random)}};
    bool really_inside = true;
    for (int i = 0; i < 3; ++i) really_inside = really_inside && x[i] >= 0 && x[i] <= 1;
    auto found = locator.localize(x, trial % 2 ? kNoIndex : Index(trial % mesh.element_count()));
    ASSERT_NE(found.element, kNoIndex);
    EXPECT_EQ(found.inside, really_inside);
    if (really_inside) continue;
    ++outside;
    // The chosen element's boundary is as close to x as any boundary face of the mesh.
    double best = 1e300;
    for (Index k = 0; k < mesh.element_count(); ++k) best = std::min(best, distance_to_boundary(mesh, k, x));
    EXPECT_NEAR(distance_to_boundary(mesh, found.element, x), best, 1e-12);
    // Barycentrics are the affine extension: they still reproduce x.
    Vec3 back = combination<3>(locator.element_points(found.element), found.barycentrics);
    EXPECT_LT(norm(back - x), 1e-12);
  }
  EXPECT_GT(outside, 100);
}

}  // namespace
}  // namespace hocav
