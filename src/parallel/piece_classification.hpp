// The corners and feature lines of a mesh read in pieces (read_mesh_file_piece), as
// classify_vertices finds them on the whole mesh (docs/distributed.md §Adapting from pieces): a
// boundary side's dihedral angle needs both of its facets, which may lie in two pieces.
#pragma once

#include "parallel/mesh_parts.hpp"

namespace hocav {

// Each process with its piece (prepared, its facets ordered outward) and the whole boundary of the
// pieces (boundary_of_parts, the same on every process): classifies a copy of the boundary as
// classify_vertices classifies the whole mesh, and adds to the piece the corners it holds and the
// feature lines along its elements' edges, so the parts carry them. The non-manifold places are
// not looked for (nor are they by the pieces' check, piece_input_check.hpp).
template <int D>
void classify_piece_vertices(MeshPart<D>& piece, MeshPart<D> boundary, double feature_angle_degrees);

}  // namespace hocav
