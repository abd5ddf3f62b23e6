// Certified bounds of J by depth-first subdivision of its Bernstein form (docs/method.md §8).
#include "bezier/jacobian_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "bezier/bernstein_subdivision.hpp"

namespace hocav {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <int D>
double min_coefficient(const JacobianCoefficients<D>& coefficients) {
  return *std::min_element(coefficients.begin(), coefficients.end());
}

// The corners come first in the coefficient order; they are exact values of the polynomial.
template <int D>
double min_corner(const JacobianCoefficients<D>& coefficients) {
  return *std::min_element(coefficients.begin(), coefficients.begin() + D + 1);
}

template <int D>
bool all_finite(const JacobianCoefficients<D>& coefficients) {
  return std::all_of(coefficients.begin(), coefficients.end(), [](double c) { return std::isfinite(c); });
}

enum class Visit { kLeaf, kSplit, kStop };

template <int D>
struct SubdivisionNode {
  JacobianCoefficients<D> coefficients;
  double minimum;  // of the coefficients: a lower bound of the polynomial on the sub-simplex
  int depth;
};

// Depth-first walk of the subdivision tree with an explicit fixed-size stack, smallest-minimum child
// first. visit(coefficients, minimum, can_split) returns what to do with a sub-simplex; can_split is
// false at the depth limit or once the split budget is spent. Returns the number of splits.
template <int D, class Visitor>
int walk_subdivision(const JacobianCoefficients<D>& root, const SubdivisionLimits& limits, Visitor&& visit) {
  constexpr int kChildren = kSubdivisionChildCount<D>;
  const int max_depth = std::clamp(limits.max_depth, 0, kMaxSubdivisionDepth);
  // Depth first: at most kChildren − 1 pending siblings per level, plus the children of the last.
  std::array<SubdivisionNode<D>, (kChildren - 1) * kMaxSubdivisionDepth + 1> stack;
  SubdivisionChildren<D> children;
  int size = 0, splits = 0;
  stack[size++] = {root, min_coefficient<D>(root), 0};
  while (size > 0) {
    const SubdivisionNode<D> node = stack[--size];
    const bool can_split = node.depth < max_depth && splits < limits.max_subdivisions;
    const Visit decision = visit(node.coefficients, node.minimum, can_split);
    if (decision == Visit::kStop) break;
    if (decision == Visit::kLeaf) continue;
    ++splits;
    subdivide_bernstein<D>(node.coefficients, children);
    std::array<double, kChildren> minima;
    std::array<int, kChildren> order;
    for (int child = 0; child < kChildren; ++child) minima[child] = min_coefficient<D>(children[child]);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return minima[a] > minima[b]; });
    for (int child : order) stack[size++] = {children[child], minima[child], node.depth + 1};
  }
  return splits;
}

// Min and max bounds of J itself (not normalized); the max from the minimum of −J.
template <int D>
JacobianRange jacobian_range(const JacobianCoefficients<D>& coefficients, const RefinementOptions& options) {
  double magnitude = 0.0;
  for (double c : coefficients) magnitude = std::max(magnitude, std::abs(c));
  const double tolerance = options.relative_tolerance * magnitude;
  JacobianCoefficients<D> negated;
  for (int i = 0; i < kJacobianCoefficientCount<D>; ++i) negated[i] = -coefficients[i];
  const MinimumBounds min = bound_bernstein_minimum<D>(coefficients, tolerance, options.limits);
  const MinimumBounds negated_min = bound_bernstein_minimum<D>(negated, tolerance, options.limits);
  return {min.lower, min.upper, -negated_min.upper, -negated_min.lower, min.converged && negated_min.converged};
}

}  // namespace

template <int D>
JacobianCertificate certify_bernstein_above(const JacobianCoefficients<D>& coefficients, double threshold,
                                            const SubdivisionLimits& limits) {
  if (!all_finite<D>(coefficients)) return {false, true, 0};
  JacobianCertificate certificate{true, true, 0};
  auto visit = [&](const JacobianCoefficients<D>& c, double minimum, bool can_split) {
    if (minimum > threshold) return Visit::kLeaf;
    if (min_corner<D>(c) <= threshold) {
      certificate = {false, true, 0};
      return Visit::kStop;
    }
    if (can_split) return Visit::kSplit;
    certificate = {false, false, 0};
    return Visit::kStop;
  };
  certificate.subdivisions = walk_subdivision<D>(coefficients, limits, visit);
  return certificate;
}

