#include "curve/kink_descent.hpp"

#include <array>
#include <cmath>

namespace hocav {
namespace {

// Barycentrics this close to 0 put X on the face: the test then holds within ~1e-10 of the back
// element's size of X, far below the optimizer's step tolerance.
constexpr double kOnFace = 1e-10;
// The kink must cross the bisector plane at a clear angle, else the sectors degenerate: a back-mesh edge
// makes |cos| above this with the edge, a face's normal |sin| above this.
constexpr double kTransverse = 0.5;
// A closed ring around a back-mesh edge has a handful of elements; more means a corrupt mesh.
constexpr int kMaxRing = 64;
// Two rays bounding a sector this close to (anti)parallel (|sin| of their angle below this) leave its
// interior to the rays' own slopes.
constexpr double kSectorSine = 1e-6;

// ⟨∂ℓ/∂L^L, R_v⟩: the rate of ℓ per unit of the barycentric of back vertex v.
template <int D>
double vertex_rate(const MetricField<D>& field, const EdgeLengthValue<D>& value, Index v) {
  return frobenius_dot(value.log_node_gradient, field.vertex_log_metric(v));
}

// The least of ℓ'(X; ρ/|ρ|) so far and the argument that attains it.
template <int D>
void consider(KinkDescent<D>& best, double slope, const Vec<D>& direction, Index element) {
  if (best.element == kNoIndex || slope < best.slope) {
    best.slope = slope;
    best.direction = direction;
    best.element = element;
  }
}

KinkDescent<2> descent_2d(const MetricField<2>& field, const Localization<2>& where, const Vec2& edge_direction,
                          const EdgeLengthValue<2>& value) {
  const Mesh<2>& mesh = field.back_mesh();
  int zero = -1;
  for (int i = 0; i < 3; ++i)
    if (std::abs(where.barycentrics[i]) <= kOnFace) {
      if (zero >= 0) return {};  // at a vertex
      zero = i;
    }
  if (zero < 0) return {};
  const auto& element = mesh.element(where.element);
  const Vec2 facet = mesh.vertex(element[(zero + 2) % 3]) - mesh.vertex(element[(zero + 1) % 3]);
  if (std::abs(dot(facet, edge_direction)) <= kTransverse * norm(facet)) return {};
  const Index other = mesh.neighbor(where.element, zero);
  // The bisector line's two rays, ±n: one enters this triangle (∇λ_zero·ρ > 0), the other the neighbour.
  const Vec2 normal{{-edge_direction[1], edge_direction[0]}};
  auto slope_into = [&](Index k, const std::array<Vec2, 3>& gradients, const Vec2& ray) {
    double slope = dot(value.node_gradient, ray);
    for (int j = 0; j < 3; ++j) slope += vertex_rate(field, value, mesh.element(k)[j]) * dot(gradients[j], ray);
    return slope;
  };
  const auto gradients = barycentric_gradients<2>(field.locator().element_points(where.element));
  const Vec2 inward = dot(gradients[zero], normal) > 0 ? normal : -normal;
  KinkDescent<2> best;
  consider(best, slope_into(where.element, gradients, inward), inward, where.element);
  if (other != kNoIndex) {  // else a boundary edge: the ray into the domain only
    consider(best, slope_into(other, barycentric_gradients<2>(field.locator().element_points(other)), -inward), -inward, other);
    best.whole_plane = true;
  }
  best.analysed = true;
  return best;
}

// ∂ℓ/∂X in back element k: the part at fixed L^L plus Σ_j ⟨∂ℓ/∂L^L, R_j⟩ ∇λ_j.
Vec3 element_gradient(const MetricField<3>& field, const EdgeLengthValue<3>& value, Index k, const std::array<Vec3, 4>& gradients) {
  Vec3 result = value.node_gradient;
  for (int j = 0; j < 4; ++j) result += vertex_rate(field, value, field.back_mesh().element(k)[j]) * gradients[j];
  return result;
}

// X on the face opposite corner `zero` of its element k1, shared with k2: the plane meets the face in a
// line (direction t), which splits the plane into two half planes, one in each element. On each the
// directional derivative is g_k·d; its least unit value is −|g_k| when −g_k points into that half, else
// the smaller of ±g·t (equal from both sides: L^L is linear on the face).
KinkDescent<3> face_descent(const MetricField<3>& field, const Localization<3>& where, int zero, const Vec3& m,
                            const EdgeLengthValue<3>& value) {
  const Mesh<3>& mesh = field.back_mesh();
  const Index k1 = where.element, k2 = mesh.neighbor(k1, zero);
  const auto gradients1 = barycentric_gradients<3>(field.locator().element_points(k1));
  const Vec3& face_normal = gradients1[zero];  // into k1
  const Vec3 line = cross(m, face_normal);
  const double line_length = norm(line);
  if (line_length <= kTransverse * norm(face_normal)) return {};
  const Vec3 t = (1 / line_length) * line;
  const Vec3 into_k1 = cross(t, m);  // in the plane, normal to t; oriented by face_normal below
  const double side = dot(into_k1, face_normal) > 0 ? 1 : -1;
  auto onto_plane = [&](const Vec3& v) { return v - dot(v, m) * m; };
  const Vec3 g1 = onto_plane(element_gradient(field, value, k1, gradients1));
  KinkDescent<3> best;
  const double along = dot(g1, t);
  consider(best, along, t, k1);
  consider(best, -along, -t, k1);
  const double norm1 = norm(g1);
  if (norm1 > 0 && side * dot(g1, into_k1) < 0) consider(best, -norm1, (-1 / norm1) * g1, k1);
  if (k2 != kNoIndex) {  // else a boundary face: the domain's half plane only
    const Vec3 g2 = onto_plane(element_gradient(field, value, k2, barycentric_gradients<3>(field.locator().element_points(k2))));
    const double norm2 = norm(g2);
    if (norm2 > 0 && side * dot(g2, into_k1) > 0) consider(best, -norm2, (-1 / norm2) * g2, k2);
    best.whole_plane = true;
  }
  best.analysed = true;
  return best;
}

KinkDescent<3> descent_3d(const MetricField<3>& field, const Localization<3>& where, const Vec3& edge_direction,
                          const EdgeLengthValue<3>& value) {
  const Mesh<3>& mesh = field.back_mesh();
  int zeros[2], count = 0;
  for (int i = 0; i < 4; ++i)
    if (std::abs(where.barycentrics[i]) <= kOnFace) {
      if (count == 2) return {};  // at a vertex
      zeros[count++] = i;
    }
  if (count == 0) return {};
  if (count == 1) return face_descent(field, where, zeros[0], edge_direction, value);
  const auto& corners = mesh.element(where.element);
  Index p = kNoIndex, q = kNoIndex;
  for (int i = 0; i < 4; ++i)
    if (i != zeros[0] && i != zeros[1]) (p == kNoIndex ? p : q) = corners[i];
  const Vec3 point_p = mesh.vertex(p), along = mesh.vertex(q) - point_p;
  if (std::abs(dot(along, edge_direction)) <= kTransverse * norm(along)) return {};
  const double rate_p = vertex_rate(field, value, p), rate_q = vertex_rate(field, value, q);

  // Around the edge (p, q): cross the face opposite one ring vertex, into the next element, and so on
  // until the ring closes. Each face (p, q, s) holds one sector boundary ρ = m × ((q − p) × (s − p)) (in the
  // plane and the face) = (m·(s − p)) (q − p) − (m·(q − p)) (s − p), oriented towards s: ρ = dq (q − p) + ds (s − p)
  // with ds = ∓m·(q − p) > 0, the same sign for every face. Each element's sector lies between the rays
  // of its two faces through p and q.
  const double orientation = dot(edge_direction, along) > 0 ? -1 : 1;
  const double ds = -orientation * dot(edge_direction, along);
  KinkDescent<3> best;
  // Inside a sector between rays a and b: g = c_a ρ_a + c_b ρ_b with g·ρ_a = σ_a, g·ρ_b = σ_b (σ the slope
  // ℓ'(X; ρ) for the ray as it is, not normalized); −g lies in the sector's cone when both coefficients are
  // negative, and then ℓ'(X; −g/|g|) = −|g|, |g|² = c_a σ_a + c_b σ_b.
  auto consider_sector = [&](const Vec3& ray_a, double sa, const Vec3& ray_b, double sb, Index sector_element) {
    const double gaa = dot(ray_a, ray_a), gab = dot(ray_a, ray_b), gbb = dot(ray_b, ray_b);
    const double det = gaa * gbb - gab * gab;
    if (!(det > kSectorSine * kSectorSine * gaa * gbb)) return;
    const double ca = (sa * gbb - sb * gab) / det, cb = (sb * gaa - sa * gab) / det;
    const double squared = ca * sa + cb * sb;
    if (!(ca < 0 && cb < 0 && squared > 0)) return;
    const double magnitude = std::sqrt(squared);
    consider(best, -magnitude, (-1 / magnitude) * (ca * ray_a + cb * ray_b), sector_element);
  };
  // The ray on the face of `element` opposite its corner `opposite` (a face through p and q), its slope, and
  // the face's third vertex s.
  struct Ray {
    Vec3 ray;
    double slope;
    Index s;
  };
  auto ray_on_face = [&](Index element, int opposite) {
    const auto& vertices = mesh.element(element);
    Index s = kNoIndex;
    for (int i = 0; i < 4; ++i)
      if (i != opposite && vertices[i] != p && vertices[i] != q) s = vertices[i];
    const Vec3 to_s = mesh.vertex(s) - point_p;
    const double dq = orientation * dot(edge_direction, to_s);
    const Vec3 ray = dq * along + ds * to_s;
    const double slope = dot(value.node_gradient, ray) + rate_q * dq + vertex_rate(field, value, s) * ds - rate_p * (dq + ds);
    const double length = norm(ray);
    consider(best, slope / length, (1 / length) * ray, element);
    return Ray{ray, slope, s};
  };
  // From `element`, leaving through its face opposite `opposite` (whose ray is `exit`): the elements beyond,
  // each sector between the ray it is entered by and the one it is left by, until the ring closes or meets
  // the boundary. `exit` ends as the last ray.
  enum class WalkEnd { kClosed, kBoundary, kTooLong };
  int steps = 0;
  auto walk = [&](Index element, int opposite, Ray& exit) {
    for (;;) {
      const Index next = mesh.neighbor(element, opposite);
      if (next == kNoIndex) return WalkEnd::kBoundary;
      if (next == where.element) return WalkEnd::kClosed;
      if (++steps == kMaxRing) return WalkEnd::kTooLong;
      const auto& next_vertices = mesh.element(next);
      for (int i = 0; i < 4; ++i)
        if (next_vertices[i] == exit.s) opposite = i;
      element = next;
      const Ray entry = exit;
      exit = ray_on_face(element, opposite);
      consider_sector(entry.ray, entry.slope, exit.ray, exit.slope, element);
    }
  };
  // Element 0 lies between its faces opposite zeros[0] and zeros[1]: around one way, and when the ring is
  // open (a boundary edge) the other way too, which covers the domain's side of the plane only.
  const Ray first = ray_on_face(where.element, zeros[0]);
  Ray last = first;
  const WalkEnd end = walk(where.element, zeros[0], last);
  if (end == WalkEnd::kTooLong) return {};
  if (end == WalkEnd::kClosed) {
    consider_sector(last.ray, last.slope, first.ray, first.slope, where.element);
    best.whole_plane = true;
  } else {
    Ray other = ray_on_face(where.element, zeros[1]);
    consider_sector(other.ray, other.slope, first.ray, first.slope, where.element);
    if (walk(where.element, zeros[1], other) != WalkEnd::kBoundary) return {};  // a ring open one way only
  }
  best.analysed = true;
  return best;
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

KinkDescent<2> steepest_descent_on_kink(const MetricField<2>& field, const Localization<2>& where, const Vec2& edge_direction,
                                        const EdgeLengthValue<2>& value) {
  return where.inside ? descent_2d(field, where, edge_direction, value) : KinkDescent<2>{};
}

KinkDescent<3> steepest_descent_on_kink(const MetricField<3>& field, const Localization<3>& where, const Vec3& edge_direction,
                                        const EdgeLengthValue<3>& value) {
  return where.inside ? descent_3d(field, where, edge_direction, value) : KinkDescent<3>{};
}

}  // namespace hocav
