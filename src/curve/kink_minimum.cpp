#include "curve/kink_minimum.hpp"

#include <cmath>

namespace hocav {
namespace {

// Barycentrics this close to 0 put X on the face: the test then holds within ~1e-10 of the back
// element's size of X, far below the optimizer's step tolerance.
constexpr double kOnFace = 1e-10;
// The kink's face must cross the bisector plane at a clear angle (|cos| of edge and face above this),
// else the sectors degenerate.
constexpr double kTransverse = 0.5;
// A closed ring around a back-mesh edge has a handful of elements; more means a corrupt mesh.
constexpr int kMaxRing = 64;

// ⟨∂ℓ/∂L^L, R_v⟩: the rate of ℓ per unit of the barycentric of back vertex v.
template <int D>
double vertex_rate(const MetricField<D>& field, const EdgeLengthValue<D>& value, Index v) {
  return frobenius_dot(value.log_node_gradient, field.vertex_log_metric(v));
}

bool on_kink_2d(const MetricField<2>& field, const Localization<2>& where, const Vec2& edge_direction,
                const EdgeLengthValue<2>& value, double margin) {
  const Mesh<2>& mesh = field.back_mesh();
  int zero = -1;
  for (int i = 0; i < 3; ++i)
    if (std::abs(where.barycentrics[i]) <= kOnFace) {
      if (zero >= 0) return false;  // at a vertex
      zero = i;
    }
  if (zero < 0) return false;
  const auto& element = mesh.element(where.element);
  const Vec2 facet = mesh.vertex(element[(zero + 2) % 3]) - mesh.vertex(element[(zero + 1) % 3]);
  if (std::abs(dot(facet, edge_direction)) <= kTransverse * norm(facet)) return false;
  const Index other = mesh.neighbor(where.element, zero);
  if (other == kNoIndex) return false;
  // The bisector line's two rays, ±n: one enters this triangle (∇λ_zero·ρ > 0), the other the neighbour.
  const Vec2 normal{{-edge_direction[1], edge_direction[0]}};
  auto slope_into = [&](Index k, const Vec2& ray) {
    const auto gradients = barycentric_gradients<2>(field.locator().element_points(k));
    double slope = dot(value.node_gradient, ray);
    for (int j = 0; j < 3; ++j) slope += vertex_rate(field, value, mesh.element(k)[j]) * dot(gradients[j], ray);
    return slope;
  };
  const auto gradients = barycentric_gradients<2>(field.locator().element_points(where.element));
  const Vec2 inward = dot(gradients[zero], normal) > 0 ? normal : -normal;
  return slope_into(where.element, inward) > margin && slope_into(other, -inward) > margin;
}

bool on_kink_3d(const MetricField<3>& field, const Localization<3>& where, const Vec3& edge_direction,
                const EdgeLengthValue<3>& value, double margin) {
  const Mesh<3>& mesh = field.back_mesh();
  int zeros[2], count = 0;
  for (int i = 0; i < 4; ++i)
    if (std::abs(where.barycentrics[i]) <= kOnFace) {
      if (count == 2) return false;  // at a vertex
      zeros[count++] = i;
    }
  if (count != 2) return false;  // inside, or on a face: no strict first-order test (see the header)
  const auto& first = mesh.element(where.element);
  Index p = kNoIndex, q = kNoIndex;
  for (int i = 0; i < 4; ++i)
    if (i != zeros[0] && i != zeros[1]) (p == kNoIndex ? p : q) = first[i];
  const Vec3 point_p = mesh.vertex(p), along = mesh.vertex(q) - point_p;
  if (std::abs(dot(along, edge_direction)) <= kTransverse * norm(along)) return false;
  const double rate_p = vertex_rate(field, value, p), rate_q = vertex_rate(field, value, q);

  // Around the edge (p, q): cross the face opposite one ring vertex, into the next element, and so on
  // until the ring closes. Each face (p, q, s) holds one sector boundary ρ = m × n_F (in the plane
  // and the face), oriented towards s; in the face, ρ = dλ_q (q − p) + dλ_s (s − p).
  Index element = where.element;
  int opposite = zeros[0];
  for (int step = 0; step < kMaxRing; ++step) {
    const auto& vertices = mesh.element(element);
    Index s = kNoIndex;
    for (int i = 0; i < 4; ++i)
      if (i != opposite && vertices[i] != p && vertices[i] != q) s = vertices[i];
    const Vec3 to_s = mesh.vertex(s) - point_p;
    Vec3 ray = cross(edge_direction, cross(along, to_s));
    const double aa = dot(along, along), as = dot(along, to_s), ss = dot(to_s, to_s);
    const double ra = dot(ray, along), rs = dot(ray, to_s), det = aa * ss - as * as;
    double dq = (ra * ss - rs * as) / det, ds = (rs * aa - ra * as) / det;
    if (ds < 0) ray = -ray, dq = -dq, ds = -ds;
    const double slope = dot(value.node_gradient, ray) + rate_q * dq + vertex_rate(field, value, s) * ds -
                         rate_p * (dq + ds);
    if (!(slope > margin * norm(ray))) return false;
    const Index next = mesh.neighbor(element, opposite);
    if (next == kNoIndex) return false;  // a boundary edge: the ring is open
    if (next == where.element) return true;
    const auto& next_vertices = mesh.element(next);
    for (int i = 0; i < 4; ++i)
      if (next_vertices[i] == s) opposite = i;
    element = next;
  }
  return false;
}

}  // namespace

template <int D>
bool on_back_mesh_face(const Localization<D>& where) {
  for (double lambda : where.barycentrics)
    if (std::abs(lambda) <= kOnFace) return true;
  return false;
}
template bool on_back_mesh_face(const Localization<2>&);
template bool on_back_mesh_face(const Localization<3>&);

bool is_strict_minimum_on_kink(const MetricField<2>& field, const Localization<2>& where, const Vec2& edge_direction,
                               const EdgeLengthValue<2>& value, double margin) {
  return where.inside && on_kink_2d(field, where, edge_direction, value, margin);
}

bool is_strict_minimum_on_kink(const MetricField<3>& field, const Localization<3>& where, const Vec3& edge_direction,
                               const EdgeLengthValue<3>& value, double margin) {
  return where.inside && on_kink_3d(field, where, edge_direction, value, margin);
}

}  // namespace hocav
