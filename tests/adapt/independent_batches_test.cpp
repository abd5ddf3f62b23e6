#include "adapt/independent_batches.hpp"

#include <gtest/gtest.h>

#include <deque>

#include "adapt/reinsertion_curving.hpp"
#include "cases/structured.hpp"

namespace hocav {
namespace {

// Graph distances from v, by breadth-first search.
std::vector<int> distances_from(const VertexGraph& graph, Index v) {
  std::vector<int> distance(static_cast<std::size_t>(graph.vertex_count()), -1);
  std::deque<Index> queue{v};
  distance[v] = 0;
  while (!queue.empty()) {
    Index u = queue.front();
    queue.pop_front();
    for (Index w : graph.neighbors_of(u))
      if (distance[w] < 0) distance[w] = distance[u] + 1, queue.push_back(w);
  }
  return distance;
}

TEST(IndependentBatches, VerticesOfABatchAreFarEnoughApartAndAllAreBatched) {
  Mesh<3> mesh = generate_cube(5);
  VertexGraph graph = vertex_graph(mesh);
  std::vector<Index> vertices = volume_vertices(mesh);
  for (int min_distance : {3, 4}) {
    auto batches = independent_batches(graph, vertices, min_distance);
    std::size_t total = 0;
    for (const auto& batch : batches) {
      total += batch.size();
      for (Index v : batch) {
        auto distance = distances_from(graph, v);
        for (Index w : batch)
          if (w != v) {
            EXPECT_GE(distance[w], min_distance);
          }
      }
    }
    EXPECT_EQ(total, vertices.size());
    EXPECT_LT(batches.size(), vertices.size());  // some batch holds more than one vertex
  }
}

}  // namespace
}  // namespace hocav
