// Small dense D×D matrices (docs/method.md §1, §6): the eigenvector bases V of the spectral forms
// M = V diag(λ) Vᵀ, and the few products the metric kernels need.
#pragma once

#include <array>

#include "geom/vec.hpp"

namespace hocav {

template <int D>
struct Mat {
  std::array<double, D * D> entries{};  // row by row

  constexpr double& operator()(int i, int j) { return entries[static_cast<std::size_t>(i * D + j)]; }
  constexpr double operator()(int i, int j) const { return entries[static_cast<std::size_t>(i * D + j)]; }

  static constexpr Mat identity() {
    Mat a;
    for (int i = 0; i < D; ++i) a(i, i) = 1.0;
    return a;
  }
  static constexpr Mat from_columns(const std::array<Vec<D>, D>& columns) {
    Mat a;
    for (int j = 0; j < D; ++j)
      for (int i = 0; i < D; ++i) a(i, j) = columns[static_cast<std::size_t>(j)][i];
    return a;
  }

  constexpr Vec<D> column(int j) const {
    Vec<D> v;
    for (int i = 0; i < D; ++i) v[i] = (*this)(i, j);
    return v;
  }
  constexpr void set_column(int j, const Vec<D>& v) {
    for (int i = 0; i < D; ++i) (*this)(i, j) = v[i];
  }
  constexpr void swap_columns(int j, int k) {
    for (int i = 0; i < D; ++i) {
      double t = (*this)(i, j);
      (*this)(i, j) = (*this)(i, k);
      (*this)(i, k) = t;
    }
  }

  friend constexpr bool operator==(const Mat&, const Mat&) = default;
};

using Mat2 = Mat<2>;
using Mat3 = Mat<3>;

template <int D>
constexpr Mat<D> transpose(const Mat<D>& a) {
  Mat<D> t;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) t(j, i) = a(i, j);
  return t;
}

template <int D>
constexpr Mat<D> operator*(const Mat<D>& a, const Mat<D>& b) {
  Mat<D> p;
  for (int i = 0; i < D; ++i)
    for (int k = 0; k < D; ++k)
      for (int j = 0; j < D; ++j) p(i, j) += a(i, k) * b(k, j);
  return p;
}

template <int D>
constexpr Vec<D> operator*(const Mat<D>& a, const Vec<D>& v) {
  Vec<D> w;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) w[i] += a(i, j) * v[j];
  return w;
}

// aᵀ v without forming aᵀ: the coordinates of v in an orthonormal basis held in the columns of a.
template <int D>
constexpr Vec<D> transpose_times(const Mat<D>& a, const Vec<D>& v) {
  Vec<D> w;
  for (int j = 0; j < D; ++j)
    for (int i = 0; i < D; ++i) w[j] += a(i, j) * v[i];
  return w;
}

}  // namespace hocav
