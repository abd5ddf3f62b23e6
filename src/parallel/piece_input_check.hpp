// The pieces of an input mesh read in pieces (read_mesh_file_piece), prepared and checked together
// as prepare_input_mesh and check_input_mesh prepare and check a whole input (src/mesh/input_check.hpp):
// no process holds the whole mesh, so the processes decide together.
#pragma once

#include <functional>
#include <string>

#include "parallel/mesh_file_pieces.hpp"

namespace hocav {

// Every process at once, each with its piece of the file at `path`. When every element of the file
// is negatively oriented, every piece is reoriented; else an element of non-positive measure is
// refused: Error naming the file and the first such element's file id, thrown by the process that
// read it (the others wait in the next collective call, which the error's abort ends). The faces of
// the domain's boundary without a facet get one of ref 0, with the file ids the serial preparation
// gives them (after the file's facets, in element order). Each change is said once, by rank 0,
// through `warn` (may be empty), with the whole file's counts. What the whole mesh's check also
// finds (non-manifold places, overlaps) is not looked for.
template <int D>
void prepare_input_piece(MeshFilePiece<D>& piece, const std::string& path, const std::function<void(const std::string&)>& warn);

}  // namespace hocav
