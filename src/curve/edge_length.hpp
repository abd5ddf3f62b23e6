// Riemannian length of a P2 edge as a function of its Lagrange (mid) node X (docs/method.md §3–6, eq 12):
//   ℓ(X) = Σ_q w_q sqrt(g(t_q)),  g(t) = γ'(t)ᵀ exp(T(t)) γ'(t),
//   γ'(t) = (4t−3)A + 4(1−2t)X + (4t−1)B,  T(t) = φ_A(t) L_A + φ_M(t) L^L + φ_B(t) L_B,
// with L_A, L_B the log-metrics of the edge's vertices and L^L the back-mesh log-metric at X. The
// metric is not re-interpolated at quadrature points: that keeps the closed form differentiable.
// Gradient and Hessian with respect to X use ∂L^L/∂X_i = Σ_j ∂_iλ_j R_j (constant in one back
// element) and the Fréchet derivatives of exp.
#pragma once

#include <array>

#include "base/lazy_slot.hpp"
#include "curve/quadrature.hpp"
#include "geom/sym_functions.hpp"
#include "geom/sym_mat.hpp"
#include "geom/vec.hpp"

namespace hocav {

template <int D>
struct EdgeLengthValue {
  double length = 0;
  Vec<D> gradient{};   // ∂ℓ/∂X (when asked)
  SymMat<D> hessian{};  // ∂²ℓ/∂X² (when asked)
  // With the gradient, its two parts: ∂ℓ/∂X with L^L held fixed, and ∂ℓ/∂L^L with X held fixed, so that
  // gradient_i = node_gradient_i + ⟨log_node_gradient, ∂L^L/∂X_i⟩. Where L^L(X) has a kink (a back-mesh
  // face), each side's ∂L^L/∂X gives that side's one-sided derivatives.
  Vec<D> node_gradient{};
  SymMat<D> log_node_gradient{};
};

// An edge's vertex with its metric: exp(log_metric), the metric at the nodes t = 0, 1 of rules that
// have them. A caller curving many edges around one vertex makes it once (docs/method.md §4).
template <int D>
struct EdgeEndpoint {
  Vec<D> position{};
  SymMat<D> log_metric{};
  SymMat<D> metric{};
};
template <int D>
EdgeEndpoint<D> edge_endpoint(const Vec<D>& position, const SymMat<D>& log_metric);

// ℓ as a function of X for one edge and one quadrature rule; the parts that do not depend on X
// (the vertex metrics at nodes where φ_M = 0, i.e. t = 0 and 1) come with the endpoints. The
// eigen-decompositions of the last evaluation are kept (rules of up to kCachedNodes nodes), and their
// Fréchet set-ups once made, so raising the order at the same point (the accepted trial of a line
// search) or asking a curvature there does not repeat them: one object per thread. Nothing is allocated: the optimizer makes one object per edge.
template <int D>
class EdgeLengthFunction {
 public:
  EdgeLengthFunction(const EdgeEndpoint<D>& a, const EdgeEndpoint<D>& b, const QuadratureRule& rule);
  EdgeLengthFunction(const Vec<D>& a, const Vec<D>& b, const SymMat<D>& log_a, const SymMat<D>& log_b,
                     const QuadratureRule& rule)
      : EdgeLengthFunction(edge_endpoint(a, log_a), edge_endpoint(b, log_b), rule) {}

  enum class Order { kValue, kGradient, kHessian };
  // `log_node` = L^L(X), `log_node_gradient[i]` = ∂L^L/∂X_i (needed from Order::kGradient on).
  EdgeLengthValue<D> evaluate(const Vec<D>& node, const SymMat<D>& log_node,
                              const std::array<SymMat<D>, D>& log_node_gradient, Order order) const;
  double length(const Vec<D>& node, const SymMat<D>& log_node) const;
  // dᵀ ∂²ℓ/∂X² d, the curvature of ℓ along the line X + s·d, where `log_node_derivative` = Σ_i d_i ∂L^L/∂X_i:
  // one direction of the Hessian for a fraction of its cost (a step along a known direction needs no more).
  double curvature(const Vec<D>& node, const SymMat<D>& log_node, const Vec<D>& d,
                   const SymMat<D>& log_node_derivative) const;

  const Vec<D>& a() const { return a_.position; }
  const Vec<D>& b() const { return b_.position; }

  // The 3-point rules (the optimizer's): larger rules recompute at each evaluation. The cache is part of
  // the object, made once per edge, so it stays small.
  static constexpr std::size_t kCachedNodes = 3;

 private:
  // exp_spectrum(T(t_q)) at node q, from the cache when L^L(X) is the last one evaluated.
  const ExpSpectrum<D>& spectrum_at(std::size_t q, const SymMat<D>& log_node, bool same_point,
                                    LazySlot<ExpSpectrum<D>>& scratch) const;
  // ExpFrechet of `spectrum`, the one spectrum_at just gave for node q: from the cache when it was made at the
  // same point (a curvature after a gradient there).
  const ExpFrechet<D>& frechet_at(std::size_t q, const ExpSpectrum<D>& spectrum,
                                  LazySlot<ExpFrechet<D>>& scratch) const;
  // Remembers L^L(X) as the point of the cached decompositions.
  void remember(const SymMat<D>& log_node) const;

  EdgeEndpoint<D> a_, b_;
  const QuadratureRule& rule_;
  // exp_spectrum(T(t_q)) where φ_M(t_q) ≠ 0 at the last evaluated L^L(X) (T depends on X only through it).
  mutable std::array<LazySlot<ExpSpectrum<D>>, kCachedNodes> last_spectrum_;
  mutable std::array<LazySlot<ExpFrechet<D>>, kCachedNodes> last_frechet_;
  mutable SymMat<D> last_log_node_;
  mutable bool has_last_ = false;
};

extern template class EdgeLengthFunction<2>;
extern template class EdgeLengthFunction<3>;

}  // namespace hocav
