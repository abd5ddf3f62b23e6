#include "curve/edge_optimizer.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "curve/kink_minimum.hpp"

namespace hocav {
namespace {

// A start on a kink is declared optimal when every one-sided slope of ℓ in the bisector plane exceeds this
// fraction of ℓ/|AB|: a thousand times the error of the slopes (round-off, and the ~1e-10 off-face tolerance).
constexpr double kKinkSlopeMargin = 1e-8;

template <int D>
double high_precision_length(const MetricField<D>& field, const EdgeEndpoint<D>& a, const EdgeEndpoint<D>& b,
                             const Vec<D>& node, Index hint) {
  return EdgeLengthFunction<D>(a, b, high_precision_rule()).length(node, field.log_metric_at(node, hint));
}

// Solves H p = −g for a symmetric positive definite H by Cholesky; false when H is not.
template <int D>
bool newton_direction(const SymMat<D>& h, const Vec<D>& g, Vec<D>& p) {
  double l[D][D] = {};
  for (int j = 0; j < D; ++j) {
    double diagonal = h(j, j);
    for (int k = 0; k < j; ++k) diagonal -= l[j][k] * l[j][k];
    if (!(diagonal > 0)) return false;
    l[j][j] = std::sqrt(diagonal);
    for (int i = j + 1; i < D; ++i) {
      double value = h(i, j);
      for (int k = 0; k < j; ++k) value -= l[i][k] * l[j][k];
      l[i][j] = value / l[j][j];
    }
  }
  Vec<D> y;
  for (int i = 0; i < D; ++i) {
    double value = -g[i];
    for (int k = 0; k < i; ++k) value -= l[i][k] * y[k];
    y[i] = value / l[i][i];
  }
  for (int i = D - 1; i >= 0; --i) {
    double value = y[i];
    for (int k = i + 1; k < D; ++k) value -= l[k][i] * p[k];
    p[i] = value / l[i][i];
  }
  return true;
}

}  // namespace

template <int D>
EdgeOptimization<D> optimize_edge_length(const MetricField<D>& field, const EdgeEndpoint<D>& end_a,
                                         const EdgeEndpoint<D>& end_b, const Vec<D>& start, Index hint,
                                         const EdgeOptimizerOptions& options) {
  using Order = typename EdgeLengthFunction<D>::Order;
  const EdgeLengthFunction<D> function(end_a, end_b, *options.rule);
  const Vec<D>& a = end_a.position;
  const Vec<D>& b = end_b.position;
  const double edge_size = norm(b - a);
  const Vec<D> midpoint = 0.5 * (a + b);
  const double max_displacement = options.max_displacement * edge_size;
  EdgeOptimization<D> result;
  // The node moves in the bisector plane of the edge: sliding it along the edge changes only the
  // parametrization, which the 3-point rule cannot see (a flat valley in a uniform metric).
  const Vec<D> direction = (1 / edge_size) * (b - a);
  auto onto_plane = [&](const Vec<D>& v) { return v - dot(v, direction) * direction; };
  const Vec<D> first = midpoint + onto_plane(start - midpoint);

  // ∂L^L/∂X is constant in a back element, and successive iterates often stay in one: its frame serves their
  // localization and derivatives.
  typename MetricField<D>::ElementFrame frame;
  auto frame_of = [&](Index element) -> const typename MetricField<D>::ElementFrame& {
    if (element != frame.element) frame = field.element_frame(element);
    return frame;
  };

  auto sample = field.sample(first, hint);
  result.node = first;
  result.back_element = sample.where.element;
  auto value =
      function.evaluate(first, sample.log_metric, frame_of(sample.where.element).log_metric_gradient, Order::kHessian);
  ++result.evaluations;
  // On a kink, the Newton model of the element found misses the other elements' slopes; when all of them
  // ascend, the start is optimal (kink_minimum.hpp) and no trial is needed.
  const bool optimal_start =
      on_back_mesh_face(sample.where) &&
      is_strict_minimum_on_kink(field, sample.where, direction, value, kKinkSlopeMargin * value.length / edge_size);
  const double initial_length = value.length;
  const bool starts_straight = norm(first - midpoint) == 0;
  double trust = 0.25 * edge_size;

  for (; !optimal_start && result.iterations < options.max_iterations; ++result.iterations) {
    // Newton in the plane: project gradient and Hessian, and make the Hessian regular along the
    // edge so the step has no component there.
    const Vec<D> gradient = onto_plane(value.gradient);
    SymMat<D> projected;
    for (int i = 0; i < D; ++i) {
      Vec<D> unit{};
      unit[i] = 1;
      Vec<D> column = onto_plane(value.hessian * onto_plane(unit));
      for (int j = 0; j <= i; ++j) projected(i, j) = column[j];
    }
    double scale = std::max(1e-300, std::abs(trace(projected)));
    for (int i = 0; i < D; ++i)
      for (int j = 0; j <= i; ++j) projected(i, j) += scale * direction[i] * direction[j];
    // Shift the Hessian until it is positive definite: between Newton and gradient descent.
    Vec<D> step;
    SymMat<D> h = projected;
    double shift = 0;
    while (!newton_direction(h, gradient, step)) {
      shift = shift == 0 ? 1e-8 * scale : 10 * shift;
      h = projected + shift * SymMat<D>::identity();
      if (!std::isfinite(shift)) return result;
    }
    step = onto_plane(step);
    double step_size = norm(step);
    // Converged: a step this small, or one whose predicted decrease −gᵀp/2 is this small, only meets
    // round-off, where every halving of the line search would fail.
    if (step_size < options.step_tolerance * edge_size ||
        -0.5 * dot(gradient, step) < options.decrease_tolerance * value.length)
      break;
    // Futile (options.futile_model_factor): the edge would stay straight.
    if (options.futile_model_factor > 0 && starts_straight && result.iterations > 0 && shift == 0 &&
        (initial_length - value.length) + options.futile_model_factor * (-0.5 * dot(gradient, step)) <
            options.min_relative_decrease * initial_length)
      break;
    if (step_size > trust) step = (trust / step_size) * step, step_size = trust;

    // Backtracking: accept the first trial that decreases ℓ (kinks rule out stricter tests). Along a
    // smooth ray of descent slope (σ < 0, Δ(s) = σs + κs²/2), a rejected increase Δ(s) > 0 shrinks more
    // than 4-fold when s is halved; a small one (< 1e-3 ℓ, where that model holds) that shrinks less
    // grows to first order: the direction ascends from the node, which sits on a kink (a back-mesh face
    // or edge), and further halvings would fail too. The node is then taken as the optimum.
    bool accepted = false;
    double rejected_increase = 0;
    for (int halving = 0; halving < 12 && !accepted; ++halving, step = 0.5 * step, step_size *= 0.5) {
      Vec<D> trial = result.node + step;
      Vec<D> offset = trial - midpoint;
      double displacement = norm(offset);
      if (displacement > max_displacement) trial = midpoint + (max_displacement / displacement) * offset;
      auto trial_sample = field.sample(trial, frame_of(result.back_element));
      ++result.evaluations;
      double trial_length = function.length(trial, trial_sample.log_metric);
      if (trial_length < value.length) {
        accepted = true;
        result.node = trial;
        result.back_element = trial_sample.where.element;
        value = function.evaluate(trial, trial_sample.log_metric,
                                  frame_of(trial_sample.where.element).log_metric_gradient, Order::kHessian);
      } else {
        const double increase = trial_length - value.length;
        if (rejected_increase > 0 && rejected_increase < 1e-3 * value.length && increase > 0.25 * rejected_increase)
          break;
        rejected_increase = increase;
      }
    }
    if (!accepted || step_size < options.step_tolerance * edge_size) {
      if (accepted) ++result.iterations;
      break;
    }
    trust = std::min(0.5 * edge_size, 2 * step_size);
  }
  result.length = value.length;

  // Worth curving? Compare with the straight edge in the same rule.
  double straight_length =
      starts_straight ? initial_length : function.length(midpoint, field.log_metric_at(midpoint, hint));
  if (result.length > (1 - options.min_relative_decrease) * straight_length) {
    result.node = midpoint;
    result.length = straight_length;
  }

  if (options.measure_gain) {
    result.straight_length = high_precision_length(field, end_a, end_b, midpoint, hint);
    result.optimized_length = high_precision_length(field, end_a, end_b, result.node, result.back_element);
    result.gain = 1 - result.optimized_length / result.straight_length;
  }
  return result;
}

template <int D>
double high_precision_edge_length(const MetricField<D>& field, const Vec<D>& a, const Vec<D>& b,
                                  const SymMat<D>& log_a, const SymMat<D>& log_b, const Vec<D>& node, Index hint) {
  return high_precision_length(field, edge_endpoint(a, log_a), edge_endpoint(b, log_b), node, hint);
}

#define HOCAV_INSTANTIATE(D)                                                                                        \
  template EdgeOptimization<D> optimize_edge_length(const MetricField<D>&, const EdgeEndpoint<D>&,                 \
                                                    const EdgeEndpoint<D>&, const Vec<D>&, Index,                    \
                                                    const EdgeOptimizerOptions&);                                   \
  template double high_precision_edge_length(const MetricField<D>&, const Vec<D>&, const Vec<D>&, const SymMat<D>&, \
                                             const SymMat<D>&, const Vec<D>&, Index);
HOCAV_INSTANTIATE(2)
HOCAV_INSTANTIATE(3)
#undef HOCAV_INSTANTIATE

}  // namespace hocav
