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
  Vec<D> gradient{};    // ∂ℓ/∂X (when asked)
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

// What an EdgeLengthFunction reuses between evaluations at the same point: the eigen-decompositions of
// T(t_q) at the last evaluated L^L(X) (rules of up to kCachedNodes nodes) and their Fréchet set-ups once
// made, so raising the order at the same point (the accepted trial of a line search) or asking a
// curvature there does not repeat them. The caller owns it (one per thread), so the function itself is
// immutable and may be shared by threads; a scratch last used by another function is not reused, and
// it does not outlive the functions it serves (one at the same address would take its contents).
template <int D>
struct EdgeLengthScratch {
  // The 3-point rules (the optimizer's): larger rules recompute at each evaluation. Made once per edge,
  // so it stays small; nothing is allocated.
  static constexpr std::size_t kCachedNodes = 3;
  std::array<LazySlot<ExpSpectrum<D>>, kCachedNodes> spectrum;
  std::array<LazySlot<ExpFrechet<D>>, kCachedNodes> frechet;
  SymMat<D> log_node{};
  const void* owner = nullptr;  // the function whose last point this is; none: nothing kept
};

// ℓ as a function of X for one edge and one quadrature rule; the parts that do not depend on X
// (the vertex metrics at nodes where φ_M = 0, i.e. t = 0 and 1) come with the endpoints. Each
// evaluation may take an EdgeLengthScratch to reuse the work of the previous one at the same point.
template <int D>
class EdgeLengthFunction {
 public:
  EdgeLengthFunction(const EdgeEndpoint<D>& a, const EdgeEndpoint<D>& b, const QuadratureRule& rule);
  EdgeLengthFunction(const Vec<D>& a, const Vec<D>& b, const SymMat<D>& log_a, const SymMat<D>& log_b, const QuadratureRule& rule)
      : EdgeLengthFunction(edge_endpoint(a, log_a), edge_endpoint(b, log_b), rule) {}

  enum class Order { kValue, kGradient, kHessian };
  // `log_node` = L^L(X), `log_node_gradient[i]` = ∂L^L/∂X_i (needed from Order::kGradient on).
  EdgeLengthValue<D> evaluate(const Vec<D>& node, const SymMat<D>& log_node, const std::array<SymMat<D>, D>& log_node_gradient, Order order,
                              EdgeLengthScratch<D>& scratch) const;
  double length(const Vec<D>& node, const SymMat<D>& log_node, EdgeLengthScratch<D>& scratch) const;
  // dᵀ ∂²ℓ/∂X² d, the curvature of ℓ along the line X + s·d, where `log_node_derivative` = Σ_i d_i ∂L^L/∂X_i:
  // one direction of the Hessian for a fraction of its cost (a step along a known direction needs no more).
  double curvature(const Vec<D>& node, const SymMat<D>& log_node, const Vec<D>& d, const SymMat<D>& log_node_derivative,
                   EdgeLengthScratch<D>& scratch) const;

  // The same, nothing reused.
  EdgeLengthValue<D> evaluate(const Vec<D>& node, const SymMat<D>& log_node, const std::array<SymMat<D>, D>& log_node_gradient,
                              Order order) const {
    EdgeLengthScratch<D> scratch;
    return evaluate(node, log_node, log_node_gradient, order, scratch);
  }
  double length(const Vec<D>& node, const SymMat<D>& log_node) const {
    EdgeLengthScratch<D> scratch;
    return length(node, log_node, scratch);
  }
  double curvature(const Vec<D>& node, const SymMat<D>& log_node, const Vec<D>& d, const SymMat<D>& log_node_derivative) const {
    EdgeLengthScratch<D> scratch;
    return curvature(node, log_node, d, log_node_derivative, scratch);
  }

  const Vec<D>& a() const { return a_.position; }
  const Vec<D>& b() const { return b_.position; }

 private:
  static constexpr std::size_t kCachedNodes = EdgeLengthScratch<D>::kCachedNodes;
  // Whether `scratch` holds this function's decompositions at L^L(X) = log_node.
  bool same_point(const EdgeLengthScratch<D>& scratch, const SymMat<D>& log_node) const {
    return scratch.owner == this && log_node == scratch.log_node;
  }
  // exp_spectrum(T(t_q)) at node q, from the scratch when at the same point.
  const ExpSpectrum<D>& spectrum_at(std::size_t q, const SymMat<D>& log_node, bool at_same_point, EdgeLengthScratch<D>& scratch,
                                    LazySlot<ExpSpectrum<D>>& uncached) const;
  // ExpFrechet of `spectrum`, the one spectrum_at just gave for node q: from the scratch when it was made at
  // the same point (a curvature after a gradient there).
  const ExpFrechet<D>& frechet_at(std::size_t q, const ExpSpectrum<D>& spectrum, EdgeLengthScratch<D>& scratch,
                                  LazySlot<ExpFrechet<D>>& uncached) const;
  // Marks the scratch as holding the decompositions at L^L(X) = log_node.
  void remember(const SymMat<D>& log_node, EdgeLengthScratch<D>& scratch) const;

  EdgeEndpoint<D> a_, b_;
  const QuadratureRule& rule_;
};

extern template class EdgeLengthFunction<2>;
extern template class EdgeLengthFunction<3>;

}  // namespace hocav
