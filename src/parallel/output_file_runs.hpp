// The output mesh file of a run that ends in its parts, written in runs whatever its format
// (docs/distributed.md §Writing in runs, §A .vtu in runs): no process holds the whole mesh.
#pragma once

#include <string>

#include "parallel/mesh_file_runs.hpp"

namespace hocav {

// Every process at once: the counts of the distributed mesh the parts hold, each vertex and P2 node
// once however many parts hold it (by global ids), and its elements; no facets or lines (a .vtu's
// cells are the elements alone).
template <int D>
MeshFileCounts distinct_mesh_counts(const MeshPart<D>& part);

// Every process at once: the mesh file `path` of the parts written in runs, a Gamma file
// (write_mesh_runs: .meshb binary, the entities in `orders`), a gmsh .msh (write_gmsh_msh_runs: in
// blocks by ref, in `orders` within a block) or a .vtu of the mesh alone, as write_mesh_file
// writes one (write_vtu_runs: a vertex several parts hold is a point of each); the Gamma or .msh
// file's counts, or the .vtu's mesh's (distinct_mesh_counts).
template <int D>
MeshFileCounts write_mesh_file_runs(const std::string& path, const MeshPart<D>& part, const EntityOrders& orders = {});

}  // namespace hocav
