// Checks every shell case must pass (the gmsh annulus and sphere shell, the polar annulus, the
// cubed-sphere shell): a consistent mesh of the region between two circles/spheres centred at the
// origin, boundary refs 1 inner and 2 outer, boundary vertices on their circle/sphere, outward facets.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "mesh/consistency.hpp"
#include "mesh/measure.hpp"

namespace hocav::shell_test {

template <int D>
double exact_measure(double inner_radius, double outer_radius) {
  return (D == 2 ? std::numbers::pi : 4.0 / 3.0 * std::numbers::pi) * (std::pow(outer_radius, D) - std::pow(inner_radius, D));
}

// Consistency with positive elements and a facet on every boundary face; element ref 1; facet refs
// {1, 2} on the inner and outer wall with their vertices on it (to 1e-12); other vertices strictly
// inside; facets outward: by the divergence theorem with the field x (divergence D), the flux of x
// through the facets is D times the measure only if every facet is outward and they close the domain.
template <int D>
void expect_valid_shell(const Mesh<D>& mesh, double inner_radius, double outer_radius) {
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  options.require_positive_orientation = true;
  EXPECT_EQ(check_consistency(mesh, options), std::vector<std::string>{});

  std::set<int> element_refs, facet_refs;
  for (Index k = 0; k < mesh.element_count(); ++k) element_refs.insert(mesh.element_ref(k));
  EXPECT_EQ(element_refs, std::set<int>{1});
  std::vector<bool> on_boundary(static_cast<std::size_t>(mesh.vertex_count()), false);
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    facet_refs.insert(mesh.facet_ref(f));
    const double radius = mesh.facet_ref(f) == 1 ? inner_radius : outer_radius;
    for (Index v : mesh.facet(f)) {
      EXPECT_NEAR(norm(mesh.vertex(v)), radius, 1e-12 * radius) << "facet " << f << " ref " << mesh.facet_ref(f);
      on_boundary[static_cast<std::size_t>(v)] = true;
    }
  }
  EXPECT_EQ(facet_refs, (std::set<int>{1, 2}));
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (on_boundary[static_cast<std::size_t>(v)]) continue;
    const double r = norm(mesh.vertex(v));
    EXPECT_GT(r, inner_radius * (1 + 1e-12)) << "vertex " << v;
    EXPECT_LT(r, outer_radius * (1 - 1e-12)) << "vertex " << v;
  }
  double outward_flux = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    const auto& facet = mesh.facet(f);
    if constexpr (D == 2)
      outward_flux += determinant(mesh.vertex(facet[0]), mesh.vertex(facet[1]));
    else
      outward_flux += determinant(mesh.vertex(facet[0]), mesh.vertex(facet[1]), mesh.vertex(facet[2])) / 2.0;
  }
  EXPECT_NEAR(outward_flux / D, total_measure(mesh), 1e-10 * exact_measure<D>(inner_radius, outer_radius)) << "facets are not all outward";
}

// The same vertices, elements and facets, bit for bit.
template <int D>
void expect_identical(const Mesh<D>& first, const Mesh<D>& second) {
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

}  // namespace hocav::shell_test
