#include "cases/radial_layers.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "base/error.hpp"

namespace hocav {
namespace {

std::vector<double> thicknesses(const std::vector<double>& radii) {
  std::vector<double> result;
  for (std::size_t i = 0; i + 1 < radii.size(); ++i) result.push_back(radii[i + 1] - radii[i]);
  return result;
}

void expect_increasing_from_to(const std::vector<double>& radii, double inner, double outer) {
  ASSERT_GE(radii.size(), 2u);
  EXPECT_EQ(radii.front(), inner);
  EXPECT_EQ(radii.back(), outer);
  for (std::size_t i = 0; i + 1 < radii.size(); ++i) EXPECT_LT(radii[i], radii[i + 1]) << "layer " << i;
}

TEST(RadialLayers, IsotropicLayersAreAsThickAsTheCellsAreWide) {
  const double step = 0.05;
  const auto radii = layer_radii({0.5, 1.0}, step);
  expect_increasing_from_to(radii, 0.5, 1.0);
  EXPECT_EQ(radii.size() - 1, static_cast<std::size_t>(std::lround(std::log(2.0) / step)));
  // Equal ratios r_{i+1} / r_i, each close to 1 + step: thickness / (r step) near 1.
  for (std::size_t i = 0; i + 1 < radii.size(); ++i) {
    EXPECT_NEAR(radii[i + 1] / radii[i], std::pow(2.0, 1.0 / static_cast<double>(radii.size() - 1)), 1e-12);
    EXPECT_NEAR((radii[i + 1] - radii[i]) / (radii[i] * step), 1, 0.05);
  }
}

TEST(RadialLayers, InnerBoundaryLayerGrowsGeometricallyUntilTheTangentialSize) {
  ShellLayering layering{0.5, 1.0, LayerWalls::kInner};
  const double step = 0.02;
  const auto radii = layer_radii(layering, step);
  expect_increasing_from_to(radii, 0.5, 1.0);
  const auto t = thicknesses(radii);
  const double first = 0.5 * step / kDefaultWallAspect;
  EXPECT_NEAR(t[0], first, 1e-15);
  // Geometric while thinner than the tangential size, then isotropic (thickness ~ r step).
  std::size_t i = 1;
  for (; t[i - 1] * 1.2 < radii[i] * step; ++i) EXPECT_NEAR(t[i] / t[i - 1], 1.2, 1e-9) << "layer " << i;
  EXPECT_NEAR(static_cast<double>(i), std::log(kDefaultWallAspect) / std::log(1.2), 2);
  for (++i; i < t.size(); ++i) {
    EXPECT_NEAR(t[i] / (radii[i] * step), 1, 0.25) << "layer " << i;
    EXPECT_GE(t[i] / t[i - 1], 0.99);  // no thinner layer after the boundary layer
  }
}

TEST(RadialLayers, GivenFirstLayerAndLayerCount) {
  ShellLayering layering{0.5, 1.0, LayerWalls::kInner, 1e-3, 1.5, 5};
  const auto radii = layer_radii(layering, 0.05);
  const auto t = thicknesses(radii);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(t[i], 1e-3 * std::pow(1.5, static_cast<double>(i)), 1e-15);
  // Then isotropic from r_5 to the outer wall.
  const double r5 = radii[5];
  const std::size_t isotropic = static_cast<std::size_t>(std::lround(std::log(1.0 / r5) / 0.05));
  EXPECT_EQ(radii.size(), 6 + isotropic);
}

TEST(RadialLayers, BothWallsGrowUntilTheFrontsMeet) {
  ShellLayering layering{0.5, 1.0, LayerWalls::kBoth};
  const double step = 0.02;
  const auto radii = layer_radii(layering, step);
  expect_increasing_from_to(radii, 0.5, 1.0);
  const auto t = thicknesses(radii);
  const double first = 0.5 * step / kDefaultWallAspect;
  EXPECT_NEAR(t.front(), first, 1e-15);
  EXPECT_NEAR(t.back(), first, 1e-15);
  // Every layer is part of one of the two geometric stacks except the one or two closing layers,
  // which are about as thick as their neighbours: thicknesses rise, then fall, by at most the
  // growth ratio (and a little for the closure).
  std::size_t thickest = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] > t[thickest]) thickest = i;
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double ratio = i <= thickest ? t[i] / t[i - 1] : t[i - 1] / t[i];
    EXPECT_GE(ratio, 0.5) << "layer " << i;
    EXPECT_LE(ratio, 2.0) << "layer " << i;
  }
  // The fronts advanced in turn: as many layers on each side, give or take the closure.
  const double outer_layers = static_cast<double>(t.size() - thickest);
  EXPECT_NEAR(static_cast<double>(thickest), outer_layers, 3);
  // Both stacks reach the middle: far thicker there than the isotropic size (the default growth
  // keeps going until they meet).
  EXPECT_GT(t[thickest], 0.75 * step);
}

