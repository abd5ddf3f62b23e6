// The curved passes' boundary operations (src/adapt/curved_boundary.hpp) one by one, in 2D and 3D:
// a P2 split of a boundary edge, a P2 collapse of a boundary vertex and a P2 flip of a boundary edge
// keep the mesh consistent and every element certified, put the new vertex and the new boundary
// edges' nodes on the geometry, and re-star the boundary facets; feature lines, corners and
// interior edges get no placement.
#include "adapt/curved_boundary.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "adapt/boundary_pieces.hpp"
#include "base/small_set.hpp"
#include "bezier/jacobian_bounds.hpp"
#include "bezier/p2_element.hpp"
#include "cases/cubed_sphere_shell.hpp"
#include "cases/polar_annulus.hpp"
#include "cases/structured.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/consistency.hpp"
#include "surface/analytic_boundary.hpp"
#include "surface/boundary_proposals.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

constexpr std::array<double, 4> kRadii{0.5, 0.6, 0.75, 1.0};
constexpr double kFloor = 0.01;

// A shell whose boundary nodes lie on its circles or spheres, in an isotropic metric of size h.
template <int D>
struct ConcentricShell {
  Mesh<D> mesh;
  AnalyticBoundary<D> geometry = concentric_shell_boundary<D>(kRadii.front(), kRadii.back());
  std::unique_ptr<MetricField<D>> field;
  // `cells`: around the circle (2D), or along each cube face's side (3D).
  explicit ConcentricShell(double h, int cells = D == 2 ? 24 : 8) {
    if constexpr (D == 2)
      mesh = generate_polar_annulus(cells, kRadii);
    else
      mesh = generate_cubed_sphere_shell(cells, kRadii);
    mesh.build_topology();
    mesh.orient_boundary_facets_outward();
    SymMat<D> metric{};
    for (int i = 0; i < D; ++i) metric(i, i) = 1 / (h * h);
    field = std::make_unique<MetricField<D>>(mesh, std::vector<SymMat<D>>(static_cast<std::size_t>(mesh.vertex_count()), metric));
    BoundaryProposals<D> proposals(mesh, geometry);
    apply_boundary_proposals(mesh, proposals);
  }
};

template <int D>
bool every_element_certified(const Mesh<D>& mesh) {
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (!certify_min_normalized_jacobian_above(gather_p2_element(mesh, k), kFloor)) return false;
  return true;
}

template <int D>
void expect_consistent(const Mesh<D>& mesh) {
  ConsistencyOptions options;
  options.require_positive_orientation = false;
  const auto problems = check_consistency(mesh, options);
  EXPECT_TRUE(problems.empty()) << problems.front();
}

// On the inner circle or sphere (ref 1), to round-off.
template <int D>
bool on_inner_wall(const Vec<D>& x) {
  return std::abs(norm(x) - kRadii.front()) < 1e-12;
}

// The edges of the facets through v: their nodes must be on the wall.
template <int D>
void expect_wall_edges_on_geometry(const Mesh<D>& mesh, Index v) {
  int edges = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_removed(f) || !small_set_holds(mesh.facet(f), v)) continue;
    for (Index w : mesh.facet(f)) {
      if (w == v) continue;
      ++edges;
      EXPECT_TRUE(on_inner_wall<D>(mesh.edge_node(mesh.find_edge(v, w))))
          << "edge (" << v << ", " << w << ") " << norm(mesh.edge_node(mesh.find_edge(v, w))) - kRadii.front();
    }
  }
  EXPECT_GT(edges, 0);
}

// An edge of the inner wall, and a vertex of it.
template <int D>
std::array<Index, 2> wall_edge(const Mesh<D>& mesh) {
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (mesh.facet_ref(f) == 1) return {mesh.facet(f)[0], mesh.facet(f)[1]};
  return {kNoIndex, kNoIndex};
}

