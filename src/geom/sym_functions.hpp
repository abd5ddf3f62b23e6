// Functions of symmetric matrices through their spectral form f(M) = R f(Λ) Rᵀ: the logarithm and
// exponential that move metrics to and from log form (docs/method.md §1, §2, §4), powers and square roots
// (for intersections and sizes, §1, §10), and the first and second Fréchet derivatives of exp that the
// edge-length derivatives are built on (§6).
//
// Which eigen-solver: functions of SPD inputs (log_spd, pow_spd, sqrt_spd, is_spd) use spd_eigen, so the
// small eigenvalues of a metric keep their relative accuracy; exp_sym and ExpFrechet take a log-metric T and
// use the fast sym_eigen, whose absolute accuracy on θ is the relative accuracy of e^θ.
//
// Conditioning, a property of the data and not of the code: an explicit metric M whose eigenvalues span
// κ = λmax/λmin holds its small eigenvalues only to about eps·κ relative when its eigenvectors are not the
// axes, since each entry is rounded relative to λmax. At a size ratio of 1e8 (κ = 1e16) that is all of λmin.
// Keep metrics in log form once they are read; log(exp(T)) returns T to about eps·(|θ| + κ).
#pragma once

#include <array>

#include "geom/sym_eigen.hpp"
#include "geom/sym_mat.hpp"

namespace hocav {

// True when every eigenvalue found by spd_eigen is finite and > 0 (so false for NaN or infinite entries):
// exactly when log_spd, pow_spd and sqrt_spd succeed.
template <int D>
bool is_spd(const SymMat<D>& m);

// log M; throws Error unless is_spd(m).
template <int D>
SymMat<D> log_spd(const SymMat<D>& m);

// exp T for any symmetric T (SPD result).
template <int D>
SymMat<D> exp_sym(const SymMat<D>& t);

// M^p for SPD M and any real p; throws Error unless is_spd(m).
template <int D>
SymMat<D> pow_spd(const SymMat<D>& m, double p);

// M^{1/2} for SPD M; throws Error unless is_spd(m).
template <int D>
SymMat<D> sqrt_spd(const SymMat<D>& m);

// Divided differences of exp, exp[a, b] = (e^a − e^b)/(a − b) and exp[a, b, c] = (exp[a, b] − exp[b, c])/(a − c),
// accurate to a few ulps for every argument, the confluent cases (equal arguments: e^a, e^a/2) included.
double exp_divided_difference(double a, double b);
double exp_divided_difference(double a, double b, double c);

// The sym_eigen decomposition of a log-metric T = V diag(θ) Vᵀ with e^θ: what uᵀ exp(T) u and the Fréchet
// set-up share, so that raising the order at one T computes no exponential twice.
template <int D>
struct ExpSpectrum {
  SymEigen<D> eigen;
  Vec<D> exp_values;
};
template <int D>
ExpSpectrum<D> exp_spectrum(const SymMat<D>& log_metric);

// exp(T) and its Fréchet derivatives at one T, sharing one eigendecomposition T = V diag(θ) Vᵀ (Daleckii–Krein):
//   Dexp(T)[H]        = V (Γ ∘ (Vᵀ H V)) Vᵀ,                       Γ_kl = exp[θk, θl],
//   D²exp(T)[H1, H2]_kl = Σ_m exp[θk, θm, θl] (H1'_km H2'_ml + H2'_km H1'_ml)   in the eigenbasis, H' = Vᵀ H V.
// Build one per evaluation point and ask for as many directions as needed.
// For metric lengths prefer squared_length and squared_length_gradient: they work in the eigenbasis, so they keep
// the relative accuracy of lengths along the small eigenvalues, which the explicit matrix value() rounds away
// (each entry is rounded relative to λmax: a relative error eps·κ on uᵀ value() u, all of it at κ = 1e16).
template <int D>
class ExpFrechet {
 public:
  explicit ExpFrechet(const SymMat<D>& log_metric);
  // From the spectrum of the log-metric, when it is already known.
  explicit ExpFrechet(const ExpSpectrum<D>& log_metric_spectrum);

  const SymMat<D>& value() const { return value_; }
  SymMat<D> derivative(const SymMat<D>& direction) const;
  SymMat<D> second_derivative(const SymMat<D>& direction1, const SymMat<D>& direction2) const;

  // uᵀ exp(T) u = Σ_k e^θk (v_kᵀu)², a sum of positive terms each relatively accurate.
  double squared_length(const Vec<D>& u) const;
  // G = Dexp(T)[u uᵀ] = V (Γ ∘ w wᵀ) Vᵀ with w = Vᵀu. Dexp(T) is self-adjoint for the Frobenius product, so the
  // derivative of uᵀ exp(T) u along any H is frobenius_dot(G, H): one G serves all directions of a gradient.
  SymMat<D> squared_length_gradient(const Vec<D>& u) const;
  // The D×D matrix uᵀ D²exp(T)[Hi, Hj] u for D directions Hi. ⟨D²exp(T)[H1, H2], H3⟩ is symmetric in H1, H2, H3,
  // so it is frobenius_dot(D²exp(T)[Hi, u uᵀ], Hj): D second derivatives, not D(D+1)/2, sharing one set of divided
  // differences, and all in the eigenbasis (the Frobenius product is invariant under V), never rotated back.
  SymMat<D> squared_length_hessian(const std::array<SymMat<D>, D>& directions, const Vec<D>& u) const;
  // uᵀ Dexp(T)[H] u and uᵀ D²exp(T)[H, H] u: the first two derivatives of uᵀ exp(T + sH) u at s = 0, along one
  // direction H (a curvature along one line: one contraction instead of squared_length_hessian's D).
  struct SquaredLengthDerivatives {
    double first = 0, second = 0;
  };
  SquaredLengthDerivatives squared_length_derivatives(const SymMat<D>& direction, const Vec<D>& u) const;

 private:
  // V (Γ ∘ H') Vᵀ for a direction H' = Vᵀ H V already in the eigenbasis.
  SymMat<D> derivative_from_eigenbasis(SymMat<D> direction_in_eigenbasis) const;
  // exp[θk, θm, θl], indexed [k][m][l].
  using SecondDifferences = std::array<std::array<std::array<double, D>, D>, D>;
  SecondDifferences second_differences() const;
  // D²exp(T)[A, B] in the eigenbasis, for directions a = VᵀAV, b = VᵀBV already in it.
  SymMat<D> second_derivative_in_eigenbasis(const SecondDifferences& second, const SymMat<D>& a, const SymMat<D>& b) const;

  SymEigen<D> eigen_;
  SymMat<D> value_;
  SymMat<D> first_differences_;  // Γ_kl = exp[θk, θl]; Γ_kk = e^θk
};

// uᵀ exp(T) u = Σ_k e^θk (v_kᵀu)² from the spectrum of T: squared_length without the Fréchet set-up.
template <int D>
double exp_squared_length(const ExpSpectrum<D>& log_metric_spectrum, const Vec<D>& u);

// One-off forms of the above.
template <int D>
SymMat<D> dexp(const SymMat<D>& t, const SymMat<D>& h);
template <int D>
SymMat<D> d2exp(const SymMat<D>& t, const SymMat<D>& h1, const SymMat<D>& h2);

}  // namespace hocav
