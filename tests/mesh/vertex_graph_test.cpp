#include "mesh/vertex_graph.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "cases/structured.hpp"

namespace hocav {
namespace {

template <int D>
void expect_graph_matches_edge_table(Mesh<D> mesh) {
  VertexGraph graph = vertex_graph(mesh);
  mesh.build_edges();
  ASSERT_EQ(graph.vertex_count(), mesh.vertex_count());
  EXPECT_EQ(graph.neighbors.size(), 2 * static_cast<std::size_t>(mesh.edge_count()));
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    auto neighbors = graph.neighbors_of(v);
    EXPECT_TRUE(std::is_sorted(neighbors.begin(), neighbors.end()));
    EXPECT_EQ(std::adjacent_find(neighbors.begin(), neighbors.end()), neighbors.end());
    for (Index u : neighbors) EXPECT_NE(mesh.find_edge(u, v), kNoIndex) << u << " " << v;
  }
}

TEST(VertexGraph, HoldsEveryEdgeOnceEachWayInSortedRows) {
  expect_graph_matches_edge_table(generate_square(4));
  expect_graph_matches_edge_table(generate_cube(3));
  VertexGraph graph = vertex_graph(generate_square(1));  // two triangles on the diagonal (0, 3)
  EXPECT_EQ(std::vector<Index>(graph.neighbors_of(0).begin(), graph.neighbors_of(0).end()), (std::vector<Index>{1, 2, 3}));
  EXPECT_EQ(std::vector<Index>(graph.neighbors_of(1).begin(), graph.neighbors_of(1).end()), (std::vector<Index>{0, 3}));
}

TEST(VertexGraph, UnusedVerticesHaveNoNeighbours) {
  Mesh<2> mesh = generate_square(1);
  mesh.add_vertex({{3, 3}});
  EXPECT_TRUE(vertex_graph(mesh).neighbors_of(4).empty());
}

TEST(VertexElements, ListEachVertexsElementsInAscendingOrder) {
  const Mesh<3> mesh = generate_cube(2);
  const VertexElements around = vertex_elements(mesh);
  std::size_t listed = 0;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const auto elements = around.of(v);
    EXPECT_TRUE(std::is_sorted(elements.begin(), elements.end()));
    for (Index k : elements) EXPECT_NE(std::find(mesh.element(k).begin(), mesh.element(k).end(), v), mesh.element(k).end());
    listed += elements.size();
  }
  EXPECT_EQ(listed, 4 * static_cast<std::size_t>(mesh.element_count()));  // every element under each of its vertices
}

TEST(VertexGraph, RowsOfFlaggedVerticesAreTheWholeGraphsOthersEmpty) {
  const Mesh<3> mesh = generate_cube(3);
  const VertexGraph whole = vertex_graph(mesh);
  std::vector<char> rows(static_cast<std::size_t>(mesh.vertex_count()), 0);
  for (Index v = 0; v < mesh.vertex_count(); v += 3) rows[v] = 1;
  const VertexGraph some = vertex_graph(mesh, vertex_elements(mesh), rows);
  ASSERT_EQ(some.vertex_count(), mesh.vertex_count());
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const auto expected = rows[v] ? whole.neighbors_of(v) : std::span<const Index>{};
    EXPECT_TRUE(std::ranges::equal(some.neighbors_of(v), expected)) << v;
  }
}

}  // namespace
}  // namespace hocav
