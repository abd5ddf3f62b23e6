// Quadrature rules on [0, 1] for the length integral of a P2 edge (docs/method.md §5), and the rules by
// name for the command line.
//
// The optimizer's default is Simpson's rule: the paper's three points (t = 0, 1/2, 1: one
// back-mesh interpolation and one exponential per evaluation) with weights 1/6, 4/6, 1/6, exact for
// cubics. The paper's trapezoid weights (1/4, 1/2, 1/4) are exact for linear integrands only, and
// the optimizer exploits their error: on the UGAWG "linear" case (a field with no intrinsic
// curvature) trapezoid-optimized edges bend for a 16-point gain of −0.01% and pull the average
// normalized Jacobian down to 0.78, where Simpson leaves them straight (1.00) at the same cost and
// gains more where curvature is real (docs/benchmarks.md).
#pragma once

#include <functional>
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

// t = 0, 1/2, 1 with weights 1/6, 4/6, 1/6: the same single interpolation as the trapezoid rule,
// exact for cubics.
const QuadratureRule& simpson_rule();

// n-point Gauss–Legendre on [0, 1] (exact for polynomials of degree 2n − 1), 1 <= n <= 128.
QuadratureRule gauss_legendre_rule(int points);

// The rule used for every reported length and gain (docs/method.md §5: >= 16 points).
const QuadratureRule& high_precision_rule();

// The optimizer's default (Simpson).
const QuadratureRule& default_optimizer_rule();

// "trapezoid", "simpson" or "gauss-N"; throws Error for anything else.
QuadratureRule quadrature_rule_named(const std::string& name);

// ∫₀¹ f to a relative tolerance, by globally adaptive Gauss–Kronrod (7 Gauss points nested in 15
// Kronrod points, exact for degree 22 on each piece): the piece with the largest error estimate
// |K15 − G7| is bisected until the estimates sum to at most tolerance·|integral| or `max_pieces` is
// reached, starting from `initial_pieces` equal pieces. Kinks of f (the metric crossing back-mesh
// faces) are isolated by bisection; on a piece with kinks K15 and G7 may agree by chance, which more
// initial pieces guard against. Not a QuadratureRule: its nodes depend on f, so it cannot serve the
// optimizer's closed-form derivatives.
struct AdaptiveIntegral {
  double value = 0;
  double error_estimate = 0;  // Σ |K15 − G7| over the final pieces
  int evaluations = 0;        // calls of f: 15 per piece
  bool converged = false;     // error_estimate <= tolerance·|value|
};
AdaptiveIntegral adaptive_integral(const std::function<double(double)>& f, double tolerance, int initial_pieces = 1, int max_pieces = 1000);

}  // namespace hocav
