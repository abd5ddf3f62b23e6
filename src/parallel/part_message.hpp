// A mesh part as bytes, for sending it to another process (docs/distributed.md §Migration): every
// array of the part, its tags, its P2 nodes and its global vertex ids, read back into the same part.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "parallel/mesh_parts.hpp"

namespace hocav {

// `global_ids` per vertex, or empty (a whole mesh, sent to every process).
template <int D>
std::vector<std::byte> pack_part(const Mesh<D>& mesh, std::span<const Index> global_ids);

// The dimension of a packed part.
int packed_dimension(const std::vector<std::byte>& bytes);

// Throws Error on bytes that are no packed part of dimension D.
template <int D>
MeshPart<D> unpack_part(const std::vector<std::byte>& bytes);

}  // namespace hocav
