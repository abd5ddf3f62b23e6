#include "curve/quadrature.hpp"

#include <cmath>
#include <numbers>

#include "base/error.hpp"

namespace hocav {

const QuadratureRule& trapezoid_rule() {
  static const QuadratureRule rule{"trapezoid-3", {0.0, 0.5, 1.0}, {0.25, 0.5, 0.25}};
  return rule;
}

const QuadratureRule& simpson_rule() {
  static const QuadratureRule rule{"simpson-3", {0.0, 0.5, 1.0}, {1.0 / 6, 4.0 / 6, 1.0 / 6}};
  return rule;
}

QuadratureRule gauss_legendre_rule(int points) {
  if (points < 1 || points > 128) throw Error("Gauss-Legendre rule: 1 to 128 points, got " + std::to_string(points));
  QuadratureRule rule{"gauss-legendre-" + std::to_string(points), std::vector<double>(points), std::vector<double>(points)};
  // Roots of P_n by Newton from the classical cosine guesses; weights 2 / ((1 − x²) P_n'(x)²) on [−1, 1].
  for (int i = 0; i < (points + 1) / 2; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (points + 0.5));
    double derivative = 1;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= points; ++k) {
        double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = points * (x * p1 - p0) / (x * x - 1);
      double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    double weight = 2 / ((1 - x * x) * derivative * derivative);
    rule.nodes[i] = 0.5 * (1 - x);
    rule.nodes[points - 1 - i] = 0.5 * (1 + x);
    rule.weights[i] = rule.weights[points - 1 - i] = 0.5 * weight;
  }
  return rule;
}

const QuadratureRule& high_precision_rule() {
  static const QuadratureRule rule = gauss_legendre_rule(16);
  return rule;
}

}  // namespace hocav

namespace hocav {

const QuadratureRule& default_optimizer_rule() { return simpson_rule(); }

QuadratureRule quadrature_rule_named(const std::string& name) {
  if (name == "trapezoid") return trapezoid_rule();
  if (name == "simpson") return simpson_rule();
  if (name.starts_with("gauss-") && name.size() > 6 && name.find_first_not_of("0123456789", 6) == std::string::npos &&
      name.size() < 10)
    return gauss_legendre_rule(std::stoi(name.substr(6)));
  throw Error("unknown quadrature '" + name + "' (trapezoid, simpson, gauss-N)");
}

}  // namespace hocav
