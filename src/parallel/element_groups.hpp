// Groups of face-neighbouring elements of a part, the vertices of the coarser dual graph PT-Scotch
// cuts (docs/distributed.md §Partitioning): a few elements to a graph vertex take PT-Scotch a
// fraction of the memory one vertex per element takes, its peak in the distributed loop.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

struct ElementGroups {
  std::vector<Index> group_of;  // per element
  Index count = 0;
};

// Every element its own group.
ElementGroups single_element_groups(Index element_count);

// Stars of neighbours, greedy in element order: an element not yet grouped starts a group with those
// of its face neighbours not yet grouped (up to D + 2 elements), or, when every neighbour is grouped
// already, joins its first neighbour's group. `mesh` has its topology; a group never crosses a face
// without a neighbour (the part's interfaces, its boundary).
template <int D>
ElementGroups neighbouring_element_groups(const Mesh<D>& mesh);

}  // namespace hocav
