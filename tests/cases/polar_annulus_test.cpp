#include "cases/polar_annulus.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "base/error.hpp"
#include "shell_test_support.hpp"

namespace hocav {
namespace {

using shell_test::exact_measure;

TEST(PolarAnnulus, CountsValidityAndLayerRadii) {
  const std::vector<double> radii{0.5, 0.52, 0.6, 1.0};
  const Mesh<2> mesh = generate_polar_annulus(12, radii);
  EXPECT_EQ(mesh.vertex_count(), 12 * 4);
  EXPECT_EQ(mesh.element_count(), 2 * 12 * 3);
  EXPECT_EQ(polar_annulus_triangle_count(12, radii.size()), mesh.element_count());
  EXPECT_EQ(mesh.facet_count(), 2 * 12);
  shell_test::expect_valid_shell(mesh, 0.5, 1.0);
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    EXPECT_NEAR(norm(mesh.vertex(v)), radii[static_cast<std::size_t>(v / 12)], 1e-15) << "vertex " << v;
  // The inscribed polygons: the exact area of 12-gons.
  const double polygon = 12 * std::sin(2 * std::numbers::pi / 12) / 2;
  EXPECT_NEAR(total_measure(mesh), polygon * (1.0 - 0.25), 1e-12);
}

TEST(PolarAnnulus, ThreeSectorsAreEnough) {
  shell_test::expect_valid_shell(generate_polar_annulus(3, std::vector<double>{0.5, 1.0}), 0.5, 1.0);
}

TEST(PolarAnnulus, BoundaryLayersOnOneAndBothCircles) {
  for (LayerWalls walls : {LayerWalls::kInner, LayerWalls::kBoth}) {
    const ShellLayering layering{0.5, 1.0, walls, 2e-4, 1.25};
    const Mesh<2> mesh = generate_polar_annulus(layering, 20000);
    shell_test::expect_valid_shell(mesh, 0.5, 1.0);
    // Sectors from the boundary edges; the first layer from the second circle of vertices.
    const Index sectors = mesh.facet_count() / 2;
    EXPECT_NEAR(norm(mesh.vertex(sectors)) - 0.5, 2e-4, 1e-12);
    EXPECT_NEAR(norm(mesh.vertex(2 * sectors)) - norm(mesh.vertex(sectors)), 2.5e-4, 1e-12);
    // The outer wall's layer: the first layer again with both walls, else the isotropic spacing.
    const Index last = mesh.vertex_count() - sectors;
    const double outer_first = 1.0 - norm(mesh.vertex(last - sectors));
    if (walls == LayerWalls::kBoth) {
      EXPECT_NEAR(outer_first, 2e-4, 1e-12);
    } else {
      EXPECT_NEAR(outer_first, polar_angular_step(sectors), 0.2 * outer_first);
    }
  }
}

TEST(PolarAnnulus, TargetSizeIsMetAndAreaConverges) {
  double previous_error = 0;
  for (double target : {1e3, 4e3, 1.6e4}) {
    const Mesh<2> mesh = generate_polar_annulus(ShellLayering{}, target);
    EXPECT_GT(mesh.element_count(), target / 1.2);
    EXPECT_LT(mesh.element_count(), target * 1.2);
    const double error = std::abs(total_measure(mesh) - exact_measure<2>(0.5, 1.0));
    if (previous_error > 0) {
      EXPECT_LT(error, previous_error / 3) << target;
    }
    previous_error = error;
  }
}

TEST(PolarAnnulus, IsDeterministicAndRejectsBadParameters) {
  const ShellLayering layering{0.3, 2.0, LayerWalls::kBoth};
  shell_test::expect_identical(generate_polar_annulus(layering, 3000), generate_polar_annulus(layering, 3000));
  EXPECT_THROW(generate_polar_annulus(2, std::vector<double>{0.5, 1.0}), Error);
  EXPECT_THROW(generate_polar_annulus(8, std::vector<double>{1.0, 1.0}), Error);
  EXPECT_THROW(generate_polar_annulus(ShellLayering{}, -5), Error);
  EXPECT_THROW(generate_polar_annulus(ShellLayering{0.5, 1.0, LayerWalls::kInner, 1e-3, 0.5}, 1000), Error);
}

}  // namespace
}  // namespace hocav
