// Bernstein coefficients of the Jacobian of a P2 simplex (math.md §8).
//
// F(λ) = Σ_{|α|=2} (2/α!) λ^α C_α, so ∂F/∂ξ_k = 2 Σ_i λ_i d_ik with d_ik = C_{e_i+e_k} − C_{e_i+e_0}
// (the a_i, b_i, c_i of math.md for k = 1, 2, 3). Expanding the determinant multilinearly,
//   J = 2^D Σ_{i,j(,k)} λ_i λ_j (λ_k) det(d_i1, d_j2(, d_k3)),
// and a monomial λ^γ is (γ!/D!) B_γ, hence N_γ = 2^D (γ!/D!) Σ det(...) over the index tuples
// whose multiset is γ.
#include "bezier/jacobian_coefficients.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hocav {
namespace {

constexpr int factorial(int n) { return n <= 1 ? 1 : n * factorial(n - 1); }

// 2^D γ!/D! for every coefficient.
template <int D>
constexpr JacobianCoefficients<D> make_tuple_weights() {
  JacobianCoefficients<D> weights{};
  for (int position = 0; position < kJacobianCoefficientCount<D>; ++position) {
    int gamma_factorial = 1;
    for (int count : kJacobianMultiIndices<D>[position]) gamma_factorial *= factorial(count);
    weights[position] = double(1 << D) * gamma_factorial / factorial(D);
  }
  return weights;
}

// Coefficient position of e_i + e_j + e_k (3D) and of e_i + e_j (2D, k unused).
template <int D>
constexpr std::array<std::array<std::array<int, D + 1>, D + 1>, D + 1> make_tuple_positions() {
  std::array<std::array<std::array<int, D + 1>, D + 1>, D + 1> positions{};
  for (int i = 0; i <= D; ++i)
    for (int j = 0; j <= D; ++j)
      for (int k = 0; k <= D; ++k) {
        BernsteinMultiIndex<D> gamma{};
        ++gamma[i];
        ++gamma[j];
        if constexpr (D == 3) ++gamma[k];
        positions[i][j][k] = jacobian_coefficient_index<D>(gamma);
      }
  return positions;
}

template <int D>
constexpr auto kTupleWeights = make_tuple_weights<D>();
template <int D>
constexpr auto kTuplePositions = make_tuple_positions<D>();

}  // namespace

template <int D>
JacobianCoefficients<D> jacobian_coefficients(const P2Element<D>& element) {
  // Work on offsets from vertex 0, exact to one rounding of their own size: in absolute coordinates
  // the rounding of the control nodes scales with the distance to the origin, not with the element.
  P2Element<D> local = element;
  for (Vec<D>& node : local.nodes) node -= element.vertex(0);
  const BezierControlNet<D> net = control_net(local);
  // derivative[k - 1][i] = d_ik: the control vectors of ∂F/∂ξ_k (halved).
  std::array<std::array<Vec<D>, D + 1>, D> derivative;
  for (int k = 1; k <= D; ++k)
    for (int i = 0; i <= D; ++i) derivative[k - 1][i] = net.of_pair(i, k) - net.of_pair(i, 0);

  JacobianCoefficients<D> coefficients{};
  if constexpr (D == 2) {
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j <= D; ++j)
        coefficients[kTuplePositions<D>[i][j][0]] += determinant(derivative[0][i], derivative[1][j]);
  } else {
    // det(a_i, b_j, c_k) = a_i · (b_j × c_k): 16 cross products shared by the 64 triples.
    for (int j = 0; j <= D; ++j)
      for (int k = 0; k <= D; ++k) {
        const Vec3 normal = cross(derivative[1][j], derivative[2][k]);
        for (int i = 0; i <= D; ++i) coefficients[kTuplePositions<D>[i][j][k]] += dot(derivative[0][i], normal);
      }
  }
  for (int position = 0; position < kJacobianCoefficientCount<D>; ++position)
    coefficients[position] *= kTupleWeights<D>[position];
  return coefficients;
}

double normalize_jacobian(double value, double straight_jacobian) {
  const double scale = std::abs(straight_jacobian);
  if (scale > 0.0) return value / scale;
  if (value == 0.0) return 0.0;
  return std::copysign(std::numeric_limits<double>::infinity(), value);
}

template <int D>
JacobianCoefficients<D> normalized_jacobian_coefficients(const P2Element<D>& element) {
  JacobianCoefficients<D> coefficients = jacobian_coefficients(element);
  const double straight = straight_jacobian(element);
  for (double& coefficient : coefficients) coefficient = normalize_jacobian(coefficient, straight);
  return coefficients;
}

template <int D>
double jacobian_rounding_margin(const P2Element<D>& element, const JacobianCoefficients<D>& coefficients) {
  double extent = 0.0, magnitude = 0.0;
  for (const Vec<D>& node : element.nodes)
    for (int r = 0; r < D; ++r) extent = std::max(extent, std::abs(node[r] - element.vertex(0)[r]));
  for (double coefficient : coefficients) magnitude = std::max(magnitude, std::abs(coefficient));
  constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;
  return 1024 * kUnitRoundoff * (std::pow(extent, D) + magnitude);
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

template JacobianCoefficients<2> jacobian_coefficients(const P2Element<2>&);
template JacobianCoefficients<3> jacobian_coefficients(const P2Element<3>&);
template JacobianCoefficients<2> normalized_jacobian_coefficients(const P2Element<2>&);
template JacobianCoefficients<3> normalized_jacobian_coefficients(const P2Element<3>&);
template double jacobian_rounding_margin(const P2Element<2>&, const JacobianCoefficients<2>&);
template double jacobian_rounding_margin(const P2Element<3>&, const JacobianCoefficients<3>&);
template double evaluate_bernstein(const JacobianCoefficients<2>&, const Barycentrics<2>&);
template double evaluate_bernstein(const JacobianCoefficients<3>&, const Barycentrics<3>&);

}  // namespace hocav
