// Certified validity and quality of P2 elements: bounds of the Jacobian determinant J by
// subdivision of its Bernstein form (docs/method.md §8).
//
// Over any sub-simplex, the minimum of J's coefficients there is a lower bound of J, and the corner
// coefficients are values J takes. Subdividing (bernstein_subdivision.hpp) shrinks the gap between
// the two quadratically with the sub-simplex size, so a false negative of the coefficients (a
// negative coefficient while J > 0) disappears after a few levels.
//
// Certification rule: J > floor·|J_straight| everywhere is claimed only when every leaf of the
// subdivision has all its coefficients above the threshold. A corner coefficient at or below it
// decides the other way (J reaches it there). If the depth or split budget runs out first, the
// answer is "undecided", and undecided is NOT certified: a valid element may be refused, an invalid
// one is never accepted. Floating-point rounding is covered by raising the threshold by a bound of
// the coefficients' rounding error (ElementJacobian::rounding_margin, ~1e-13 of the element's size^D).
#pragma once

#include "bezier/jacobian_coefficients.hpp"
#include "bezier/p2_element.hpp"

namespace hocav {

inline constexpr int kMaxSubdivisionDepth = 16;

struct SubdivisionLimits {
  int max_depth = 8;           // levels below the element; clamped to [0, kMaxSubdivisionDepth]
  int max_subdivisions = 256;  // sub-simplices split in all, which bounds the work on degenerate elements
};

struct JacobianCertificate {
  bool certified = false;  // proven: J > threshold on the whole element
  bool decided = false;    // settled either way; false when the limits were hit first (then not certified)
  int subdivisions = 0;    // sub-simplices split; 0 on the fast path
};

// Is the polynomial with these Bernstein coefficients > threshold on the whole simplex?
template <int D>
JacobianCertificate certify_bernstein_above(const JacobianCoefficients<D>& coefficients, double threshold,
                                            const SubdivisionLimits& limits = {});

// Is J / |J_straight| > floor on the whole element? Tested as J > floor·|J_straight| + rounding margin.
// Fast path: all coefficients above the threshold, no subdivision.
template <int D>
JacobianCertificate certify_min_normalized_jacobian(const P2Element<D>& element, double floor, const SubdivisionLimits& limits = {});

// The cavity operator's question: true only when proven.
template <int D>
bool certify_min_normalized_jacobian_above(const P2Element<D>& element, double floor, const SubdivisionLimits& limits = {}) {
  return certify_min_normalized_jacobian(element, floor, limits).certified;
}

struct MinimumBounds {
  double lower = 0.0;      // ≤ the minimum (the smallest coefficient over the leaves)
  double upper = 0.0;      // ≥ the minimum, and a value the polynomial takes (a leaf corner)
  bool converged = false;  // upper − lower ≤ tolerance
  int subdivisions = 0;
};

// Bounds of the minimum of the polynomial over the simplex, refined depth first (most promising
// sub-simplex first) until upper − lower ≤ tolerance or the limits are hit.
template <int D>
MinimumBounds bound_bernstein_minimum(const JacobianCoefficients<D>& coefficients, double tolerance, const SubdivisionLimits& limits);

struct RefinementOptions {
  double relative_tolerance = 1e-3;  // wanted gap of the bounds, relative to max |N_γ| (≈ max |J|)
  SubdivisionLimits limits{12, 4096};
};

// For figures a user reads (reports, .vtu): bounds within 1e-6, so an element certified just above
// a floor does not read below it, and the figures match gmsh's element by element.
inline constexpr RefinementOptions kReportedRefinement{1e-6, {16, 1 << 14}};

// Bounds of min and max of J / |J_straight| over the element: min_lower ≤ min ≤ min_upper and
// max_lower ≤ max ≤ max_upper.
struct JacobianRange {
  double min_lower = 0.0, min_upper = 0.0;
  double max_lower = 0.0, max_upper = 0.0;
  bool converged = false;  // both gaps within tolerance
};

template <int D>
JacobianRange normalized_jacobian_range(const P2Element<D>& element, const RefinementOptions& options = {});

struct JacobianQuality {
  double min_normalized_jacobian = 0.0;  // min of J / |J_straight| (its refined lower bound); ≤ 0: invalid
  double scaled_jacobian = 0.0;          // min J / max J as gmsh's minJ/maxJ (refined bounds); 1 straight
};

template <int D>
JacobianQuality jacobian_quality(const P2Element<D>& element, const RefinementOptions& options = {});

// min J / max J from bounds of both. For the usual max J > 0 it is min_lower / max_upper; an element
// with J ≤ 0 everywhere gets min / |max| (−1 for an inverted straight element).
double scaled_jacobian(double min_lower, double max_upper);

}  // namespace hocav