TEST(RadialLayers, ThinGapBetweenWallsCloses) {
  // The walls are so close that the first layers meet at once.
  ShellLayering layering{1.0, 1.001, LayerWalls::kBoth, 4e-4, 1.2, 0};
  const auto radii = layer_radii(layering, 0.1);
  expect_increasing_from_to(radii, 1.0, 1.001);
  EXPECT_LE(radii.size(), 5u);
}

TEST(RadialLayers, RejectsBadParameters) {
  EXPECT_THROW(layer_radii({1.0, 0.5}, 0.1), Error);
  EXPECT_THROW(layer_radii({0.5, 1.0}, 0), Error);
  EXPECT_THROW(layer_radii({0.5, 1.0, LayerWalls::kInner, 1e-3, 0.9}, 0.1), Error);
  EXPECT_THROW(layer_radii({0.5, 1.0, LayerWalls::kInner, -1e-3}, 0.1), Error);
  EXPECT_THROW(layer_radii({0.5, 1.0, LayerWalls::kInner, 1e-3, 1.2, -1}, 0.1), Error);
  // Growth 1 from a tiny first layer would need a billion layers.
  EXPECT_THROW(layer_radii({0.5, 1.0, LayerWalls::kBoth, 1e-10, 1.0}, 0.1), Error);
  EXPECT_THROW(layer_radii({0.5, 1.0}, 1e-9), Error);
}

TEST(UnitLayerRadii, UniformSizeGivesEqualLayers) {
  const auto radii = unit_layer_radii(0.5, 1.0, [](double) { return 0.01; });
  ASSERT_EQ(radii.size(), 51u);
  for (std::size_t i = 0; i < radii.size(); ++i) EXPECT_NEAR(radii[i], 0.5 + 0.01 * static_cast<double>(i), 1e-12);
}

TEST(UnitLayerRadii, SizeProportionalToTheRadiusGivesGeometricLayers) {
  // ∫ dr / (a r) = ln(r_out / r_in) / a: the radii are in geometric progression.
  const double a = 0.02;
  const auto radii = unit_layer_radii(0.5, 1.0, [a](double r) { return a * r; });
  ASSERT_EQ(radii.size() - 1, static_cast<std::size_t>(std::lround(std::log(2.0) / a)));
  const double ratio = std::pow(2.0, 1.0 / static_cast<double>(radii.size() - 1));
  for (std::size_t i = 0; i + 1 < radii.size(); ++i) EXPECT_NEAR(radii[i + 1] / radii[i], ratio, 1e-7);
}

TEST(UnitLayerRadii, RejectsANonPositiveSize) {
  EXPECT_THROW(unit_layer_radii(0.5, 1.0, [](double r) { return r - 0.75; }), Error);
  EXPECT_THROW(unit_layer_radii(1.0, 0.5, [](double) { return 0.1; }), Error);
  EXPECT_THROW(unit_layer_radii(0.5, 1.0, [](double) { return 1e-7; }), Error);  // 5 million layers
}

}  // namespace
}  // namespace hocav
