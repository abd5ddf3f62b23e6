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

}  // namespace hocav
