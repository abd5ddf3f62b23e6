// The boundary of a mesh as a mesh of its own: what a boundary geometry is made of (its facets,
// lines and tags, and the vertices), without the elements. A distributed run's processes make their
// geometry from it instead of from the whole mesh (docs/distributed.md §What each process holds).
#pragma once

#include "mesh/mesh.hpp"

namespace hocav {

// The vertices of `mesh` (P1) with their refs and ids, its facets, lines, corners, ridges and
// required entities; no elements. Every vertex is kept, inner ones too: a geometry answers some
// questions by vertex ids (the P3 surrogate's edge curves, asked by the parts' global ids), which
// must be the mesh's.
template <int D>
Mesh<D> boundary_mesh_of(const Mesh<D>& mesh);

}  // namespace hocav
