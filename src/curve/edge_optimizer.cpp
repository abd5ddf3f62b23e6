#include "curve/edge_optimizer.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "base/lazy_slot.hpp"
#include "curve/kink_descent.hpp"
#include "geom/orthonormal_complement.hpp"

namespace hocav {
namespace {

// A node on a kink descends when some one-sided slope of ℓ in the bisector plane falls below minus this
// fraction of ℓ/|AB|: a thousand times the error of the slopes (round-off, and the ~1e-10 off-face
// tolerance). A slope above it gains at most 5e-9 ℓ over the longest step (|AB|/2).
constexpr double kKinkSlopeMargin = 1e-8;

// A rejected trial is retried at its element's face only if that is this far along the step: from on a face
// (a kink iterate), the step out of it is left to halving.
constexpr double kLeastFaceFraction = 1e-3;

// The fraction of the segment from x (in the frame's element) to y that lies in the element: 1 when y is
// in it too.
template <int D>
double fraction_inside(const typename MetricField<D>::ElementFrame& frame, const Vec<D>& x, const Vec<D>& y) {
  const Barycentrics<D> at_x = barycentric_coordinates<D>(frame.barycentric_gradients, frame.origin, x);
  const Barycentrics<D> at_y = barycentric_coordinates<D>(frame.barycentric_gradients, frame.origin, y);
  double fraction = 1;
  for (int i = 0; i <= D; ++i)
    if (at_y[i] < 0 && at_x[i] > at_y[i]) fraction = std::min(fraction, std::max(at_x[i], 0.0) / (at_x[i] - at_y[i]));
  return fraction;
}

// The Newton step of ℓ in the bisector plane (spanned by `basis`): gradient and Hessian in the plane, the
// Hessian shifted until positive definite (between Newton and gradient descent). `shift` is 0 for a pure
// Newton step; false when no shift makes it definite (non-finite values).
template <int D>
bool newton_step_in_plane(const EdgeLengthValue<D>& value, const std::array<Vec<D>, D - 1>& basis, Vec<D>& step, double& shift) {
  if constexpr (D == 2) {
    const double g = dot(value.gradient, basis[0]), h = dot(basis[0], value.hessian * basis[0]);
    const double scale = std::max(1e-300, std::abs(h));
    shift = 0;
    while (!(h + shift > 0)) {
      shift = shift == 0 ? 1e-8 * scale : 10 * shift;
      if (!std::isfinite(shift)) return false;
    }
    step = (-g / (h + shift)) * basis[0];
  } else {
    const double g0 = dot(value.gradient, basis[0]), g1 = dot(value.gradient, basis[1]);
    const Vec3 h_basis0 = value.hessian * basis[0];
    const double h00 = dot(basis[0], h_basis0), h01 = dot(basis[1], h_basis0);
    const double h11 = dot(basis[1], value.hessian * basis[1]);
    const double scale = std::max(1e-300, std::abs(h00 + h11));
    // Cholesky of [[h00 + σ, h01], [h01, h11 + σ]].
    shift = 0;
    for (;;) {
      const double a = h00 + shift;
      const double c = a > 0 ? h11 + shift - h01 * h01 / a : 0;
      if (a > 0 && c > 0) {
        // Solve: p1 from the Schur complement, then p0.
        const double p1 = (-g1 + h01 * g0 / a) / c;
        const double p0 = (-g0 - h01 * p1) / a;
        step = p0 * basis[0] + p1 * basis[1];
        break;
      }
      shift = shift == 0 ? 1e-8 * scale : 10 * shift;
      if (!std::isfinite(shift)) return false;
    }
  }
  return true;
}

}  // namespace

template <int D>
EdgeOptimization<D> optimize_edge_length(const MetricField<D>& field, const EdgeEndpoint<D>& end_a, const EdgeEndpoint<D>& end_b,
                                         const Vec<D>& start, Index hint, const EdgeOptimizerOptions& options, LocatorScratch& scratch) {
  using Order = typename EdgeLengthFunction<D>::Order;
  const EdgeLengthFunction<D> function(end_a, end_b, options.rule);
  EdgeLengthScratch<D> length_scratch;  // the decompositions of the last point, for its next evaluation
  const Vec<D>& a = end_a.position;
  const Vec<D>& b = end_b.position;
  const double edge_size = norm(b - a);
  const Vec<D> midpoint = 0.5 * (a + b);
  const double max_displacement = options.max_displacement * edge_size;
  EdgeOptimization<D> result;
  // The node moves in the bisector plane of the edge: sliding it along the edge changes only the
  // parametrization, which the 3-point rule cannot see (a flat valley in a uniform metric).
  const Vec<D> direction = (1 / edge_size) * (b - a);
  const std::array<Vec<D>, D - 1> basis = orthonormal_complement(direction);
  const Vec<D> first = start - dot(start - midpoint, direction) * direction;  // start moved onto the plane

  // ∂L^L/∂X is constant in a back element, and successive iterates often stay in one: its frame serves their
  // localization and derivatives.
  LazySlot<typename MetricField<D>::ElementFrame> frame;
  auto frame_of = [&](Index element) -> const typename MetricField<D>::ElementFrame& {
    if (!frame || (*frame).element != element) frame.emplace(field.element_frame(element));
    return *frame;
  };

  // ℓ at an accepted node with what its next step needs. On a kink, the Newton model of one element misses
  // the other elements' slopes: the gradient parts give them all (kink_descent.hpp). When none descends
  // beyond round-off (a strict minimum, or a stationary point such as the straight edge in a uniform
  // metric, where a descent could only be of second order) the node is taken as optimal; else the next step
  // follows the steepest descent, in the model of the element it enters, which needs the curvature along
  // it only, not the Hessian.
  EdgeLengthValue<D> value;
  KinkDescent<D> kink;
  SymMat<D> node_log_metric;
  bool optimal = false;
  auto arrive = [&](const Vec<D>& node, const typename MetricField<D>::Sample& at) {
    result.node = node;
    result.back_element = at.where.element;
    node_log_metric = at.log_metric;
    kink = {};
    if (on_back_mesh_face(at.where)) {
      // The kink analysis needs only the gradient's parts, which no element's ∂L^L/∂X enters (a constant
      // zero: a temporary would be cleared at every call).
      static const std::array<SymMat<D>, D> no_log_metric_gradient{};
      value = function.evaluate(node, at.log_metric, no_log_metric_gradient, Order::kGradient, length_scratch);
      kink = steepest_descent_on_kink(field, at.where, direction, value);
      const double margin = kKinkSlopeMargin * value.length / edge_size;
      optimal = kink.analysed && kink.whole_plane && kink.slope >= -margin;
      if (optimal) return;
      if (kink.analysed && kink.slope < -margin) {
        result.back_element = kink.element;  // X lies on its face too
        return;
      }
      kink = {};  // at the boundary, no descent into the domain: Newton's model decides
    }
    value = function.evaluate(node, at.log_metric, frame_of(result.back_element).log_metric_gradient, Order::kHessian, length_scratch);
  };
  // The slope and curvature of ℓ along d in the model of the node's element.
  auto log_metric_derivative = [&](const Vec<D>& d) {
    const auto& gradient = frame_of(result.back_element).log_metric_gradient;
    SymMat<D> derivative;
    for (int i = 0; i < D; ++i) derivative += d[i] * gradient[i];
    return derivative;
  };
  auto slope_along = [&](const Vec<D>& d) {
    return kink.analysed ? dot(value.node_gradient, d) + frobenius_dot(value.log_node_gradient, log_metric_derivative(d))
                         : dot(value.gradient, d);
  };
  auto curvature_along = [&](const Vec<D>& d) {
    return kink.analysed ? function.curvature(result.node, node_log_metric, d, log_metric_derivative(d), length_scratch)
                         : dot(d, value.hessian * d);
  };
  arrive(first, field.sample(first, hint, scratch));
  ++result.evaluations;
  const double initial_length = value.length;
  const bool starts_straight = norm(first - midpoint) == 0;
  double trust = 0.25 * edge_size;

  for (; !optimal && result.iterations < options.max_iterations; ++result.iterations) {
    Vec<D> step;
    double predicted;   // the decrease the step's model predicts
    bool convex_model;  // and whether that model is convex
    if (kink.analysed) {
      // Along d* the model is ℓ + s*t + κt²/2, κ of the element d* enters.
      const double curvature = curvature_along(kink.direction);
      convex_model = curvature > 0;
      step = (convex_model ? -kink.slope / curvature : trust) * kink.direction;
      predicted = convex_model ? 0.5 * kink.slope * kink.slope / curvature : -kink.slope * trust;
    } else {
      double shift;
      if (!newton_step_in_plane(value, basis, step, shift)) return result;
      predicted = -0.5 * dot(value.gradient, step);  // the step lies in the plane
      convex_model = shift == 0;
    }
    // On the displacement bound, a step out of it would be clipped back onto the bound in another direction,
    // which need not descend: the node moves along the bound instead (in 3D; the 2D bound is two points), the
    // way that descends in the model of its element, as far as that model goes (trials are clipped onto the
    // bound). Where neither way descends the node is optimal on the bound.
    const Vec<D> outward = result.node - midpoint;
    const double radius = norm(outward);
    const bool along_bound = radius >= (1 - 1e-9) * max_displacement && dot(step, outward) > 0;
    if (along_bound) {
      if constexpr (D == 2) {
        break;
      } else {
        Vec<D> tangent = step - (dot(step, outward) / (radius * radius)) * outward;
        // A step straight out (a kink's d* continued from the midpoint): the tangent is the plane's other axis.
        if (norm(tangent) <= 1e-12 * norm(step)) tangent = cross(direction, outward);
        tangent = (1 / norm(tangent)) * tangent;
        double slope = slope_along(tangent);
        if (slope > 0) tangent = -1.0 * tangent, slope = -slope;
        if (!(slope < 0)) break;
        // Along the bound's arc, s from the node, the node also moves in by s²/(2r): ℓ gains −(∂ℓ/∂r) s²/(2r)
        // over the tangent line's model, a curvature that bounds the step when ℓ pulls outward.
        const double curvature = curvature_along(tangent) + std::max(0.0, -slope_along((1 / radius) * outward)) / radius;
        convex_model = curvature > 0;
        const double length = convex_model ? std::min(max_displacement, -slope / curvature) : max_displacement;
        step = length * tangent;
        predicted = -(slope * length + 0.5 * curvature * length * length);
      }
    }
    const double step_size = norm(step);
    const bool along_kink = kink.analysed;
    // Converged: a step this small, or one whose predicted decrease is this small, only meets
    // round-off, where every halving of the line search would fail.
    if (step_size < options.step_tolerance * edge_size || predicted < options.decrease_tolerance * value.length) break;
    // Futile (options.futile_model_factor): the edge would stay straight. Newton's model at the start, inside
    // one element, may miss other elements' descent across a kink: only after an accepted step then.
    if (options.futile_model_factor > 0 && starts_straight && (result.iterations > 0 || kink.analysed) && convex_model &&
        (initial_length - value.length) + options.futile_model_factor * predicted < options.min_relative_decrease * initial_length)
      break;
    if (step_size > trust) step = (trust / step_size) * step;

    // Backtracking: accept the first trial that decreases ℓ (kinks rule out stricter tests). Along a
    // smooth ray of descent slope (σ < 0, Δ(s) = σs + κs²/2), a rejected increase Δ(s) > 0 shrinks more
    // than 4-fold when s is halved; a small one (< 1e-3 ℓ, where that model holds) that shrinks less
    // grows to first order: the direction ascends from the node, which sits on a kink (a back-mesh face
    // or edge), and further halvings would fail too. The node is then taken as the optimum.
    // A rejected first trial outside the node's element is followed by the point where the step leaves it,
    // exactly on the face: ℓ has a kink there, which the element's model did not see, and from a face the
    // kink analysis can follow a valley along it (instead of zigzagging across it).
    bool accepted = false;
    double rejected_increase = 0, moved = 0;
    for (int halving = 0; halving < 12; ++halving, step = 0.5 * step) {
      Vec<D> trial = result.node + step;
      Vec<D> offset = trial - midpoint;
      double displacement = norm(offset);
      if (displacement > max_displacement) trial = midpoint + (max_displacement / displacement) * offset;
      auto trial_sample = field.sample(trial, frame_of(result.back_element), scratch);
      ++result.evaluations;
      double trial_length = function.length(trial, trial_sample.log_metric, length_scratch);
      if (trial_length < value.length) {
        accepted = true;
        moved = norm(trial - result.node);
        arrive(trial, trial_sample);
        break;
      }
      const double increase = trial_length - value.length;
      if (rejected_increase > 0 && rejected_increase < 1e-3 * value.length && increase > 0.25 * rejected_increase) break;
      rejected_increase = increase;
      // (Not along the bound: the segment to a trial clipped onto it cuts inside, where ℓ grows fast.)
      if (halving == 0 && !along_bound) {
        const double leaving = fraction_inside(frame_of(result.back_element), result.node, trial);
        if (leaving > kLeastFaceFraction && leaving < 1) {
          step = (2 * leaving) * (trial - result.node);  // halved by the loop
          rejected_increase = 0;
        }
      }
    }
    if (!accepted || moved < options.step_tolerance * edge_size) {
      if (accepted) ++result.iterations;
      break;
    }
    // Twice the step accepted. A step along d* ends at the minimum of a one-dimensional model: a short one
    // says nothing of the region where the next (Newton) model holds, so it only ever widens the radius.
    const double widened = std::min(0.5 * edge_size, 2 * moved);
    trust = along_kink ? std::max(trust, widened) : widened;
  }
  result.length = value.length;

  // Worth curving? Compare with the straight edge in the same rule.
  double straight_length = starts_straight ? initial_length
                                           : function.length(midpoint, field.sample(midpoint, hint, scratch).log_metric, length_scratch);
  if (result.length > (1 - options.min_relative_decrease) * straight_length) {
    result.node = midpoint;
    result.length = straight_length;
  }

  if (options.measure_gain) {
    result.straight_length = high_precision_edge_length(field, end_a, end_b, midpoint, hint);
    result.optimized_length = high_precision_edge_length(field, end_a, end_b, result.node, result.back_element);
    result.gain = 1 - result.optimized_length / result.straight_length;
  }
  return result;
}

template <int D>
double high_precision_edge_length(const MetricField<D>& field, const EdgeEndpoint<D>& a, const EdgeEndpoint<D>& b, const Vec<D>& node,
                                  Index hint) {
  return high_precision_edge_length(a, b, node, field.log_metric_at(node, hint));
}

template <int D>
double high_precision_edge_length(const EdgeEndpoint<D>& a, const EdgeEndpoint<D>& b, const Vec<D>& node, const SymMat<D>& log_node) {
  return EdgeLengthFunction<D>(a, b, high_precision_rule()).length(node, log_node);
}

#define HOCAV_INSTANTIATE(D)                                                                                                               \
  template EdgeOptimization<D> optimize_edge_length(const MetricField<D>&, const EdgeEndpoint<D>&, const EdgeEndpoint<D>&, const Vec<D>&,  \
                                                    Index, const EdgeOptimizerOptions&, LocatorScratch&);                                  \
  template double high_precision_edge_length(const MetricField<D>&, const EdgeEndpoint<D>&, const EdgeEndpoint<D>&, const Vec<D>&, Index); \
  template double high_precision_edge_length(const EdgeEndpoint<D>&, const EdgeEndpoint<D>&, const Vec<D>&, const SymMat<D>&);
HOCAV_INSTANTIATE(2)
HOCAV_INSTANTIATE(3)
#undef HOCAV_INSTANTIATE

}  // namespace hocav