template <int D>
JacobianCertificate certify_min_normalized_jacobian(const P2Element<D>& element, double floor, const SubdivisionLimits& limits) {
  const ElementJacobian<D> jacobian = element_jacobian(element);
  // Compare J with floor·|J_straight| rather than dividing: no division, and a flat straight element
  // (|J_straight| = 0, normalized J infinite) simply asks for J > 0. The rounding margin keeps a
  // computed coefficient that is only positive by rounding from certifying anything.
  const double threshold = floor * std::abs(jacobian.straight_jacobian) + jacobian.rounding_margin;
  const auto& coefficients = jacobian.coefficients;
  if (std::all_of(coefficients.begin(), coefficients.end(), [&](double c) { return c > threshold; })) return {true, true, 0};
  return certify_bernstein_above<D>(coefficients, threshold, limits);
}

template <int D>
MinimumBounds bound_bernstein_minimum(const JacobianCoefficients<D>& coefficients, double tolerance, const SubdivisionLimits& limits) {
  MinimumBounds bounds{kInfinity, min_corner<D>(coefficients), false, 0};
  auto visit = [&](const JacobianCoefficients<D>& c, double minimum, bool can_split) {
    bounds.upper = std::min(bounds.upper, min_corner<D>(c));
    // A sub-simplex that cannot lower the bounds' gap below the tolerance is final.
    if (minimum >= bounds.upper - tolerance || !can_split) {
      bounds.lower = std::min(bounds.lower, minimum);
      return Visit::kLeaf;
    }
    return Visit::kSplit;
  };
  bounds.subdivisions = walk_subdivision<D>(coefficients, limits, visit);
  bounds.converged = bounds.upper - bounds.lower <= tolerance;
  return bounds;
}

template <int D>
JacobianRange normalized_jacobian_range(const P2Element<D>& element, const RefinementOptions& options) {
  const ElementJacobian<D> jacobian = element_jacobian(element);
  const JacobianRange range = jacobian_range<D>(jacobian.coefficients, options);
  const double straight = jacobian.straight_jacobian;
  return {normalize_jacobian(range.min_lower, straight), normalize_jacobian(range.min_upper, straight),
          normalize_jacobian(range.max_lower, straight), normalize_jacobian(range.max_upper, straight), range.converged};
}

template <int D>
JacobianQuality jacobian_quality(const P2Element<D>& element, const RefinementOptions& options) {
  const ElementJacobian<D> jacobian = element_jacobian(element);
  const JacobianRange range = jacobian_range<D>(jacobian.coefficients, options);
  return {normalize_jacobian(range.min_lower, jacobian.straight_jacobian), scaled_jacobian(range.min_lower, range.max_upper)};
}

double scaled_jacobian(double min_lower, double max_upper) {
  if (max_upper != 0.0) return min_lower / std::abs(max_upper);
  return min_lower < 0.0 ? -kInfinity : 0.0;
}

template JacobianCertificate certify_bernstein_above(const JacobianCoefficients<2>&, double, const SubdivisionLimits&);
template JacobianCertificate certify_bernstein_above(const JacobianCoefficients<3>&, double, const SubdivisionLimits&);
template JacobianCertificate certify_min_normalized_jacobian(const P2Element<2>&, double, const SubdivisionLimits&);
template JacobianCertificate certify_min_normalized_jacobian(const P2Element<3>&, double, const SubdivisionLimits&);
template MinimumBounds bound_bernstein_minimum(const JacobianCoefficients<2>&, double, const SubdivisionLimits&);
template MinimumBounds bound_bernstein_minimum(const JacobianCoefficients<3>&, double, const SubdivisionLimits&);
template JacobianRange normalized_jacobian_range(const P2Element<2>&, const RefinementOptions&);
template JacobianRange normalized_jacobian_range(const P2Element<3>&, const RefinementOptions&);
template JacobianQuality jacobian_quality(const P2Element<2>&, const RefinementOptions&);
template JacobianQuality jacobian_quality(const P2Element<3>&, const RefinementOptions&);

}  // namespace hocav