template <int D>
void check_boundary_split() {
  ConcentricShell<D> shell(0.02);
  Mesh<D>& mesh = shell.mesh;
  ASSERT_TRUE(every_element_certified(mesh));
  CurvedBoundary<D> boundary(mesh, shell.geometry, 45);
  P2Operations<D> operations(mesh, *shell.field, nullptr, {.jacobian_floor = kFloor});
  const auto [a, b] = wall_edge(mesh);
  const Index facets_before = mesh.facet_count();
  std::vector<Index> cavity;
  collect_shell(mesh, a, b, cavity);
  const auto placement = boundary.edge_placement(cavity, a, b, true);
  ASSERT_TRUE(placement);
  // Without the placement, the boundary edge is refused as before.
  EXPECT_EQ(operations.split_edge(a, b), CavityStatus::kCrossesBoundary);
  Index m = kNoIndex;
  ASSERT_EQ(operations.split_edge(a, b, &m, {}, &*placement), CavityStatus::kAccepted);
  boundary.add_boundary_vertex(m, VertexClass::kSurface);
  EXPECT_TRUE(on_inner_wall<D>(mesh.vertex(m)));
  expect_wall_edges_on_geometry(mesh, m);
  EXPECT_EQ(mesh.find_edge(a, b), kNoIndex);
  mesh.compact();
  expect_consistent(mesh);
  EXPECT_TRUE(every_element_certified(mesh));
  EXPECT_EQ(mesh.facet_count(), facets_before + (D == 2 ? 1 : 2));  // one facet in two (2D), two in four (3D)
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (!small_set_holds(mesh.facet(f), m)) continue;
    EXPECT_EQ(mesh.facet_ref(f), 1);
  }
}

template <int D>
void check_boundary_collapse() {
  // A metric of size 0.5: the wall's edges are short, and its vertices may go.
  ConcentricShell<D> shell(0.5);
  Mesh<D>& mesh = shell.mesh;
  CurvedBoundary<D> boundary(mesh, shell.geometry, 45);
  P2Operations<D> operations(mesh, *shell.field, nullptr, {.jacobian_floor = kFloor});
  const auto [removed, kept] = wall_edge(mesh);
  const Index facets_before = mesh.facet_count();
  std::vector<Index> ball;
  collect_ball(mesh, removed, ball);
  auto placement = boundary.collapse_placement(ball, removed, kept);
  ASSERT_TRUE(placement);
  EXPECT_EQ(operations.collapse_edge(removed, kept), CavityStatus::kCrossesBoundary);
  // Its new boundary edges (about two wall edges long, a fraction of the metric's size 0.5) are
  // measured along the geometry: refused when they may be no longer than a hundredth.
  placement->longest_edge = 0.01;
  EXPECT_EQ(operations.collapse_edge(removed, kept, {}, &*placement), CavityStatus::kNoImprovement);
  EXPECT_FALSE(mesh.vertex_removed(removed));
  placement->longest_edge = INFINITY;
  ASSERT_EQ(operations.collapse_edge(removed, kept, {}, &*placement), CavityStatus::kAccepted);
  EXPECT_TRUE(mesh.vertex_removed(removed));
  expect_wall_edges_on_geometry(mesh, kept);
  const Vec<D> kept_point = mesh.vertex(kept);
  mesh.compact();
  expect_consistent(mesh);
  EXPECT_TRUE(every_element_certified(mesh));
  EXPECT_EQ(mesh.facet_count(), facets_before - (D == 2 ? 1 : 2));  // the edge's facets go
  EXPECT_TRUE(on_inner_wall<D>(kept_point));
}

// A wall edge flipped on the sphere: the edge between the far vertices of its two facets replaces it,
// its node on the sphere, the facets as many as before and of the wall's ref. (The structured shell's
// first wall edges fold their shell when flipped: the first flip the certificate accepts is checked.)
TEST(CurvedBoundary, ABoundaryEdgeSwappedInP2IsFlippedOnTheGeometry) {
  ConcentricShell<3> shell(0.05);
  Mesh<3>& mesh = shell.mesh;
  CurvedBoundary<3> boundary(mesh, shell.geometry, 45);
  P2Operations<3> operations(mesh, *shell.field, nullptr, {.jacobian_floor = kFloor});
  const Index facets_before = mesh.facet_count();
  std::vector<Index> cavity, far;
  Index flipped = kNoIndex, tried = 0;
  for (Index f = 0; f < facets_before && flipped == kNoIndex; ++f) {
    if (mesh.facet_ref(f) != 1) continue;
    const Index a = mesh.facet(f)[0], b = mesh.facet(f)[1];
    collect_shell(mesh, a, b, cavity);
    const auto placement = boundary.edge_placement(cavity, a, b, true);
    ASSERT_TRUE(placement);
    far.clear();
    for (Index g : placement->facets)
      for (Index w : mesh.facet(g))
        if (w != a && w != b) far.push_back(w);
    ASSERT_EQ(far.size(), 2u);
    EXPECT_EQ(operations.swap_edge(a, b, far), CavityStatus::kCrossesBoundary);
    ++tried;
    if (operations.swap_edge(a, b, far, {}, &*placement) != CavityStatus::kAccepted) continue;
    EXPECT_EQ(mesh.find_edge(a, b), kNoIndex);
    flipped = mesh.find_edge(far[0], far[1]);
  }
  ASSERT_NE(flipped, kNoIndex) << tried << " flips tried";
  EXPECT_TRUE(on_inner_wall<3>(mesh.edge_node(flipped)));
  mesh.compact();
  expect_consistent(mesh);
  EXPECT_TRUE(every_element_certified(mesh));
  EXPECT_EQ(mesh.facet_count(), facets_before);
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (!small_set_holds(mesh.facet(f), far[0]) || !small_set_holds(mesh.facet(f), far[1])) continue;
    EXPECT_EQ(mesh.facet_ref(f), 1);
  }
}

