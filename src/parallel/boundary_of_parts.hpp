// The boundary of a distributed mesh on every process, made of the parts' boundaries: what the
// curving of a distributed adaptation's output makes its geometry of, no process holding the whole
// mesh (docs/distributed.md §Curving in the parts).
#pragma once

#include <span>
#include <vector>

#include "parallel/mesh_parts.hpp"

namespace hocav {

// Every process at once, each with its part (compact, global ids, pinned flags): the whole mesh's
// boundary, the same on every process. Its vertices are those of the mesh's facets and lines, its
// corners and required vertices, in the order of their global ids (its `global_ids`); its facets
// are the parts' (not the interfaces'), part after part in rank order; its lines once each; the
// tags as the parts carry them (a vertex required by the mesh, kPinnedByMesh, not by an interface).
// No elements, no topology. Adds the bytes this process sends the others to `bytes_sent` when given.
template <int D>
MeshPart<D> boundary_of_parts(const MeshPart<D>& part, long long* bytes_sent = nullptr);

// Per vertex of `part`: its index in the boundary whose vertices have the sorted global ids
// `boundary_ids`, or kNoIndex when it is not there (ProposalScope::geometry_ids).
template <int D>
std::vector<Index> boundary_indices(const MeshPart<D>& part, std::span<const Index> boundary_ids);

// Per vertex of `part`: its value in `at_boundary` (per vertex of the boundary of sorted global ids
// `boundary_ids`), or `elsewhere` when it is not on the boundary.
template <int D, typename T>
std::vector<T> values_from_boundary(const MeshPart<D>& part, std::span<const Index> boundary_ids, const std::vector<T>& at_boundary,
                                    const T& elsewhere) {
  std::vector<T> values;
  for (Index b : boundary_indices(part, boundary_ids))
    values.push_back(b == kNoIndex ? elsewhere : at_boundary[static_cast<std::size_t>(b)]);
  return values;
}

}  // namespace hocav
