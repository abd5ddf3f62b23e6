// The Hessian-based Lp metric (docs/method.md §10), optimal for the Lp norm of the P1 interpolation error
// of a field with Hessian H at a target complexity N:
//   |H| = R |Λ| Rᵀ, the eigenvalues' absolute values clamped to [h_max⁻², h_min⁻²],
//   M = D_N det(|H|)^{−1/(2p+d)} |H|,   D_N = N^{2/d} ( ∫ det(|H|)^{p/(2p+d)} )^{−2/d}.
// The clamp keeps det(|H|) > 0 where the field is linear (H = 0) and caps the anisotropy of |H| at
// (h_max/h_min)², reading H as the metric of a field of order one (error 1); the sizes of M itself
// follow from N. Integrals over the mesh use P1 vertex values on the straight elements:
//   ∫ f = Σ_v f_v w_v,  w_v = Σ_{K ∋ v} |K| / (d + 1),
// and with this rule the complexity ∫ sqrt(det M) of the result is N exactly (to round-off).
#pragma once

#include <span>
#include <vector>

#include "geom/sym_mat.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

// The default h_min of a Hessian metric, as a fraction of its h_max: a bound on |H| that only extreme
// fields reach (`hocav metric --hessian`).
constexpr double kHessianSizeRange = 1e-6;

struct LpMetricOptions {
  double complexity = 1000;  // N > 0
  double norm = 2;           // p > 0
  double h_min = 1e-6;       // 0 < h_min <= h_max
  double h_max = 1;
};

// The P1 quadrature weights w_v (the absolute straight measures of the elements, shared equally).
template <int D>
std::vector<double> vertex_volumes(const Mesh<D>& mesh);

// ∫ sqrt(det M) with the P1 vertex rule: the number of vertices a unit mesh of M would have, up to a
// constant factor of the element shape.
template <int D>
double metric_complexity(const Mesh<D>& mesh, const std::vector<SymMat<D>>& metrics);

// The same sum for given vertex weights (vertex_volumes' of some vertices: one process's share of
// a mesh read in pieces).
template <int D>
double metric_complexity(std::span<const double> volumes, std::span<const SymMat<D>> metrics);

// Throws Error for invalid options.
void check_lp_options(const LpMetricOptions& options);

// A vertex's Lp metric before its scale D_N, and its density det(|H|)^{p/(2p+d)}; the whole metric is
// D_N times the first, D_N from the integral of the second (lp_scale). Throws Error naming vertex
// `vertex_number` for a Hessian that is not finite.
template <int D>
struct LpVertex {
  SymMat<D> metric;
  double density = 0;
};
template <int D>
LpVertex<D> lp_vertex(const SymMat<D>& hessian, const LpMetricOptions& options, Index vertex_number);

// D_N from the density's integral over the mesh; throws Error for a mesh of no volume.
template <int D>
double lp_scale(const LpMetricOptions& options, double density_integral);

// One metric per vertex from one Hessian per vertex. Throws Error for invalid options or a mesh of
// zero measure.
template <int D>
std::vector<SymMat<D>> lp_metric(const Mesh<D>& mesh, const std::vector<SymMat<D>>& hessians, const LpMetricOptions& options);

}  // namespace hocav
