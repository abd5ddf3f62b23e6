// The steepest first-order descent of ℓ at a Lagrange node X that lies on a kink (docs/method.md §7): the
// back-mesh log-metric L^L(X) is continuous and piecewise linear, so on a back-mesh face shared by
// several elements each element gives its own gradient of ℓ, and Newton's smooth model (one
// element's) can neither tell whether X is optimal nor find the direction that descends. The straight
// midpoint of an edge of the back mesh itself lies on such a kink (the bench's edges, and every edge a
// mesh keeps from its input).
//
// What is computed: the least directional derivative s* = min ℓ'(X; d) over unit directions d of the
// bisector plane of the edge (the plane normal to `edge_direction` through X), a direction d* that
// attains it and a back element that d* enters. ℓ is continuous and C² on each element, so
// ℓ(X + d) − ℓ(X) = ℓ'(X; d) + O(|d|²) uniformly in the direction:
//   s* > 0: X is a strict local minimum of ℓ over the plane (zero in the convex hull of the elements'
//           gradients, Clarke stationarity, would not be enough: it holds at saddles and maxima too);
//   s* < 0: ℓ descends along d* at rate |s*|, and no direction descends faster.
//
// The directional derivative is linear on each element's sector of the plane, and the sectors (convex,
// at most π) tile the plane. Its least value over one sector's unit directions is −|g_k| at −g_k/|g_k|
// when that lies inside the sector (g_k the element's gradient in the plane), else the smaller slope of
// the sector's bounding rays, which lie on the back-mesh faces through X:
//   3D, X on a back-mesh edge e transverse to the plane: the ray on each face (p, q, s) around e (g_k
//       fixed by the slopes on its sector's two rays);
//   3D, X inside a back-mesh face crossing the plane: two half planes, bounded by the line ±t where the
//       face meets the plane (no strict minimum there: the slopes along ±t are opposite);
//   2D, X on a back-mesh edge transverse to the bisector line: the two rays, one in each triangle.
// Along a direction d in element k, ℓ'(X; d) = ∂ℓ/∂X·d + Σ_j ⟨∂ℓ/∂L^L, R_j⟩ ∇λ_j^k·d (R_j the vertex
// log-metrics). Every other position (inside an element, at a vertex, a face or edge nearly parallel to the
// plane) is not analysed: the optimizer's Newton iteration decides there.
#pragma once

#include "curve/edge_length.hpp"
#include "metric/metric_field.hpp"

namespace hocav {

// X lies on a face of its back element (some barycentric within ~1e-10 of 0): the only positions
// where the analysis can apply.
template <int D>
bool on_back_mesh_face(const Localization<D>& where);

template <int D>
struct KinkDescent {
  bool analysed = false;  // X is on a kink of the kinds above; the rest holds only then
  // Whether the sectors tile the whole plane. At the boundary (an open ring of a boundary edge, a boundary
  // face, a 2D boundary edge) only the domain's side is analysed: s* is then the least slope into the domain,
  // which proves a descent when negative but no minimum (outside, the metric is an extension).
  bool whole_plane = false;
  double slope = 0;          // s*, per unit length of the direction
  Vec<D> direction{};        // d*, a unit vector of the plane
  Index element = kNoIndex;  // a back element whose closed sector of the plane holds d*
};

// `where`: the localization of X; `edge_direction`: the unit direction of the edge; `value`: ℓ at X
// with the parts of its gradient (EdgeLengthValue::node_gradient and log_node_gradient).
KinkDescent<2> steepest_descent_on_kink(const MetricField<2>& field, const Localization<2>& where, const Vec2& edge_direction,
                                        const EdgeLengthValue<2>& value);
KinkDescent<3> steepest_descent_on_kink(const MetricField<3>& field, const Localization<3>& where, const Vec3& edge_direction,
                                        const EdgeLengthValue<3>& value);

}  // namespace hocav
