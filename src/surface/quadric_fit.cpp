// Least-squares quadric normals (docs/method.md §9).
#include "surface/quadric_fit.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "geom/orthonormal_complement.hpp"

namespace hocav {
namespace {

// Solves the n×n system a s = b in place by Gaussian elimination with partial pivoting; false
// when a pivot is negligible against the matrix's largest diagonal entry.
template <int N>
bool solve(std::array<std::array<double, N>, N>& a, std::array<double, N>& b) {
  double scale = 0;
  for (int i = 0; i < N; ++i) scale = std::max(scale, std::abs(a[i][i]));
  for (int column = 0; column < N; ++column) {
    int pivot = column;
    for (int row = column + 1; row < N; ++row)
      if (std::abs(a[row][column]) > std::abs(a[pivot][column])) pivot = row;
    if (!(std::abs(a[pivot][column]) > 1e-12 * scale)) return false;
    std::swap(a[pivot], a[column]);
    std::swap(b[pivot], b[column]);
    for (int row = column + 1; row < N; ++row) {
      const double factor = a[row][column] / a[column][column];
      for (int k = column; k < N; ++k) a[row][k] -= factor * a[column][k];
      b[row] -= factor * b[column];
    }
  }
  for (int row = N - 1; row >= 0; --row) {
    for (int k = row + 1; k < N; ++k) b[row] -= a[row][k] * b[k];
    b[row] /= a[row][row];
  }
  return true;
}

// One fit in the frame of `normal`: slope terms x (and y), then the quadratic ones.
template <int D>
bool fit_once(const Vec<D>& point, std::span<const Vec<D>> neighbors, Vec<D>& normal) {
  constexpr int K = D - 1;                        // tangent coordinates
  constexpr int kUnknowns = K + K * (K + 1) / 2;  // slopes, then x², (xy, y²)
  if (static_cast<int>(neighbors.size()) < kUnknowns + 1) return false;
  const auto tangents = orthonormal_complement(normal);
  // Coordinates in units of the mean neighbour distance keep the system well scaled.
  double scale = 0;
  for (const Vec<D>& q : neighbors) scale += norm(q - point);
  scale = static_cast<double>(neighbors.size()) / scale;
  std::array<std::array<double, kUnknowns>, kUnknowns> normal_matrix{};
  std::array<double, kUnknowns> right_side{};
  for (const Vec<D>& q : neighbors) {
    const Vec<D> offset = (q - point) * scale;
    std::array<double, kUnknowns> basis{};
    std::array<double, K> x{};
    for (int i = 0; i < K; ++i) basis[i] = x[i] = dot(offset, tangents[i]);
    int next = K;
    for (int i = 0; i < K; ++i)
      for (int j = i; j < K; ++j) basis[next++] = x[i] * x[j];
    const double height = dot(offset, normal);
    const double weight = 1 / dot(offset, offset);
    for (int r = 0; r < kUnknowns; ++r) {
      right_side[r] += weight * basis[r] * height;
      for (int c = 0; c < kUnknowns; ++c) normal_matrix[r][c] += weight * basis[r] * basis[c];
    }
  }
  if (!solve<kUnknowns>(normal_matrix, right_side)) return false;
  // The graph z = g·x + ... has the normal (−g, 1) in the frame (the slopes are scale-free).
  Vec<D> fitted = normal;
  for (int i = 0; i < K; ++i) fitted -= right_side[i] * tangents[i];
  normal = fitted * (1 / norm(fitted));
  return true;
}

}  // namespace

template <int D>
Vec<D> quadric_fitted_normal(const Vec<D>& point, std::span<const Vec<D>> neighbors, const Vec<D>& initial,
                             double max_turn_radians) {
  Vec<D> normal = initial;
  for (int pass = 0; pass < 2; ++pass)
    if (!fit_once(point, neighbors, normal)) return initial;
  return dot(normal, initial) >= std::cos(max_turn_radians) ? normal : initial;
}

template Vec2 quadric_fitted_normal(const Vec2&, std::span<const Vec2>, const Vec2&, double);
template Vec3 quadric_fitted_normal(const Vec3&, std::span<const Vec3>, const Vec3&, double);

}  // namespace hocav
