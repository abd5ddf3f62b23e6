// Symmetric eigen-solvers (docs/method.md §1, §6); see sym_eigen.hpp for the choice of two solvers.
#include "geom/sym_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace hocav {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// The plane rotation that zeroes a_pq in the block [[a_pp, a_pq], [a_pq, a_qq]], angle in [−π/4, π/4],
// in Rutishauser's form: the diagonal updates a_pp − t·a_pq and a_qq + t·a_pq are what make Jacobi
// relatively accurate on SPD matrices.
struct Rotation {
  double cos, sin, tan;
};

Rotation jacobi_rotation(double a_pp, double a_qq, double a_pq) {
  double zeta = (a_qq - a_pp) / (2.0 * a_pq);
  // Past 1e150, ζ² would overflow; tan ≈ 1/(2ζ) is then exact to rounding.
  double tan = std::abs(zeta) < 1e150 ? std::copysign(1.0, zeta) / (std::abs(zeta) + std::sqrt(1.0 + zeta * zeta)) : 0.5 / zeta;
  double cos = 1.0 / std::sqrt(1.0 + tan * tan);
  return {cos, tan * cos, tan};
}

// a ← Jᵀ a J and v ← v J for the rotation J in the plane (p, q) that zeroes a_pq.
template <int D>
void apply_rotation(SymMat<D>& a, Mat<D>& v, int p, int q) {
  double a_pq = a(p, q);
  Rotation r = jacobi_rotation(a(p, p), a(q, q), a_pq);
  a(p, p) -= r.tan * a_pq;
  a(q, q) += r.tan * a_pq;
  a(p, q) = 0.0;
  for (int k = 0; k < D; ++k) {
    if (k != p && k != q) {
      double a_kp = a(k, p), a_kq = a(k, q);
      a(k, p) = r.cos * a_kp - r.sin * a_kq;
      a(k, q) = r.sin * a_kp + r.cos * a_kq;
    }
    double v_kp = v(k, p), v_kq = v(k, q);
    v(k, p) = r.cos * v_kp - r.sin * v_kq;
    v(k, q) = r.sin * v_kp + r.cos * v_kq;
  }
}

template <int D>
void sort_ascending(SymEigen<D>& e) {
  for (int i = 1; i < D; ++i)
    for (int j = i; j > 0 && e.values[j] < e.values[j - 1]; --j) {
      std::swap(e.values[j], e.values[j - 1]);
      e.vectors.swap_columns(j, j - 1);
    }
}

// A 2×2 symmetric matrix is diagonalized exactly by one rotation.
SymEigen<2> eigen_by_one_rotation(const SymMat<2>& m) {
  SymMat<2> a = m;
  SymEigen<2> e{{}, Mat<2>::identity()};
  if (a(0, 1) != 0.0) apply_rotation(a, e.vectors, 0, 1);
  e.values = a.diagonal();
  sort_ascending(e);
  return e;
}

template <int D>
SymEigen<D> cyclic_jacobi(const SymMat<D>& m) {
  // Quadratic convergence takes 3×3 matrices to rounding level in 4–6 sweeps; the cap only stops NaN inputs.
  constexpr int kMaxSweeps = 50;
  SymMat<D> a = m;
  SymEigen<D> e{{}, Mat<D>::identity()};
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    bool rotated = false;
    for (int p = 0; p < D - 1; ++p)
      for (int q = p + 1; q < D; ++q) {
        // Demmel–Veselić: an entry below eps·sqrt(|a_pp a_qq|) moves no eigenvalue beyond its own rounding.
        if (std::abs(a(p, q)) <= kEpsilon * std::sqrt(std::abs(a(p, p))) * std::sqrt(std::abs(a(q, q)))) continue;
        apply_rotation(a, e.vectors, p, q);
        rotated = true;
      }
    if (!rotated) break;
  }
  e.values = a.diagonal();
  sort_ascending(e);
  return e;
}

