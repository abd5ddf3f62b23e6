// The mean-ratio quality of a straight simplex in a metric M (constant over the element, e.g. M at
// its centroid): the shape measure the adaptation literature reports next to the unit-edge share.
//   3D: Q = 36 / 3^(1/3) · V_M^(2/3) / Σ l_M²      2D: Q = 4√3 · A_M / Σ l_M²
// with V_M = √det(M) V (A_M = √det(M) A) the measure in the metric and l_M² = eᵀ M e over the edges.
// Q is 1 for a simplex that is regular in M (of any size), in (0, 1) otherwise, 0 for a flat one
// and negative for an inverted one (the signed measure), so that it is invariant under any affine
// map x ↦ A x + b that carries M to A⁻ᵀ M A⁻¹.
#pragma once

#include <array>

#include "geom/barycentric.hpp"
#include "geom/sym_mat.hpp"

namespace hocav {

template <int D>
double metric_mean_ratio(const SimplexPoints<D>& points, const SymMat<D>& metric);

// The same in the metric at the simplex's centroid, log-Euclidean from its vertices' log-metrics
// (exp of their mean): the straight element's quality `hocav stats` reports.
template <int D>
double centroid_metric_mean_ratio(const SimplexPoints<D>& points, const std::array<SymMat<D>, D + 1>& vertex_log_metrics);

}  // namespace hocav
