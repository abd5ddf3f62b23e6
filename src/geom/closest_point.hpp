// Closest point of a segment or a triangle to a point, as barycentric weights of the face's
// vertices (used to localize points that fall outside the back mesh).
#pragma once

#include <algorithm>
#include <array>

#include "geom/vec.hpp"

namespace hocav {

// Weights (w0, w1) of the point of segment [a, b] closest to x.
template <int D>
std::array<double, 2> closest_on_segment(const Vec<D>& a, const Vec<D>& b, const Vec<D>& x) {
  Vec<D> ab = b - a;
  double length2 = dot(ab, ab);
  double t = length2 > 0 ? std::clamp(dot(x - a, ab) / length2, 0.0, 1.0) : 0.0;
  return {1 - t, t};
}

// Weights (w0, w1, w2) of the point of triangle (a, b, c) closest to x: the projection when it
// falls inside, otherwise the closest point of the closest edge.
inline std::array<double, 3> closest_on_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x) {
  Vec3 ab = b - a, ac = c - a, ax = x - a;
  // Solve the 2x2 normal equations of the projection onto the plane.
  double d00 = dot(ab, ab), d01 = dot(ab, ac), d11 = dot(ac, ac);
  double d20 = dot(ax, ab), d21 = dot(ax, ac);
  double denominator = d00 * d11 - d01 * d01;
  if (denominator > 0) {
    double v = (d11 * d20 - d01 * d21) / denominator;
    double w = (d00 * d21 - d01 * d20) / denominator;
    if (v >= 0 && w >= 0 && v + w <= 1) return {1 - v - w, v, w};
  }
  std::array<double, 3> best{};
  double best_distance2 = -1;
  auto consider = [&](int i, int j, const Vec3& p, const Vec3& q) {
    auto [wi, wj] = closest_on_segment<3>(p, q, x);
    Vec3 point = wi * p + wj * q - x;
    double distance2 = dot(point, point);
    if (best_distance2 < 0 || distance2 < best_distance2) {
      best_distance2 = distance2;
      best = {0, 0, 0};
      best[static_cast<std::size_t>(i)] = wi;
      best[static_cast<std::size_t>(j)] = wj;
    }
  };
  consider(0, 1, a, b);
  consider(1, 2, b, c);
  consider(2, 0, c, a);
  return best;
}

}  // namespace hocav
