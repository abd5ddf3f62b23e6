// Barycentric coordinates of a point in a straight simplex and their (constant) gradients
// (docs/method.md §2: λ_i are ratios of signed sub-volumes; ∇λ_i are rows of the inverse edge matrix).
#pragma once

#include <array>

#include "geom/vec.hpp"

namespace hocav {

template <int D>
using SimplexPoints = std::array<Vec<D>, D + 1>;

template <int D>
using Barycentrics = std::array<double, D + 1>;

// Gradients of λ_0..λ_D with respect to the point; throws nothing, returns infinities for a flat
// simplex (callers check the measure first).
template <int D>
std::array<Vec<D>, D + 1> barycentric_gradients(const SimplexPoints<D>& p) {
  std::array<Vec<D>, D + 1> gradient{};
  if constexpr (D == 2) {
    Vec2 a = p[1] - p[0], b = p[2] - p[0];
    double inverse = 1.0 / determinant(a, b);
    gradient[1] = Vec2{{b[1] * inverse, -b[0] * inverse}};
    gradient[2] = Vec2{{-a[1] * inverse, a[0] * inverse}};
  } else {
    Vec3 a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
    double inverse = 1.0 / determinant(a, b, c);
    gradient[1] = cross(b, c) * inverse;
    gradient[2] = cross(c, a) * inverse;
    gradient[3] = cross(a, b) * inverse;
  }
  gradient[0] = Vec<D>{};
  for (int i = 1; i <= D; ++i) gradient[0] -= gradient[i];
  return gradient;
}

// λ of x from the gradients of a simplex and its first corner p0, for callers that keep the gradients of
// one simplex for many points.
template <int D>
Barycentrics<D> barycentric_coordinates(const std::array<Vec<D>, D + 1>& gradient, const Vec<D>& p0, const Vec<D>& x) {
  Barycentrics<D> lambda{};
  Vec<D> offset = x - p0;
  double rest = 1.0;
  for (int i = 1; i <= D; ++i) {
    lambda[i] = dot(gradient[i], offset);
    rest -= lambda[i];
  }
  lambda[0] = rest;
  return lambda;
}

// λ with Σλ = 1 and Σ λ_i p_i = x (exactly affine, extrapolating outside the simplex).
template <int D>
Barycentrics<D> barycentric_coordinates(const SimplexPoints<D>& p, const Vec<D>& x) {
  return barycentric_coordinates<D>(barycentric_gradients<D>(p), p[0], x);
}

}  // namespace hocav
