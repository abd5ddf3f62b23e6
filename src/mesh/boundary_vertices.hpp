// Which vertices lie on a boundary facet: the vertices the curving keeps in place, and the ends of
// the edges it does not count as volume edges. Removed facets (a boundary operation's, until the
// mesh is compacted) hold none.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

template <int D>
std::vector<bool> boundary_vertex_flags(const Mesh<D>& mesh) {
  std::vector<bool> on_boundary(static_cast<std::size_t>(mesh.vertex_count()), false);
  for (const auto& facet : mesh.facets())
    if (facet[0] != kNoIndex)
      for (Index v : facet) on_boundary[v] = true;
  return on_boundary;
}

}  // namespace hocav
