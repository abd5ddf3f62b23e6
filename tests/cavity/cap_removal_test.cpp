// A cap's removal (CavityOptions::exposes_faces; docs/curving.md, "Caps"): a tetrahedron whose two
// faces on the boundary meet along a ridge-like edge (a roof over a valley of the surface) goes,
// and its inner faces become the boundary. The P1 operator refuses the empty star unless asked;
// the P2 flip of the roof's edge removes the cap, puts the valley edge's node where the placement
// says, and keeps every element certified.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "bezier/jacobian_bounds.hpp"
#include "bezier/p2_element.hpp"
#include "cavity/cavity_operator.hpp"
#include "cavity/p2_operations.hpp"
#include "mesh/consistency.hpp"
#include "mesh/measure.hpp"
#include "roof_mesh.hpp"

namespace hocav {
namespace {

using cap_test::Roof;

void expect_consistent(const Mesh<3>& mesh) {
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  EXPECT_EQ(check_consistency(mesh, options), std::vector<std::string>{});
}

// Whether the mesh has a live facet with these vertices.
bool has_facet(const Mesh<3>& mesh, std::array<Index, 3> vertices) {
  std::sort(vertices.begin(), vertices.end());
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    auto facet = mesh.facet(f);
    std::sort(facet.begin(), facet.end());
    if (!mesh.facet_removed(f) && facet == vertices) return true;
  }
  return false;
}

TEST(CapRemoval, TheP1OperatorExposesTheCapsInnerFacesOnlyWhenAsked) {
  Roof roof(0.1);
  CavityOperator<3> plan;
  const std::array<Index, 1> cavity{roof.cap};
  CavityOptions options;
  options.removed_facets = roof.roof;
  EXPECT_EQ(plan.plan(roof.mesh, cavity, Roof::c, options), CavityStatus::kNotStarShaped);  // an empty star
  options.exposes_faces = true;
  ASSERT_EQ(plan.plan(roof.mesh, cavity, Roof::c, options), CavityStatus::kAccepted);
  EXPECT_TRUE(plan.new_elements().empty());
  EXPECT_EQ(plan.new_facets().size(), 2u);
  plan.commit(roof.mesh);
  roof.mesh.compact();
  EXPECT_EQ(roof.mesh.element_count(), 2);
  EXPECT_TRUE(has_facet(roof.mesh, {Roof::a, Roof::c, Roof::d}));
  EXPECT_TRUE(has_facet(roof.mesh, {Roof::b, Roof::c, Roof::d}));
  EXPECT_FALSE(has_facet(roof.mesh, {Roof::a, Roof::b, Roof::c}));
  expect_consistent(roof.mesh);
}

// A roof whose valley edge (c, d) is on the boundary already: the elements under its inner faces
// have different apexes below, e toward a and f toward b, so the faces (c, d, e) and (c, d, f) are
// facets. Exposing the roof's inner faces would give (c, d) four facets: refused.
TEST(CapRemoval, AValleyOnTheBoundaryAlreadyIsNotExposed) {
  constexpr Index a = 0, b = 1, c = 2, d = 3, e = 4, f = 5;
  Mesh<3> mesh;
  for (const Vec3& p : {Vec3{{0, 0, 0.1}}, Vec3{{1, 1, 0.1}}, Vec3{{1, 0, 0}}, Vec3{{0, 1, 0}}, Vec3{{0.2, 0.2, -1}}, Vec3{{0.8, 0.8, -1}}})
    mesh.add_vertex(p);
  for (std::array<Index, 4> element : {std::array<Index, 4>{a, b, c, d}, {a, c, d, e}, {b, c, d, f}}) {
    const auto& x = mesh.vertices();
    if (signed_measure(x[element[0]], x[element[1]], x[element[2]], x[element[3]]) < 0) std::swap(element[0], element[1]);
    mesh.add_element(element, 1);
  }
  for (const std::array<Index, 3> facet :
       {std::array<Index, 3>{a, b, c}, {a, b, d}, {a, c, e}, {a, d, e}, {c, d, e}, {b, c, f}, {b, d, f}, {c, d, f}})
    mesh.add_facet(facet, 7);
  mesh.build_topology();
  mesh.orient_boundary_facets_outward();
  expect_consistent(mesh);
  CavityOperator<3> plan;
  const std::array<Index, 1> cavity{0};
  const std::array<Index, 2> roof{0, 1};
  CavityOptions options;
  options.removed_facets = roof;
  options.exposes_faces = true;
  EXPECT_EQ(plan.plan(mesh, cavity, c, options), CavityStatus::kNotStarShaped);
}

// A face with a facet on it, or on the domain's boundary, is never exposed: the cap of a lone
// tetrahedron has no element under its inner faces.
TEST(CapRemoval, ALoneTetrahedronIsNoCap) {
  Mesh<3> mesh;
  for (const Vec3& p : {Vec3{{0, 0, 0}}, Vec3{{1, 0, 0}}, Vec3{{0, 1, 0}}, Vec3{{0, 0, 1}}}) mesh.add_vertex(p);
  mesh.add_element({0, 1, 2, 3}, 1);
  for (const std::array<Index, 3> facet : {std::array<Index, 3>{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}}) mesh.add_facet(facet, 1);
  mesh.build_topology();
  CavityOperator<3> plan;
  const std::array<Index, 1> cavity{0};
  const std::array<Index, 2> removed{2, 3};  // (0, 1, 3) and (0, 1, 2): their edge (0, 1)
  CavityOptions options;
  options.removed_facets = removed;
  options.exposes_faces = true;
  EXPECT_EQ(plan.plan(mesh, cavity, 2, options), CavityStatus::kNotStarShaped);
}

// The P2 flip of the roof's edge: the cap goes, the valley edge (c, d) becomes a boundary edge with
// its node where the placement puts it, and the elements under it stay certified. A placement the
// elements cannot follow is refused, the mesh unchanged.
TEST(CapRemoval, TheP2FlipOfACapsEdgeRemovesIt) {
  for (const double lift : {0.05, -2.0}) {
    Roof roof(0.1);
    Mesh<3>& mesh = roof.mesh;
    mesh.make_p2();
    const SymMat<3> identity = SymMat<3>::identity();
    const MetricField<3> field(mesh, std::vector<SymMat<3>>(static_cast<std::size_t>(mesh.vertex_count()), identity));
    P2Operations<3> operations(mesh, field, nullptr, {.jacobian_floor = 0.01});
    const Vec3 up{{0, 0, lift}};
    BoundaryPlacement<3> placement;
    placement.facets = roof.roof;
    placement.place = [&](const Vec3& x, Index) { return x + up; };
    const std::array<Index, 2> apexes{Roof::c, Roof::d};
    // Without the placement the roof's edge is a boundary edge, refused as ever.
    EXPECT_EQ(operations.swap_edge(Roof::a, Roof::b, apexes), CavityStatus::kCrossesBoundary);
    const Vec3 valley_node = mesh.edge_node(mesh.find_edge(Roof::c, Roof::d));
    const CavityStatus status = operations.swap_edge(Roof::a, Roof::b, apexes, {}, &placement);
    if (lift < 0) {  // the node through the elements under it would invert them: refused
      EXPECT_EQ(status, CavityStatus::kBoundaryGeometry) << to_string(status);  // the node pulled back off its place
      EXPECT_EQ(mesh.element_count(), 3);
      EXPECT_EQ(mesh.edge_node(mesh.find_edge(Roof::c, Roof::d)), valley_node);
      continue;
    }
    ASSERT_EQ(status, CavityStatus::kAccepted);
    EXPECT_EQ(mesh.find_edge(Roof::a, Roof::b), kNoIndex);
    EXPECT_EQ(mesh.edge_node(mesh.find_edge(Roof::c, Roof::d)), valley_node + up);
    mesh.compact();
    EXPECT_EQ(mesh.element_count(), 2);
    expect_consistent(mesh);
    for (Index k = 0; k < mesh.element_count(); ++k)
      EXPECT_TRUE(certify_min_normalized_jacobian_above(gather_p2_element(mesh, k), 0.01)) << "element " << k;
  }
}

}  // namespace
}  // namespace hocav
