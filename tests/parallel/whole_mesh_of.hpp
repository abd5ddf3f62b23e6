// The mesh a part holds when it holds every element (migrate_part gathered it), for the tests that
// send a mesh around and compare it with where it started: its required vertices those the mesh had
// (pinned by the mesh), without those pinned as non-manifold places. Throws Error when the part has
// an interface facet left.
#pragma once

#include <algorithm>

#include "base/error.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

template <int D>
Mesh<D> whole_mesh_of(MeshPart<D> part) {
  if (std::find(part.mesh.facet_refs().begin(), part.mesh.facet_refs().end(), kInterfaceRef) != part.mesh.facet_refs().end())
    throw Error("a gathered mesh still has an interface facet");
  part.mesh.required_vertices().clear();
  for (Index v = 0; v < part.mesh.vertex_count(); ++v)
    if (part.pinned[v] & kPinnedByMesh) part.mesh.required_vertices().push_back(v);
  return std::move(part.mesh);
}

}  // namespace hocav
