// Baffles: facets inside the domain with one element ref on both sides (an inner surface of one
// material). Unlike a boundary or interface facet, such a facet has no side to be oriented from,
// yet the cavity operator's surface cavity needs the facets of a patch oriented alike (their sides
// cancel in pairs: docs/mesh-model.md, "Boundary-aware cavities"). Files leave it free.
#pragma once

#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

// The baffle facets to turn around so that each patch (baffle facets of one ref joined by sides
// that exactly two of them share) is oriented like its first facet in the file. A patch that cannot
// be oriented (a Möbius band) keeps its remaining facets as they are. Needs the topology.
template <int D>
std::vector<Index> baffle_facets_to_turn(const Mesh<D>& mesh);

// The same rule on a list of baffle facets (their vertices, in the order the file gives them, and
// their refs), in the order of their file ids: per baffle, whether to turn it (1) or not (0). A
// mesh read in pieces gathers its baffles to orient them as the whole mesh's are.
template <int D>
std::vector<char> baffle_turns(std::span<const typename Mesh<D>::Facet> baffles, std::span<const int> refs);

}  // namespace hocav
