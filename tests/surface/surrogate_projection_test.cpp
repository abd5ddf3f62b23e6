// Projection onto the P3 surrogate: the tree search, the hinted walk and ref restrictions against
// brute force over every patch.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "base/error.hpp"
#include "surface/p3_surrogate.hpp"
#include "surface/patch_tree.hpp"
#include "surface_test_meshes.hpp"

namespace hocav {
namespace {

using testing::capped_cylinder;
using testing::icosphere;

// The smallest distance from x to the patches (of one ref, when given), by sampling every patch on
// a lattice of n intervals per side.
template <int D>
double sampled_distance(const P3Surrogate<D>& surrogate, const Vec<D>& x, int n, std::optional<int> ref = {}) {
  double best = std::numeric_limits<double>::infinity();
  for (Index p = 0; p < surrogate.patch_count(); ++p) {
    if (ref && surrogate.patch_ref(p) != *ref) continue;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= (D == 3 ? n - i : 0); ++j) {
        PatchParameters<D> parameters;
        parameters[0] = double(i) / n;
        if constexpr (D == 3) parameters[1] = double(j) / n;
        best = std::min(best, norm(evaluate(surrogate.patch(p), parameters) - x));
      }
  }
  return best;
}

// Random points within `spread` of the unit sphere.
std::vector<Vec3> points_near_unit_sphere(int count, double spread, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> radius(1 - spread, 1 + spread);
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) {
    Vec3 direction{{gaussian(random), gaussian(random), gaussian(random)}};
    points.push_back(direction * (radius(random) / norm(direction)));
  }
  return points;
}

// The projection lies on its patch and no sampled point of any patch is closer.
template <int D>
void expect_closest(const P3Surrogate<D>& surrogate, const Vec<D>& x, const BoundaryPoint<D>& found, std::optional<int> ref = {}) {
  const int n = 24;
  const double sampled = sampled_distance(surrogate, x, n, ref);
  EXPECT_LE(found.distance, sampled + 1e-12);
  EXPECT_NEAR(found.distance, norm(found.point - x), 1e-15);
  EXPECT_LT(norm(surrogate.project(found.point).point - found.point), 1e-12) << "not on the surrogate";
  if (ref) {
    EXPECT_EQ(found.ref, *ref);
  }
  EXPECT_EQ(found.ref, surrogate.patch_ref(found.patch));
}

TEST(SurfaceProjection, ClosestPointOnTheSphereSurrogate) {
  const Mesh<3> mesh = icosphere(2, 1.0, 0.2);
  const P3Surrogate<3> surrogate(mesh);
  for (const Vec3& x : points_near_unit_sphere(40, 0.3, 5)) expect_closest(surrogate, x, surrogate.project(x));
  // Points far from the surface, and the centre, are still projected to the closest patch.
  for (const Vec3& x : {Vec3{{0, 0, 0}}, Vec3{{3, -2, 1}}, Vec3{{0.1, 0.2, -0.1}}}) expect_closest(surrogate, x, surrogate.project(x));
}

TEST(SurfaceProjection, ClosestPointOnACreasedSurrogate) {
  const Mesh<3> mesh = capped_cylinder(12);
  const P3Surrogate<3> surrogate(mesh);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-1.3, 1.3), height(-0.3, 1.3);
  for (int k = 0; k < 40; ++k) {
    const Vec3 x{{coordinate(random), coordinate(random), height(random)}};
    expect_closest(surrogate, x, surrogate.project(x));
  }
}

