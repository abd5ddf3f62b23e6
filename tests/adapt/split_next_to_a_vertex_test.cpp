// A split whose new point lies next to a vertex already there (docs/adaptation.md §Split): inside
// the domain the split and its snap are made in one, the long edge's cavity re-starred from that
// vertex with no new vertex; when that cannot be made, an edge shorter than 2 is not split.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "adapt/adaptation_mesh.hpp"
#include "adapt/adaptation_operations.hpp"
#include "adapt_test_support.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

// A hexagon (boundary ref 1) around four interior vertices: the edge a = 0, b = 1 (length 1.6,
// middle at the origin) between w = 2 (0.3 above its middle) and c = 3 (0.5 below). Every other
// edge is at most 1.42 long.
constexpr Index kA = 0, kB = 1, kW = 2, kC = 3;

Mesh<2> hexagon_around_a_long_edge() {
  Mesh<2> mesh;
  for (const Vec2 x : {Vec2{{-0.8, 0}}, Vec2{{0.8, 0}}, Vec2{{0, 0.3}}, Vec2{{0, -0.5}}, Vec2{{-1.6, 0}}, Vec2{{-0.7, 1.1}},
                       Vec2{{0.7, 1.1}}, Vec2{{1.6, 0}}, Vec2{{0.7, -1.1}}, Vec2{{-0.7, -1.1}}})
    mesh.add_vertex(x);
  const Index r0 = 4, r1 = 5, r2 = 6, r3 = 7, r4 = 8, r5 = 9;
  for (const std::array<Index, 3> element : {std::array<Index, 3>{kA, kW, r1},
                                             {kW, r2, r1},
                                             {kW, kB, r2},
                                             {kB, r3, r2},
                                             {kA, r1, r0},
                                             {kA, kB, kW},
                                             {kA, kC, kB},
                                             {kA, r5, kC},
                                             {kC, r5, r4},
                                             {kC, r4, kB},
                                             {kB, r4, r3},
                                             {kA, r0, r5}})
    mesh.add_element(element, 1);
  for (Index i = 0; i < 6; ++i) mesh.add_facet({4 + i, 4 + (i + 1) % 6}, 1);
  mesh.build_topology();
  return mesh;
}

bool joined(const Mesh<2>& mesh, Index x, Index y) {
  std::vector<Index> shell;
  collect_shell(mesh, x, y, shell);
  return !shell.empty();
}

// Only a-b is longer than the split length; the metric is the Euclidean one.
AdaptationLimits only_the_long_edge() {
  AdaptationLimits limits;
  limits.split_length = 1.5;
  return limits;
}

TEST(SplitNextToAVertex, TheLongEdgeIsCutAtTheVertexWithNoNewVertex) {
  Mesh<2> mesh = hexagon_around_a_long_edge();
  const double area = total_measure(mesh);
  const AdaptationMetric<2> metric = adapt_test::uniform_metric<2>(1);
  AdaptationMesh<2> am(mesh, metric, nullptr, 45);
  ThreadPool pool(1);
  const Index vertices = mesh.vertex_count();
  const OperationCount splits = split_long_edges(am, only_the_long_edge(), pool).count;
  EXPECT_EQ(splits.done, 1);
  EXPECT_EQ(mesh.vertex_count(), vertices);  // not even a vertex made and removed
  EXPECT_FALSE(joined(mesh, kA, kB));
  EXPECT_TRUE(joined(mesh, kW, kC));
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_NEAR(total_measure(mesh), area, 1e-12);
}

// The star from w would have an edge longer than a collapse may make (w-c, 0.8): then the edge is
// left as it is, refused for the new vertex's short edge.
TEST(SplitNextToAVertex, WhenTheCutAtTheVertexIsRefusedTheEdgeIsLeft) {
  Mesh<2> mesh = hexagon_around_a_long_edge();
  const AdaptationMetric<2> metric = adapt_test::uniform_metric<2>(1);
  AdaptationMesh<2> am(mesh, metric, nullptr, 45);
  ThreadPool pool(1);
  AdaptationLimits limits = only_the_long_edge();
  limits.collapse_new_length = 0.75;
  const Index vertices = mesh.vertex_count(), elements = mesh.element_count();
  const OperationCount splits = split_long_edges(am, limits, pool).count;
  EXPECT_EQ(splits.done, 0);
  EXPECT_EQ(splits.refused[static_cast<std::size_t>(Refusal::kLength)], 1);
  EXPECT_EQ(mesh.vertex_count(), vertices);
  EXPECT_EQ(mesh.element_count(), elements);
  EXPECT_TRUE(joined(mesh, kA, kB));
  adapt_test::expect_closed_and_consistent(mesh);
}

