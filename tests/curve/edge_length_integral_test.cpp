#include "curve/edge_length_integral.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "cases/structured.hpp"
#include "curve/edge_length.hpp"
#include "metric/analytic_metric.hpp"

namespace hocav {
namespace {

// A curved edge across the shear layer (radius 0.75, width 0.1, size ratio 100) of a coarse back mesh of
// the unit square or cube: its points cross a few dozen back-mesh faces, where the localized metric has kinks.
template <int D>
Mesh<D> coarse_back_mesh() {
  if constexpr (D == 2)
    return generate_square(12);
  else
    return generate_cube(6);
}

template <int D>
struct CrossingCase {
  Mesh<D> back = coarse_back_mesh<D>();
  std::unique_ptr<MetricField<D>> field;
  Vec<D> a{}, b{}, node{};
  CrossingCase() {
    AnalyticMetricSpec spec;
    spec.name = D == 2 ? "shear-circle" : "shear-sphere";
    spec.h_max = 0.2;
    spec.h_min = 0.002;
    spec.width = 0.1;
    field = std::make_unique<MetricField<D>>(back, analytic_metric_at_vertices(spec, back));
    for (int i = 0; i < D; ++i) a[i] = 0.3, b[i] = 0.6;
    a[0] = 0.2;
    node = 0.5 * (a + b);
    node[1] += 0.05;
  }
};

// The rule of `pieces` copies of the 8-point Gauss–Legendre rule on [0, 1]: a reference for kinked integrands,
// whose error falls like pieces⁻² (each kink costs O(h²) in its piece).
QuadratureRule composite_gauss_rule(int pieces) {
  const QuadratureRule gauss = gauss_legendre_rule(8);
  QuadratureRule rule{"composite", {}, {}};
  for (int p = 0; p < pieces; ++p)
    for (std::size_t q = 0; q < gauss.nodes.size(); ++q) {
      rule.nodes.push_back((p + gauss.nodes[q]) / pieces);
      rule.weights.push_back(gauss.weights[q] / pieces);
    }
  return rule;
}

template <int D>
void check_interpolated_model_matches_gauss_legendre() {
  CrossingCase<D> c;
  const SymMat<D> log_a = c.field->log_metric_at(c.a), log_b = c.field->log_metric_at(c.b);
  const QuadratureRule rule = gauss_legendre_rule(128);
  EdgeLengthFunction<D> gauss(c.a, c.b, log_a, log_b, rule);
  const double reference = gauss.length(c.node, c.field->log_metric_at(c.node));
  int previous = 0;
  for (double tolerance : {1e-4, 1e-7, 1e-10, 1e-13}) {
    auto adaptive = adaptive_edge_length(*c.field, c.a, c.b, log_a, log_b, c.node, tolerance);
    EXPECT_TRUE(adaptive.converged);
    EXPECT_LE(std::abs(adaptive.value - reference), tolerance * reference) << tolerance;
    EXPECT_GE(adaptive.evaluations, previous);
    EXPECT_LE(adaptive.evaluations, 400) << tolerance;  // smooth: a few pieces, even at 1e-13
    previous = adaptive.evaluations;
  }
}

TEST(EdgeLengthIntegral, InterpolatedModelMatchesHighOrderGaussLegendre2D) { check_interpolated_model_matches_gauss_legendre<2>(); }
TEST(EdgeLengthIntegral, InterpolatedModelMatchesHighOrderGaussLegendre3D) { check_interpolated_model_matches_gauss_legendre<3>(); }

template <int D>
void check_true_length_across_kinks() {
  CrossingCase<D> c;
  // The composite reference, and its own error from one halving of its pieces.
  const double reference = true_edge_length(*c.field, c.a, c.b, c.node, composite_gauss_rule(4096));
  const double coarser = true_edge_length(*c.field, c.a, c.b, c.node, composite_gauss_rule(2048));
  const double reference_error = std::abs(reference - coarser) / 3;  // error ∝ pieces⁻²
  ASSERT_LT(reference_error, 1e-8 * reference);
  // A single high-order rule is not accurate across kinks (what the adaptive rule is for).
  const double gauss_error = std::abs(true_edge_length(*c.field, c.a, c.b, c.node, gauss_legendre_rule(16)) - reference);
  EXPECT_GT(gauss_error, 1e-6 * reference);
  int previous = 0;
  for (double tolerance : {1e-3, 1e-5, 1e-7}) {
    auto adaptive = adaptive_true_edge_length(*c.field, c.a, c.b, c.node, tolerance);
    EXPECT_TRUE(adaptive.converged);
    EXPECT_LE(std::abs(adaptive.value - reference), tolerance * reference + reference_error) << tolerance;
    EXPECT_GT(adaptive.evaluations, previous);
    previous = adaptive.evaluations;
  }
  EXPECT_LT(previous, 20000);  // far fewer than the 32,768 points of the reference
}

TEST(EdgeLengthIntegral, TrueLengthAcrossBackMeshFacesReachesItsTolerance2D) { check_true_length_across_kinks<2>(); }
TEST(EdgeLengthIntegral, TrueLengthAcrossBackMeshFacesReachesItsTolerance3D) { check_true_length_across_kinks<3>(); }

}  // namespace
}  // namespace hocav
