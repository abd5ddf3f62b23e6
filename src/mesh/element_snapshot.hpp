// Whether elements read earlier are still as they were: an operation previewed or gathered before
// others changed the mesh is still current while every element it read holds the same vertices.
#pragma once

#include <span>

#include "mesh/mesh.hpp"

namespace hocav {

// Whether each slot `elements[i]` still exists and holds `vertices[i]`. Compared word by word: it
// runs for every swap and split candidate, and std::array's comparison called memcmp (1.4% of a
// one-thread adaptation, docs/benchmarks.md).
template <int D>
bool elements_unchanged(const Mesh<D>& mesh, std::span<const Index> elements, std::span<const typename Mesh<D>::Element> vertices) {
  for (std::size_t i = 0; i < elements.size(); ++i) {
    if (elements[i] >= mesh.element_count()) return false;
    const typename Mesh<D>::Element& now = mesh.element(elements[i]);
    Index differ = 0;
    for (int j = 0; j <= D; ++j) differ |= now[j] ^ vertices[i][j];
    if (differ != 0) return false;
  }
  return true;
}

}  // namespace hocav
