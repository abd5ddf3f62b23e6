// The Hausdorff bound as a metric (docs/adaptation.md §The Hausdorff bound): at each boundary vertex of
// the back mesh, the sizes that keep a unit boundary facet within `hausd` of the geometry, from the
// curvature the geometry has along the vertex's boundary edges. Intersected with the given metric
// before its gradation, as mmg does with its -hausd: the split then refines a curved boundary
// because the metric asks for it, and no collapse undoes that split.
#pragma once

#include <span>
#include <vector>

#include "geom/sym_mat.hpp"
#include "mesh/mesh.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

struct HausdorffBound {
  double hausd = 0;                   // > 0
  double feature_angle_degrees = 45;  // ridges and corners as the loop finds them (AdaptationSettings)
  // When > 0, at each boundary vertex also at most this times the smallest size the given metric
  // asks there (docs/adaptation.md §The Hausdorff bound: a wall's sag within its first layer).
  double relative_to_size = 0;
};

// The default relative_to_size when the adapted mesh is curved (`hocav adapt --order 2`): a wall
// edge may sag at most the size across it. A deeper sag cannot be curved onto the geometry: the
// edge's node would fold the first layer's elements (docs/adaptation.md §The Hausdorff bound).
constexpr double kCurvedRelativeHausd = 1.0;

// The bound spreads inside at mmg's default gradation (-hgrad 1.3): the metric between the boundary
// and the back mesh's inner vertices, interpolated, then keeps it.
constexpr double kHausdorffGradation = 1.3;

// The bound where it asks for nothing: sizes of the mesh's bounding-box `diagonal`.
template <int D>
SymMat<D> unbounded_metric(double diagonal);

// The bound at every vertex of `mesh` (P1, with its boundary facets), `given` the metric at its
// vertices: at the boundary vertices where the geometry's curvature asks for smaller sizes than
// `given`, those sizes, graded into the domain; sizes of the domain's diagonal elsewhere, which ask
// for nothing.
template <int D>
std::vector<SymMat<D>> hausdorff_metrics(const Mesh<D>& mesh, const BoundaryGeometry<D>& geometry, const HausdorffBound& bound,
                                         std::span<const SymMat<D>> given);

// metric ∩ bound, or `metric` itself, bit for bit, when it is at least as fine every way (metric −
// bound positive semi-definite).
template <int D>
SymMat<D> within_bound(const SymMat<D>& metric, const SymMat<D>& bound);

// Makes each vertex's metric within_bound of the bound's.
// Returns how many vertices changed.
template <int D>
Index bound_metrics_by_hausdorff(const Mesh<D>& mesh, std::vector<SymMat<D>>& metrics, const BoundaryGeometry<D>& geometry,
                                 const HausdorffBound& bound);

}  // namespace hocav
