#include "cases/cubed_sphere_shell.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "cases/target_resolution.hpp"
#include "shell_test_support.hpp"

namespace hocav {
namespace {

using shell_test::exact_measure;

// The distinct vertex radii, ascending (vertices of one layer share their radius to rounding).
std::vector<double> vertex_radii(const Mesh<3>& mesh) {
  std::vector<double> radii;
  for (const Vec3& x : mesh.vertices()) radii.push_back(norm(x));
  std::sort(radii.begin(), radii.end());
  std::vector<double> distinct{radii.front()};
  for (double r : radii)
    if (r > distinct.back() * (1 + 1e-12)) distinct.push_back(r);
  return distinct;
}

TEST(CubedSphereShell, CountsAndValidityForGivenRadii) {
  const std::vector<double> radii{0.5, 0.6, 0.8, 1.0};
  for (int n : {1, 2, 5}) {
    SCOPED_TRACE("n " + std::to_string(n));
    const Mesh<3> mesh = generate_cubed_sphere_shell(n, radii);
    EXPECT_EQ(mesh.vertex_count(), (6 * n * n + 2) * 4);
    EXPECT_EQ(mesh.element_count(), 36 * n * n * 3);
    EXPECT_EQ(cubed_sphere_shell_tet_count(n, radii.size()), mesh.element_count());
    EXPECT_EQ(mesh.facet_count(), 2 * 12 * n * n);
    // The consistency checker finds every face matched or carrying a facet: the prisms' diagonals
    // agree across neighbours, including across the cube's edges and corners.
    shell_test::expect_valid_shell(mesh, 0.5, 1.0);
    const auto found = vertex_radii(mesh);
    ASSERT_EQ(found.size(), radii.size());
    for (std::size_t i = 0; i < radii.size(); ++i) EXPECT_NEAR(found[i], radii[i], 1e-14);
  }
}

TEST(CubedSphereShell, EveryTetrahedronIsReasonablyShapedInTheIsotropicShell) {
  // Isotropic layers: the worst tetrahedron's volume against its longest edge cubed stays bounded
  // away from zero whatever the resolution (no sliver from the cube's corners or the diagonals).
  for (int n : {4, 12}) {
    const Mesh<3> mesh = generate_cubed_sphere_shell(n, layer_radii({0.5, 1.0}, cubed_sphere_angular_step(n)));
    double worst = 1;
    for (Index k = 0; k < mesh.element_count(); ++k) {
      const auto& t = mesh.element(k);
      double longest = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) longest = std::max(longest, norm(mesh.vertex(t[i]) - mesh.vertex(t[j])));
      worst = std::min(worst, element_measure(mesh, k) / std::pow(longest, 3));
    }
    EXPECT_GT(worst, 0.02) << "n " << n;  // the regular tetrahedron has 0.118, a cube's Kuhn tet 0.032
  }
}

TEST(CubedSphereShell, VolumeConvergesAtSecondOrder) {
  double previous_error = 0;
  for (int n : {4, 8, 16}) {
    const Mesh<3> mesh = generate_cubed_sphere_shell(n, layer_radii({0.5, 1.0}, cubed_sphere_angular_step(n)));
    const double error = std::abs(total_measure(mesh) - exact_measure<3>(0.5, 1.0));
    // The caps under the boundary triangles: a relative loss of the order of the angular step squared.
    EXPECT_LT(error, std::pow(cubed_sphere_angular_step(n), 2) * exact_measure<3>(0.5, 1.0));
    if (previous_error > 0) {
      EXPECT_LT(error, previous_error / 3) << "n " << n;
    }
    previous_error = error;
  }
}

TEST(CubedSphereShell, BoundaryLayerThicknessAndAspectRatioAtTheWall) {
  const int n = 8;
  const double step = cubed_sphere_angular_step(n);
  ShellLayering layering{0.5, 1.0, LayerWalls::kInner};
  const Mesh<3> mesh = generate_cubed_sphere_shell(n, layer_radii(layering, step));
  shell_test::expect_valid_shell(mesh, 0.5, 1.0);
  const auto radii = vertex_radii(mesh);
  const double first = radii[1] - radii[0];
  EXPECT_NEAR(first, 0.5 * step / kDefaultWallAspect, 1e-12);
  EXPECT_NEAR((radii[2] - radii[1]) / first, 1.2, 1e-9);
  // Wall tangential edges: between 0.5 and 1.1 times the arc r_in step (equiangular grid).
  double shortest = 1e9, longest = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_ref(f) != 1) continue;
    const auto& t = mesh.facet(f);
    for (int i = 0; i < 3; ++i) {
      const double length = norm(mesh.vertex(t[i]) - mesh.vertex(t[(i + 1) % 3]));
      shortest = std::min(shortest, length);
      longest = std::max(longest, length);
    }
  }
  EXPECT_GT(shortest / first, 0.5 * kDefaultWallAspect);
  EXPECT_LT(longest / first, 2 * kDefaultWallAspect);  // the diagonals: up to sqrt(2) longer
}

