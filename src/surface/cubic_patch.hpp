// One cubic Bézier patch of the P3 boundary surrogate (docs/method.md §9): a curve with 4 control points
// (D = 2) or a triangle with 10 (D = 3), evaluated with its first and second derivatives by de
// Casteljau, and the rules that place its control points from vertices and normals.
//
// Control point layout: the vertices P_0..P_{D-1}, then two points per patch edge e = (i, j), in
// the edge order of kPatchEdges (b_ij next to P_i, then b_ji), then (D = 3) the centre b_111:
//   curve    P0 P1 b01 b10
//   triangle P0 P1 P2 b01 b10 b12 b21 b20 b02 b111
// Parameters: the patch barycentrics (λ_0, ..., λ_{D-1}) with λ_0 = 1 − Σ the others; a patch is
// evaluated at the D − 1 free ones (t for the curve, (u, v) = (λ_1, λ_2) for the triangle).
#pragma once

#include <array>

#include "geom/vec.hpp"

namespace hocav {

template <int D>
struct CubicPatch {
  static constexpr int kParameters = D - 1;
  static constexpr int kEdges = D == 2 ? 1 : 3;
  static constexpr int kControlPoints = D == 2 ? 4 : 10;
  std::array<Vec<D>, kControlPoints> control{};

  const Vec<D>& vertex(int i) const { return control[i]; }
  // b_ij and b_ji of edge e.
  const Vec<D>& edge_point(int edge, int end) const { return control[D + 2 * edge + end]; }
  Vec<D>& edge_point(int edge, int end) { return control[D + 2 * edge + end]; }
};

template <int D>
using PatchParameters = std::array<double, D - 1>;

// The local vertices of patch edge e (the curve's only edge, or the triangle's edges 01, 12, 20).
template <int D>
inline constexpr std::array<std::array<int, 2>, CubicPatch<D>::kEdges> kPatchEdges = [] {
  if constexpr (D == 2)
    return std::array<std::array<int, 2>, 1>{{{0, 1}}};
  else
    return std::array<std::array<int, 2>, 3>{{{0, 1}, {1, 2}, {2, 0}}};
}();

// Position, first derivatives (∂/∂λ_1, ...) and second derivatives (2D: tt; 3D: uu, uv, vv).
template <int D>
struct PatchJet {
  Vec<D> point;
  std::array<Vec<D>, D - 1> first;
  std::array<Vec<D>, D*(D - 1) / 2> second;
};

template <int D>
PatchJet<D> evaluate_jet(const CubicPatch<D>& patch, const PatchParameters<D>& parameters) {
  const auto& b = patch.control;
  PatchJet<D> jet;
  if constexpr (D == 2) {
    const double t = parameters[0], w = 1 - t;
    // Degree-2 and degree-1 de Casteljau points; S' = 3(l1 − l0), S'' = 6(q02 − 2 q11 + q20).
    const Vec2 q20 = w * b[0] + t * b[2], q11 = w * b[2] + t * b[3], q02 = w * b[3] + t * b[1];
    const Vec2 l0 = w * q20 + t * q11, l1 = w * q11 + t * q02;
    jet.point = w * l0 + t * l1;
    jet.first[0] = 3.0 * (l1 - l0);
    jet.second[0] = 6.0 * (q02 - 2.0 * q11 + q20);
  } else {
    const double u = parameters[0], v = parameters[1], w = 1 - u - v;
    // b[0..2] = b300 b030 b003; b[3..8] = b210 b120 b021 b012 b102 b201; b[9] = b111.
    const Vec3 q200 = w * b[0] + u * b[3] + v * b[8];
    const Vec3 q020 = w * b[4] + u * b[1] + v * b[5];
    const Vec3 q002 = w * b[7] + u * b[6] + v * b[2];
    const Vec3 q110 = w * b[3] + u * b[4] + v * b[9];
    const Vec3 q011 = w * b[9] + u * b[5] + v * b[6];
    const Vec3 q101 = w * b[8] + u * b[9] + v * b[7];
    const Vec3 l0 = w * q200 + u * q110 + v * q101;
    const Vec3 l1 = w * q110 + u * q020 + v * q011;
    const Vec3 l2 = w * q101 + u * q011 + v * q002;
    jet.point = w * l0 + u * l1 + v * l2;
    // ∂_a S = 3 l_a and ∂_a ∂_b S = 6 q_{e_a + e_b} in barycentrics; u and v move λ_0 the other way.
    jet.first[0] = 3.0 * (l1 - l0);
    jet.first[1] = 3.0 * (l2 - l0);
    jet.second[0] = 6.0 * (q020 - 2.0 * q110 + q200);
    jet.second[1] = 6.0 * (q011 - q110 - q101 + q200);
    jet.second[2] = 6.0 * (q002 - 2.0 * q101 + q200);
  }
  return jet;
}

template <int D>
Vec<D> evaluate(const CubicPatch<D>& patch, const PatchParameters<D>& parameters) {
  return evaluate_jet(patch, parameters).point;
}

// The point of the cubic curve of edge e at its parameter 1/2: (P_i + 3 b_ij + 3 b_ji + P_j) / 8.
template <int D>
Vec<D> edge_curve_midpoint(const CubicPatch<D>& patch, int edge) {
  const auto& ends = kPatchEdges<D>[edge];
  return (patch.vertex(ends[0]) + patch.vertex(ends[1]) + 3.0 * (patch.edge_point(edge, 0) + patch.edge_point(edge, 1))) * 0.125;
}

// How far along its tangent an edge control point goes: b_ij = P_i + d t_i, t_i the unit tangent
// at P_i toward P_j, e = P_j − P_i, cos α = (e·t_i) / |e|.
enum class TangentLength {
  // d = (e·t_i) / 3: the third of the edge projected on the tangent, docs/method.md §9's rule
  // b_ij = (2 P_i + P_j − (e·n_i) n_i) / 3. On a circular arc its midpoint errs by 9 r θ⁴ / 384.
  kProjectedThird,
  // d = 2 |e| / (3 (1 + cos α)) = |e| / (3 cos²(α/2)): a cubic with these end tangents reproduces
  // a circular arc to O(θ⁶) and meets its midpoint exactly; straight edges (α = 0) keep |e| / 3.
  kCircularArc,
};

// The edge control point at `from` toward `to` along the unit tangent t (t·(to − from) ≥ 0).
template <int D>
Vec<D> edge_control_point(const Vec<D>& from, const Vec<D>& to, const Vec<D>& tangent, TangentLength rule) {
  const Vec<D> edge = to - from;
  const double along = dot(edge, tangent);
  if (rule == TangentLength::kProjectedThird) return from + along / 3 * tangent;
  const double length = norm(edge);
  return length > 0 ? from + 2 * length / (3 * (1 + along / length)) * tangent : from;
}

// The unit tangent at `from` toward `to` in the plane of unit normal n: the edge projected on the
// plane (zero when the edge runs along the normal).
template <int D>
Vec<D> tangent_in_plane(const Vec<D>& from, const Vec<D>& to, const Vec<D>& normal) {
  const Vec<D> edge = to - from;
  const Vec<D> projected = edge - dot(edge, normal) * normal;
  const double length = norm(projected);
  return length > 0 ? projected * (1 / length) : Vec<D>{};
}

// The unit tangent along the line of direction `line` (unit), oriented toward `to`.
template <int D>
Vec<D> tangent_on_line(const Vec<D>& from, const Vec<D>& to, const Vec<D>& line) {
  return dot(to - from, line) < 0 ? -line : line;
}

// The triangle's centre b_111 = E + (E − V) / 2, E and V the means of its edge points and vertices
// (Farin's choice: it reproduces quadratic patches exactly and keeps planar patches planar).
inline void place_centre_control_point(CubicPatch<3>& patch) {
  Vec3 edge_mean{}, vertex_mean{};
  for (int i = 3; i < 9; ++i) edge_mean += patch.control[i];
  for (int i = 0; i < 3; ++i) vertex_mean += patch.control[i];
  edge_mean *= 1.0 / 6.0;
  vertex_mean *= 1.0 / 3.0;
  patch.control[9] = edge_mean + 0.5 * (edge_mean - vertex_mean);
}

}  // namespace hocav
