// Symmetric D×D matrices (docs/method.md §1): metrics M and their logarithms log M, and the directions
// H of the Fréchet derivatives of exp (§6).
// Storage is the D(D+1)/2 entries in the Gamma .sol order, the lower triangle row by row
// (2D: m11 m12 m22; 3D: m11 m12 m22 m13 m23 m33), so the file readers and writers pass rows through.
#pragma once

#include <array>
#include <cmath>

#include "geom/mat.hpp"
#include "geom/vec.hpp"

namespace hocav {

template <int D>
struct SymMat {
  static constexpr int kEntryCount = D * (D + 1) / 2;
  std::array<double, kEntryCount> entries{};

  // Position of (i, j) in `entries`, for either order of i and j.
  static constexpr int index(int i, int j) { return i >= j ? i * (i + 1) / 2 + j : j * (j + 1) / 2 + i; }

  constexpr double& operator()(int i, int j) { return entries[static_cast<std::size_t>(index(i, j))]; }
  constexpr double operator()(int i, int j) const { return entries[static_cast<std::size_t>(index(i, j))]; }

  static constexpr SymMat identity() {
    SymMat s;
    for (int i = 0; i < D; ++i) s(i, i) = 1.0;
    return s;
  }
  static constexpr SymMat from_diagonal(const Vec<D>& diagonal) {
    SymMat s;
    for (int i = 0; i < D; ++i) s(i, i) = diagonal[i];
    return s;
  }
  // R diag(values) Rᵀ: the matrix whose eigenvectors are the columns of R (orthonormal).
  static constexpr SymMat from_eigen(const Mat<D>& vectors, const Vec<D>& values) {
    SymMat s;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j <= i; ++j)
        for (int k = 0; k < D; ++k) s(i, j) += vectors(i, k) * values[k] * vectors(j, k);
    return s;
  }

  constexpr Vec<D> diagonal() const {
    Vec<D> d;
    for (int i = 0; i < D; ++i) d[i] = (*this)(i, i);
    return d;
  }

  constexpr SymMat& operator+=(const SymMat& o) {
    for (int k = 0; k < kEntryCount; ++k) entries[k] += o.entries[k];
    return *this;
  }
  constexpr SymMat& operator-=(const SymMat& o) {
    for (int k = 0; k < kEntryCount; ++k) entries[k] -= o.entries[k];
    return *this;
  }
  constexpr SymMat& operator*=(double s) {
    for (double& e : entries) e *= s;
    return *this;
  }
  friend constexpr SymMat operator+(SymMat a, const SymMat& b) { return a += b; }
  friend constexpr SymMat operator-(SymMat a, const SymMat& b) { return a -= b; }
  friend constexpr SymMat operator*(SymMat a, double s) { return a *= s; }
  friend constexpr SymMat operator*(double s, SymMat a) { return a *= s; }
  friend constexpr SymMat operator-(SymMat a) { return a *= -1.0; }
  friend constexpr bool operator==(const SymMat&, const SymMat&) = default;
};

using SymMat2 = SymMat<2>;
using SymMat3 = SymMat<3>;

template <int D>
constexpr Vec<D> operator*(const SymMat<D>& s, const Vec<D>& v) {
  Vec<D> w;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) w[i] += s(i, j) * v[j];
  return w;
}

// vᵀ S v, the squared length of v in the metric S.
template <int D>
constexpr double quadratic_form(const SymMat<D>& s, const Vec<D>& v) {
  return dot(v, s * v);
}

template <int D>
constexpr double trace(const SymMat<D>& s) {
  double t = 0.0;
  for (int i = 0; i < D; ++i) t += s(i, i);
  return t;
}

template <int D>
constexpr double determinant(const SymMat<D>& s) {
  if constexpr (D == 2) {
    return s(0, 0) * s(1, 1) - s(0, 1) * s(0, 1);
  } else {
    return s(0, 0) * (s(1, 1) * s(2, 2) - s(1, 2) * s(1, 2)) - s(0, 1) * (s(0, 1) * s(2, 2) - s(1, 2) * s(0, 2)) +
           s(0, 2) * (s(0, 1) * s(1, 2) - s(1, 1) * s(0, 2));
  }
}

// Frobenius inner product Σ_ij a_ij b_ij (off-diagonal entries count twice).
template <int D>
constexpr double frobenius_dot(const SymMat<D>& a, const SymMat<D>& b) {
  double s = 0.0;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) s += a(i, j) * b(i, j);
  return s;
}

template <int D>
inline double frobenius_norm(const SymMat<D>& s) {
  return std::sqrt(frobenius_dot(s, s));
}

// v vᵀ.
template <int D>
constexpr SymMat<D> outer(const Vec<D>& v) {
  SymMat<D> s;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j <= i; ++j) s(i, j) = v[i] * v[j];
  return s;
}

// A S Aᵀ: S expressed back in the standard basis when the columns of A are the basis vectors.
template <int D>
constexpr SymMat<D> congruence(const Mat<D>& a, const SymMat<D>& s) {
  Mat<D> as;
  for (int i = 0; i < D; ++i)
    for (int k = 0; k < D; ++k)
      for (int j = 0; j < D; ++j) as(i, k) += a(i, j) * s(j, k);
  SymMat<D> result;
  for (int i = 0; i < D; ++i)
    for (int l = 0; l <= i; ++l)
      for (int k = 0; k < D; ++k) result(i, l) += as(i, k) * a(l, k);
  return result;
}

// Aᵀ S A: S expressed in the basis held in the columns of A.
template <int D>
constexpr SymMat<D> congruence_transposed(const Mat<D>& a, const SymMat<D>& s) {
  Mat<D> sa;
  for (int j = 0; j < D; ++j)
    for (int k = 0; k < D; ++k)
      for (int l = 0; l < D; ++l) sa(j, l) += s(j, k) * a(k, l);
  SymMat<D> result;
  for (int i = 0; i < D; ++i)
    for (int l = 0; l <= i; ++l)
      for (int j = 0; j < D; ++j) result(i, l) += a(j, i) * sa(j, l);
  return result;
}

}  // namespace hocav
