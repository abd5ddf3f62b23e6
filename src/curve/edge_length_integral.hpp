// ℓ of a P2 edge as an integral along the curve, ∫₀¹ sqrt(γ'(t)ᵀ M(t) γ'(t)) dt (docs/method.md §3, §5), by a
// fixed rule or adaptively to a tolerance, under either metric model:
// - interpolated: log M(t) = φ_A(t) L_A + φ_M(t) L^L + φ_B(t) L_B with L^L the back-mesh log-metric at the
//   node, the closed form of eq 12 that the optimizer minimizes (smooth in t);
// - localized ("true" length): every point γ(t) is localized in the back mesh and its log-metric
//   interpolated there (piecewise smooth in t: kinks where the curve crosses back-mesh faces).
#pragma once

#include "curve/quadrature.hpp"
#include "metric/metric_field.hpp"

namespace hocav {

// The "true" Riemannian length of the curve by a fixed rule: a diagnostic (docs/method.md §5).
template <int D>
double true_edge_length(const MetricField<D>& field, const Vec<D>& a, const Vec<D>& b, const Vec<D>& node, const QuadratureRule& rule);

// The same to a relative tolerance (adaptive Gauss–Kronrod).
template <int D>
AdaptiveIntegral adaptive_true_edge_length(const MetricField<D>& field, const Vec<D>& a, const Vec<D>& b, const Vec<D>& node,
                                           double tolerance);

// The interpolated model (vertex log-metrics log_a, log_b; L^L localized at the node from `hint`) to a
// relative tolerance.
template <int D>
AdaptiveIntegral adaptive_edge_length(const MetricField<D>& field, const Vec<D>& a, const Vec<D>& b, const SymMat<D>& log_a,
                                      const SymMat<D>& log_b, const Vec<D>& node, double tolerance, Index hint = kNoIndex);

}  // namespace hocav
