// The input ids of a distributed mesh's feature lines (3D), found by their ends: a line is the only
// one on its edge, so the global ids of its ends name it wherever the migrations took it. The
// output then writes the lines in the input's order, as it writes the elements and facets
// (docs/distributed.md §Curving from pieces).
#pragma once

#include <vector>

#include "parallel/face_key.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// A line whose input id a process knows: its ends' sorted global ids, and its id.
struct KnownLine {
  FaceKey<2> ends;
  Index id;
};

// The known lines of `part`: per line, its ends by global id and ids[l].
template <int D>
std::vector<KnownLine> known_lines(const MeshPart<D>& part, const std::vector<Index>& ids);

// Per line of `part`, its id among `lines` (in any order). Throws Error for a line they do not hold.
template <int D>
std::vector<Index> line_ids_among(const MeshPart<D>& part, std::vector<KnownLine> lines);

// Every process at once, each with the lines whose ids it knows (a piece's, or rank 0's whole
// mesh's; a line may be known to several): per line of `part`, its id. Every process gathers every
// known line, which is no more than reading a file in pieces holds (every process reads the file's
// whole list of lines). Throws Error as line_ids_among does.
template <int D>
std::vector<Index> line_ids_by_ends(const MeshPart<D>& part, const std::vector<KnownLine>& known);

}  // namespace hocav
