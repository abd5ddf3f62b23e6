// Vertex normals of the boundary, one per smooth side of each vertex (docs/method.md §9: "a normal n_i at
// each surface vertex ... split at ridges/feature edges").
//
// The facets around a vertex fall into sides: two facets sharing a side through the vertex that is
// not a ridge (surface_topology.hpp) are on the same side. Two sides that meet at a ridge where
// the surface does not fold (a ref boundary or a tagged ridge across a smooth part, a fillet tangent
// to a plane) are merged into one, since the ridge rule would need a well-defined tangent n_A × n_B:
// along a feature line when their normals fitted in the line's normal plane (section_circle_fit.hpp)
// are within 5°, elsewhere when their weighted normals are within the smooth-ridge angle. With the
// quadric fit, a side whose neighbourhood spans several refs takes the fit over one ref's points
// where that explains them far better (docs/surface.md). Each side gets one normal, the weighted
// mean of its facets' unit normals, or the normal of a given geometry (analytic or CAD) at the
// vertex when that one agrees with the facets within the feature angle (at a ridge, where the
// geometry's single normal cannot serve both sides, the facets' normal is kept). Facets of one side
// thus use the very same normal at the vertex, which is what keeps the surrogate free of cracks.
#pragma once

#include <array>
#include <vector>

#include "mesh/mesh.hpp"
#include "surface/boundary_geometry.hpp"
#include "surface/surface_topology.hpp"

namespace hocav {

// How the facets of a side are weighted at a vertex.
enum class NormalWeights {
  kAngle,  // by the facet's angle at the vertex (3D; 2D: equal weights)
  kArea,   // by the facet's area (2D: length)
  // N. Max (1999): sin(angle) / (|e_1| |e_2|) for a triangle with edges e_1, e_2 at the vertex
  // (2D: 1 / length): exact when the vertex and its neighbours lie on one sphere (circle).
  kMax,
};

template <int D>
struct VertexNormalOptions {
  // Facets meeting at more than this angle are on different sides.
  double feature_angle_degrees = 45;
  // Ridges (refs, tags) where the sides' weighted normals differ by less than this are smooth there
  // (where no section fit decides). Half fans of a smooth surface differ by about
  // h / (curvature radius), hence a margin; below the machined part's 20° crease.
  double smooth_ridge_angle_degrees = 15;
  NormalWeights weights = NormalWeights::kAngle;
  // Refine each side's weighted normal by a least-squares quadric (quadric_fit.hpp) through the
  // vertices of its facets and of their neighbours on the same side. Off, the weighted normals err
  // by O(h) on irregular meshes; the measured effect is in docs/surface.md.
  bool quadric_fit = true;
  // When set, normals come from this geometry (with the facet's ref) where it agrees with the facets.
  const BoundaryGeometry<D>* normal_source = nullptr;
};

template <int D>
struct VertexNormals {
  std::vector<Vec<D>> normals;                     // unit, outward like the facets; one per side
  std::vector<std::array<Index, D>> corner_sides;  // per facet and local vertex: its side's normal

  const Vec<D>& at(Index f, int local_vertex) const { return normals[corner_sides[f][local_vertex]]; }
};

template <int D>
VertexNormals<D> compute_vertex_normals(const Mesh<D>& mesh, const SurfaceTopology<D>& topology, const VertexNormalOptions<D>& options);

}  // namespace hocav
