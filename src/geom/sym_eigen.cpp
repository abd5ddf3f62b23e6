// Symmetric eigen-solvers (math.md §1, §6); see sym_eigen.hpp for the choice of two solvers.
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
  double tan = std::abs(zeta) < 1e150 ? std::copysign(1.0, zeta) / (std::abs(zeta) + std::sqrt(1.0 + zeta * zeta))
                                      : 0.5 / zeta;
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

// Unit null vector of the rank-2 matrix b − βI: the longest cross product of two of its rows.
Vec3 null_vector(const SymMat<3>& b, double beta) {
  std::array<Vec3, 3> rows;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rows[i][j] = b(i, j) - (i == j ? beta : 0.0);
  std::array<Vec3, 3> candidates = {cross(rows[0], rows[1]), cross(rows[0], rows[2]), cross(rows[1], rows[2])};
  int best = 0;
  double best_norm2 = dot(candidates[0], candidates[0]);
  for (int k = 1; k < 3; ++k) {
    double norm2 = dot(candidates[k], candidates[k]);
    if (norm2 > best_norm2) best = k, best_norm2 = norm2;
  }
  return candidates[best] * (1.0 / std::sqrt(best_norm2));
}

// Two unit vectors completing the unit vector n to an orthonormal basis (Duff et al., "Building an
// orthonormal basis, revisited", 2017): branch-free and well conditioned for every n.
std::array<Vec3, 2> orthonormal_complement(const Vec3& n) {
  double sign = std::copysign(1.0, n[2]);
  double a = -1.0 / (sign + n[2]);
  double b = n[0] * n[1] * a;
  return {{{{1.0 + sign * n[0] * n[0] * a, sign * b, -sign * n[0]}}, {{b, sign + n[1] * n[1] * a, -n[1]}}}};
}

SymEigen<3> closed_form_eigen(const SymMat<3>& m) {
  double max_abs = 0.0;
  for (double x : m.entries) max_abs = std::max(max_abs, std::abs(x));
  if (max_abs == 0.0) return {{}, Mat<3>::identity()};
  // Scaling by a power of two is exact and keeps the cubes and cross products below clear of overflow.
  int exponent = 0;
  std::frexp(max_abs, &exponent);
  SymMat<3> a = m * std::ldexp(1.0, -exponent);

  // b = (a − qI)/p has trace 0 and ‖b‖²_F = 6, so its eigenvalues are 2cos(φ + 2πk/3), φ = acos(det(b)/2)/3.
  double shift = trace(a) / 3.0;
  SymMat<3> b = a - shift * SymMat<3>::identity();
  // When a is within a few ulps of shift·I, the rounded shift leaves b with a trace as large as b itself; remove
  // it, or the trigonometric form (which assumes trace 0) may return an eigenvalue b does not have.
  double residual_shift = trace(b) / 3.0;
  b -= residual_shift * SymMat<3>::identity();
  double p2 = frobenius_dot(b, b) / 6.0;
  if (p2 < std::numeric_limits<double>::min()) {
    // a = shift·I to within 1e-154 relative: the diagonal is the spectrum to that accuracy.
    SymEigen<3> e{m.diagonal(), Mat<3>::identity()};
    sort_ascending(e);
    return e;
  }
  double p = std::sqrt(p2);
  b *= 1.0 / p;
  double half_det = std::clamp(determinant(b) / 2.0, -1.0, 1.0);
  double angle = std::acos(half_det) / 3.0;
  // The largest eigenvalue (when det(b) ≥ 0) or the smallest (otherwise) is at least √3 away from the other
  // two, so its eigenvector is well conditioned; the other two may coincide and are left to the 2×2 block.
  double separated = half_det >= 0.0 ? 2.0 * std::cos(angle) : 2.0 * std::cos(angle + 2.0 * std::numbers::pi / 3.0);
  Vec3 v0 = null_vector(b, separated);
  auto [u, w] = orthonormal_complement(v0);
  Vec3 bu = b * u, bw = b * w;
  SymMat<2> block{{dot(u, bu), dot(u, bw), dot(w, bw)}};
  Mat<2> rotation = Mat<2>::identity();
  if (block(0, 1) != 0.0) apply_rotation(block, rotation, 0, 1);

  SymEigen<3> e;
  e.vectors.set_column(0, v0);
  e.vectors.set_column(1, rotation(0, 0) * u + rotation(1, 0) * w);
  e.vectors.set_column(2, rotation(0, 1) * u + rotation(1, 1) * w);
  Vec3 betas{{quadratic_form(b, v0), block(0, 0), block(1, 1)}};
  double unscale = std::ldexp(1.0, exponent);
  for (int k = 0; k < 3; ++k) e.values[k] = (shift + (residual_shift + p * betas[k])) * unscale;
  sort_ascending(e);
  return e;
}

}  // namespace

template <int D>
SymEigen<D> sym_eigen(const SymMat<D>& m) {
  if constexpr (D == 2) {
    return eigen_by_one_rotation(m);
  } else {
    return closed_form_eigen(m);
  }
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