TEST(SurfaceProjection, HintGivesTheSameClosestPointNearTheSurface) {
  const Mesh<3> mesh = icosphere(3, 1.0, 0.2);
  const P3Surrogate<3> surrogate(mesh);
  std::mt19937 random(9);
  std::uniform_int_distribution<Index> any_patch(0, surrogate.patch_count() - 1);
  int walked_far = 0;
  for (const Vec3& x : points_near_unit_sphere(200, 0.05, 7)) {
    const BoundaryPoint<3> cold = surrogate.project(x);
    // A hint a few patches away, as an earlier projection nearby would give, and a useless one.
    Index hint = cold.patch;
    for (int step = 0; step < 3; ++step) hint = surrogate.topology().neighbors[hint][step];
    for (Index start : {cold.patch, hint, any_patch(random)}) {
      const BoundaryPoint<3> hinted = surrogate.project(x, {.hint = start});
      EXPECT_NEAR(hinted.distance, cold.distance, 1e-13);
      EXPECT_LT(norm(hinted.point - cold.point), 1e-9);
      walked_far += start != cold.patch;
    }
  }
  EXPECT_GT(walked_far, 0);
}

TEST(SurfaceProjection, RefRestrictsTheCandidates) {
  const Mesh<3> mesh = capped_cylinder(12);
  const P3Surrogate<3> surrogate(mesh);
  // A point just outside the side, near the bottom rim: closest to the side, restricted to the caps.
  const Vec3 x{{1.05, 0.1, 0.1}};
  EXPECT_EQ(surrogate.project(x).ref, 1);
  for (int ref : {2, 3}) {
    const BoundaryPoint<3> restricted = surrogate.project(x, {.ref = ref});
    expect_closest(surrogate, x, restricted, ref);
    // With a hint on another ref the restriction still holds.
    EXPECT_EQ(surrogate.project(x, {.ref = ref, .hint = surrogate.project(x).patch}).ref, ref);
  }
  EXPECT_THROW(surrogate.project(x, {.ref = 7}), Error);
}

TEST(SurfaceProjection, CircleSurrogate) {
  const Mesh<2> mesh = testing::circle_polygon(20, 1.0, 0.2);
  const P3Surrogate<2> surrogate(mesh);
  std::mt19937 random(1);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  for (int k = 0; k < 40; ++k) {
    const Vec2 x{{coordinate(random), coordinate(random)}};
    const BoundaryPoint<2> cold = surrogate.project(x);
    expect_closest(surrogate, x, cold);
    EXPECT_NEAR(surrogate.project(x, {.hint = (cold.patch + 2) % 20}).distance, cold.distance, 1e-13);
  }
}

TEST(SurfaceProjection, NormalIsTheSurfaceNormalAtTheProjection) {
  const Mesh<3> mesh = icosphere(3, 1.0, 0.0);
  const P3Surrogate<3> surrogate(mesh);
  for (const Vec3& x : points_near_unit_sphere(20, 0.2, 2)) {
    const Vec3 normal = surrogate.normal(x);
    EXPECT_NEAR(norm(normal), 1.0, 1e-14);
    const Vec3 radial = surrogate.project(x).point;
    EXPECT_GT(dot(normal, radial * (1 / norm(radial))), 0.999);  // outward, and nearly radial
  }
}

// The tree's nearest search visits what brute force would find.
TEST(SurfacePatchTree, NearestMatchesBruteForce) {
  std::mt19937 random(4);
  std::uniform_real_distribution<double> coordinate(0, 10), extent(0, 0.5);
  std::vector<Box<3>> boxes(500);
  for (Box<3>& box : boxes) {
    box = Box<3>::empty();
    Vec3 corner{{coordinate(random), coordinate(random), coordinate(random)}};
    box.add(corner);
    box.add(corner + Vec3{{extent(random), extent(random), extent(random)}});
  }
  const PatchTree<3> tree(boxes);
  for (int k = 0; k < 100; ++k) {
    const Vec3 x{{coordinate(random), coordinate(random), coordinate(random)}};
    int visited = 0;
    const double found = tree.nearest(x, [&](Index p, double) {
      ++visited;
      return boxes[p].distance2(x) + 1;  // the patch's distance: never below its box's
    });
    double brute = std::numeric_limits<double>::infinity();
    for (const Box<3>& box : boxes) brute = std::min(brute, box.distance2(x) + 1);
    EXPECT_EQ(found, brute);
    EXPECT_LT(visited, 100);  // pruned
  }
}

}  // namespace
}  // namespace hocav