TEST(CubedSphereShell, BothWallsCarryLayersOfTheFirstThickness) {
  const int n = 6;
  ShellLayering layering{0.5, 1.0, LayerWalls::kBoth, 1e-3, 1.3};
  const Mesh<3> mesh = generate_cubed_sphere_shell(n, layer_radii(layering, cubed_sphere_angular_step(n)));
  shell_test::expect_valid_shell(mesh, 0.5, 1.0);
  const auto radii = vertex_radii(mesh);
  EXPECT_NEAR(radii[1] - radii[0], 1e-3, 1e-12);
  EXPECT_NEAR(radii[radii.size() - 1] - radii[radii.size() - 2], 1e-3, 1e-12);
  EXPECT_NEAR(radii[radii.size() - 2] - radii[radii.size() - 3], 1.3e-3, 1e-12);
}

TEST(CubedSphereShell, TargetSizeIsMetWithinAFactor) {
  for (LayerWalls walls : {LayerWalls::kNone, LayerWalls::kInner, LayerWalls::kBoth}) {
    SCOPED_TRACE("walls " + std::to_string(static_cast<int>(walls)));
    const ShellLayering layering{0.5, 1.0, walls};
    auto tets = [&layering](int n) { return cubed_sphere_shell_tet_count(n, layer_radii(layering, cubed_sphere_angular_step(n)).size()); };
    // Counted at the benchmark sizes (neighbouring resolutions differ by less than 20% there).
    for (double target : {1e6, 5e6, 2e7}) {
      const double count = tets(resolution_for_target("target-tets", target, 1, tets));
      EXPECT_GT(count, target / 1.1) << target;
      EXPECT_LT(count, target * 1.1) << target;
    }
    const Mesh<3> mesh = generate_cubed_sphere_shell(layering, 2e4);
    EXPECT_GT(mesh.element_count(), 2e4 / 1.25);
    EXPECT_LT(mesh.element_count(), 2e4 * 1.25);
    shell_test::expect_valid_shell(mesh, 0.5, 1.0);
  }
}

TEST(CubedSphereShell, IsDeterministic) {
  const ShellLayering layering{0.5, 1.0, LayerWalls::kBoth};
  shell_test::expect_identical(generate_cubed_sphere_shell(layering, 5000), generate_cubed_sphere_shell(layering, 5000));
}

TEST(CubedSphereShell, RejectsBadParameters) {
  const std::vector<double> radii{0.5, 1.0};
  EXPECT_THROW(generate_cubed_sphere_shell(0, radii), Error);
  EXPECT_THROW(generate_cubed_sphere_shell(20000, radii), Error);  // more than 2³¹ tetrahedra
  EXPECT_THROW(generate_cubed_sphere_shell(2, std::vector<double>{0.5}), Error);
  EXPECT_THROW(generate_cubed_sphere_shell(2, std::vector<double>{0.5, 0.4}), Error);
  EXPECT_THROW(generate_cubed_sphere_shell(2, std::vector<double>{0.0, 1.0}), Error);
  EXPECT_THROW(generate_cubed_sphere_shell(ShellLayering{}, 0), Error);
  EXPECT_THROW(generate_cubed_sphere_shell(ShellLayering{}, 1e9), Error);
  EXPECT_THROW(generate_cubed_sphere_shell(ShellLayering{1.0, 0.5}, 1000), Error);
}

}  // namespace
}  // namespace hocav
