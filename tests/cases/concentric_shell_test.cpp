#include "cases/concentric_shell.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "base/error.hpp"
#include "gmsh_requirement.hpp"
#include "shell_test_support.hpp"

namespace hocav {
namespace {

template <int D>
Mesh<D> generate(const ShellParameters& parameters) {
  if constexpr (D == 2)
    return generate_annulus(parameters);
  else
    return generate_sphere_shell(parameters);
}

template <int D>
double exact_measure(const ShellParameters& p) {
  return shell_test::exact_measure<D>(p.inner_radius, p.outer_radius);
}

// Inscribed polygons/polyhedra lose a sliver under each boundary facet: about pi r theta^2 / 6 = pi h^2 / 6
// per circle; under each sphere triangle a cap of height ~ h^2 / (6 r), about pi r h^2 / 3 per sphere.
template <int D>
double measure_tolerance(const ShellParameters& p) {
  double h = p.size;
  return D == 2 ? 2 * std::numbers::pi * h * h / 6 * 1.5 : std::numbers::pi * (p.inner_radius + p.outer_radius) * h * h / 2;
}

template <int D>
void expect_valid_shell(const ShellParameters& p) {
  SCOPED_TRACE("r_in " + std::to_string(p.inner_radius) + " r_out " + std::to_string(p.outer_radius) + " h " + std::to_string(p.size));
  Mesh<D> mesh = generate<D>(p);
  shell_test::expect_valid_shell(mesh, p.inner_radius, p.outer_radius);
  EXPECT_NEAR(total_measure(mesh), exact_measure<D>(p), measure_tolerance<D>(p));
}

template <int D>
void expect_deterministic(const ShellParameters& p) {
  shell_test::expect_identical(generate<D>(p), generate<D>(p));
}

TEST(Annulus, DefaultIsValidAndHasTheExactArea) {
  HOCAV_SKIP_WITHOUT_GMSH();
  expect_valid_shell<2>({});
}

TEST(Annulus, OtherRadiiAndSizes) {
  HOCAV_SKIP_WITHOUT_GMSH();
  expect_valid_shell<2>({0.2, 1.5, 0.05});
  expect_valid_shell<2>({0.9, 1.0, 0.02});
  expect_valid_shell<2>({1.0, 3.0, 0.3});
}

// The outer and inner slivers cancel to first order, so the convergence is checked on a skinny
// shell, where the outer boundary dominates: halving h must divide the error by about 4.
template <int D>
void expect_measure_convergence(double coarse_size) {
  ShellParameters coarse{0.1, 1.0, coarse_size}, fine{0.1, 1.0, coarse_size / 2};
  double coarse_error = std::abs(total_measure(generate<D>(coarse)) - exact_measure<D>(coarse));
  double fine_error = std::abs(total_measure(generate<D>(fine)) - exact_measure<D>(fine));
  EXPECT_LT(fine_error, coarse_error / 3) << "coarse error " << coarse_error << ", fine error " << fine_error;
}

TEST(Annulus, AreaConvergesAsTheSizeDecreases) {
  HOCAV_SKIP_WITHOUT_GMSH();
  expect_measure_convergence<2>(0.1);
}

TEST(Annulus, IsDeterministic) {
  HOCAV_SKIP_WITHOUT_GMSH();
  expect_deterministic<2>({0.5, 1.0, 0.07});
}

TEST(Annulus, RejectsBadParameters) {
  HOCAV_SKIP_WITHOUT_GMSH();
  EXPECT_THROW(generate_annulus({1.0, 0.5, 0.1}), Error);
  EXPECT_THROW(generate_annulus({0.0, 1.0, 0.1}), Error);
  EXPECT_THROW(generate_annulus({0.5, 1.0, 0.0}), Error);
  EXPECT_THROW(generate_annulus({0.5, 1.0, std::nan("")}), Error);
  EXPECT_THROW(generate_annulus({0.5, 1.0, 1e-6}), Error);  // far too many elements
}

TEST(SphereShell, DefaultIsValidAndHasTheExactVolume) {
  HOCAV_SKIP_WITHOUT_GMSH();
  expect_valid_shell<3>({0.5, 1.0, 0.25});
}

TEST(SphereShell, OtherRadiiAndSizes) {
  HOCAV_SKIP_WITHOUT_GMSH();
  expect_valid_shell<3>({0.3, 1.0, 0.15});
  expect_valid_shell<3>({2.0, 3.0, 0.5});
}

TEST(SphereShell, VolumeConvergesAsTheSizeDecreases) {
  HOCAV_SKIP_WITHOUT_GMSH();
  expect_measure_convergence<3>(0.3);
}

TEST(SphereShell, IsDeterministic) {
  HOCAV_SKIP_WITHOUT_GMSH();
  expect_deterministic<3>({0.5, 1.0, 0.25});
}

TEST(SphereShell, RejectsBadParameters) {
  HOCAV_SKIP_WITHOUT_GMSH();
  EXPECT_THROW(generate_sphere_shell({0.5, 0.5, 0.1}), Error);
  EXPECT_THROW(generate_sphere_shell({0.5, 1.0, -1.0}), Error);
  EXPECT_THROW(generate_sphere_shell({0.5, 1.0, 1e-4}), Error);
}

}  // namespace
}  // namespace hocav