// On a coarse shell (4 cells along a cube face's side), collapsing a wall vertex doubles wall edges
// whose nodes on the sphere would fold their elements: the certification pulls them off the
// geometry, so the collapse is refused and the mesh left as it was.
TEST(CurvedBoundary, AnOperationWhoseBoundaryNodesCannotReachTheGeometryIsRefused) {
  ConcentricShell<3> shell(0.5, 4);
  Mesh<3>& mesh = shell.mesh;
  CurvedBoundary<3> boundary(mesh, shell.geometry, 45);
  P2Operations<3> operations(mesh, *shell.field, nullptr, {.jacobian_floor = kFloor});
  const auto [removed, kept] = wall_edge(mesh);
  std::vector<Index> ball;
  collect_ball(mesh, removed, ball);
  const auto placement = boundary.collapse_placement(ball, removed, kept);
  ASSERT_TRUE(placement);
  const Mesh<3> before = mesh;
  EXPECT_EQ(operations.collapse_edge(removed, kept, {}, &*placement), CavityStatus::kBoundaryGeometry);
  EXPECT_GT(operations.cavity_operator().counters().corrections, 0);
  EXPECT_TRUE(std::ranges::equal(mesh.vertices(), before.vertices()));
  EXPECT_TRUE(std::ranges::equal(mesh.elements(), before.elements()));
  EXPECT_TRUE(std::ranges::equal(mesh.facets(), before.facets()));
  EXPECT_TRUE(std::ranges::equal(mesh.edge_nodes(), before.edge_nodes()));
  EXPECT_FALSE(mesh.vertex_removed(removed));
}

TEST(CurvedBoundary, ABoundaryEdgeSplitInP2PutsItsVertexAndNewBoundaryNodesOnTheGeometry2D) { check_boundary_split<2>(); }
TEST(CurvedBoundary, ABoundaryEdgeSplitInP2PutsItsVertexAndNewBoundaryNodesOnTheGeometry3D) { check_boundary_split<3>(); }
TEST(CurvedBoundary, ASurfaceVertexCollapsedInP2LeavesItsNewBoundaryNodesOnTheGeometry2D) { check_boundary_collapse<2>(); }
TEST(CurvedBoundary, ASurfaceVertexCollapsedInP2LeavesItsNewBoundaryNodesOnTheGeometry3D) { check_boundary_collapse<3>(); }

