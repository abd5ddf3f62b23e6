// The first cut of the input among the processes (docs/distributed.md §Partitioning): the elements
// in the Morton order of their centroids, cut into runs of balanced load. It needs a code per
// element, where Scotch's graph of the whole mesh took several times the mesh's memory on rank 0;
// PT-Scotch then cuts the scattered parts' distributed graph.
#pragma once

#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

// Per element of `mesh` (compact), its part in [0, parts): runs of the Morton order of the
// elements' centroids, each holding about 1/parts of the summed `loads` (per element, >= 0).
template <int D>
std::vector<int> spatial_cut(const Mesh<D>& mesh, std::span<const double> loads, int parts);

}  // namespace hocav
