// Quadrature rules on [0, 1] for the length integral of a P2 edge (math.md §5): the 3-point
// trapezoid rule the optimizer minimizes, and Gauss–Legendre rules for diagnostics and gains.
#pragma once

#include <string>
#include <vector>

namespace hocav {

struct QuadratureRule {
  std::string name;
  std::vector<double> nodes;    // in [0, 1]
  std::vector<double> weights;  // summing to 1
};

// t = 0, 1/2, 1 with weights 1/4, 1/2, 1/4: one back-mesh interpolation per evaluation.
const QuadratureRule& trapezoid_rule();

// n-point Gauss–Legendre on [0, 1] (exact for polynomials of degree 2n − 1), 1 <= n <= 128.
QuadratureRule gauss_legendre_rule(int points);

// The rule used for every reported length and gain (math.md §5: >= 16 points).
const QuadratureRule& high_precision_rule();

}  // namespace hocav
