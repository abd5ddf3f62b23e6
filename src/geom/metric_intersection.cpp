// Metric intersection by simultaneous reduction (docs/method.md §1).
#include "geom/metric_intersection.hpp"

#include <cmath>

#include "base/error.hpp"
#include "geom/sym_eigen.hpp"
#include "geom/sym_functions.hpp"

namespace hocav {

template <int D>
SymMat<D> intersect_metrics(const SymMat<D>& m1, const SymMat<D>& m2) {
  // The reduction is done in the eigenbasis of M1 = V Λ Vᵀ (Jacobi, so Λ keeps its small entries), where
  // Λ^{-1/2} is a diagonal scaling rather than an explicit, ill-conditioned matrix M1^{-1/2}.
  SymEigen<D> first = spd_eigen(m1);
  if (!is_positive_definite(first)) throw Error("intersect_metrics: the first metric is not positive definite");
  Vec<D> sqrt_values;
  for (int k = 0; k < D; ++k) sqrt_values[k] = std::sqrt(first.values[k]);
  // M2 in the basis where M1 is the identity: N = Λ^{-1/2} Vᵀ M2 V Λ^{-1/2}, congruent to M2 (same signs).
  SymMat<D> reduced = congruence_transposed(first.vectors, m2);
  for (int i = 0; i < D; ++i)
    for (int j = 0; j <= i; ++j) reduced(i, j) /= sqrt_values[i] * sqrt_values[j];
  SymEigen<D> relative = spd_eigen(reduced);
  // N has the signs of M2's eigenvalues; ask is_spd itself only in the rare case N looks indefinite, which rounding
  // can cause for an SPD M2 near κ = 1/eps (its directions with ν ≤ 0 < 1 are then simply not grown).
  if (!is_positive_definite(relative) && !is_spd(m2)) throw Error("intersect_metrics: the second metric is not positive definite");
  // N = Q diag(ν) Qᵀ gives p_k = V Λ^{-1/2} q_k, p_kᵀM1p_k = 1, p_kᵀM2p_k = ν_k, hence
  // M1∩M2 = M1 + Σ_k (ν_k − 1)⁺ w_k w_kᵀ with w_k = V Λ^{1/2} q_k. Adding PSD terms to M1 itself keeps the
  // result ≥ M1 to rounding however ill-conditioned M1 is, and returns M1 unchanged when M2 ≤ M1.
  SymMat<D> result = m1;
  for (int k = 0; k < D; ++k) {
    double growth = relative.values[k] - 1.0;
    if (growth <= 0.0) continue;
    Vec<D> scaled;
    for (int i = 0; i < D; ++i) scaled[i] = sqrt_values[i] * relative.vectors(i, k);
    result += growth * outer(first.vectors * scaled);
  }
  return result;
}

template SymMat<2> intersect_metrics(const SymMat<2>&, const SymMat<2>&);
template SymMat<3> intersect_metrics(const SymMat<3>&, const SymMat<3>&);

}  // namespace hocav
