// Spectral functions of symmetric matrices and the Fréchet derivatives of exp (docs/method.md §1, §6).
#include "geom/sym_functions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/error.hpp"

namespace hocav {
namespace {

// Below this spread the difference quotients (e^a − e^b)/(a − b) and (exp[a,b] − exp[b,c])/(a − c) would cancel
// more than a factor ~4, so closer arguments go through expm1 or a Taylor series instead.
constexpr double kDirectQuotientSpread = 1.0;

template <int D, class Function>
SymMat<D> spectral_map(const SymEigen<D>& eigen, Function f) {
  Vec<D> mapped;
  for (int k = 0; k < D; ++k) mapped[k] = f(eigen.values[k]);
  return SymMat<D>::from_eigen(eigen.vectors, mapped);
}

template <int D>
SymEigen<D> checked_spd_eigen(const SymMat<D>& m, const char* caller) {
  SymEigen<D> eigen = spd_eigen(m);
  if (!is_positive_definite(eigen)) {
    char smallest[32];
    std::snprintf(smallest, sizeof smallest, "%.3g", eigen.values[0]);
    throw Error(std::string(caller) + ": the matrix is not symmetric positive definite (smallest eigenvalue " + smallest + ")");
  }
  return eigen;
}

// exp[a, b] from e^a and e^b.
double first_difference(double a, double b, double exp_a, double exp_b) {
  double delta = a - b;
  if (std::abs(delta) >= kDirectQuotientSpread) return (exp_a - exp_b) / delta;
  return delta == 0.0 ? exp_b : exp_b * (std::expm1(delta) / delta);
}

// The Taylor series of exp[x, y, z] below: 1/(k+2)! and 1/k for k ≤ kMaxTerms, made by the same divisions a
// loop would do, so that no division remains in the hot loop.
constexpr int kMaxTerms = 16;
struct TaylorCoefficients {
  std::array<double, kMaxTerms + 1> inverse_factorial{}, inverse{};
};
constexpr TaylorCoefficients kTaylor = [] {
  TaylorCoefficients c;
  c.inverse_factorial[0] = 0.5;
  for (int k = 1; k <= kMaxTerms; ++k) {
    c.inverse_factorial[k] = c.inverse_factorial[k - 1] / (k + 2);
    c.inverse[k] = 1.0 / k;
  }
  return c;
}();

// exp[lo, mid, hi] for lo ≤ mid ≤ hi, given upper = exp[hi, mid], lower = exp[mid, lo] and e^lo, e^hi.
double second_difference(double lo, double mid, double hi, double upper, double lower, double exp_lo, double exp_hi) {
  if (hi - lo >= kDirectQuotientSpread) return (upper - lower) / (hi - lo);
  // exp[x, y, z] = Σ_k h_k(x, y, z)/(k+2)! with h_k the complete homogeneous polynomials, about the centre so
  // that |x|, |y|, |z| ≤ r = (hi − lo)/2 ≤ 1/2. |h_k| ≤ (k+1)(k+2)/2 r^k, so term k is at most r^k/(2 k!), and
  // the tail after it is smaller still; the sum is ≥ e^{-1/2}/2. Stop once r^k/k! < 1e-17: by k = 16 at
  // r = 1/2, at once for equal arguments (a locally isotropic metric).
  double centre = 0.5 * (lo + hi);
  double x = hi - centre, y = mid - centre, z = lo - centre;
  double power_x = 1.0, h_xy = 1.0, h_xyz = 1.0, sum = 0.5, term_bound = 1.0;
  for (int k = 1; k <= kMaxTerms && term_bound >= 1e-17; ++k) {
    power_x *= x;
    h_xy = power_x + y * h_xy;  // h_k(x, y) = x^k + y h_{k−1}(x, y)
    h_xyz = h_xy + z * h_xyz;   // h_k(x, y, z) = h_k(x, y) + z h_{k−1}(x, y, z)
    sum += h_xyz * kTaylor.inverse_factorial[k];
    term_bound *= x * kTaylor.inverse[k];
  }
  // e^centre = sqrt(e^lo e^hi) to ~2 ulps, a square root instead of an exponential, while the product is a
  // normal number (|lo + hi| < ~1400).
  const double product = exp_lo * exp_hi;
  const double exp_centre = std::isnormal(product) && product < 1e300 ? std::sqrt(product) : std::exp(centre);
  return exp_centre * sum;
}

}  // namespace

template <int D>
bool is_spd(const SymMat<D>& m) {
  return is_positive_definite(spd_eigen(m));
}

template <int D>
SymMat<D> log_spd(const SymMat<D>& m) {
  return spectral_map(checked_spd_eigen(m, "log_spd"), [](double x) { return std::log(x); });
}

template <int D>
SymMat<D> exp_sym(const SymMat<D>& t) {
  return spectral_map(sym_eigen(t), [](double x) { return std::exp(x); });
}

template <int D>
SymMat<D> pow_spd(const SymMat<D>& m, double p) {
  return spectral_map(checked_spd_eigen(m, "pow_spd"), [p](double x) { return std::pow(x, p); });
}

template <int D>
SymMat<D> sqrt_spd(const SymMat<D>& m) {
  return spectral_map(checked_spd_eigen(m, "sqrt_spd"), [](double x) { return std::sqrt(x); });
}

double exp_divided_difference(double a, double b) { return first_difference(a, b, std::exp(a), std::exp(b)); }

double exp_divided_difference(double a, double b, double c) {
  std::array<double, 3> sorted = {a, b, c};
  std::sort(sorted.begin(), sorted.end());
  auto [lo, mid, hi] = sorted;
  return second_difference(lo, mid, hi, exp_divided_difference(hi, mid), exp_divided_difference(mid, lo), std::exp(lo), std::exp(hi));
}

template <int D>
ExpSpectrum<D> exp_spectrum(const SymMat<D>& log_metric) {
  ExpSpectrum<D> spectrum{sym_eigen(log_metric), {}};
  for (int k = 0; k < D; ++k) spectrum.exp_values[k] = std::exp(spectrum.eigen.values[k]);
  return spectrum;
}

template <int D>
ExpFrechet<D>::ExpFrechet(const SymMat<D>& log_metric) : ExpFrechet(exp_spectrum(log_metric)) {}

template <int D>
ExpFrechet<D>::ExpFrechet(const ExpSpectrum<D>& log_metric_spectrum) : eigen_(log_metric_spectrum.eigen) {
  const Vec<D>& exp_values = log_metric_spectrum.exp_values;
  value_ = SymMat<D>::from_eigen(eigen_.vectors, exp_values);
  for (int k = 0; k < D; ++k)
    for (int l = 0; l <= k; ++l)
      first_differences_(k, l) = first_difference(eigen_.values[k], eigen_.values[l], exp_values[k], exp_values[l]);
}

template <int D>
SymMat<D> ExpFrechet<D>::derivative_from_eigenbasis(SymMat<D> direction_in_eigenbasis) const {
  for (int k = 0; k < SymMat<D>::kEntryCount; ++k) direction_in_eigenbasis.entries[k] *= first_differences_.entries[k];
  return congruence(eigen_.vectors, direction_in_eigenbasis);
}

template <int D>
SymMat<D> ExpFrechet<D>::derivative(const SymMat<D>& direction) const {
  return derivative_from_eigenbasis(congruence_transposed(eigen_.vectors, direction));
}

template <int D>
double ExpFrechet<D>::squared_length(const Vec<D>& u) const {
  Vec<D> w = transpose_times(eigen_.vectors, u);
  double sum = 0.0;
  for (int k = 0; k < D; ++k) sum += first_differences_(k, k) * w[k] * w[k];
  return sum;
}

template <int D>
double exp_squared_length(const ExpSpectrum<D>& log_metric_spectrum, const Vec<D>& u) {
  Vec<D> w = transpose_times(log_metric_spectrum.eigen.vectors, u);
  double sum = 0.0;
  for (int k = 0; k < D; ++k) sum += log_metric_spectrum.exp_values[k] * w[k] * w[k];
  return sum;
}

template <int D>
SymMat<D> ExpFrechet<D>::squared_length_gradient(const Vec<D>& u) const {
  return derivative_from_eigenbasis(outer(transpose_times(eigen_.vectors, u)));
}

template <int D>
typename ExpFrechet<D>::SecondDifferences ExpFrechet<D>::second_differences() const {
  // exp[θi, θj, θk] is symmetric in its arguments: compute it for i ≤ j ≤ k (ascending θ) and copy it to the
  // permutations.
  SecondDifferences second;
  const Vec<D>& theta = eigen_.values;
  for (int i = 0; i < D; ++i)
    for (int j = i; j < D; ++j)
      for (int k = j; k < D; ++k) {
        double f = second_difference(theta[i], theta[j], theta[k], first_differences_(k, j), first_differences_(j, i),
                                     first_differences_(i, i), first_differences_(k, k));
        second[i][j][k] = second[i][k][j] = second[j][i][k] = second[j][k][i] = second[k][i][j] = second[k][j][i] = f;
      }
  return second;
}

template <int D>
SymMat<D> ExpFrechet<D>::second_derivative_in_eigenbasis(const SecondDifferences& second, const SymMat<D>& a, const SymMat<D>& b) const {
  SymMat<D> in_eigenbasis;
  for (int k = 0; k < D; ++k)
    for (int l = 0; l <= k; ++l)
      for (int m = 0; m < D; ++m) in_eigenbasis(k, l) += second[k][m][l] * (a(k, m) * b(m, l) + b(k, m) * a(m, l));
  return in_eigenbasis;
}

template <int D>
SymMat<D> ExpFrechet<D>::second_derivative(const SymMat<D>& direction1, const SymMat<D>& direction2) const {
  return congruence(eigen_.vectors, second_derivative_in_eigenbasis(second_differences(), congruence_transposed(eigen_.vectors, direction1),
                                                                    congruence_transposed(eigen_.vectors, direction2)));
}

template <int D>
SymMat<D> ExpFrechet<D>::squared_length_hessian(const std::array<SymMat<D>, D>& directions, const Vec<D>& u) const {
  const SecondDifferences second = second_differences();
  const SymMat<D> length_direction = outer(transpose_times(eigen_.vectors, u));  // u uᵀ in the eigenbasis
  std::array<SymMat<D>, D> in_eigenbasis;
  for (int i = 0; i < D; ++i) in_eigenbasis[i] = congruence_transposed(eigen_.vectors, directions[i]);
  SymMat<D> hessian;
  for (int i = 0; i < D; ++i) {
    const SymMat<D> along = second_derivative_in_eigenbasis(second, in_eigenbasis[i], length_direction);
    for (int j = 0; j <= i; ++j) hessian(i, j) = frobenius_dot(along, in_eigenbasis[j]);
  }
  return hessian;
}

template <int D>
typename ExpFrechet<D>::SquaredLengthDerivatives ExpFrechet<D>::squared_length_derivatives(const SymMat<D>& direction,
                                                                                           const Vec<D>& u) const {
  const SecondDifferences second = second_differences();
  const Vec<D> w = transpose_times(eigen_.vectors, u);
  const SymMat<D> h = congruence_transposed(eigen_.vectors, direction);
  // first = Σ_kl Γ_kl h_kl w_k w_l; second = 2 Σ_klm exp[θk, θm, θl] w_k h_km h_ml w_l.
  SquaredLengthDerivatives result;
  for (int k = 0; k < D; ++k)
    for (int l = 0; l < D; ++l) {
      result.first += first_differences_(k, l) * h(k, l) * w[k] * w[l];
      double inner = 0;
      for (int m = 0; m < D; ++m) inner += second[k][m][l] * h(k, m) * h(m, l);
      result.second += 2 * w[k] * w[l] * inner;
    }
  return result;
}

template <int D>
SymMat<D> dexp(const SymMat<D>& t, const SymMat<D>& h) {
  return ExpFrechet<D>(t).derivative(h);
}

template <int D>
SymMat<D> d2exp(const SymMat<D>& t, const SymMat<D>& h1, const SymMat<D>& h2) {
  return ExpFrechet<D>(t).second_derivative(h1, h2);
}

template bool is_spd(const SymMat<2>&);
template bool is_spd(const SymMat<3>&);
template SymMat<2> log_spd(const SymMat<2>&);
template SymMat<3> log_spd(const SymMat<3>&);
template SymMat<2> exp_sym(const SymMat<2>&);
template SymMat<3> exp_sym(const SymMat<3>&);
template SymMat<2> pow_spd(const SymMat<2>&, double);
template SymMat<3> pow_spd(const SymMat<3>&, double);
template SymMat<2> sqrt_spd(const SymMat<2>&);
template SymMat<3> sqrt_spd(const SymMat<3>&);
template ExpSpectrum<2> exp_spectrum(const SymMat<2>&);
template ExpSpectrum<3> exp_spectrum(const SymMat<3>&);
template double exp_squared_length(const ExpSpectrum<2>&, const Vec<2>&);
template double exp_squared_length(const ExpSpectrum<3>&, const Vec<3>&);
template class ExpFrechet<2>;
template class ExpFrechet<3>;
template SymMat<2> dexp(const SymMat<2>&, const SymMat<2>&);
template SymMat<3> dexp(const SymMat<3>&, const SymMat<3>&);
template SymMat<2> d2exp(const SymMat<2>&, const SymMat<2>&, const SymMat<2>&);
template SymMat<3> d2exp(const SymMat<3>&, const SymMat<3>&, const SymMat<3>&);

}  // namespace hocav
