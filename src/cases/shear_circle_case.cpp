#include "cases/shear_circle_case.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cases/parameter_checks.hpp"
#include "cases/polar_annulus.hpp"
#include "cases/radial_layers.hpp"
#include "cases/target_resolution.hpp"

namespace hocav {

Mesh<2> generate_shear_circle_annulus(double inner_radius, double outer_radius, const AnalyticMetricSpec& metric) {
  if (metric.name != "shear-circle") throw Error("the shear-circle case needs the shear-circle metric, not " + metric.name);
  if (metric.origin != std::array<double, 3>{0, 0, 0}) throw Error("the shear-circle case is centred at the origin");
  check_shell_radii(inner_radius, outer_radius);
  if (!(inner_radius < metric.radius && metric.radius < outer_radius))
    throw Error("the shear layer's radius " + number_text(metric.radius) + " must lie between r-in and r-out");
  // Sizes along the positive x axis, where e_r = (1, 0): h_r = M₁₁^(−1/2), h_t = M₂₂^(−1/2).
  auto radial_size = [&metric](double r) { return 1 / std::sqrt(analytic_metric<2>(metric, Vec2{{r, 0}})(0, 0)); };
  const double tangential_size = 1 / std::sqrt(analytic_metric<2>(metric, Vec2{{metric.radius, 0}})(1, 1));
  const double sectors = std::ceil(2 * std::numbers::pi * metric.radius / tangential_size);
  if (!(sectors <= kMaximumCaseElements)) throw Error("the shear-circle metric's tangential size is too small");
  const std::vector<double> radii = unit_layer_radii(inner_radius, outer_radius, radial_size);
  if (polar_annulus_triangle_count(static_cast<int>(sectors), radii.size()) > kMaximumCaseElements)
    throw Error("the shear-circle mesh would exceed " + number_text(kMaximumCaseElements) + " triangles: h-min or h-max is too small");
  return generate_polar_annulus(std::max(3, static_cast<int>(sectors)), radii);
}

}  // namespace hocav
