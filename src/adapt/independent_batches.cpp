#include "adapt/independent_batches.hpp"

namespace hocav {

std::vector<std::vector<Index>> independent_batches(const VertexGraph& graph, std::span<const Index> vertices, int min_distance) {
  const auto vertex_count = static_cast<std::size_t>(graph.vertex_count());
  std::vector<int> color(vertex_count, -1);
  std::vector<std::size_t> reached(vertex_count, 0);  // stamp: position + 1 of the search that reached it
  std::vector<std::size_t> taken;                     // per colour: stamp of the search that found it nearby
  std::vector<Index> frontier, next;
  std::vector<std::vector<Index>> batches;
  for (std::size_t position = 0; position < vertices.size(); ++position) {
    const std::size_t stamp = position + 1;
    const Index v = vertices[position];
    // Every vertex closer than min_distance: a breadth-first search of min_distance − 1 levels.
    frontier.assign(1, v);
    reached[v] = stamp;
    for (int level = 1; level < min_distance; ++level) {
      next.clear();
      for (Index u : frontier)
        for (Index w : graph.neighbors_of(u))
          if (reached[w] != stamp) {
            reached[w] = stamp;
            next.push_back(w);
            if (color[w] >= 0) taken[static_cast<std::size_t>(color[w])] = stamp;
          }
      frontier.swap(next);
    }
    std::size_t chosen = 0;
    while (chosen < taken.size() && taken[chosen] == stamp) ++chosen;
    if (chosen == taken.size()) {
      taken.push_back(0);
      batches.emplace_back();
    }
    color[v] = static_cast<int>(chosen);
    batches[chosen].push_back(v);
  }
  return batches;
}

}  // namespace hocav
