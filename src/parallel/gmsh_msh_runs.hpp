// A gmsh .msh 4.1 file written by every process at once, each its part of a distributed mesh
// (docs/distributed.md §A .msh in runs): no process holds the whole mesh.
#pragma once

#include <string>

#include "parallel/mesh_file_runs.hpp"

namespace hocav {

// Every process at once: the .msh file at `path` of the distributed mesh whose parts the processes
// hold (each compact, with global ids and pinned flags, interface facets of ref kInterfaceRef not
// written), as write_gmsh_msh writes a mesh: one entity per ref of each dimension, the corners as
// points, the 3D feature lines, the facets and the elements in blocks by ref. Its vertices and P2
// nodes are numbered as write_mesh_runs numbers them (FileNumbers), each once. Within a block the
// entities come part after part in rank order, or, for a kind that `orders` orders (as
// write_mesh_runs takes them), in the order's. One process holding a whole mesh (the others empty)
// writes write_gmsh_msh's file byte for byte when its global ids are its vertex ids and its corners
// are listed in increasing order; so does a distributed P1 mesh given its entities' orders. Returns
// the file's counts; throws Error as FileNumbers does, when the places of an order are no
// permutation, or when the file cannot be written.
template <int D>
MeshFileCounts write_gmsh_msh_runs(const std::string& path, const MeshPart<D>& part, const EntityOrders& orders = {});

}  // namespace hocav
