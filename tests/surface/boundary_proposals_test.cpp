#include "surface/boundary_proposals.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "cases/structured.hpp"
#include "surface/analytic_boundary.hpp"
#include "surface/p3_surrogate.hpp"
#include "surface_test_meshes.hpp"

namespace hocav {
namespace {

using testing::icosphere;

// The boundary edges of a mesh's facets, as sorted vertex pairs.
template <int D>
std::set<std::pair<Index, Index>> boundary_edges(const Mesh<D>& mesh) {
  std::set<std::pair<Index, Index>> edges;
  for (const auto& facet : mesh.facets())
    for (const auto& ends : kPatchEdges<D>) edges.insert(std::minmax(facet[ends[0]], facet[ends[1]]));
  return edges;
}

TEST(SurfaceProposals, TableHoldsEveryBoundaryEdgeUntilTaken) {
  const Mesh<3> mesh = icosphere(2, 1.0, 0.2);
  const P3Surrogate<3> surrogate(mesh);
  BoundaryProposals<3> proposals(mesh, surrogate);
  const auto edges = boundary_edges(mesh);
  ASSERT_EQ(proposals.size(), edges.size());
  for (const auto& [a, b] : edges) {
    // On the surrogate, the proposal is the edge curve's midpoint, found in either vertex order.
    ASSERT_TRUE(proposals.find(a, b));
    EXPECT_EQ(*proposals.find(a, b), *surrogate.edge_midpoint(a, b));
    EXPECT_EQ(*proposals.find(b, a), *proposals.find(a, b));
  }
  const auto [a, b] = *edges.begin();
  const Vec3 proposal = *proposals.find(a, b);
  EXPECT_EQ(proposals.take(b, a), proposal);
  EXPECT_FALSE(proposals.find(a, b));
  EXPECT_FALSE(proposals.take(a, b));
  EXPECT_EQ(proposals.size(), edges.size() - 1);
  EXPECT_FALSE(proposals.find(0, 0));  // not an edge
}

TEST(SurfaceProposals, AnalyticProposalsLieOnTheSurface) {
  const Mesh<3> mesh = icosphere(2, 0.5, 0.2);
  const AnalyticBoundary<3> shell = concentric_shell_boundary<3>(0.5, 1.0);
  BoundaryProposals<3> proposals(mesh, shell);
  for (const auto& [a, b] : boundary_edges(mesh)) {
    const Vec3 node = *proposals.find(a, b);
    EXPECT_NEAR(norm(node), 0.5, 1e-15);
    // The projection of the straight midpoint: along it.
    const Vec3 middle = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
    EXPECT_LT(norm(node - middle * (0.5 / norm(middle))), 1e-15);
  }
}

TEST(SurfaceProposals, ApplyCurvesEveryBoundaryEdgeOnce) {
  Mesh<2> mesh = testing::circle_polygon(12);
  const AnalyticBoundary<2> circle = concentric_shell_boundary<2>(1.0, 2.0);
  BoundaryProposals<2> proposals(mesh, circle);
  EXPECT_EQ(apply_boundary_proposals(mesh, proposals), 12);
  EXPECT_TRUE(mesh.is_p2());
  EXPECT_EQ(proposals.size(), 0u);
  for (Index e = 0; e < mesh.edge_count(); ++e) EXPECT_NEAR(norm(mesh.edge_node(e)), 1.0, 1e-15);
  EXPECT_EQ(apply_boundary_proposals(mesh, proposals), 0);  // consumed
}

// On a P2 mesh the current node is what gets projected.
TEST(SurfaceProposals, CurvedInputProjectsItsNodes) {
  Mesh<2> mesh = testing::circle_polygon(8);
  mesh.make_p2();
  const Index edge = mesh.find_edge(0, 1);
  mesh.edge_node(edge) = Vec2{{2, 1}};
  const AnalyticBoundary<2> circle = concentric_shell_boundary<2>(1.0, 2.0);
  const BoundaryProposals<2> proposals(mesh, circle);
  EXPECT_LT(norm(*proposals.find(0, 1) - Vec2{{2, 1}} * (1 / std::sqrt(5.0))), 1e-15);
}

// Cube: the edges along the cube's ridges keep their straight midpoints, and so do all others.
TEST(SurfaceProposals, CubeProposalsAreStraightMidpoints) {
  Mesh<3> mesh = generate_cube(2);
  BoundaryProposals<3> proposals(mesh, P3Surrogate<3>(mesh));
  for (const auto& [a, b] : boundary_edges(mesh)) EXPECT_LT(norm(*proposals.find(a, b) - 0.5 * (mesh.vertex(a) + mesh.vertex(b))), 1e-15);
  EXPECT_EQ(apply_boundary_proposals(mesh, proposals), Index(boundary_edges(mesh).size()));
}

// `mesh` with its vertices in reverse order (as a part numbers them), facet 0's ref changed to `ref`.
Mesh<3> reversed_with_facet_ref(const Mesh<3>& mesh, int ref, std::vector<Index>& original_ids) {
  Mesh<3> out;
  const Index n = mesh.vertex_count();
  for (Index v = n - 1; v >= 0; --v) {
    out.add_vertex(mesh.vertex(v));
    original_ids.push_back(v);
  }
  for (const auto& element : mesh.elements())
    out.add_element({n - 1 - element[0], n - 1 - element[1], n - 1 - element[2], n - 1 - element[3]});
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    const auto& facet = mesh.facet(f);
    out.add_facet({n - 1 - facet[0], n - 1 - facet[1], n - 1 - facet[2]}, f == 0 ? ref : mesh.facet_ref(f));
  }
  return out;
}

TEST(SurfaceProposals, AScopeLeavesOutFrozenEdgesKeepsToItsRegionAndMapsIds) {
  const Mesh<3> mesh = icosphere(2, 1.0, 0.2);
  const P3Surrogate<3> surrogate(mesh);
  std::vector<Index> original_ids;
  const Mesh<3> part = reversed_with_facet_ref(mesh, -7, original_ids);
  const auto& frozen = part.facet(0);
  std::vector<char> region(static_cast<std::size_t>(part.vertex_count()), 1);
  region[frozen[0]] = 0;  // with it, every edge at the frozen facet's first vertex leaves the region
  const ProposalScope scope{-7, region, original_ids};
  const BoundaryProposals<3> proposals(part, surrogate, scope);
  std::size_t expected = 0;
  for (const auto& [a, b] : boundary_edges(part)) {
    const bool on_frozen = std::count(frozen.begin(), frozen.end(), a) + std::count(frozen.begin(), frozen.end(), b) == 2;
    if (on_frozen || !region[a] || !region[b]) {
      EXPECT_FALSE(proposals.find(a, b)) << a << ' ' << b;
      continue;
    }
    ++expected;
    ASSERT_TRUE(proposals.find(a, b));
    // The surrogate knows the edge by the whole mesh's ids.
    EXPECT_EQ(*proposals.find(a, b), *surrogate.edge_midpoint(original_ids[a], original_ids[b]));
  }
  EXPECT_EQ(proposals.size(), expected);
  EXPECT_LT(expected, boundary_edges(part).size() - 2);
}

}  // namespace
}  // namespace hocav
