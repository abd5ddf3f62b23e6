// The facets of a mesh read in pieces, oriented as Mesh::orient_boundary_facets_outward orients the
// whole mesh's (docs/distributed.md §Reading in pieces): a facet between two pieces learns the ref
// of the element across it from the other piece, and the baffles are oriented patch by patch on the
// list of every piece's baffles in file order, which a patch crossing pieces needs.
#pragma once

#include <span>

#include "parallel/mesh_parts.hpp"

namespace hocav {

// Every process at once, each with its piece (with topology; its interface facets of ref
// kInterfaceRef on the faces towards other pieces, left as they are) and per facet of it its file
// id (`facet_ids`, as MeshFilePiece has them): every other facet ordered as the whole mesh's
// orient_boundary_facets_outward orders it, the pieces' global ids being the file's vertex ids.
template <int D>
void orient_piece_facets(MeshPart<D>& piece, std::span<const Index> facet_ids);

}  // namespace hocav
