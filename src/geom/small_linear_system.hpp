// Small dense linear systems (the least-squares fits of docs/surface.md): Gaussian elimination with
// partial pivoting on an N×N array.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace hocav {

// Solves the n×n system a s = b in place by Gaussian elimination with partial pivoting; false
// when a pivot is negligible against the matrix's largest diagonal entry.
template <int N>
bool solve_small_system(std::array<std::array<double, N>, N>& a, std::array<double, N>& b) {
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

}  // namespace hocav
