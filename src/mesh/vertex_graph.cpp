#include "mesh/vertex_graph.hpp"

#include <algorithm>

namespace hocav {

template <int D>
VertexGraph vertex_graph(const Mesh<D>& mesh) {
  // Every element edge once (sorted keys, deduplicated), then both of its directions by counting.
  std::vector<std::uint64_t> edges;
  edges.reserve(static_cast<std::size_t>(mesh.element_count()) * Simplex<D>::kEdges);
  for (const auto& element : mesh.elements())
    for (const auto& [i, j] : Simplex<D>::kEdgeLocalVertices) edges.push_back(Mesh<D>::edge_key(element[i], element[j]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  auto low = [](std::uint64_t key) { return static_cast<Index>(key >> 32); };
  auto high = [](std::uint64_t key) { return static_cast<Index>(key & 0xffffffffu); };
  VertexGraph graph;
  graph.offsets.assign(static_cast<std::size_t>(mesh.vertex_count()) + 1, 0);
  for (std::uint64_t key : edges) {
    ++graph.offsets[low(key) + 1];
    ++graph.offsets[high(key) + 1];
  }
  for (std::size_t v = 1; v < graph.offsets.size(); ++v) graph.offsets[v] += graph.offsets[v - 1];
  graph.neighbors.resize(2 * edges.size());
  std::vector<Index> next(graph.offsets.begin(), graph.offsets.end() - 1);
  // Keys ascend by low vertex, so each row receives its lower neighbours (from the high side) in
  // ascending order, then its higher ones: rows come out sorted.
  for (std::uint64_t key : edges) graph.neighbors[next[high(key)]++] = low(key);
  for (std::uint64_t key : edges) graph.neighbors[next[low(key)]++] = high(key);
  return graph;
}

template VertexGraph vertex_graph(const Mesh<2>&);
template VertexGraph vertex_graph(const Mesh<3>&);

}  // namespace hocav
