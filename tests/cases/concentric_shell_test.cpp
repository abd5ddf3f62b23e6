#include "cases/concentric_shell.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "base/error.hpp"
#include "mesh/consistency.hpp"
#include "mesh/measure.hpp"

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
  double power_out = std::pow(p.outer_radius, D), power_in = std::pow(p.inner_radius, D);
  return (D == 2 ? std::numbers::pi : 4.0 / 3.0 * std::numbers::pi) * (power_out - power_in);
}

// Inscribed polygons/polyhedra lose a sliver under each boundary facet: about pi r theta^2 / 6 = pi h^2 / 6
// per circle; under each sphere triangle a cap of height ~ h^2 / (6 r), about pi r h^2 / 3 per sphere.
template <int D>
double measure_tolerance(const ShellParameters& p) {
  double h = p.size;
  return D == 2 ? 2 * std::numbers::pi * h * h / 6 * 1.5 : std::numbers::pi * (p.inner_radius + p.outer_radius) * h * h / 2;
}

template <int D>
double total_measure(const Mesh<D>& mesh) {
  double total = 0;
  for (Index k = 0; k < mesh.element_count(); ++k) total += element_measure(mesh, k);
  return total;
}

template <int D>
void expect_valid_shell(const ShellParameters& p) {
  SCOPED_TRACE("r_in " + std::to_string(p.inner_radius) + " r_out " + std::to_string(p.outer_radius) + " h " +
               std::to_string(p.size));
  Mesh<D> mesh = generate<D>(p);
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  options.require_positive_orientation = true;
  EXPECT_EQ(check_consistency(mesh, options), std::vector<std::string>{});
  EXPECT_NEAR(total_measure(mesh), exact_measure<D>(p), measure_tolerance<D>(p));

  std::set<int> element_refs, facet_refs;
  for (Index k = 0; k < mesh.element_count(); ++k) element_refs.insert(mesh.element_ref(k));
  EXPECT_EQ(element_refs, std::set<int>{1});
  std::set<Index> boundary_vertices;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    facet_refs.insert(mesh.facet_ref(f));
    double radius = mesh.facet_ref(f) == 1 ? p.inner_radius : p.outer_radius;
    for (Index v : mesh.facet(f)) {
      EXPECT_NEAR(norm(mesh.vertex(v)), radius, 1e-12 * radius) << "facet " << f << " ref " << mesh.facet_ref(f);
      boundary_vertices.insert(v);
    }
  }
  EXPECT_EQ(facet_refs, (std::set<int>{1, 2}));
  // Inner vertices lie strictly inside the shell.
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (boundary_vertices.contains(v)) continue;
    double r = norm(mesh.vertex(v));
    EXPECT_GT(r, p.inner_radius * (1 + 1e-9)) << "vertex " << v;
    EXPECT_LT(r, p.outer_radius * (1 - 1e-9)) << "vertex " << v;
  }
  // Divergence theorem with the field x (divergence D): the flux of x through the facets is D times
  // the measure only if every facet is outward and they close the domain.
  double outward_flux = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    const auto& facet = mesh.facet(f);
    if constexpr (D == 2)
      outward_flux += determinant(mesh.vertex(facet[0]), mesh.vertex(facet[1]));
    else
      outward_flux += determinant(mesh.vertex(facet[0]), mesh.vertex(facet[1]), mesh.vertex(facet[2])) / 2.0;
  }
  EXPECT_NEAR(outward_flux / D, total_measure(mesh), 1e-10 * exact_measure<D>(p)) << "facets are not all outward";
}

template <int D>
void expect_deterministic(const ShellParameters& p) {
  Mesh<D> first = generate<D>(p), second = generate<D>(p);
  ASSERT_EQ(first.vertex_count(), second.vertex_count());
  ASSERT_EQ(first.element_count(), second.element_count());
  ASSERT_EQ(first.facet_count(), second.facet_count());
  for (Index v = 0; v < first.vertex_count(); ++v) EXPECT_EQ(first.vertex(v), second.vertex(v));
  for (Index k = 0; k < first.element_count(); ++k) EXPECT_EQ(first.element(k), second.element(k));
  for (Index f = 0; f < first.facet_count(); ++f) {
    EXPECT_EQ(first.facet(f), second.facet(f));
    EXPECT_EQ(first.facet_ref(f), second.facet_ref(f));
  }
}

TEST(Annulus, DefaultIsValidAndHasTheExactArea) { expect_valid_shell<2>({}); }

TEST(Annulus, OtherRadiiAndSizes) {
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

TEST(Annulus, AreaConvergesAsTheSizeDecreases) { expect_measure_convergence<2>(0.1); }

TEST(Annulus, IsDeterministic) { expect_deterministic<2>({0.5, 1.0, 0.07}); }

TEST(Annulus, RejectsBadParameters) {
  EXPECT_THROW(generate_annulus({1.0, 0.5, 0.1}), Error);
  EXPECT_THROW(generate_annulus({0.0, 1.0, 0.1}), Error);
  EXPECT_THROW(generate_annulus({0.5, 1.0, 0.0}), Error);
  EXPECT_THROW(generate_annulus({0.5, 1.0, std::nan("")}), Error);
  EXPECT_THROW(generate_annulus({0.5, 1.0, 1e-6}), Error);  // far too many elements
}

TEST(SphereShell, DefaultIsValidAndHasTheExactVolume) { expect_valid_shell<3>({0.5, 1.0, 0.25}); }

TEST(SphereShell, OtherRadiiAndSizes) {
  expect_valid_shell<3>({0.3, 1.0, 0.15});
  expect_valid_shell<3>({2.0, 3.0, 0.5});
}

TEST(SphereShell, VolumeConvergesAsTheSizeDecreases) { expect_measure_convergence<3>(0.3); }

TEST(SphereShell, IsDeterministic) { expect_deterministic<3>({0.5, 1.0, 0.25}); }

TEST(SphereShell, RejectsBadParameters) {
  EXPECT_THROW(generate_sphere_shell({0.5, 0.5, 0.1}), Error);
  EXPECT_THROW(generate_sphere_shell({0.5, 1.0, -1.0}), Error);
  EXPECT_THROW(generate_sphere_shell({0.5, 1.0, 1e-4}), Error);
}

}  // namespace
}  // namespace hocav
