#include "metric/point_locator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cases/structured.hpp"
#include "geom/closest_point.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

template <int D>
Vec<D> combination(const SimplexPoints<D>& points, const Barycentrics<D>& lambda) {
  Vec<D> x{};
  for (int i = 0; i <= D; ++i) x += lambda[i] * points[i];
  return x;
}

// The squared distance from x to face `face` of element k, computed plainly (as the closest-element rule
// was first written).
template <int D>
double squared_distance_to_face(const Mesh<D>& mesh, Index k, int face, const Vec<D>& x) {
  std::array<Vec<D>, D> c;
  for (int i = 0; i < D; ++i) c[i] = mesh.vertex(mesh.element(k)[face_vertices<D>(face)[i]]);
  Vec<D> closest{};
  if constexpr (D == 2) {
    auto w = closest_on_segment<2>(c[0], c[1], x);
    closest = w[0] * c[0] + w[1] * c[1];
  } else {
    auto w = closest_on_triangle(c[0], c[1], c[2], x);
    closest = w[0] * c[0] + w[1] * c[1] + w[2] * c[2];
  }
  return dot(closest - x, closest - x);
}

template <int D>
double distance_to_boundary(const Mesh<D>& mesh, Index k, const Vec<D>& x) {
  double best = 1e300;
  for (int face = 0; face <= D; ++face)
    if (mesh.neighbor(k, face) == kNoIndex) best = std::min(best, std::sqrt(squared_distance_to_face(mesh, k, face, x)));
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

// The closest-element rule as first written, plainly: the balls of the exit face's vertices one after the
// other (an element in two balls is met twice), every boundary face of each, the first strictly closest wins.
template <int D>
Localization<D> reference_closest_boundary_element(const PointLocator<D>& locator, const Vec<D>& x, Index near_element, int near_face) {
  const Mesh<D>& mesh = locator.mesh();
  std::vector<Index> candidates, ball;
  for (int i = 0; i < D; ++i) {
    collect_ball(mesh, mesh.element(near_element)[face_vertices<D>(near_face)[i]], ball);
    candidates.insert(candidates.end(), ball.begin(), ball.end());
  }
  Index best = kNoIndex;
  double best_distance2 = std::numeric_limits<double>::infinity();
  for (Index k : candidates)
    for (int face = 0; face <= D; ++face) {
      if (mesh.neighbor(k, face) != kNoIndex) continue;
      const double distance2 = squared_distance_to_face(mesh, k, face, x);
      if (distance2 < best_distance2) {
        best_distance2 = distance2;
        best = k;
      }
    }
  return {best, barycentric_coordinates<D>(locator.element_points(best), x), false};
}

// Points around every boundary face (k, f) — just outside and just inside at random spots, and on a lattice of
// exact binary offsets from its vertices, where faces tie exactly — give, from (k, f), bit for bit the reference's
// element and barycentrics.
template <int D>
void expect_closest_rule_matches_reference(const Mesh<D>& mesh, std::uint32_t seed) {
  PointLocator<D> locator(mesh);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), offset(-0.3, 0.3);
  int compared = 0;
  LocatorScratch scratch;  // reused, as an optimizer does
  auto expect_same = [&](const Vec<D>& x, Index k, int face) {
    auto found = locator.closest_boundary_element(x, k, face, scratch);
    auto expected = reference_closest_boundary_element(locator, x, k, face);
    ASSERT_EQ(found.element, expected.element);
    EXPECT_FALSE(found.inside);
    for (int i = 0; i <= D; ++i) ASSERT_EQ(found.barycentrics[i], expected.barycentrics[i]);  // bit for bit
    ++compared;
  };
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face) {
      if (mesh.neighbor(k, face) != kNoIndex) continue;
      const SimplexPoints<D> corners = locator.element_points(k);
      const double h = norm(corners[face_vertices<D>(face)[1]] - corners[face_vertices<D>(face)[0]]);
      for (int trial = 0; trial < 4; ++trial) {
        Vec<D> x{};
        double sum = 0;
        Barycentrics<D> weights;
        for (auto& w : weights) sum += (w = -std::log(unit(random) + 1e-300));
        for (int i = 0; i <= D; ++i) x += (weights[i] / sum) * corners[i];
        // Pushed across the face, a little or a lot, or left inside.
        const double push = trial == 0 ? -0.1 : trial == 1 ? 0.01 : trial == 2 ? 0.3 : 2.0;
        expect_same(x + push * (x - corners[face]), k, face);
      }
      for (int i = 0; i < D; ++i) {
        Vec<D> vertex = corners[face_vertices<D>(face)[i]];
        Vec<D> step;
        for (int j = 0; j < D; ++j) step[j] = std::round(offset(random) * 64) / 64 * h;
        expect_same(vertex + step, k, face);
        for (int j = 0; j < D; ++j) step[j] = std::round(offset(random) * 8) / 8 * h;
        expect_same(vertex + step, k, face);
      }
    }
  EXPECT_GT(compared, 300);
}

