// The P3 surrogate of the boundary (docs/method.md §9): the input boundary's facets lifted once to cubic
// Bézier patches that stand in for the CAD during the whole run.
//
// Per facet one patch (cubic_patch.hpp): the vertices, two control points per edge and (3D) the
// centre. Edge control points b_ij = P_i + d t_i follow the vertex normals (vertex_normals.hpp): on
// a smooth edge t_i is the edge projected on the tangent plane of n_i; on a ridge edge (3D: its two
// facets are on different sides at P_i) t_i runs along the feature line through P_i
// (feature_lines.hpp), or along n_i^A × n_i^B at a corner, so that the edge curve lies in both
// sides' tangent planes (at an input corner, Corners or RequiredVertices, along its own branch of the
// line); an edge that does not join exactly two facets stays straight. The
// length d is the usual third of the projected edge (docs/method.md §9), b_ij = (2 P_i + P_j − ((P_j − P_i)·n_i) n_i) / 3,
// or by default the circular-arc length (cubic_patch.hpp: TangentLength), which removes the
// O(θ⁴) error the third leaves at edge midpoints on curved surfaces. Each edge control
// point depends only on the edge's two vertices and on normals both facets of the edge share, so
// the two patches of an edge have the same edge curve (C0 across edges), and every patch at a
// vertex is tangent to its side's plane there (G1 at vertices).
//
// Ridge curves: the edge curves of feature edges (refs or sides differ), kept apart with the refs
// on their two sides, answer project_on_intersection and project_on_ridge exactly on the curve the
// proposed mid nodes follow.
//
// Projection: candidate patches from a bounding-box tree, Newton with clamping on each
// (patch_closest_point.hpp), the closest kept. With a hint, the search first walks from the hinted
// patch to the neighbour across the side its closest point is clamped to, and stops at a patch whose
// closest point is interior (a local minimum of the distance, taken as the closest when it lies
// within a patch diameter of the point); a walk that ends at a vertex falls back to the tree.
#pragma once

#include <optional>
#include <vector>

#include "mesh/mesh.hpp"
#include "surface/boundary_geometry.hpp"
#include "surface/cubic_patch.hpp"
#include "surface/feature_lines.hpp"
#include "surface/patch_closest_point.hpp"
#include "surface/patch_tree.hpp"
#include "surface/ridge_curves.hpp"
#include "surface/surface_topology.hpp"
#include "surface/vertex_normals.hpp"

namespace hocav {

template <int D>
struct SurrogateOptions {
  VertexNormalOptions<D> normals{};
  TangentLength tangent_length = TangentLength::kCircularArc;
};

template <int D>
class P3Surrogate final : public BoundaryGeometry<D> {
 public:
  // Built from the mesh's boundary facets and vertices (P2 nodes are not used); patch p is facet p.
  explicit P3Surrogate(const Mesh<D>& mesh, const SurrogateOptions<D>& options = {});

  BoundaryPoint<D> project(const Vec<D>& x, const ProjectionQuery& query = {}) const override;
  // The patch normal at the projection, outward like the facets.
  Vec<D> normal(const Vec<D>& x, const ProjectionQuery& query = {}) const override;
  // 3D: the closest point on the ridge curves between the two refs (ridge_curves.hpp); the
  // defaults where none separates them, and in 2D.
  Vec<D> project_on_intersection(const Vec<D>& x, int ref_a, int ref_b) const override;
  Vec<D> project_on_ridge(const Vec<D>& x, int ref_a, int ref_b) const override;
  // The midpoint of the surrogate's edge curve when (a, b) is an edge of the surrogate: it lies on
  // the surrogate exactly, ridge edges included. Other edges: the default projection.
  Vec<D> propose_edge_node(const BoundaryEdge<D>& edge) const override;

  Index patch_count() const { return static_cast<Index>(patches_.size()); }
  const CubicPatch<D>& patch(Index p) const { return patches_[p]; }
  int patch_ref(Index p) const { return refs_[p]; }
  const SurfaceTopology<D>& topology() const { return topology_; }
  const VertexNormals<D>& vertex_normals() const { return normals_; }
  // The point of the edge curve of mesh edge (a, b) at its parameter 1/2, when (a, b) is a boundary
  // edge of the mesh the surrogate was built from.
  std::optional<Vec<D>> edge_midpoint(Index a, Index b) const;

 private:
  struct Closest {
    Index patch = kNoIndex;
    PatchClosestPoint<D> on_patch;
  };
  Closest closest(const Vec<D>& x, const ProjectionQuery& query) const;
  std::optional<Closest> walk_from(Index patch, const Vec<D>& x, const ProjectionQuery& query) const;
  void build_patch(const Mesh<D>& mesh, Index f, TangentLength tangent_length);
  std::optional<Vec<D>> closest_on_ridges(const Vec<D>& x, int ref_a, int ref_b) const;

  std::vector<CubicPatch<D>> patches_;
  std::vector<int> refs_;
  std::vector<Box<D>> boxes_;
  SurfaceTopology<D> topology_;
  VertexNormals<D> normals_;
  FeatureLines<D> lines_;
  PatchTree<D> tree_;
  RidgeCurves ridge_curves_;   // 3D
  IndexHashMap edge_patches_;  // mesh edge key -> CubicPatch<D>::kEdges * patch + local edge
};

extern template class P3Surrogate<2>;
extern template class P3Surrogate<3>;

}  // namespace hocav
