// A side's normal from a circle in the feature line's normal plane (docs/surface.md).
#include "surface/section_circle_fit.hpp"

#include <array>
#include <cmath>

#include "geom/small_linear_system.hpp"

namespace hocav {
namespace {

// Points whose (x, z) moments are this close to singular lie on a line through the vertex.
constexpr double kCollinear = 1e-10;
// The largest root-mean-square distance of the points to the fitted surface, in units of their mean
// distance to the vertex, for the fit to count.
constexpr double kMaxResidual = 1e-3;

}  // namespace

std::optional<Vec3> section_circle_normal(const Vec3& point, const Vec3& tangent, std::span<const Vec3> neighbors, const Vec3& initial) {
  if (static_cast<int>(neighbors.size()) < kSectionFitPoints) return std::nullopt;
  // A frame of the normal plane: w along the initial normal, u across.
  Vec3 w = initial - dot(initial, tangent) * tangent;
  if (!(norm(w) > 0)) return std::nullopt;
  w *= 1 / norm(w);
  const Vec3 u = cross(w, tangent);
  // Coordinates x (across), y (along the line), z (along w), scaled by the mean distance.
  double scale = 0;
  for (const Vec3& q : neighbors) scale += norm(q - point);
  if (!(scale > 0)) return std::nullopt;
  scale = static_cast<double>(neighbors.size()) / scale;
  // Least squares for D x + E z + B y + F y² = −(x² + z²), and the second moments of (x, z), for
  // the line through the vertex when the points project onto one (a plane containing the tangent).
  std::array<std::array<double, 4>, 4> matrix{};
  std::array<double, 4> right{};
  std::array<double, 3> moments{};  // xx, xz, zz
  auto coordinates = [&](const Vec3& q) {
    const Vec3 offset = (q - point) * scale;
    return std::array<double, 3>{dot(offset, u), dot(offset, tangent), dot(offset, w)};
  };
  for (const Vec3& q : neighbors) {
    const auto [x, y, z] = coordinates(q);
    const std::array<double, 4> basis{x, z, y, y * y};
    for (int r = 0; r < 4; ++r) {
      right[r] -= basis[r] * (x * x + z * z);
      for (int c = 0; c < 4; ++c) matrix[r][c] += basis[r] * basis[c];
    }
    moments[0] += x * x;
    moments[1] += x * z;
    moments[2] += z * z;
  }
  const double determinant = moments[0] * moments[2] - moments[1] * moments[1];
  const double trace = moments[0] + moments[2];
  if (!(trace > 0)) return std::nullopt;
  Vec3 normal;
  if (determinant > kCollinear * trace * trace) {
    if (!solve_small_system<4>(matrix, right)) return std::nullopt;
    normal = right[0] * u + right[1] * w + right[2] * tangent;  // the gradient at the vertex
    // The points' distances to the fitted surface, about its value over its gradient there: a
    // surface the model does not describe (a cylinder across the line, a free-form face) says
    // nothing reliable.
    double squares = 0;
    for (const Vec3& q : neighbors) {
      const auto [x, y, z] = coordinates(q);
      const double value = x * x + z * z + right[0] * x + right[1] * z + right[2] * y + right[3] * y * y;
      squares += value * value;
    }
    if (!(std::sqrt(squares / static_cast<double>(neighbors.size())) <= kMaxResidual * norm(normal))) return std::nullopt;
  } else {
    const double angle = 0.5 * std::atan2(2 * moments[1], moments[0] - moments[2]);  // the line's direction
    normal = -std::sin(angle) * u + std::cos(angle) * w;
  }
  if (!(norm(normal) > 0)) return std::nullopt;
  normal *= 1 / norm(normal);
  return dot(normal, initial) < 0 ? -normal : normal;
}

}  // namespace hocav
