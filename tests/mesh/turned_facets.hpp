// A mesh with some boundary facets listed in the other orientation, as the file formats allow, for
// the tests of what must not depend on it.
#pragma once

#include <utility>

#include "mesh/mesh.hpp"

namespace hocav::mesh_test {

// A copy of `mesh` (vertices, elements, facets with their refs, then its topology) whose facets
// 0, every, 2 every, ... are turned over.
template <int D>
Mesh<D> with_facets_turned(const Mesh<D>& mesh, Index every) {
  Mesh<D> turned;
  for (const auto& p : mesh.vertices()) turned.add_vertex(p);
  for (Index k = 0; k < mesh.element_count(); ++k) turned.add_element(mesh.element(k), mesh.element_ref(k));
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    auto facet = mesh.facet(f);
    if (f % every == 0) std::swap(facet[0], facet[1]);
    turned.add_facet(facet, mesh.facet_ref(f));
  }
  turned.build_topology();
  return turned;
}

}  // namespace hocav::mesh_test
