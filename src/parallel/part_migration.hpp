// Migration of elements between processes, peer to peer (docs/distributed.md §Migration): every
// process sends the elements that leave its part straight to their new process, with their vertices,
// facets, feature lines, tags and P2 nodes, and builds its new part from what it keeps and what
// arrives. The interfaces follow the elements; no process sees more than its own part.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "parallel/mesh_parts.hpp"

namespace hocav {

// Every process at once: element k of this process's `part` (with its topology) goes to process
// destination[k] (this one included). Returns the process's new part, with its topology, and
// otherwise as split_mesh makes parts: its vertices in the
// order of their global ids; its elements by the process they come from, in rank order, each
// process's in its part's order; the mesh's facets on its elements, then a required facet of ref
// kInterfaceRef on each face towards another process, whose vertices are required; lines along its
// elements' edges; P2 nodes when the parts are P2. Pinned vertices stay required, corners stay
// corners. A facet of the mesh goes with the element the topology links it to.
// Throws Error when `part` lacks its topology, a vertex's global id or pinned flag, a destination is no process,
// or two processes give one vertex different points. Adds the bytes it sends other processes to
// `bytes_sent` when given.
template <int D>
MeshPart<D> migrate_part(const MeshPart<D>& part, std::span<const int> destination, long long* bytes_sent = nullptr);

// The same, letting `part` go (left empty) once its shipments are packed, before the new part is
// built: a process then holds its elements twice at most, not three times.
template <int D>
MeshPart<D> migrate_part(MeshPart<D>&& part, std::span<const int> destination, long long* bytes_sent = nullptr);

// Every process at once, with the `destination` of a migrate_part call: per element of the part that
// migration makes, in its order, the value `values` gives the element here (per element of `part`),
// such as its place in an input's element order. Adds the bytes it sends other processes to
// `bytes_sent` when given.
std::vector<Index> migrated_element_values(std::span<const Index> values, std::span<const int> destination,
                                           long long* bytes_sent = nullptr);

// The same for the facets (interface facets left out): per facet of the part that migration makes
// but its interface facets, which come after the others, in its order, the value `values` gives the
// facet here (per facet of `part`; those of interface facets unused).
template <int D>
std::vector<Index> migrated_facet_values(const MeshPart<D>& part, std::span<const Index> values, std::span<const int> destination,
                                         long long* bytes_sent = nullptr);

// Every process at once: the parts cut again by PT-Scotch (the distributed graph of the parts, weighed
// by `loads` per element and heavy across faces near the `kept_inside` vertices, which may be empty:
// distributed_element_graph) and the elements migrated to the new parts (`part` let go once packed).
template <int D>
MeshPart<D> repartition(MeshPart<D>&& part, std::span<const double> loads, std::span<const char> kept_inside, std::int64_t partition_seed,
                        long long* bytes_sent = nullptr);

}  // namespace hocav
