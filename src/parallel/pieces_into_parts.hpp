// A P1 mesh read in pieces (read_mesh_file_piece), and its metric file, cut into the parts of a
// curving in the parts (`mpirun hocav curve`, docs/distributed.md §Curving from pieces): no process
// holds the whole mesh or the whole metric. PT-Scotch cuts the pieces' distributed graph, the
// elements migrate to their parts, and each part asks its vertices' metrics of the processes whose
// runs of the metric file's rows hold them.
#pragma once

#include <cstdint>
#include <string>

#include "parallel/mesh_file_pieces.hpp"
#include "parallel/root_mesh_scatter.hpp"

namespace hocav {

// Every process at once, each with its piece of the mesh file (prepared: piece_input_check.hpp) and
// the path of the metric file given with it (a metric, or mmg's sizes, per file vertex: checked as
// the serial run checks it, by the process that reads each row). The parts have about equal element
// counts; the same file and seed give the same parts on the same process count.
template <int D>
ScatteredPart<D> parts_of_pieces(MeshFilePiece<D> piece, const std::string& metric_path, std::int64_t seed);

}  // namespace hocav
