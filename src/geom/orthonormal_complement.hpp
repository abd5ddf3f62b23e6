// An orthonormal basis of the plane (line in 2D) orthogonal to a unit vector: the tangent plane of a surface
// normal, or the bisector plane of an edge direction.
#pragma once

#include <array>
#include <cmath>

#include "geom/vec.hpp"

namespace hocav {

template <int D>
std::array<Vec<D>, D - 1> orthonormal_complement(const Vec<D>& n) {
  if constexpr (D == 2) {
    return {Vec2{{-n[1], n[0]}}};
  } else {
    // Against an axis far enough from n for a well-conditioned cross product (|n × helper| ≥ 0.6).
    const Vec3 helper = std::abs(n[0]) < 0.6 ? Vec3{{1, 0, 0}} : Vec3{{0, 1, 0}};
    Vec3 first = cross(n, helper);
    first *= 1 / norm(first);
    return {first, cross(n, first)};
  }
}

}  // namespace hocav
