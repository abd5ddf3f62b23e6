// A mesh file written by every process at once, each its part of a distributed mesh (docs/distributed.md
// §Writing in runs): no process holds the whole mesh. The vertices go to the processes of their runs
// of global ids, which number them and write them; what several parts hold (interface vertices,
// edges, feature lines) is written once, by the process its ids hash to; the rest each process
// writes where the file's layout puts its records.
#pragma once

#include <span>
#include <string>

#include "parallel/mesh_parts.hpp"

namespace hocav {

// The places of an entity order a writer in runs sends at once (docs/distributed.md §Writing in
// runs): the messages never hold more than a window's rows.
constexpr Index kOrderWindow = Index{1} << 16;

// The entities of a written mesh file.
struct MeshFileCounts {
  Index vertices = 0, nodes = 0, elements = 0, facets = 0, lines = 0;  // nodes: a P2 file's, beyond its vertices
};

// The order in which a mesh file written in runs puts a part's entities: per element, per facet of
// the part but its interface facets (in order), per feature line, its place among the file's; over
// every part, each a permutation of the places (a line several parts hold has one place), such as
// an input's ids. Empty: part after part.
struct EntityOrders {
  std::span<const Index> elements, facets, lines;
};

// Every process at once: the Gamma file at `path` (.meshb when `binary`, else .mesh; `version` as
// write_gamma_mesh takes it) of the distributed mesh whose parts the processes hold. Each part is
// compact, P1 or P2 as every other, with global vertex ids (MeshPart::global_ids) and pinned flags;
// every element lies in one part, and the faces between parts carry interface facets (ref
// kInterfaceRef), which are not written. The file holds:
// - the vertices in the order of their global ids, numbered from 1 without gaps; a P2 mesh's nodes
//   after them, those of each process's edges in its edge table's order, rank after rank, with the
//   edges several parts hold written once;
// - the feature lines (3D) once each, the facets (but the interfaces') and the elements part by
//   part in rank order, or each kind in its order when `orders` gives one, each entity then written
//   by the process of its run of places;
// - the corners, the ridges, the vertices required by the mesh (kPinnedByMesh, not the interfaces'),
//   and the required edges and triangles.
// One process holding a whole mesh (whole_mesh_part, the others empty) writes write_gamma_mesh's file
// byte for byte when the mesh's tag lists are in increasing order. Rank 0 writes the keywords with
// holes for the records (the output's temporary in the command's OutputSet), then every process
// writes its records in place. Throws Error when two parts give a vertex different points or an
// edge different nodes, the places are no permutation, or the file cannot be written.
template <int D>
MeshFileCounts write_mesh_runs(const std::string& path, const MeshPart<D>& part, bool binary, int version = 0,
                               const EntityOrders& orders = {});

}  // namespace hocav
