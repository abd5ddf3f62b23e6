// The vertices joined by an element edge, as compressed rows: the neighbours of every vertex, for the
// edge-based metric kernels (gradation and Hessian recovery, docs/method.md §10). Built from the elements
// alone, so it needs neither the edge table nor the topology.
#pragma once

#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

struct VertexGraph {
  std::vector<Index> offsets;    // vertex_count + 1 entries
  std::vector<Index> neighbors;  // the neighbours of v are neighbors[offsets[v] .. offsets[v + 1]), ascending

  Index vertex_count() const { return static_cast<Index>(offsets.size()) - 1; }
  std::span<const Index> neighbors_of(Index v) const {
    return std::span<const Index>(neighbors).subspan(offsets[v], offsets[v + 1] - offsets[v]);
  }
};

template <int D>
VertexGraph vertex_graph(const Mesh<D>& mesh);

// The elements around every vertex, as compressed rows of ascending element ids: a counting sort of
// the elements' vertices, with no sort, so it costs a fraction of the graph. Like the graph, built
// from the elements alone (a vertex pinching two parts of the mesh has both parts' elements).
struct VertexElements {
  std::vector<Index> offsets;   // vertex_count + 1 entries
  std::vector<Index> elements;  // the elements around v are elements[offsets[v] .. offsets[v + 1]), ascending

  std::span<const Index> of(Index v) const { return std::span<const Index>(elements).subspan(offsets[v], offsets[v + 1] - offsets[v]); }
};

template <int D>
VertexElements vertex_elements(const Mesh<D>& mesh);

// The graph's rows of the vertices flagged in `rows` (the same as vertex_graph's), the others empty:
// what a kernel local to a few vertices reads, for the cost of their neighbourhoods.
template <int D>
VertexGraph vertex_graph(const Mesh<D>& mesh, const VertexElements& around, std::span<const char> rows);

}  // namespace hocav
