// Bernstein (control) coefficients of the Jacobian determinant of a P2 triangle or tetrahedron
// (docs/method.md §8).
//
// J is a polynomial of degree D over the reference simplex, written in barycentrics λ_0..λ_D
// (reference axes ξ_k = λ_k, k ≥ 1):  J(λ) = Σ_{|γ| = D} N_γ B_γ(λ),  B_γ = (D!/γ!) λ^γ.
// The Bernstein polynomials are ≥ 0 and sum to 1, so min N ≤ J ≤ max N everywhere, and J is
// positive on the whole element as soon as every coefficient is.
//
// Coefficient order (kJacobianMultiIndices), corners first:
//   [0, D]   corner coefficients D·e_i, i = 0..D: J at vertex i, exactly;
//   2D [3, 5]   e_i + e_j for the edges (0,1) (1,2) (2,0): the same order as the P2 nodes;
//   3D [4, 15]  for each edge (i, j) in the P2 edge order (01, 12, 20, 03, 13, 23):
//               2e_i + e_j, then e_i + 2e_j;
//   3D [16, 19] e_j + e_k + e_l for the face opposite vertex 0, 1, 2, 3.
//
// Normalization: the normalized coefficients are N_γ / |det(P_1 − P_0, …)|. Dividing by the
// magnitude (not the signed straight Jacobian) keeps the sign of J: a straight element gives all
// coefficients +1 when positive and −1 when inverted, and a curved element that is valid although
// its straight counterpart is inverted (the paper's Fig. 9) keeps positive coefficients.
#pragma once

#include <array>

#include "bezier/p2_element.hpp"
#include "geom/barycentric.hpp"

namespace hocav {

template <int D>
inline constexpr int kJacobianDegree = D;  // D(n − 1) with n = 2

template <int D>
inline constexpr int kJacobianCoefficientCount = D == 2 ? 6 : 20;  // binomial(2D, D)

// A distinct type (not an alias of std::array) so that D is deduced in calls.
template <int D>
struct JacobianCoefficients : std::array<double, kJacobianCoefficientCount<D>> {};

template <int D>
using BernsteinMultiIndex = std::array<int, D + 1>;

namespace detail {

template <int D>
constexpr std::array<BernsteinMultiIndex<D>, kJacobianCoefficientCount<D>> make_jacobian_multi_indices() {
  std::array<BernsteinMultiIndex<D>, kJacobianCoefficientCount<D>> indices{};
  int next = 0;
  for (int i = 0; i <= D; ++i) indices[next++][i] = D;
  for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
    const auto& ends = edge_vertices<D>(edge);
    if constexpr (D == 2) {
      indices[next][ends[0]] = 1;
      indices[next++][ends[1]] = 1;
    } else {
      indices[next][ends[0]] = 2;
      indices[next++][ends[1]] = 1;
      indices[next][ends[0]] = 1;
      indices[next++][ends[1]] = 2;
    }
  }
  if constexpr (D == 3)
    for (int face = 0; face <= D; ++face, ++next)
      for (int i = 0; i <= D; ++i) indices[next][i] = i == face ? 0 : 1;
  return indices;
}

}  // namespace detail

template <int D>
inline constexpr auto kJacobianMultiIndices = detail::make_jacobian_multi_indices<D>();

// Position of multi-index γ (|γ| = D) in the coefficient order.
template <int D>
constexpr int jacobian_coefficient_index(const BernsteinMultiIndex<D>& gamma) {
  for (int position = 0; position < kJacobianCoefficientCount<D>; ++position)
    if (kJacobianMultiIndices<D>[position] == gamma) return position;
  return -1;
}

// J of one element: its coefficients and what is needed to read them.
template <int D>
struct ElementJacobian {
  JacobianCoefficients<D> coefficients{};  // N_γ in the order above, not normalized
  double straight_jacobian = 0.0;          // det(P_1 − P_0, …); normalization divides by its magnitude
  // An upper bound of the rounding error of the coefficients and of their subdivisions:
  // 1024 u (L^D + max |N_γ|), u = 2^-53, L the largest coordinate offset of a node from vertex 0.
  // (Everything is computed from offsets to vertex 0, so the error scales with the element, not
  // with its distance to the origin; measured errors stay below 40 u L^D.)
  double rounding_margin = 0.0;
};

template <int D>
ElementJacobian<D> element_jacobian(const P2Element<D>& element);

template <int D>
JacobianCoefficients<D> jacobian_coefficients(const P2Element<D>& element) {
  return element_jacobian(element).coefficients;
}

// N_γ / |det(P_1 − P_0, …)|; see normalize_jacobian for a flat straight element.
template <int D>
JacobianCoefficients<D> normalized_jacobian_coefficients(const P2Element<D>& element);

// value / |straight_jacobian|. When the straight element is flat (all vertices on a line or plane,
// possible for a valid curved element) the ratio is +inf, −inf or 0 by the sign of value.
double normalize_jacobian(double value, double straight_jacobian);

// Σ N_γ B_γ(λ): the polynomial the coefficients stand for, at barycentrics λ.
template <int D>
double evaluate_bernstein(const JacobianCoefficients<D>& coefficients, const Barycentrics<D>& lambda);

}  // namespace hocav
