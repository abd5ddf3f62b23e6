// Length optimization of one P2 edge (docs/method.md §7): minimize ℓ(X) over the Lagrange node X in the
// bisector plane of the edge (sliding along the edge only reparametrizes it), endpoints fixed, re-localizing X in the back mesh at every
// iterate. ℓ is only piecewise smooth (∇λ jumps across back-mesh faces), so the method is a safeguarded Newton iteration: Newton steps
// where the Hessian is positive definite (shifted towards gradient descent where it is not), a
// trust radius tied to the edge's length, and backtracking that accepts only decrease.
#pragma once

#include "curve/edge_length.hpp"
#include "curve/edge_length_integral.hpp"  // the "true" length and adaptive lengths
#include "metric/metric_field.hpp"

namespace hocav {

struct EdgeOptimizerOptions {
  QuadratureRule rule = default_optimizer_rule();
  int max_iterations = 30;
  // Stop when a step moves the node less than this fraction of |B − A|.
  double step_tolerance = 1e-7;
  // Or when the Newton model predicts a decrease of ℓ below this fraction of ℓ: ℓ is evaluated to a
  // relative ~1e-15 (3D eigen-decompositions of log-metrics up to ~20), so no line search can
  // confirm a smaller decrease; at the stop the node is within one (tiny) Newton step of the optimum.
  double decrease_tolerance = 1e-13;
  // Largest distance of the node from the straight midpoint, as a fraction of |B − A|.
  double max_displacement = 0.5;
  // An edge whose length (in the optimizer's rule) drops by less than this fraction stays
  // straight: bending an edge distorts its elements, which a negligible gain does not pay for.
  double min_relative_decrease = 1e-3;
  // From the straight midpoint, once a model is trusted (after a first accepted step, or at once on a kink,
  // whose steepest descent accounts for every back element around): stop once the decrease so far plus this
  // many times the decrease the (convex) model still predicts falls short of min_relative_decrease, as the
  // edge would stay straight. A model can miss slopes farther away: on the bench's 129k 3D edges factors 1, 10
  // and 30 lose a few curved edges, 100 and 1000 none (docs/curving.md). 0: never.
  double futile_model_factor = 100;
  // Also compute the high-precision straight and optimized lengths (and the gain).
  bool measure_gain = false;
};

template <int D>
struct EdgeOptimization {
  Vec<D> node{};
  Index back_element = kNoIndex;  // where the node was last localized (a hint for neighbours)
  double length = 0;              // ℓ(node) in the optimizer's rule
  double straight_length = 0;     // high-precision ℓ of the straight edge (measure_gain)
  double optimized_length = 0;    // high-precision ℓ at the optimum (measure_gain)
  double gain = 0;                // 1 − optimized / straight (measure_gain)
  int iterations = 0;
  int evaluations = 0;  // back-mesh localizations + length evaluations
};

// The edge is (a, b), its vertices with their metrics (edge_endpoint: make one per vertex when many
// edges share it); `start` is the first node (the current one, or the straight midpoint); `hint` a
// back element near it; `scratch` the caller's (one per thread), reused by the localizations.
template <int D>
EdgeOptimization<D> optimize_edge_length(const MetricField<D>& field, const EdgeEndpoint<D>& a, const EdgeEndpoint<D>& b,
                                         const Vec<D>& start, Index hint, const EdgeOptimizerOptions& options, LocatorScratch& scratch);
// The same with a scratch of its own.
template <int D>
EdgeOptimization<D> optimize_edge_length(const MetricField<D>& field, const EdgeEndpoint<D>& a, const EdgeEndpoint<D>& b,
                                         const Vec<D>& start, Index hint = kNoIndex, const EdgeOptimizerOptions& options = {}) {
  LocatorScratch scratch;
  return optimize_edge_length(field, a, b, start, hint, options, scratch);
}
// The same from the vertices' positions and log-metrics (log_a, log_b).
template <int D>
EdgeOptimization<D> optimize_edge_length(const MetricField<D>& field, const Vec<D>& a, const Vec<D>& b, const SymMat<D>& log_a,
                                         const SymMat<D>& log_b, const Vec<D>& start, Index hint = kNoIndex,
                                         const EdgeOptimizerOptions& options = {}) {
  return optimize_edge_length(field, edge_endpoint(a, log_a), edge_endpoint(b, log_b), start, hint, options);
}

// High-precision ℓ of the P2 edge (a, node, b) in the closed form of eq 12 (metric from the back
// mesh at the node only).
template <int D>
double high_precision_edge_length(const MetricField<D>& field, const EdgeEndpoint<D>& a, const EdgeEndpoint<D>& b, const Vec<D>& node,
                                  Index hint = kNoIndex);
// The same with the back mesh's log-metric at the node already sampled.
template <int D>
double high_precision_edge_length(const EdgeEndpoint<D>& a, const EdgeEndpoint<D>& b, const Vec<D>& node, const SymMat<D>& log_node);
// The same from the vertices' positions and log-metrics.
template <int D>
double high_precision_edge_length(const MetricField<D>& field, const Vec<D>& a, const Vec<D>& b, const SymMat<D>& log_a,
                                  const SymMat<D>& log_b, const Vec<D>& node, Index hint = kNoIndex) {
  return high_precision_edge_length(field, edge_endpoint(a, log_a), edge_endpoint(b, log_b), node, hint);
}

}  // namespace hocav
