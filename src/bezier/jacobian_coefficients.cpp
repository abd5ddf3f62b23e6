// Bernstein coefficients of the Jacobian of a P2 simplex (docs/method.md §8).
//
// F(λ) = Σ_{|α|=2} (2/α!) λ^α C_α, so ∂F/∂ξ_k = 2 Σ_i λ_i d_ik with d_ik = C_{e_i+e_k} − C_{e_i+e_0}
// (the a_i, b_i, c_i of docs/method.md §8 for k = 1, 2, 3). Expanding the determinant multilinearly,
//   J = 2^D Σ_{i,j(,k)} λ_i λ_j (λ_k) det(a_i, b_j(, c_k)),
// and a monomial λ^γ is (γ!/D!) B_γ, hence N_γ = 2^D (γ!/D!) Σ det(...) over the index tuples whose
// multiset is γ:
//   2D  N_{2e_i} = 4 det(a_i, b_i),  N_{e_i+e_j} = 2 [det(a_i, b_j) + det(a_j, b_i)];
//   3D  with S_jj = b_j × c_j and S_jk = b_j × c_k + b_k × c_j (the sum over both orders),
//       N_{3e_i} = 8 a_i·S_ii,  N_{2e_i+e_j} = 8/3 [a_i·S_ij + a_j·S_ii],
//       N_{e_i+e_j+e_k} = 4/3 [a_i·S_jk + a_j·S_ik + a_k·S_ij]:
//       16 cross and 40 dot products per tetrahedron.
#include "bezier/jacobian_coefficients.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hocav {
namespace {

constexpr int factorial(int n) { return n <= 1 ? 1 : n * factorial(n - 1); }

}  // namespace

template <int D>
ElementJacobian<D> element_jacobian(const P2Element<D>& element) {
  // Work on offsets from vertex 0, exact to one rounding of their own size: in absolute coordinates
  // the rounding of the control nodes scales with the distance to the origin, not with the element.
  P2Element<D> local = element;
  double extent = 0.0;
  for (Vec<D>& node : local.nodes) {
    node -= element.vertex(0);
    for (int r = 0; r < D; ++r) extent = std::max(extent, std::abs(node[r]));
  }
  ElementJacobian<D> result;
  result.straight_jacobian = straight_jacobian(local);
  const BezierControlNet<D> net = control_net(local);
  // d[k - 1][i] = d_ik: the control vectors of ∂F/∂ξ_k (halved): a = d[0], b = d[1], c = d[2].
  std::array<std::array<Vec<D>, D + 1>, D> d;
  for (int k = 1; k <= D; ++k)
    for (int i = 0; i <= D; ++i) d[k - 1][i] = net.of_pair(i, k) - net.of_pair(i, 0);

  // Written family by family in the order of kJacobianMultiIndices: corners, edges, faces.
  JacobianCoefficients<D>& coefficients = result.coefficients;
  if constexpr (D == 2) {
    for (int i = 0; i <= D; ++i) coefficients[i] = 4 * determinant(d[0][i], d[1][i]);
    for (int edge = 0; edge < Simplex<2>::kEdges; ++edge) {
      const int i = edge_vertices<2>(edge)[0], j = edge_vertices<2>(edge)[1];
      coefficients[D + 1 + edge] = 2 * (determinant(d[0][i], d[1][j]) + determinant(d[0][j], d[1][i]));
    }
  } else {
    // S in the layout of the P2 nodes: S_jj at vertex j, S_jk at the node of edge {j, k}.
    std::array<Vec3, kP2NodeCount<3>> s;
    for (int j = 0; j <= D; ++j) s[j] = cross(d[1][j], d[2][j]);
    for (int edge = 0; edge < Simplex<3>::kEdges; ++edge) {
      const int j = edge_vertices<3>(edge)[0], k = edge_vertices<3>(edge)[1];
      s[D + 1 + edge] = cross(d[1][j], d[2][k]) + cross(d[1][k], d[2][j]);
    }
    const auto& a = d[0];
    for (int i = 0; i <= D; ++i) coefficients[i] = 8 * dot(a[i], s[i]);
    for (int edge = 0; edge < Simplex<3>::kEdges; ++edge) {
      const int i = edge_vertices<3>(edge)[0], j = edge_vertices<3>(edge)[1];
      const Vec3& s_ij = s[D + 1 + edge];
      coefficients[D + 1 + 2 * edge] = (8.0 / 3) * (dot(a[i], s_ij) + dot(a[j], s[i]));
      coefficients[D + 2 + 2 * edge] = (8.0 / 3) * (dot(a[j], s_ij) + dot(a[i], s[j]));
    }
    for (int face = 0; face <= D; ++face) {
      const auto& [i, j, k] = face_vertices<3>(face);
      coefficients[kJacobianCoefficientCount<3> - 4 + face] = (4.0 / 3) * (dot(a[i], s[p2_node_of_pair<3>(j, k)]) +
                                                                           dot(a[j], s[p2_node_of_pair<3>(i, k)]) +
                                                                           dot(a[k], s[p2_node_of_pair<3>(i, j)]));
    }
  }

  double magnitude = 0.0, extent_power = 1.0;
  for (double coefficient : coefficients) magnitude = std::max(magnitude, std::abs(coefficient));
  for (int r = 0; r < D; ++r) extent_power *= extent;
  constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;
  result.rounding_margin = 1024 * kUnitRoundoff * (extent_power + magnitude);
  return result;
}

double normalize_jacobian(double value, double straight_jacobian) {
  const double scale = std::abs(straight_jacobian);
  if (scale > 0.0) return value / scale;
  if (value == 0.0) return 0.0;
  return std::copysign(std::numeric_limits<double>::infinity(), value);
}

template <int D>
JacobianCoefficients<D> normalized_jacobian_coefficients(const P2Element<D>& element) {
  ElementJacobian<D> jacobian = element_jacobian(element);
  for (double& coefficient : jacobian.coefficients) coefficient = normalize_jacobian(coefficient, jacobian.straight_jacobian);
  return jacobian.coefficients;
}

template <int D>
double evaluate_bernstein(const JacobianCoefficients<D>& coefficients, const Barycentrics<D>& lambda) {
  double sum = 0.0;
  for (int position = 0; position < kJacobianCoefficientCount<D>; ++position) {
    double basis = factorial(D);
    for (int i = 0; i <= D; ++i) {
      const int power = kJacobianMultiIndices<D>[position][i];
      basis *= std::pow(lambda[i], power) / factorial(power);
    }
    sum += coefficients[position] * basis;
  }
  return sum;
}

template ElementJacobian<2> element_jacobian(const P2Element<2>&);
template ElementJacobian<3> element_jacobian(const P2Element<3>&);
template JacobianCoefficients<2> normalized_jacobian_coefficients(const P2Element<2>&);
template JacobianCoefficients<3> normalized_jacobian_coefficients(const P2Element<3>&);
template double evaluate_bernstein(const JacobianCoefficients<2>&, const Barycentrics<2>&);
template double evaluate_bernstein(const JacobianCoefficients<3>&, const Barycentrics<3>&);

}  // namespace hocav
