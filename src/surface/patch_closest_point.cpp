// Closest point on one cubic patch (math.md §9, projection).
#include "surface/patch_closest_point.hpp"

#include <algorithm>
#include <cmath>

#include "geom/closest_point.hpp"

namespace hocav {
namespace {

constexpr int kMaxIterations = 40;
constexpr int kMaxHalvings = 30;
constexpr double kParameterTolerance = 1e-14;

// The Euclidean projection of parameters onto the domain {p ≥ 0, Σ p ≤ 1}: when clamping the
// negative ones leaves the sum above 1, the constraint Σ p = 1 is active at the projection.
template <int K>
std::array<double, K> clamp_to_domain(const std::array<double, K>& p) {
  std::array<double, K> clamped{};
  double sum = 0;
  for (int i = 0; i < K; ++i) sum += clamped[i] = std::max(p[i], 0.0);
  if (sum <= 1) return clamped;
  if constexpr (K == 1) {
    return {1.0};
  } else {
    const double u = std::clamp(0.5 * (p[0] - p[1] + 1), 0.0, 1.0);
    return {u, 1 - u};
  }
}

// Solves the symmetric positive-definite K×K system A s = b; false when A is not positive definite.
template <int K>
bool solve_positive_definite(const std::array<std::array<double, K>, K>& a, const std::array<double, K>& b,
                             std::array<double, K>& solution) {
  if constexpr (K == 1) {
    if (!(a[0][0] > 0)) return false;
    solution[0] = b[0] / a[0][0];
  } else {
    const double determinant = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    if (!(a[0][0] > 0 && determinant > 0)) return false;
    solution[0] = (a[1][1] * b[0] - a[0][1] * b[1]) / determinant;
    solution[1] = (a[0][0] * b[1] - a[1][0] * b[0]) / determinant;
  }
  return true;
}

}  // namespace

template <int D>
PatchClosestPoint<D> closest_point_on_patch(const CubicPatch<D>& patch, const Vec<D>& x, const PatchParameters<D>& start) {
  constexpr int K = D - 1;
  using Parameters = PatchParameters<D>;
  Parameters p = clamp_to_domain<K>(start);
  PatchJet<D> jet = evaluate_jet(patch, p);
  double f = dot(jet.point - x, jet.point - x);

  // Moves p along `direction` (clamped to the domain), halving until the distance decreases.
  double moved = 0;
  auto descend = [&](const Parameters& direction) {
    double scale = 1;
    for (int halving = 0; halving < kMaxHalvings; ++halving, scale *= 0.5) {
      Parameters trial = p;
      for (int i = 0; i < K; ++i) trial[i] += scale * direction[i];
      trial = clamp_to_domain<K>(trial);
      moved = 0;
      for (int i = 0; i < K; ++i) moved = std::max(moved, std::abs(trial[i] - p[i]));
      if (moved == 0) return false;
      PatchJet<D> trial_jet = evaluate_jet(patch, trial);
      const double trial_f = dot(trial_jet.point - x, trial_jet.point - x);
      if (trial_f < f) {
        p = trial;
        jet = trial_jet;
        f = trial_f;
        return true;
      }
    }
    return false;
  };

  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    // f/2 = |S − x|²/2: gradient g_a = r·S_a, Hessian H_ab = S_a·S_b + r·S_ab (Gauss–Newton part G).
    const Vec<D> r = jet.point - x;
    Parameters gradient{}, minus_gradient{};
    std::array<std::array<double, K>, K> hessian{}, gauss_newton{};
    double gauss_newton_trace = 0;
    for (int a = 0; a < K; ++a) {
      gradient[a] = dot(r, jet.first[a]);
      minus_gradient[a] = -gradient[a];
      for (int b = 0; b < K; ++b) {
        const int second = a + b;  // uu, uv, vv (tt in 2D) are second[0], [1], [2]
        gauss_newton[a][b] = dot(jet.first[a], jet.first[b]);
        hessian[a][b] = gauss_newton[a][b] + dot(r, jet.second[second]);
      }
      gauss_newton_trace += gauss_newton[a][a];
    }
    Parameters newton{};
    const bool has_newton = solve_positive_definite<K>(hessian, minus_gradient, newton) ||
                            solve_positive_definite<K>(gauss_newton, minus_gradient, newton);
    // The gradient step is the fallback that always descends unless p is stationary on the domain.
    Parameters steepest = minus_gradient;
    for (double& component : steepest) component /= std::max(gauss_newton_trace, 1e-300);
    if (!(has_newton && descend(newton)) && !descend(steepest)) break;
    if (moved < kParameterTolerance) break;
  }
  return {p, jet.point, f};
}

template <int D>
PatchClosestPoint<D> closest_point_on_patch(const CubicPatch<D>& patch, const Vec<D>& x) {
  if constexpr (D == 2) {
    const auto weights = closest_on_segment<2>(patch.vertex(0), patch.vertex(1), x);
    return closest_point_on_patch<2>(patch, x, {weights[1]});
  } else {
    const auto weights = closest_on_triangle(patch.vertex(0), patch.vertex(1), patch.vertex(2), x);
    return closest_point_on_patch<3>(patch, x, {weights[1], weights[2]});
  }
}

template PatchClosestPoint<2> closest_point_on_patch(const CubicPatch<2>&, const Vec2&, const PatchParameters<2>&);
template PatchClosestPoint<3> closest_point_on_patch(const CubicPatch<3>&, const Vec3&, const PatchParameters<3>&);
template PatchClosestPoint<2> closest_point_on_patch(const CubicPatch<2>&, const Vec2&);
template PatchClosestPoint<3> closest_point_on_patch(const CubicPatch<3>&, const Vec3&);

}  // namespace hocav