// The unit cube's edges are feature lines (90° > 45°) and its corners corners: a cube edge is split
// along its line but not flipped, a vertex on it collapses only along it, a corner never; an
// interior edge gets no placement; a face vertex collapses only along the face.
TEST(CurvedBoundary, FeatureLinesCornersAndInteriorEdgesGetNoPlacement) {
  Mesh<3> mesh = generate_cube(2);
  mesh.build_topology();
  mesh.orient_boundary_facets_outward();
  mesh.make_p2();
  const AnalyticBoundary<3> geometry = concentric_shell_boundary<3>(0.5, 1.0);  // never asked here
  CurvedBoundary<3> boundary(mesh, geometry, 45);
  const auto find_vertex = [&](Vec3 x) {
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      if (norm(mesh.vertex(v) - x) < 1e-12) return v;
    return kNoIndex;
  };
  const Index corner = find_vertex({0, 0, 0}), on_line = find_vertex({0.5, 0, 0}), on_face = find_vertex({0.5, 0.5, 0});
  const Index center = find_vertex({0.5, 0.5, 0.5});
  ASSERT_NE(corner, kNoIndex);
  ASSERT_NE(on_line, kNoIndex);
  ASSERT_NE(on_face, kNoIndex);
  ASSERT_NE(center, kNoIndex);
  std::vector<Index> elements;
  collect_shell(mesh, corner, on_line, elements);
  EXPECT_FALSE(boundary.edge_placement(elements, corner, on_line, false));      // a line is not flipped
  const auto along = boundary.edge_placement(elements, corner, on_line, true);  // but split along its curve
  ASSERT_TRUE(along);
  EXPECT_EQ(along->lines.size(), 1u);
  collect_shell(mesh, on_face, center, elements);
  EXPECT_FALSE(boundary.edge_placement(elements, on_face, center, true));
  collect_shell(mesh, on_line, on_face, elements);
  EXPECT_TRUE(boundary.edge_placement(elements, on_line, on_face, false));  // an edge inside face z = 0
  collect_ball(mesh, on_line, elements);
  EXPECT_FALSE(boundary.collapse_placement(elements, on_line, on_face));            // off its line
  const auto onto_corner = boundary.collapse_placement(elements, on_line, corner);  // along it
  ASSERT_TRUE(onto_corner);
  EXPECT_EQ(onto_corner->lines.size(), 2u);
  collect_ball(mesh, corner, elements);
  EXPECT_FALSE(boundary.collapse_placement(elements, corner, on_line));
  collect_ball(mesh, on_face, elements);
  EXPECT_FALSE(boundary.collapse_placement(elements, on_face, center));  // not along the boundary
  EXPECT_TRUE(boundary.collapse_placement(elements, on_face, on_line));
}

// A cube edge (a feature line between two faces of different refs) split along it in P2 on the
// cube's P3 surrogate: the new vertex and the line's new edges lie on the cube edge, the line is
// one more edge long; then the new vertex collapsed back along its line onto a corner.
TEST(CurvedBoundary, AFeatureLineIsSplitAndCollapsedAlongItsCurve) {
  Mesh<3> mesh = generate_cube(2);
  mesh.build_topology();
  mesh.orient_boundary_facets_outward();
  const P3Surrogate<3> geometry(mesh);
  mesh.make_p2();
  SymMat<3> metric{};
  for (int i = 0; i < 3; ++i) metric(i, i) = 100;  // h = 0.1
  const MetricField<3> field(mesh, std::vector<SymMat<3>>(static_cast<std::size_t>(mesh.vertex_count()), metric));
  CurvedBoundary<3> boundary(mesh, geometry, 45);
  P2Operations<3> operations(mesh, field, nullptr, {.jacobian_floor = kFloor});
  const auto find_vertex = [&](Vec3 x) {
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      if (norm(mesh.vertex(v) - x) < 1e-12) return v;
    return kNoIndex;
  };
  const Index corner = find_vertex({0, 0, 0}), on_line = find_vertex({0.5, 0, 0});
  const auto on_cube_edge = [](const Vec3& x) { return std::abs(x[1]) < 1e-12 && std::abs(x[2]) < 1e-12; };
  mesh.compact();
  const Index lines_before = mesh.line_count();
  std::vector<Index> elements, lines;
  collect_shell(mesh, corner, on_line, elements);
  const auto split = boundary.edge_placement(elements, corner, on_line, true);
  ASSERT_TRUE(split);
  Index m = kNoIndex;
  ASSERT_EQ(operations.split_edge(corner, on_line, &m, {}, &*split), CavityStatus::kAccepted);
  boundary.add_boundary_vertex(m, VertexClass::kRidge);
  EXPECT_TRUE(on_cube_edge(mesh.vertex(m)));
  for (Index end : {corner, on_line}) {
    lines_along(mesh, m, end, lines);
    EXPECT_EQ(lines.size(), 1u);
    EXPECT_TRUE(on_cube_edge(mesh.edge_node(mesh.find_edge(m, end))));
  }
  expect_consistent(mesh);
  EXPECT_TRUE(every_element_certified(mesh));

  collect_ball(mesh, m, elements);
  const auto collapse = boundary.collapse_placement(elements, m, corner);
  ASSERT_TRUE(collapse);
  ASSERT_EQ(operations.collapse_edge(m, corner, {}, &*collapse), CavityStatus::kAccepted);
  lines_along(mesh, corner, on_line, lines);
  EXPECT_EQ(lines.size(), 1u);
  EXPECT_TRUE(on_cube_edge(mesh.edge_node(mesh.find_edge(corner, on_line))));
  mesh.compact();
  EXPECT_EQ(mesh.line_count(), lines_before);
  expect_consistent(mesh);
  EXPECT_TRUE(every_element_certified(mesh));
}

}  // namespace
}  // namespace hocav
