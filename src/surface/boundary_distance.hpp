// How far a mesh's boundary is from the true geometry (docs/method.md §9, the accuracy of curved
// boundaries): the largest distance to the geometry over points sampled densely on every boundary
// facet — straight for a P1 mesh, the quadratic map of its vertices and edge nodes for a P2 mesh.
#pragma once

#include "mesh/mesh.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

// Samples each facet on a lattice of n intervals per side ((n + 1)(n + 2) / 2 points per triangle,
// n + 1 per segment) and projects every sample onto the geometry restricted to the facet's ref.
template <int D>
double max_boundary_distance(const Mesh<D>& mesh, const BoundaryGeometry<D>& geometry, int n = 15);

}  // namespace hocav
