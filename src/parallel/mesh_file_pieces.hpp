// Reading a mesh file in pieces (docs/distributed.md §Reading in pieces): every process reads one
// run of a P1 Gamma file's vertices, elements and facets (read_gamma_mesh_slice) and builds the part
// of its run of elements. It asks the processes that read its elements' vertices for their points,
// and the faces and facets of every run meet at the process each face's vertex ids hash to, which
// tells each face whether an element of another run lies across it and sends each facet to the
// run of its element. No process holds more than its runs, its part and the messages about them.
#pragma once

#include <string>
#include <vector>

#include "parallel/mesh_parts.hpp"

namespace hocav {

// Every process at once: its part of the mesh in the Gamma file (and the file's counts) at `path` (.mesh or .meshb, P1),
// made of its run of the file's elements, as migrate_part would make it from the whole mesh: its
// vertices in the order of their file ids (its global ids), its elements in file order, the file's
// facets on them (a facet between two runs goes with the element of the smaller file id), a
// required facet of ref kInterfaceRef on each face towards another run, the feature lines along
// its elements' edges, and the tags (corners, ridges, required vertices, edges and facets) of
// what it holds; required vertices pinned. Non-manifold places are not found here (the whole
// mesh's checks are not either). Throws Error naming the file, keyword and entity when an entity
// is out of range, a facet is no face of the elements, or a face has more than two elements.
template <int D>
struct MeshFilePiece {
  MeshPart<D> part;
  Index vertex_count = 0, element_count = 0, facet_count = 0;  // the file's
  std::vector<Index> facet_ids;                                // per facet of the part, its file id (kNoIndex: an interface facet)
  std::vector<Index> line_ids;                                 // per feature line of the part (3D), its file id
};

template <int D>
MeshFilePiece<D> read_mesh_file_piece(const std::string& path);

// Every process at once: the diagonal of the whole mesh's bounding box, from every piece's.
template <int D>
double whole_diagonal(const Mesh<D>& piece);

}  // namespace hocav
