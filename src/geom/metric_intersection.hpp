// Intersection of two metrics by simultaneous reduction (docs/method.md §1; used by gradation and to combine metric
// fields, §10). With P the eigenvectors of M1⁻¹M2 and μ_i = max(p_iᵀM1p_i, p_iᵀM2p_i),
// M1∩M2 = P⁻ᵀ diag(μ) P⁻¹: |v|_{M1∩M2} ≥ max(|v|_M1, |v|_M2) for every v, with equality along each p_i,
// so its unit ball is the largest ellipsoid of that family inside both unit balls.
//
// Accuracy: M1∩M2 ≥ M1 and ≥ M2 to a few eps·‖M1∩M2‖ (min eigenvalue of the difference) whatever the
// conditioning; M∩M = M and M1∩M2 = M2∩M1 to about 8 eps·sqrt(κ)·‖M1∩M2‖, κ the larger λmax/λmin of the
// inputs; diagonal inputs give the entrywise maximum to rounding.
#pragma once

#include "geom/sym_mat.hpp"

namespace hocav {

// M1∩M2 for SPD M1, M2; throws Error when is_spd fails for either (a non-SPD M2 that rounding of the reduction
// makes look SPD, possible only near κ = 1/eps, is accepted).
template <int D>
SymMat<D> intersect_metrics(const SymMat<D>& m1, const SymMat<D>& m2);

}  // namespace hocav
