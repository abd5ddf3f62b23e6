// The closest point of one cubic patch to a point (docs/method.md §9, projection): Newton on the patch
// parameters with clamping to the parameter domain (the segment [0, 1] or the triangle u, v ≥ 0,
// u + v ≤ 1), safeguarded by a projected-gradient step and halving so that every accepted step
// lowers the distance.
#pragma once

#include <array>

#include "surface/cubic_patch.hpp"

namespace hocav {

// A patch barycentric this small puts a point on the patch side opposite that vertex: clamping
// makes such barycentrics exact zeros, up to the rounding of λ_0 = 1 − Σ the others.
inline constexpr double kOnPatchSide = 1e-14;

template <int D>
struct PatchClosestPoint {
  PatchParameters<D> parameters{};
  Vec<D> point{};
  double distance2 = 0;  // squared distance to the projected point

  // The patch barycentrics (λ_0, ..., λ_{D-1}).
  std::array<double, D> barycentrics() const {
    std::array<double, D> lambda{};
    lambda[0] = 1.0;
    for (int i = 1; i < D; ++i) {
      lambda[i] = parameters[i - 1];
      lambda[0] -= lambda[i];
    }
    return lambda;
  }
};

// A local minimum of the distance from x over the patch, found from `start` (a stationary point on
// the patch, its border included).
template <int D>
PatchClosestPoint<D> closest_point_on_patch(const CubicPatch<D>& patch, const Vec<D>& x, const PatchParameters<D>& start);

// Same, started from the closest point of the straight facet through the patch's vertices (good
// while the patch is a mild bend of its facet, which is what the surrogate builds).
template <int D>
PatchClosestPoint<D> closest_point_on_patch(const CubicPatch<D>& patch, const Vec<D>& x);

}  // namespace hocav
