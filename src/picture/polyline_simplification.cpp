#include "picture/polyline_simplification.hpp"

#include <algorithm>
#include <cmath>

namespace hocav {
namespace {

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return norm(p - (a + t * ab));
}

// Marks the points to keep strictly between `first` and `last` (both kept).
void keep_between(std::span<const Vec2> points, std::size_t first, std::size_t last, double tolerance, std::vector<bool>& keep) {
  if (last <= first + 1) return;
  std::size_t farthest = first;
  double largest = -1;
  for (std::size_t i = first + 1; i < last; ++i) {
    const double distance = distance_to_segment(points[i], points[first], points[last]);
    if (distance > largest) {
      largest = distance;
      farthest = i;
    }
  }
  if (largest <= tolerance) return;
  keep[farthest] = true;
  keep_between(points, first, farthest, tolerance, keep);
  keep_between(points, farthest, last, tolerance, keep);
}

}  // namespace

std::vector<Vec2> simplified_polyline(std::span<const Vec2> points, double tolerance, bool closed) {
  if (points.size() < 3) return {points.begin(), points.end()};
  // A closed polyline runs from its first point back to it.
  std::vector<Vec2> path(points.begin(), points.end());
  if (closed) path.push_back(points.front());
  std::vector<bool> keep(path.size(), false);
  keep.front() = keep.back() = true;
  keep_between(path, 0, path.size() - 1, tolerance, keep);
  if (closed) path.pop_back();
  std::vector<Vec2> kept;
  for (std::size_t i = 0; i < path.size(); ++i)
    if (keep[i]) kept.push_back(path[i]);
  return kept;
}

}  // namespace hocav
