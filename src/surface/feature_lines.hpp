// The tangents of the boundary's feature lines (docs/surface.md, "Feature lines"): where the
// facets around a vertex split into two sides along exactly two edges (a ridge passing through,
// not a corner), the ridge curve's tangent there comes from the feature line itself — the tangent
// at the vertex of the circle through it and its two neighbours along the line — rather than from
// n_A × n_B. That is exact on circular and straight features, and it does not degrade when the two
// sides' normals are nearly parallel (a shallow ridge, a fillet's tangent edge), where the cross
// product's direction is lost in their errors. Both sides' normals at the vertex are then made
// orthogonal to the tangent, so every patch stays tangent to its side's plane (G1 at vertices) and
// both patches of a ridge edge get the same edge curve (it depends on the line only).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"
#include "surface/surface_topology.hpp"
#include "surface/vertex_normals.hpp"

namespace hocav {

// Per vertex: the unit tangent of the feature line through it (either orientation), or zero
// where no feature line passes through exactly (a smooth vertex, a corner, an end). Adjusts the
// normals of the sides at those vertices as said above. 2D: all zero (features are points).
template <int D>
std::vector<Vec<D>> feature_line_tangents(const Mesh<D>& mesh, const SurfaceTopology<D>& topology, VertexNormals<D>& normals);

}  // namespace hocav