// A power of two (exact to scale by) that brings the largest entry into [2^-100, 2^100], where squares and
// cubes of entries neither overflow nor underflow; 1 for every matrix met in practice.
template <int D>
double safe_scale(const SymMat<D>& m) {
  double max_abs = 0.0;
  for (double x : m.entries) max_abs = std::max(max_abs, std::abs(x));
  if (max_abs == 0.0 || (max_abs >= 0x1p-100 && max_abs <= 0x1p100)) return 1.0;
  int exponent = 0;
  std::frexp(max_abs, &exponent);
  return std::ldexp(1.0, -exponent);
}

// Eigenpairs of [[a, b], [b, c]] in closed form, mean ∓ radius, to absolute accuracy; entries within 2^±100.
// The eigenvector of the smaller eigenvalue is (y, −x) for the larger one's (x, y).
struct PairEigen {
  double low, high;
  Vec2 high_vector;
};

PairEigen closed_form_pair(double a, double b, double c) {
  double mean = 0.5 * (a + c), half_gap = 0.5 * (c - a);
  double radius2 = half_gap * half_gap + b * b;
  // Below 2^-900 the eigenvalue gap 2·radius is under 2^-449, nothing next to entries ≥ 2^-100: a multiple of I.
  if (radius2 < 0x1p-900) return {mean, mean, {{0.0, 1.0}}};
  double radius = std::sqrt(radius2);
  // Null vector of [[−d − r, b], [b, d − r]] (d = half_gap, r = radius) from the row free of cancellation.
  bool c_larger = half_gap >= 0.0;
  double x = c_larger ? b : radius - half_gap;
  double y = c_larger ? half_gap + radius : b;
  double inverse_norm = 1.0 / std::sqrt(x * x + y * y);
  return {mean - radius, mean + radius, {{x * inverse_norm, y * inverse_norm}}};
}

// m must have its entries within 2^±100 (see safe_scale).
SymEigen<2> closed_form_eigen(const SymMat<2>& m) {
  PairEigen pair = closed_form_pair(m(0, 0), m(0, 1), m(1, 1));
  Vec2 high = pair.high_vector, low{{high[1], -high[0]}};
  return {{{pair.low, pair.high}}, Mat<2>::from_columns({low, high})};
}

// An orthonormal basis whose first vector spans the null space of the rank-2 matrix b − βI: the longest cross
// product c = r_i × r_j of two of its rows. The row r_i is orthogonal to c by construction and c × r_i completes
// the basis, so the three normalizations run side by side instead of one after the other.
std::array<Vec3, 3> null_vector_basis(const SymMat<3>& b, double beta) {
  std::array<Vec3, 3> rows;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rows[i][j] = b(i, j) - (i == j ? beta : 0.0);
  constexpr std::array<std::array<int, 2>, 3> kPairs = {{{0, 1}, {0, 2}, {1, 2}}};
  int best = 0;
  double best_norm2 = -1.0;
  for (int k = 0; k < 3; ++k) {
    Vec3 c = cross(rows[kPairs[k][0]], rows[kPairs[k][1]]);
    double norm2 = dot(c, c);
    if (norm2 > best_norm2) best = k, best_norm2 = norm2;
  }
  const Vec3& row = rows[kPairs[best][0]];
  Vec3 null = cross(row, rows[kPairs[best][1]]);
  double inverse_null_norm = 1.0 / std::sqrt(best_norm2), inverse_row_norm = 1.0 / std::sqrt(dot(row, row));
  return {null * inverse_null_norm, row * inverse_row_norm, cross(null, row) * (inverse_null_norm * inverse_row_norm)};
}

