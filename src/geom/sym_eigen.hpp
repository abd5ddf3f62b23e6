// Eigen-decomposition of symmetric 2×2 and 3×3 matrices (docs/method.md §1 spectral form M = R Λ Rᵀ, and §6 where
// Dexp(T) is built on T = V diag(θ) Vᵀ). Two solvers, named for what they are for:
//
// - sym_eigen: fast, for log-metrics T (the hot loop: exp and its Fréchet derivatives). Accuracy is ABSOLUTE,
//   every eigenvalue within a few eps·‖M‖, residual ‖MV − VΛ‖ of the same order; that is all a log-metric
//   needs, since an absolute error δ on θ is a relative error δ on the metric eigenvalue e^θ.
//   3×3: the best separated eigenvalue in closed form (trigonometric solution of the characteristic cubic of
//   the deviatoric part), its eigenvector as the longest cross product of two rows of M − λI, and the other two
//   eigenpairs from the 2×2 block in the orthogonal complement, solved exactly, so repeated and nearly
//   repeated eigenvalues keep orthonormal eigenvectors. 2×2: mean ∓ radius.
//
// - spd_eigen: cyclic Jacobi with the Demmel–Veselić stopping rule, for metrics M (SPD, eigenvalues up to
//   1e16 apart). Each eigenvalue is found to RELATIVE accuracy ~eps·κ(Δ⁻¹MΔ⁻¹), Δ = diag(M)^{1/2}: small
//   eigenvalues of graded or axis-aligned metrics stay accurate where any closed form loses them. Two to
//   three times slower in 3D; use it once per input metric (log_spd, pow_spd, intersection), not in hot loops.
//
// Both return the eigenvalues in ascending order, with orthonormal eigenvectors (to a few eps) in the matching
// columns of `vectors`.
#pragma once

#include <cmath>

#include "geom/mat.hpp"
#include "geom/sym_mat.hpp"
#include "geom/vec.hpp"

namespace hocav {

template <int D>
struct SymEigen {
  Vec<D> values;   // ascending
  Mat<D> vectors;  // column k is the unit eigenvector of values[k]
};

template <int D>
SymEigen<D> sym_eigen(const SymMat<D>& m);

template <int D>
SymEigen<D> spd_eigen(const SymMat<D>& m);

// Every eigenvalue finite and > 0 (false for NaN or infinite inputs, whose eigenvalues are not finite).
template <int D>
bool is_positive_definite(const SymEigen<D>& eigen) {
  for (int k = 0; k < D; ++k)
    if (!(eigen.values[k] > 0.0 && std::isfinite(eigen.values[k]))) return false;
  return true;
}

}  // namespace hocav