// Interior and boundary vertices moved at random by up to a tenth of the cell (the boundary no longer flat, some
// of it concave); elements stay positive.
template <int D>
Mesh<D> perturbed(Mesh<D> mesh, double cell, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> shift(-0.1 * cell, 0.1 * cell);
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    for (int i = 0; i < D; ++i) mesh.vertex(v)[i] += shift(random);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const auto& element = mesh.element(k);
    std::array<Vec<D>, D> edges;
    for (int i = 0; i < D; ++i) edges[i] = mesh.vertex(element[i + 1]) - mesh.vertex(element[0]);
    if constexpr (D == 2)
      EXPECT_GT(determinant(edges[0], edges[1]), 0);
    else
      EXPECT_GT(determinant(edges[0], edges[1], edges[2]), 0);
  }
  return mesh;
}

TEST(PointLocator, ClosestElementRuleIsTheReferenceOnTheCube) { expect_closest_rule_matches_reference(generate_cube(5), 5); }
TEST(PointLocator, ClosestElementRuleIsTheReferenceOnTheSquare) { expect_closest_rule_matches_reference(generate_square(12), 6); }
TEST(PointLocator, ClosestElementRuleIsTheReferenceOnAPerturbedCube) {
  expect_closest_rule_matches_reference(perturbed(generate_cube(5), 0.2, 7), 8);
}
TEST(PointLocator, ClosestElementRuleIsTheReferenceOnAPerturbedSquare) {
  expect_closest_rule_matches_reference(perturbed(generate_square(12), 1.0 / 12, 9), 10);
}

TEST(PointLocator, ClosestElementRuleOfTwoLocatorsInTurnIsEachOnesReference) {
  // The rule's candidates are kept in the scratch for the next call through the same face: calls with one
  // scratch alternating between two meshes through the same (element, face) must not take the other mesh's.
  const Mesh<3> coarse = generate_cube(4), fine = generate_cube(5);
  const PointLocator<3> coarse_locator(coarse), fine_locator(fine);
  LocatorScratch scratch;
  int compared = 0;
  for (Index k = 0; k < coarse.element_count(); ++k)
    for (int face = 0; face <= 3; ++face) {
      if (coarse.neighbor(k, face) != kNoIndex || fine.neighbor(k, face) != kNoIndex) continue;
      for (const PointLocator<3>* locator : {&coarse_locator, &fine_locator, &coarse_locator}) {
        const SimplexPoints<3> corners = locator->element_points(k);
        const Vec3 x = 1.05 * corners[face_vertices<3>(face)[0]] - 0.05 * corners[face];
        auto found = locator->closest_boundary_element(x, k, face, scratch);
        auto expected = reference_closest_boundary_element(*locator, x, k, face);
        ASSERT_EQ(found.element, expected.element);
        for (int i = 0; i <= 3; ++i) ASSERT_EQ(found.barycentrics[i], expected.barycentrics[i]);
        ++compared;
      }
    }
  EXPECT_GT(compared, 100);
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
