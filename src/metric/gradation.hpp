// Size gradation (docs/method.md §10): bounds how fast the sizes of a metric field may grow along the
// mesh edges, so that a small size somewhere spreads into its surroundings instead of ending in a
// jump. This is the "metric-space" homogeneous gradation of F. Alauzet, "Size gradation control of
// anisotropic meshes", Finite Elements in Analysis and Design 46 (2010) 181–202,
// doi:10.1016/j.finel.2009.06.028, eq. (9) (the form NASA refine's ref_metric_metric_space_gradation
// also implements): the metric of p, grown to a point q, is
//   M_p(q) = η(ℓ) M_p,  η(ℓ) = (1 + ℓ log β)⁻²,  ℓ = sqrt(pqᵀ M_p pq) the length of pq in M_p,
// every size of M_p multiplied by 1 + ℓ log β, its anisotropy kept. Each end of each edge is then
// limited by the other's grown metric, M_q ← M_q ∩ M_p(q) (metric intersection, docs/method.md §1).
// Along a line in an isotropic field h(x) = h_p + |x − p| log β: sizes grow linearly with distance,
// i.e. geometrically, by β per unit of length measured in the graded field itself
// (∫ dx / h = log(h / h_p) / log β).
//
// Fixed point: a vertex whose metric changes is queued and its edges are checked again, until every
// edge pq satisfies η(ℓ) M_p ≤ (1 + tolerance) M_q (Loewner order) in both directions. Metrics only
// ever grow (sizes shrink). Grading a graded field changes nothing.
#pragma once

#include <vector>

#include "geom/sym_mat.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

struct GradationOptions {
  double growth = 1.5;      // β > 1: the size ratio allowed per unit metric length
  double tolerance = 1e-3;  // a metric changes only when a constraint is violated by more than this
};

struct GradationReport {
  Index updates = 0;  // metrics intersected with a neighbour's grown metric
};

// η(ℓ) = (1 + ℓ log β)⁻².
double gradation_factor(double length, double growth);

// The largest eigenvalue of B^{-1/2} A B^{-1/2} for SPD B: A ≤ μ B exactly for μ at least this.
template <int D>
double largest_relative_eigenvalue(const SymMat<D>& a, const SymMat<D>& b);

// Grades `metrics` (one SPD matrix per vertex) along the edges of the mesh's elements, in place.
// Throws Error for β ≤ 1, a negative tolerance, a metric that is not SPD, or no fixed point after
// 1000 updates per vertex (not observed).
template <int D>
GradationReport grade_metrics(const Mesh<D>& mesh, std::vector<SymMat<D>>& metrics, const GradationOptions& options);

}  // namespace hocav
