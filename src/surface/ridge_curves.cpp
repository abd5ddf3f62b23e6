// The surrogate's ridge curves (docs/surface.md, "Ridge curves").
#include "surface/ridge_curves.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace hocav {
namespace {

constexpr int kSamples = 8;
constexpr int kNewtonSteps = 20;

// The curve's derivatives at t: first and second.
std::pair<Vec3, Vec3> curve_derivatives(const CubicCurve& c, double t) {
  const double w = 1 - t;
  const Vec3 d0 = c[1] - c[0], d1 = c[2] - c[1], d2 = c[3] - c[2];
  const Vec3 first = 3.0 * (w * w * d0 + 2 * w * t * d1 + t * t * d2);
  const Vec3 second = 6.0 * (w * (d1 - d0) + t * (d2 - d1));
  return {first, second};
}

std::array<int, 2> sorted(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

}  // namespace

Vec3 evaluate_curve(const CubicCurve& c, double t) {
  const double w = 1 - t;
  return w * w * w * c[0] + 3 * w * w * t * c[1] + 3 * w * t * t * c[2] + t * t * t * c[3];
}

Vec3 closest_point_on_curve(const CubicCurve& curve, const Vec3& x) {
  double best_t = 0, best2 = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= kSamples; ++k) {
    const double t = static_cast<double>(k) / kSamples;
    const Vec3 offset = evaluate_curve(curve, t) - x;
    if (dot(offset, offset) < best2) {
      best2 = dot(offset, offset);
      best_t = t;
    }
  }
  // Newton on (C(t) − x)·C'(t) = 0, clamped to the curve.
  double t = best_t;
  for (int step = 0; step < kNewtonSteps; ++step) {
    const auto [first, second] = curve_derivatives(curve, t);
    const Vec3 offset = evaluate_curve(curve, t) - x;
    const double slope = dot(first, first) + dot(offset, second);
    if (!(slope > 0)) break;
    const double next = std::clamp(t - dot(offset, first) / slope, 0.0, 1.0);
    if (next == t) break;
    t = next;
  }
  const Vec3 polished = evaluate_curve(curve, t), sampled = evaluate_curve(curve, best_t);
  return dot(polished - x, polished - x) <= best2 ? polished : sampled;
}

RidgeCurves::RidgeCurves(std::vector<CubicCurve> curves, std::vector<std::array<int, 2>> refs)
    : curves_(std::move(curves)), refs_(std::move(refs)) {
  boxes_.reserve(curves_.size());
  for (std::size_t c = 0; c < curves_.size(); ++c) {
    refs_[c] = sorted(refs_[c][0], refs_[c][1]);
    Box<3> box = Box<3>::empty();
    for (const Vec3& point : curves_[c]) box.add(point);
    boxes_.push_back(box);
  }
  tree_ = PatchTree<3>(boxes_);
}

std::optional<Vec3> RidgeCurves::closest(const Vec3& x, int ref_a, int ref_b) const {
  const std::array<int, 2> wanted = sorted(ref_a, ref_b);
  std::optional<Vec3> best;
  tree_.nearest(x, [&](Index c, double best2) {
    if (refs_[c] != wanted || boxes_[c].distance2(x) >= best2) return std::numeric_limits<double>::infinity();
    const Vec3 point = closest_point_on_curve(curves_[c], x);
    const double distance2 = dot(point - x, point - x);
    if (distance2 < best2) best = point;
    return distance2;
  });
  return best;
}

}  // namespace hocav
