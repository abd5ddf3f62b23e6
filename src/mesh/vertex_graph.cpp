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

template <int D>
VertexElements vertex_elements(const Mesh<D>& mesh) {
  const auto vertex_count = static_cast<std::size_t>(mesh.vertex_count());
  VertexElements around;
  around.offsets.assign(vertex_count + 1, 0);
  for (const auto& element : mesh.elements())
    for (Index v : element) ++around.offsets[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 1; v <= vertex_count; ++v) around.offsets[v] += around.offsets[v - 1];
  around.elements.resize(static_cast<std::size_t>(around.offsets[vertex_count]));
  std::vector<Index> next(around.offsets.begin(), around.offsets.end() - 1);
  for (Index k = 0; k < mesh.element_count(); ++k)  // in order, so each row is ascending
    for (Index v : mesh.element(k)) around.elements[static_cast<std::size_t>(next[v]++)] = k;
  return around;
}

template <int D>
VertexGraph vertex_graph(const Mesh<D>& mesh, const VertexElements& around, std::span<const char> rows) {
  VertexGraph graph;
  graph.offsets.assign(static_cast<std::size_t>(mesh.vertex_count()) + 1, 0);
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const auto row_begin = static_cast<std::ptrdiff_t>(graph.neighbors.size());
    if (rows[v])
      for (Index k : around.of(v))
        for (Index w : mesh.element(k))
          if (w != v) graph.neighbors.push_back(w);
    std::sort(graph.neighbors.begin() + row_begin, graph.neighbors.end());
    graph.neighbors.erase(std::unique(graph.neighbors.begin() + row_begin, graph.neighbors.end()), graph.neighbors.end());
    graph.offsets[v + 1] = static_cast<Index>(graph.neighbors.size());
  }
  return graph;
}

template VertexGraph vertex_graph(const Mesh<2>&);
template VertexGraph vertex_graph(const Mesh<3>&);
template VertexElements vertex_elements(const Mesh<2>&);
template VertexElements vertex_elements(const Mesh<3>&);
template VertexGraph vertex_graph(const Mesh<2>&, const VertexElements&, std::span<const char>);
template VertexGraph vertex_graph(const Mesh<3>&, const VertexElements&, std::span<const char>);

}  // namespace hocav
