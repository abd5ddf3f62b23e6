#include "curve/curved_quality.hpp"

#include <cmath>

#include "geom/mat.hpp"
#include "geom/sym_functions.hpp"

namespace hocav {
namespace {

template <int D>
double determinant(const Mat<D>& a) {
  if constexpr (D == 2)
    return hocav::determinant(a.column(0), a.column(1));
  else
    return hocav::determinant(a.column(0), a.column(1), a.column(2));
}

// The cofactor matrix, det(a) a⁻ᵀ: the derivative of det(a) with respect to a. Its columns are the
// gradients of det(a) with respect to a's columns (in 3D the cross products of the other two).
template <int D>
Mat<D> cofactors(const Mat<D>& a) {
  Mat<D> c;
  if constexpr (D == 2) {
    c.set_column(0, Vec2{{a(1, 1), -a(0, 1)}});
    c.set_column(1, Vec2{{-a(1, 0), a(0, 0)}});
  } else {
    for (int j = 0; j < 3; ++j) c.set_column(j, cross(a.column((j + 1) % 3), a.column((j + 2) % 3)));
  }
  return c;
}

template <int D>
Mat<D> full(const SymMat<D>& s) {
  Mat<D> a;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) a(i, j) = s(i, j);
  return a;
}

// W⁻¹, W the map from the reference simplex (vertices 0, e_1 … e_D) to the regular simplex with
// unit edges, and det W: a Jacobian J is judged by S = M^½ J W⁻¹, which is a rotation times a
// scale exactly when the element is regular in M.
template <int D>
struct RegularSimplex {
  Mat<D> inverse;
  double det;
};
template <int D>
RegularSimplex<D> regular_simplex() {
  Mat<D> w;
  if constexpr (D == 2) {
    w(0, 0) = 1, w(0, 1) = 0.5, w(1, 1) = std::sqrt(3.0) / 2;
  } else {
    w(0, 0) = 1, w(0, 1) = 0.5, w(0, 2) = 0.5;
    w(1, 1) = std::sqrt(3.0) / 2, w(1, 2) = std::sqrt(3.0) / 6;
    w(2, 2) = std::sqrt(2.0 / 3.0);
  }
  const double det = determinant(w);
  Mat<D> inverse = transpose(cofactors(w));
  for (double& x : inverse.entries) x /= det;
  return {inverse, det};
}

// Points with positive weights, exact for degree 2 (the Jacobian of a P2 element is linear): the
// 3-point rule of the triangle and the 4-point rule of the tetrahedron; barycentric coordinates.
template <int D>
struct SimplexRule {
  std::array<std::array<double, D + 1>, D + 1> points;
  double weight;
};
template <int D>
SimplexRule<D> degree_two_rule() {
  SimplexRule<D> rule;
  const double a = D == 2 ? 2.0 / 3.0 : 0.5854101966249685, b = (1 - a) / D;
  for (int q = 0; q <= D; ++q)
    for (int i = 0; i <= D; ++i) rule.points[q][i] = i == q ? a : b;
  rule.weight = 1.0 / (D + 1);
  return rule;
}

// ∂N_n/∂ξ_b of the P2 shape functions at barycentric point λ (ξ_b = λ_b for b ≥ 1, λ_0 = 1 − Σ ξ).
template <int D>
std::array<Vec<D>, kP2NodeCount<D>> shape_gradients(const std::array<double, D + 1>& lambda) {
  const auto dlambda = [](int i) {  // ∂λ_i/∂ξ
    Vec<D> g;
    for (int b = 0; b < D; ++b) g[b] = i == 0 ? -1.0 : (i == b + 1 ? 1.0 : 0.0);
    return g;
  };
  std::array<Vec<D>, kP2NodeCount<D>> g;
  for (int i = 0; i <= D; ++i) g[static_cast<std::size_t>(i)] = (4 * lambda[i] - 1) * dlambda(i);
  for (int e = 0; e < Simplex<D>::kEdges; ++e) {
    const auto& ends = edge_vertices<D>(e);
    g[static_cast<std::size_t>(D + 1 + e)] = 4 * lambda[ends[0]] * dlambda(ends[1]) + 4 * lambda[ends[1]] * dlambda(ends[0]);
  }
  return g;
}

}  // namespace

template <int D>
CurvedQuality<D> curved_mean_ratio(const P2Element<D>& element, const std::array<SymMat<D>, D + 1>& vertex_log_metrics) {
  static const RegularSimplex<D> regular = regular_simplex<D>();
  static const SimplexRule<D> rule = degree_two_rule<D>();
  const Mat<D> wwt = regular.inverse * transpose(regular.inverse);  // W⁻¹ W⁻ᵀ
  CurvedQuality<D> out;
  for (const auto& lambda : rule.points) {
    SymMat<D> log_metric;
    for (int i = 0; i <= D; ++i) log_metric += lambda[i] * vertex_log_metrics[static_cast<std::size_t>(i)];
    const Mat<D> metric = full(exp_sym(log_metric));
    const auto dn = shape_gradients<D>(lambda);
    Mat<D> jacobian;  // J_ab = ∂x_a/∂ξ_b
    for (std::size_t n = 0; n < dn.size(); ++n)
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) jacobian(a, b) += element.nodes[n][a] * dn[n][b];
    // η = D d^(2/D) / N, d = √det M det J / det W (signed), N = tr(W⁻ᵀ Jᵀ M J W⁻¹) = tr(M J W⁻¹W⁻ᵀ Jᵀ).
    const Mat<D> mjw = metric * jacobian * wwt;  // ∂N/∂J = 2 M J W⁻¹ W⁻ᵀ
    double n_value = 0;
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) n_value += mjw(a, b) * jacobian(a, b);
    const double det_j = determinant(jacobian);
    const double d = std::sqrt(determinant(metric)) * det_j / regular.det;
    const double eta = D * std::copysign(std::pow(std::abs(d), 2.0 / D), d) / n_value;
    out.value += rule.weight * eta;
    // ∂η/∂J = η (2/D J⁻ᵀ − 2 M J W⁻¹W⁻ᵀ / N); J⁻ᵀ = cofactors / det J.
    const Mat<D> cof = cofactors(jacobian);
    Mat<D> deta;
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) deta(a, b) = eta * (2.0 / D * cof(a, b) / det_j - 2 * mjw(a, b) / n_value);
    for (std::size_t n = 0; n < dn.size(); ++n) out.gradient[n] = out.gradient[n] + rule.weight * (deta * dn[n]);
  }
  return out;
}

template CurvedQuality<2> curved_mean_ratio(const P2Element<2>&, const std::array<SymMat<2>, 3>&);
template CurvedQuality<3> curved_mean_ratio(const P2Element<3>&, const std::array<SymMat<3>, 4>&);

}  // namespace hocav