// Near the boundary nothing is refused: with w on the boundary (the hexagon's triangles above a, w
// and b cut away) and the same star from w refused, the edge is split at its middle, and the snap
// cannot collapse the new vertex onto w either.
TEST(SplitNextToAVertex, NextToABoundaryVertexTheEdgeIsStillSplit) {
  Mesh<2> mesh;
  for (const Vec2 x : {Vec2{{-0.8, 0}}, Vec2{{0.8, 0}}, Vec2{{0, 0.3}}, Vec2{{0, -0.5}}, Vec2{{-0.7, -1.1}}, Vec2{{0.7, -1.1}}})
    mesh.add_vertex(x);
  const Index r4 = 4, r5 = 5;
  for (const std::array<Index, 3> element : {std::array<Index, 3>{kA, kB, kW}, {kA, kC, kB}, {kA, r4, kC}, {kC, r4, r5}, {kC, r5, kB}})
    mesh.add_element(element, 1);
  for (const std::array<Index, 2> facet : {std::array<Index, 2>{kB, kW}, {kW, kA}, {kA, r4}, {r4, r5}, {r5, kB}}) mesh.add_facet(facet, 1);
  mesh.build_topology();
  const AdaptationMetric<2> metric = adapt_test::uniform_metric<2>(1);
  AdaptationMesh<2> am(mesh, metric, nullptr, 45);
  ThreadPool pool(1);
  AdaptationLimits limits = only_the_long_edge();
  limits.collapse_new_length = 0.75;
  const Index vertices = mesh.vertex_count();
  EXPECT_EQ(split_long_edges(am, limits, pool).count.done, 1);
  EXPECT_EQ(mesh.vertex_count(), vertices + 1);
  EXPECT_FALSE(joined(mesh, kA, kB));
  adapt_test::expect_closed_and_consistent(mesh);
}

// The vertex next to the new point may lie past the edge's shell, in the Delaunay cavity grown from
// it: here x (0.67 from a-b's middle, in a flat triangle beyond w-b) while the shell's w and c are
// 0.9 away. The long edge is cut at x, still with no new vertex.
TEST(SplitNextToAVertex, TheVertexMayLieInTheGrownCavityPastTheShell) {
  constexpr Index kX = 4;
  Mesh<2> mesh;
  for (const Vec2 x : {Vec2{{-0.8, 0}}, Vec2{{0.8, 0}}, Vec2{{0, 0.9}}, Vec2{{0, -0.9}}, Vec2{{0.45, 0.5}}}) mesh.add_vertex(x);
  for (const std::array<Index, 3> element : {std::array<Index, 3>{kA, kB, kW}, {kA, kC, kB}, {kW, kB, kX}}) mesh.add_element(element, 1);
  for (const std::array<Index, 2> facet : {std::array<Index, 2>{kA, kC}, {kC, kB}, {kB, kX}, {kX, kW}, {kW, kA}}) mesh.add_facet(facet, 1);
  mesh.build_topology();
  const double area = total_measure(mesh);
  const AdaptationMetric<2> metric = adapt_test::uniform_metric<2>(1);
  AdaptationMesh<2> am(mesh, metric, nullptr, 45);
  ThreadPool pool(1);
  AdaptationLimits limits = only_the_long_edge();
  limits.collapse_new_length = 1.6;  // x-c, 1.47, may be made
  const Index vertices = mesh.vertex_count();
  EXPECT_EQ(split_long_edges(am, limits, pool).count.done, 1);
  EXPECT_EQ(mesh.vertex_count(), vertices);  // not a vertex made and snapped onto x
  EXPECT_FALSE(joined(mesh, kA, kB));
  EXPECT_TRUE(joined(mesh, kX, kC));
  EXPECT_TRUE(joined(mesh, kX, kA));
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_NEAR(total_measure(mesh), area, 1e-12);
}

}  // namespace
}  // namespace hocav
