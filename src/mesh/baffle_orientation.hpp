// Baffles: facets inside the domain with one element ref on both sides (an inner surface of one
// material). Unlike a boundary or interface facet, such a facet has no side to be oriented from,
// yet the cavity operator's surface cavity needs the facets of a patch oriented alike (their sides
// cancel in pairs: docs/mesh-model.md, "Boundary-aware cavities"). Files leave it free.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

// The baffle facets to turn around so that each patch (baffle facets of one ref joined by sides
// that exactly two of them share) is oriented like its first facet in the file. A patch that cannot
// be oriented (a Möbius band) keeps its remaining facets as they are. Needs the topology.
template <int D>
std::vector<Index> baffle_facets_to_turn(const Mesh<D>& mesh);

}  // namespace hocav
