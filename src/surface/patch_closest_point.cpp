// Closest point on one cubic patch (docs/method.md §9, projection).
#include "surface/patch_closest_point.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "geom/closest_point.hpp"

namespace hocav {
namespace {

constexpr int kMaxNewtonSteps = 40;
constexpr int kNewtonHalvings = 8, kGradientHalvings = 30;
constexpr double kParameterTolerance = 1e-14;
// Newton converges quadratically: after a step this small the parameters are exact to rounding.
constexpr double kConvergedNewtonStep = 1e-8;

template <int K>
using Matrix = std::array<std::array<double, K>, K>;

// The gradient of barycentric λ_i in the free parameters (λ_0 = 1 − Σ p, λ_i = p_{i−1}).
template <int K>
std::array<double, K> barycentric_gradient(int i) {
  std::array<double, K> gradient{};
  if (i == 0)
    gradient.fill(-1);
  else
    gradient[i - 1] = 1;
  return gradient;
}

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

template <int K>
double largest_magnitude(const std::array<double, K>& values) {
  double largest = 0;
  for (double value : values) largest = std::max(largest, std::abs(value));
  return largest;
}

// Solves the symmetric positive-definite K×K system A s = b; false when A is not positive definite.
template <int K>
bool solve_positive_definite(const Matrix<K>& a, const std::array<double, K>& b, std::array<double, K>& solution) {
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

  // p + scale × direction, clamped to the domain.
  auto stepped = [&](const Parameters& direction, double scale) {
    Parameters trial = p;
    for (int i = 0; i < K; ++i) trial[i] += scale * direction[i];
    return clamp_to_domain<K>(trial);
  };

  // Moves p along `direction` (clamped to the domain), halving until the distance decreases.
  double moved = 0;
  auto descend = [&](const Parameters& direction, int halvings) {
    double scale = 1;
    for (int halving = 0; halving < halvings; ++halving, scale *= 0.5) {
      const Parameters trial = stepped(direction, scale);
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

  // A Newton step this small is taken without the descent test: the distance's decrease, of the
  // order of the step squared, is below its rounding, so the test would spend its halvings in vain.
  auto take_final_step = [&](const Parameters& step) {
    p = stepped(step, 1);
    jet = evaluate_jet(patch, p);
    f = dot(jet.point - x, jet.point - x);
  };

  for (int iteration = 0; iteration < kMaxNewtonSteps; ++iteration) {
    // f/2 = |S − x|²/2: gradient g_a = r·S_a, Hessian H_ab = S_a·S_b + r·S_ab (Gauss–Newton part G).
    const Vec<D> r = jet.point - x;
    Parameters descent{};  // −∇(f/2)
    Matrix<K> hessian{}, gauss_newton{};
    double gauss_newton_trace = 0;
    for (int a = 0; a < K; ++a) {
      descent[a] = -dot(r, jet.first[a]);
      for (int b = 0; b < K; ++b) {
        const int second = a + b;  // uu, uv, vv (tt in 2D) are second[0], [1], [2]
        gauss_newton[a][b] = dot(jet.first[a], jet.first[b]);
        hessian[a][b] = gauss_newton[a][b] + dot(r, jet.second[second]);
      }
      gauss_newton_trace += gauss_newton[a][a];
    }
    // Active set: the sides the point sits on while the descent pushes it out through them.
    // Newton then runs on what is left: the whole patch, or the one side (a triangle's edge).
    int active_count = 0;
    Parameters active_normal{};
    for (int i = 0; i < D; ++i) {
      const Parameters normal = barycentric_gradient<K>(i);
      const double lambda = i == 0 ? 1 - std::accumulate(p.begin(), p.end(), 0.0) : p[i - 1];
      double inward = 0;  // how fast λ_i grows along the descent
      for (int a = 0; a < K; ++a) inward += descent[a] * normal[a];
      if (lambda <= kOnPatchSide && inward < 0) {
        ++active_count;
        active_normal = normal;
      }
    }
    if (active_count >= K) break;  // pushed into a corner (a curve's end, a triangle's vertex)
    Parameters newton{};
    bool has_newton = false;
    if (active_count == 0) {
      has_newton = solve_positive_definite<K>(hessian, descent, newton) || solve_positive_definite<K>(gauss_newton, descent, newton);
    } else if constexpr (K == 2) {
      const Parameters along{-active_normal[1], active_normal[0]};
      auto curvature = [&along](const Matrix<K>& m) {
        return along[0] * (m[0][0] * along[0] + m[0][1] * along[1]) + along[1] * (m[1][0] * along[0] + m[1][1] * along[1]);
      };
      const double slope = descent[0] * along[0] + descent[1] * along[1];
      const double bend = curvature(hessian) > 0 ? curvature(hessian) : curvature(gauss_newton);
      has_newton = bend > 0;
      if (has_newton) newton = {slope / bend * along[0], slope / bend * along[1]};
    }
    if (has_newton && largest_magnitude<K>(newton) < kConvergedNewtonStep) {
      take_final_step(newton);
      break;
    }
    // The gradient step is the fallback that always descends unless p is stationary on the domain.
    Parameters steepest = descent;
    for (double& component : steepest) component /= std::max(gauss_newton_trace, 1e-300);
    if (!(has_newton && descend(newton, kNewtonHalvings)) && !descend(steepest, kGradientHalvings)) break;
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
