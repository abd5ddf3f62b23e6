// Least-squares quadric normals (docs/method.md §9).
#include "surface/quadric_fit.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "geom/orthonormal_complement.hpp"
#include "geom/small_linear_system.hpp"

namespace hocav {
namespace {

// One fit in the frame of `normal`: slope terms x (and y), then (kQuadratic) the quadratic ones.
// Sets the residual of the fit; false when it fails.
template <int D, bool kQuadratic>
bool fit_once(const Vec<D>& point, std::span<const Vec<D>> neighbors, Vec<D>& normal, double& residual) {
  constexpr int K = D - 1;                                           // tangent coordinates
  constexpr int kUnknowns = K + (kQuadratic ? K * (K + 1) / 2 : 0);  // slopes, then x², (xy, y²)
  if (static_cast<int>(neighbors.size()) < kUnknowns + 1) return false;
  const auto tangents = orthonormal_complement(normal);
  // Coordinates in units of the mean neighbour distance keep the system well scaled.
  double scale = 0;
  for (const Vec<D>& q : neighbors) scale += norm(q - point);
  scale = static_cast<double>(neighbors.size()) / scale;
  // Each neighbour's basis values (slopes, then quadratic terms), height and weight.
  auto terms = [&](const Vec<D>& q, std::array<double, kUnknowns>& basis, double& height, double& weight) {
    const Vec<D> offset = (q - point) * scale;
    std::array<double, K> x{};
    for (int i = 0; i < K; ++i) basis[i] = x[i] = dot(offset, tangents[i]);
    if constexpr (kQuadratic) {
      int next = K;
      for (int i = 0; i < K; ++i)
        for (int j = i; j < K; ++j) basis[next++] = x[i] * x[j];
    }
    height = dot(offset, normal);
    weight = 1 / dot(offset, offset);
  };
  std::array<std::array<double, kUnknowns>, kUnknowns> normal_matrix{};
  std::array<double, kUnknowns> right_side{}, basis{};
  double height = 0, weight = 0;
  for (const Vec<D>& q : neighbors) {
    terms(q, basis, height, weight);
    for (int r = 0; r < kUnknowns; ++r) {
      right_side[r] += weight * basis[r] * height;
      for (int c = 0; c < kUnknowns; ++c) normal_matrix[r][c] += weight * basis[r] * basis[c];
    }
  }
  if (!solve_small_system<kUnknowns>(normal_matrix, right_side)) return false;
  double squares = 0, weights = 0;
  for (const Vec<D>& q : neighbors) {
    terms(q, basis, height, weight);
    double misfit = -height;
    for (int r = 0; r < kUnknowns; ++r) misfit += basis[r] * right_side[r];
    squares += weight * misfit * misfit;
    weights += weight;
  }
  residual = std::sqrt(squares / weights);
  // The graph z = g·x + ... has the normal (−g, 1) in the frame (the slopes are scale-free).
  Vec<D> fitted = normal;
  for (int i = 0; i < K; ++i) fitted -= right_side[i] * tangents[i];
  normal = fitted * (1 / norm(fitted));
  return true;
}

// Two passes of fit_once, the second in the frame of the first.
template <int D, bool kQuadratic>
QuadricNormal<D> fitted_normal(const Vec<D>& point, std::span<const Vec<D>> neighbors, const Vec<D>& initial, double max_turn_radians) {
  const QuadricNormal<D> failed{initial, std::numeric_limits<double>::infinity()};
  QuadricNormal<D> fit{initial, 0};
  for (int pass = 0; pass < 2; ++pass)
    if (!fit_once<D, kQuadratic>(point, neighbors, fit.normal, fit.residual)) return failed;
  return dot(fit.normal, initial) >= std::cos(max_turn_radians) ? fit : failed;
}

}  // namespace

template <int D>
QuadricNormal<D> quadric_fitted_normal(const Vec<D>& point, std::span<const Vec<D>> neighbors, const Vec<D>& initial,
                                       double max_turn_radians) {
  return fitted_normal<D, true>(point, neighbors, initial, max_turn_radians);
}

template <int D>
QuadricNormal<D> plane_fitted_normal(const Vec<D>& point, std::span<const Vec<D>> neighbors, const Vec<D>& initial,
                                     double max_turn_radians) {
  return fitted_normal<D, false>(point, neighbors, initial, max_turn_radians);
}

template QuadricNormal<2> quadric_fitted_normal(const Vec2&, std::span<const Vec2>, const Vec2&, double);
template QuadricNormal<3> quadric_fitted_normal(const Vec3&, std::span<const Vec3>, const Vec3&, double);
template QuadricNormal<2> plane_fitted_normal(const Vec2&, std::span<const Vec2>, const Vec2&, double);
template QuadricNormal<3> plane_fitted_normal(const Vec3&, std::span<const Vec3>, const Vec3&, double);

}  // namespace hocav
