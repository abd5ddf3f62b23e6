// A mesh that rank 0 holds whole, scattered over the processes for a curving in the parts (`mpirun
// hocav curve`, docs/distributed.md §Curving in the parts): cut without the whole mesh's graph on
// rank 0 (partition_from_root), the elements migrated to their parts, and each part given its
// vertices' metrics, which rank 0 holds.
#pragma once

#include <cstdint>
#include <vector>

#include "geom/sym_mat.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

template <int D>
struct ScatteredPart {
  MeshPart<D> part;                // as migrate_part makes it: global ids the mesh's vertex ids, pinned flags
  std::vector<SymMat<D>> metrics;  // per vertex of the part
  std::vector<Index> element_ids;  // per element of the part, its id in the mesh (its place in the input's element order)
  std::vector<Index> facet_ids;    // per facet of the part but the interface facets (which come last), its id in the mesh
  std::vector<Index> line_ids;     // per feature line of the part (3D), its id in the mesh
  long long bytes_sent = 0;        // by this process
  double seconds = 0;              // the slowest process's
};

// Collective. Rank 0 passes its `mesh` (P1 or P2, compact, every vertex in an element) and per
// vertex its metric; the others pass empty ones. The parts have about equal element counts; the same
// mesh and seed give the same parts.
template <int D>
ScatteredPart<D> scatter_from_root(Mesh<D> mesh, std::vector<SymMat<D>> metrics, std::int64_t seed);

}  // namespace hocav
