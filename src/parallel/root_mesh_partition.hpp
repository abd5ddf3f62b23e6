// A partition of a mesh that rank 0 holds whole (the curving's first round: docs/distributed.md
// §Curving), made without Scotch's graph of the whole mesh on rank 0, which took several times the
// mesh's memory there: rank 0 cuts the mesh along the Morton order (spatial_cut) and sends each
// process its piece, one piece at a time; PT-Scotch cuts the pieces' distributed graph; rank 0
// gathers each element's part.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

// Collective. Rank 0 passes its `mesh` (with topology, compact) and gets per element its part in
// [0, process_count()), the parts of about equal element counts; the others pass an empty mesh and
// get nothing. The same mesh and seed give the same parts. `bytes_sent`, when given, grows by what
// this process sent.
template <int D>
std::vector<int> partition_from_root(const Mesh<D>& mesh, std::int64_t seed, long long* bytes_sent = nullptr);

}  // namespace hocav
