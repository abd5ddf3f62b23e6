// Spatial order (docs/mesh-model.md §Spatial order): renumbers a mesh so that what is near in space
// is near in memory. A remesher appends its new vertices and elements in the order it visits its
// candidates (longest edge first: all over the domain), so after a pass a cavity's records lie far
// apart and each is a cache miss.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

// The Morton (Z-order) code of x in the box [low, low + extent]: 63/D bits per axis, interleaved.
template <int D>
std::uint64_t morton_code(const Vec<D>& x, const Vec<D>& low, const Vec<D>& extent);

// Vertices in the Morton order of their positions, elements by their smallest new vertex id (in
// their old order among equals). The mesh must be compact.
template <int D>
void sort_spatially(Mesh<D>& mesh);

}  // namespace hocav
