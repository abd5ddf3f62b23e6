// Random and special symmetric matrices for the tests of the geom kernels (docs/method.md §1): random rotations
// times log-eigenvalues up to ±18.4 (metric size ratios up to 1e8, eigenvalue ratios up to 1e16),
// repeated and nearly repeated eigenvalues.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "geom/mat.hpp"
#include "geom/sym_mat.hpp"

namespace hocav::geom_test {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// log(1e8): log-eigenvalues in [−18.4, 18.4] give metric sizes h = e^{−θ/2} with ratios up to 1e8.
constexpr double kLogEigenvalueBound = 18.42;

template <int D>
Mat<D> random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  if constexpr (D == 2) {
    double angle = std::atan2(normal(rng), normal(rng));
    return Mat<2>{{std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle)}};
  } else {
    // A normalized Gaussian quaternion is uniform on the rotations.
    double w = normal(rng), x = normal(rng), y = normal(rng), z = normal(rng);
    double s = 1.0 / std::sqrt(w * w + x * x + y * y + z * z);
    w *= s, x *= s, y *= s, z *= s;
    return Mat<3>{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
                   2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),  //
                   2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  }
}

template <int D>
Vec<D> random_vec(std::mt19937_64& rng, double low, double high) {
  std::uniform_real_distribution<double> uniform(low, high);
  Vec<D> v;
  for (int i = 0; i < D; ++i) v[i] = uniform(rng);
  return v;
}

// A random symmetric matrix with the given eigenvalues.
template <int D>
SymMat<D> random_with_eigenvalues(std::mt19937_64& rng, const Vec<D>& eigenvalues) {
  return SymMat<D>::from_eigen(random_rotation<D>(rng), eigenvalues);
}

// Log-eigenvalues of the kind the tests sweep: the k-th of n cases is uniform, has a repeated pair, all
// equal, or a pair 1e-4 … 1e-14 apart; a quarter of them span the full ±18.42.
template <int D>
Vec<D> log_eigenvalues_case(std::mt19937_64& rng, int k) {
  Vec<D> theta = random_vec<D>(rng, -kLogEigenvalueBound, kLogEigenvalueBound);
  switch (k % 8) {
    case 1: theta[1] = theta[0]; break;
    case 2:
      for (int i = 1; i < D; ++i) theta[i] = theta[0];
      break;
    case 3: theta[1] = theta[0] + std::pow(10.0, -4.0 - (k / 8) % 11); break;
    case 4: theta[0] = -kLogEigenvalueBound, theta[D - 1] = kLogEigenvalueBound; break;
    case 5: theta[0] = -kLogEigenvalueBound, theta[1] = theta[D - 1] = kLogEigenvalueBound; break;
    default: break;
  }
  return theta;
}

template <int D>
double max_abs_entry(const SymMat<D>& m) {
  double largest = 0.0;
  for (double x : m.entries) largest = std::max(largest, std::abs(x));
  return largest;
}

template <int D>
double max_abs_entry(const Mat<D>& m) {
  double largest = 0.0;
  for (double x : m.entries) largest = std::max(largest, std::abs(x));
  return largest;
}

// λmax/λmin of a matrix with log-eigenvalues theta.
template <int D>
double condition_number(const Vec<D>& theta) {
  double low = theta[0], high = theta[0];
  for (int i = 1; i < D; ++i) low = std::min(low, theta[i]), high = std::max(high, theta[i]);
  return std::exp(high - low);
}

}  // namespace hocav::geom_test
