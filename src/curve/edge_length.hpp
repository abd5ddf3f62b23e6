// Riemannian length of a P2 edge as a function of its Lagrange (mid) node X (math.md §3–6, eq 12):
//   ℓ(X) = Σ_q w_q sqrt(g(t_q)),  g(t) = γ'(t)ᵀ exp(T(t)) γ'(t),
//   γ'(t) = (4t−3)A + 4(1−2t)X + (4t−1)B,  T(t) = φ_A(t) L_A + φ_M(t) L^L + φ_B(t) L_B,
// with L_A, L_B the log-metrics of the edge's vertices and L^L the back-mesh log-metric at X. The
// metric is not re-interpolated at quadrature points: that keeps the closed form differentiable.
// Gradient and Hessian with respect to X use ∂L^L/∂X_i = Σ_j ∂_iλ_j R_j (constant in one back
// element) and the Fréchet derivatives of exp.
#pragma once

#include <array>
#include <vector>

#include "curve/quadrature.hpp"
#include "geom/sym_eigen.hpp"
#include "geom/sym_mat.hpp"
#include "geom/vec.hpp"

namespace hocav {

template <int D>
struct EdgeLengthValue {
  double length = 0;
  Vec<D> gradient{};   // ∂ℓ/∂X (when asked)
  SymMat<D> hessian{};  // ∂²ℓ/∂X² (when asked)
};

// ℓ as a function of X for one edge and one quadrature rule; the parts that do not depend on X
// (exp of the vertex metrics at nodes where φ_M = 0) are computed once, at construction. The
// eigen-decompositions of the last evaluation are kept, so raising the order at the same point (the
// accepted trial of a line search) does not repeat them: one object per thread.
template <int D>
class EdgeLengthFunction {
 public:
  EdgeLengthFunction(const Vec<D>& a, const Vec<D>& b, const SymMat<D>& log_a, const SymMat<D>& log_b,
                     const QuadratureRule& rule);

  enum class Order { kValue, kGradient, kHessian };
  // `log_node` = L^L(X), `log_node_gradient[i]` = ∂L^L/∂X_i (needed from Order::kGradient on).
  EdgeLengthValue<D> evaluate(const Vec<D>& node, const SymMat<D>& log_node,
                              const std::array<SymMat<D>, D>& log_node_gradient, Order order) const;
  double length(const Vec<D>& node, const SymMat<D>& log_node) const;

  const Vec<D>& a() const { return a_; }
  const Vec<D>& b() const { return b_; }

 private:
  Vec<D> a_, b_;
  SymMat<D> log_a_, log_b_;
  const QuadratureRule& rule_;
  std::vector<SymMat<D>> fixed_metrics_;  // exp(T(t_q)) where φ_M(t_q) = 0; unused elsewhere
  // sym_eigen(T(t_q)) where φ_M(t_q) ≠ 0 at the last evaluated L^L(X) (T depends on X only through it).
  mutable std::vector<SymEigen<D>> last_eigen_;
  mutable SymMat<D> last_log_node_;
  mutable bool has_last_ = false;
};

extern template class EdgeLengthFunction<2>;
extern template class EdgeLengthFunction<3>;

}  // namespace hocav
