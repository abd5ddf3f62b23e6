#include "mesh/vertex_graph.hpp"

#include <algorithm>

namespace hocav {

template <int D>
VertexGraph vertex_graph(const Mesh<D>& mesh) {
  // Each element's vertices listed in the rows of its other vertices (a counting sort by vertex),
  // then each row sorted and made unique, packed in place: no sort of the whole mesh's edges.
  const auto vertex_count = static_cast<std::size_t>(mesh.vertex_count());
  std::vector<Index> start(vertex_count + 1, 0);
  for (const auto& element : mesh.elements())
    for (Index v : element) start[static_cast<std::size_t>(v) + 1] += D;
  for (std::size_t v = 1; v <= vertex_count; ++v) start[v] += start[v - 1];
  std::vector<Index> listed(static_cast<std::size_t>(start[vertex_count]));
  std::vector<Index> next(start.begin(), start.end() - 1);
  for (const auto& element : mesh.elements())
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j <= D; ++j)
        if (j != i) listed[static_cast<std::size_t>(next[element[i]]++)] = element[j];
  VertexGraph graph;
  graph.offsets.assign(vertex_count + 1, 0);
  auto packed = listed.begin();
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const auto row_begin = listed.begin() + start[v], row_end = listed.begin() + start[v + 1];
    std::sort(row_begin, row_end);
    // Written at or before what is read next (rows only shrink); compared with the row's last kept.
    const auto row_packed = packed;
    for (auto it = row_begin; it != row_end; ++it)
      if (packed == row_packed || *it != *(packed - 1)) *packed++ = *it;
    graph.offsets[v + 1] = static_cast<Index>(packed - listed.begin());
  }
  listed.resize(static_cast<std::size_t>(packed - listed.begin()));
  graph.neighbors = std::move(listed);
  return graph;
}

template VertexGraph vertex_graph(const Mesh<2>&);
template VertexGraph vertex_graph(const Mesh<3>&);

}  // namespace hocav
