#include "adapt/layer_bending.hpp"

#include <gtest/gtest.h>

#include <array>

#include "adapt/proposal_completion.hpp"
#include "bezier/jacobian_bounds.hpp"
#include "bezier/p2_element.hpp"
#include "cases/cubed_sphere_shell.hpp"
#include "cases/polar_annulus.hpp"
#include "mesh/ball_and_shell.hpp"
#include "surface/analytic_boundary.hpp"

namespace hocav {
namespace {

// A shell whose first layer (0.005) is thinner than its inner wall edges' sag (about 0.01).
constexpr std::array<double, 6> kThinLayerRadii{0.5, 0.505, 0.52, 0.56, 0.7, 1.0};
constexpr double kLayerFloor = 0.01;

template <int D>
Mesh<D> thin_layered_shell() {
  Mesh<D> mesh;
  if constexpr (D == 2)
    mesh = generate_polar_annulus(16, kThinLayerRadii);
  else
    mesh = generate_cubed_sphere_shell(4, kThinLayerRadii);
  mesh.build_topology();
  mesh.make_p2();
  return mesh;
}

template <int D>
bool certified(const Mesh<D>& mesh, std::span<const Index> elements) {
  for (Index k : elements)
    if (!certify_min_normalized_jacobian_above(gather_p2_element(mesh, k), kLayerFloor)) return false;
  return true;
}

template <int D>
std::vector<Index> all_elements(const Mesh<D>& mesh) {
  std::vector<Index> elements(static_cast<std::size_t>(mesh.element_count()));
  for (Index k = 0; k < mesh.element_count(); ++k) elements[static_cast<std::size_t>(k)] = k;
  return elements;
}

// The wall's edges (those of the inner facets, ref 1), once each.
template <int D>
std::vector<Index> wall_edges(const Mesh<D>& mesh) {
  std::vector<Index> edges;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_ref(f) != 1) continue;
    const auto& vertices = mesh.facet(f);
    for (int i = 0; i < D; ++i)
      for (int j = i + 1; j < D; ++j) edges.push_back(mesh.find_edge(vertices[i], vertices[j]));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

template <int D>
void check_layers_bend_with_their_wall() {
  Mesh<D> mesh = thin_layered_shell<D>();
  const AnalyticBoundary<D> geometry = concentric_shell_boundary<D>(kThinLayerRadii.front(), kThinLayerRadii.back());
  BoundaryProposals<D> proposals(mesh, geometry);
  const std::vector<Index> wall = wall_edges(mesh);

  // The wall's node alone, on the geometry, leaves its shell below the floor: a bend is needed.
  {
    Mesh<D> alone = mesh;
    const auto& ends = alone.edge_vertices(wall.front());
    alone.edge_node(wall.front()) = *proposals.find(ends[0], ends[1]);
    std::vector<Index> shell;
    collect_shell(alone, ends[0], ends[1], shell);
    EXPECT_FALSE(certified(alone, shell));
  }

  const std::vector<Vec<D>> straight(mesh.edge_nodes().begin(), mesh.edge_nodes().end());
  const ProposalCompletion completion = complete_boundary_proposals(mesh, proposals, {.jacobian_floor = kLayerFloor});
  EXPECT_GT(completion.bends, 0);
  EXPECT_GT(completion.volume_nodes_bent, 0);
  EXPECT_EQ(proposals.size(), 0u) << completion.blocked << " blocked, " << completion.pulled_back << " pulled back";
  for (Index e : wall) EXPECT_NEAR(norm(mesh.edge_node(e)), kThinLayerRadii.front(), 1e-12);
  EXPECT_TRUE(certified(mesh, all_elements(mesh)));

  // The volume moves only near the wall: edges whose ends both lie at radius 0.7 or more (the
  // outer wall's own edges aside) keep their straight nodes.
  Index moved_far = 0, kept_far = 0;
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    const auto& ends = mesh.edge_vertices(e);
    const bool far = norm(mesh.vertex(ends[0])) > 0.69 && norm(mesh.vertex(ends[1])) > 0.69;
    if (!far || std::abs(norm(mesh.edge_node(e)) - kThinLayerRadii.back()) < 1e-9) continue;
    ++(mesh.edge_node(e) == straight[static_cast<std::size_t>(e)] ? kept_far : moved_far);
  }
  EXPECT_EQ(moved_far, 0);
  EXPECT_GT(kept_far, 0);
}

TEST(LayerBending, ThinLayersBendWithTheirWallSoItsNodesReachTheGeometry2D) { check_layers_bend_with_their_wall<2>(); }
TEST(LayerBending, ThinLayersBendWithTheirWallSoItsNodesReachTheGeometry3D) { check_layers_bend_with_their_wall<3>(); }

}  // namespace
}  // namespace hocav