// a must have its entries within 2^±100 (see safe_scale).
SymEigen<3> closed_form_eigen(const SymMat<3>& a) {
  // b = a − (tr a/3)I from pairwise differences of the diagonal: these are exact when a is close to a multiple
  // of the identity, so b keeps a trace 0 to rounding of its own size, as the trigonometric form assumes.
  double shift = trace(a) / 3.0;
  double d01 = a(0, 0) - a(1, 1), d02 = a(0, 0) - a(2, 2), d12 = a(1, 1) - a(2, 2);
  SymMat<3> b{{(d01 + d02) / 3.0, a(0, 1), (d12 - d01) / 3.0, a(0, 2), a(1, 2), -(d02 + d12) / 3.0}};
  double diagonal2 = b(0, 0) * b(0, 0) + b(1, 1) * b(1, 1) + b(2, 2) * b(2, 2);
  double off_diagonal2 = b(0, 1) * b(0, 1) + b(0, 2) * b(0, 2) + b(1, 2) * b(1, 2);
  double p2 = (diagonal2 + 2.0 * off_diagonal2) / 6.0;
  if (p2 < 0x1p-600) {
    // a = shift·I to within 2^-200 relative: the diagonal is the spectrum to that accuracy. Above this bound,
    // p ≥ 2^-300 keeps p⁻³ and det(b) below clear of overflow and underflow.
    SymEigen<3> e{a.diagonal(), Mat<3>::identity()};
    sort_ascending(e);
    return e;
  }
  // b/p has trace 0 and ‖b/p‖²_F = 6, so its eigenvalues are 2cos(φ + 2πk/3), φ = acos(det(b/p)/2)/3.
  double p = std::sqrt(p2), inverse_p = 1.0 / p;
  double half_det = std::clamp(0.5 * determinant(b) * (inverse_p * inverse_p * inverse_p), -1.0, 1.0);
  b *= inverse_p;
  double angle = std::acos(half_det) / 3.0;
  // The largest eigenvalue (when det(b) ≥ 0) or the smallest (otherwise) is at least √3 away from the other
  // two, so its eigenvector is well conditioned; the other two may coincide and are left to the 2×2 block in
  // the orthogonal complement, which is solved exactly.
  bool largest_is_separated = half_det >= 0.0;
  double separated = 2.0 * std::cos(largest_is_separated ? angle : angle + 2.0 * std::numbers::pi / 3.0);
  auto [v0, u, w] = null_vector_basis(b, separated);
  Vec3 bu = b * u, bw = b * w;
  PairEigen pair = closed_form_pair(dot(u, bu), dot(u, bw), dot(w, bw));
  Vec2 x = pair.high_vector;
  Vec3 low_vector = x[1] * u - x[0] * w, high_vector = x[0] * u + x[1] * w;

  double separated_value = shift + p * quadratic_form(b, v0), low = shift + p * pair.low, high = shift + p * pair.high;
  if (largest_is_separated) return {{{low, high, separated_value}}, Mat<3>::from_columns({low_vector, high_vector, v0})};
  return {{{separated_value, low, high}}, Mat<3>::from_columns({v0, low_vector, high_vector})};
}

// Solves a copy of m scaled into the safe range when m is not already in it (rare, and off the common path).
template <int D>
SymEigen<D> closed_form_eigen_any_scale(const SymMat<D>& m) {
  double scale = safe_scale(m);
  if (scale == 1.0) return closed_form_eigen(m);
  SymEigen<D> e = closed_form_eigen(m * scale);
  e.values *= 1.0 / scale;
  return e;
}

}  // namespace

template <int D>
SymEigen<D> sym_eigen(const SymMat<D>& m) {
  return closed_form_eigen_any_scale(m);
}

template <int D>
SymEigen<D> spd_eigen(const SymMat<D>& m) {
  if constexpr (D == 2) {
    return eigen_by_one_rotation(m);
  } else {
    return cyclic_jacobi(m);
  }
}

template SymEigen<2> sym_eigen(const SymMat<2>&);
template SymEigen<3> sym_eigen(const SymMat<3>&);
template SymEigen<2> spd_eigen(const SymMat<2>&);
template SymEigen<3> spd_eigen(const SymMat<3>&);

}  // namespace hocav
