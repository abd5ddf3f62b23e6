// Parts of a mesh for the processes of a distributed adaptation (docs/distributed.md §Parts): the
// split of a mesh along an element partition, with the faces between parts kept as required
// facets; the whole mesh as a part and back; a curved part's nodes by global ids.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

// The ref of the interface facets in a part: no input facet may carry it (docs/distributed.md).
constexpr int kInterfaceRef = std::numeric_limits<int>::min();

// Why a vertex is required wherever the interfaces run (MeshPart::pinned, flags).
constexpr char kPinnedByMesh = 1;       // a required vertex of the mesh
constexpr char kPinnedNonManifold = 2;  // a non-manifold place: required in every part, not in the mesh

template <int D>
struct MeshPart {
  // P1 or P2 (as the mesh it came from), without topology. Its boundary facets are the mesh's on the part's elements plus the
  // interface facets (ref kInterfaceRef), which are required, their vertices required too: no
  // operator of the adaptation loop changes them.
  Mesh<D> mesh;
  // Per vertex, its id in the mesh the part came from; kNoIndex for a vertex the part made.
  std::vector<Index> global_ids;
  // Per vertex, whether it is required wherever the interfaces run, and why (kPinned* flags, 0 for
  // neither): split_mesh, whole_mesh_part and migrate_part set it; empty in a part from a message.
  std::vector<char> pinned;
};

// Per global id of a part's vertices, the vertex's local id (a vertex the part made has none).
template <int D>
std::unordered_map<Index, Index> local_ids_of(const MeshPart<D>& part);

// Per vertex of `part`: whether its global id is listed in `ids`.
template <int D>
std::vector<char> flags_of_global_ids(const MeshPart<D>& part, const std::vector<Index>& ids);

// Splits `mesh` (with topology, compact) into `part_count` parts, element k going to part
// `part_of[k]` (to none when negative). A part's vertices keep the mesh's order, its elements and
// facets too; a P2 mesh gives P2 parts with the same nodes.
template <int D>
std::vector<MeshPart<D>> split_mesh(const Mesh<D>& mesh, std::span<const int> part_of, int part_count);

// The same parts handed to `take` one at a time, part order[0] first, each built when the last is
// taken: a caller that sends each part away holds one at once. `order` holds each part of [0,
// order.size()) once.
template <int D>
void split_mesh_part_by_part(const Mesh<D>& mesh, std::span<const int> part_of, std::span<const int> order,
                             const std::function<void(int, MeshPart<D>)>& take);

// The parts 1, 2, ..., count - 1, then 0: the order in which rank 0 makes the parts it sends away,
// then its own, so that it holds its own only once the others are gone.
std::vector<int> own_part_last(int count);

// The ids of a part's interface facets (ref kInterfaceRef), ascending.
template <int D>
std::vector<Index> interface_facets(const Mesh<D>& mesh);

// Per vertex of a part's mesh: on one of its interface facets.
template <int D>
std::vector<char> interface_vertex_flags(const Mesh<D>& mesh);

// The edges of a part's interface facets, by Mesh::edge_key of their local vertex ids.
template <int D>
std::unordered_set<std::uint64_t> interface_edge_keys(const Mesh<D>& mesh);

// The whole mesh (with topology) as one part, for migrate_part to scatter: global ids the vertex ids,
// pinned flags for its required vertices and non-manifold places, no interface.
template <int D>
MeshPart<D> whole_mesh_part(Mesh<D> mesh);

// The global ids of the part's vertices `flagged` (per vertex), in vertex order.
template <int D>
std::vector<Index> global_ids_of(const MeshPart<D>& part, const std::vector<char>& flagged);

// A part's interface facets: each face between two parts counts once in each.
template <int D>
Index interface_facet_count(const Mesh<D>& part_mesh);

}  // namespace hocav
