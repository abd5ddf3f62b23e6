// A first-order optimality test for a Lagrange node X that lies on a kink of ℓ (math.md §7): the
// back-mesh log-metric L^L(X) is continuous and piecewise linear, so on a back-mesh face shared by
// several elements each element gives its own gradient of ℓ, and Newton's smooth model (one
// element's) cannot tell whether X is optimal. The straight midpoint of an edge of the back mesh
// itself lies on such a kink (the bench's edges, and every edge a mesh keeps from its input).
//
// What is asserted: ℓ'(X; d) > margin·|d| for every direction d ≠ 0 in the bisector plane of the
// edge (the plane normal to `edge_direction` through X). ℓ is continuous and C² on each element, so
// ℓ(X + d) − ℓ(X) = ℓ'(X; d) + O(|d|²) uniformly in the direction, and X is then a strict local
// minimum of ℓ over the plane. (Zero in the convex hull of the elements' gradients, Clarke
// stationarity, would not be enough: it holds at saddles and maxima of kinked functions too.)
//
// The directional derivative is linear on each element's sector of the plane, and the sectors
// (convex, < π) tile the plane, so it is positive everywhere when it is positive on the rays that
// bound the sectors, which lie on the back-mesh faces through X:
//   3D, X on a back-mesh edge e transverse to the plane: the ray on each face (p, q, s) around e;
//   2D, X on a back-mesh edge transverse to the bisector line: the two rays, one in each triangle.
// Along a ray ρ in element k, ℓ'(X; ρ) = ∂ℓ/∂X·ρ + Σ_j ⟨∂ℓ/∂L^L, R_j⟩ ∇λ_j^k·ρ (R_j the vertex
// log-metrics). Every other position (inside an element, on a 3D face where the sectors are half
// planes and no strict first-order test exists, at a vertex, on the boundary) returns false:
// the test only ever saves work, the optimizer's iteration decides those.
#pragma once

#include "curve/edge_length.hpp"
#include "metric/metric_field.hpp"

namespace hocav {

// X lies on a face of its back element (some barycentric within ~1e-10 of 0): the only positions
// where the test can hold.
template <int D>
bool on_back_mesh_face(const Localization<D>& where);

// `where`: the localization of X; `edge_direction`: the unit direction of the edge; `value`: ℓ at X
// with the parts of its gradient (EdgeLengthValue::node_gradient and log_node_gradient).
bool is_strict_minimum_on_kink(const MetricField<2>& field, const Localization<2>& where, const Vec2& edge_direction,
                               const EdgeLengthValue<2>& value, double margin);
bool is_strict_minimum_on_kink(const MetricField<3>& field, const Localization<3>& where, const Vec3& edge_direction,
                               const EdgeLengthValue<3>& value, double margin);

}  // namespace hocav
