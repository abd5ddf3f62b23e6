// The boundary facets as a surface (docs/method.md §9: "split at ridges/feature edges"): the neighbour of
// each facet across each of its sides, and which sides are ridges — where the surface may fold, so
// that vertex normals are not averaged across them.
//
// A side of a facet is the (D − 2)-face opposite one of its local vertices: an edge of a triangle
// (3D), a vertex of a boundary segment (2D). A side is a ridge when
//   - it does not join exactly two facets (an open border, or a non-manifold junction), or
//   - its two facets have different refs, or
//   - the angle between their normals exceeds the feature angle, or
//   - the mesh tags it: 3D, an edge listed in Ridges (through the Edges keyword); 2D, a vertex
//     listed in Corners. (3D Corners alone split nothing: the ridges through a corner do.)
#pragma once

#include <array>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

template <int D>
struct SurfaceTopology {
  // neighbors[f][s]: the facet across side s of facet f (the side opposite local vertex s), or
  // kNoIndex when the side does not join exactly two facets.
  std::vector<std::array<Index, D>> neighbors;
  std::vector<std::array<bool, D>> ridges;
};

// Facets are expected oriented consistently (outward, as Mesh<D> keeps them).
template <int D>
SurfaceTopology<D> build_surface_topology(const Mesh<D>& mesh, double feature_angle_degrees);

// The facet's normal scaled by its measure (twice the area in 3D, the length in 2D), outward.
template <int D>
Vec<D> facet_area_normal(const Mesh<D>& mesh, Index f);

// The position of vertex v in facet f, or -1.
template <int D>
int facet_local_vertex(const Mesh<D>& mesh, Index f, Index v);

}  // namespace hocav
