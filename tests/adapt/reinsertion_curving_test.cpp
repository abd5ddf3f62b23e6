#include "adapt/reinsertion_curving.hpp"

#include <gtest/gtest.h>

#include "bezier/mesh_quality.hpp"
#include "cases/structured.hpp"
#include "curve/edge_optimizer.hpp"
#include "mesh/consistency.hpp"
#include "metric/analytic_metric.hpp"

namespace hocav {
namespace {

// The square [−1, 1]² and the circular shear layer of radius 0.6 on it.
struct ShearSquare {
  Mesh<2> mesh = generate_square(24);
  AnalyticMetricSpec spec;
  ShearSquare() {
    for (Index v = 0; v < mesh.vertex_count(); ++v) mesh.vertex(v) = 2.0 * mesh.vertex(v) - Vec2{{1, 1}};
    spec.name = "shear-circle";
    spec.radius = 0.6;
    spec.width = 0.08;
    spec.h_min = 0.01;
    spec.h_max = 0.1;
  }
};

TEST(ReinsertionCurving, ShearLayerCurvesEdgesAndKeepsEveryElementValid) {
  ShearSquare square;
  Mesh<2>& mesh = square.mesh;
  MetricField<2> field(mesh, analytic_metric_at_vertices(square.spec, mesh));
  ReinsertionOptions options;
  auto result = curve_by_reinsertion<2>(mesh, field, nullptr, options);

  EXPECT_EQ(result.counters.cavities, static_cast<long long>(volume_vertices(mesh).size()));
  EXPECT_GT(result.counters.accepted, result.counters.cavities * 9 / 10);
  EXPECT_GT(result.counters.edges_optimized, 0);
  ConsistencyOptions consistency;
  consistency.require_positive_orientation = false;
  consistency.require_boundary_facets = true;
  EXPECT_EQ(check_consistency(mesh, consistency), std::vector<std::string>{});

  // Every element certified above the floor.
  auto quality = summarize_jacobian_quality(mesh_jacobian_quality(mesh));
  EXPECT_GT(quality.min_normalized_jacobian.min, options.cavity.jacobian_floor);

  // Edges are curved, and curving shortened them in the metric (high-precision lengths).
  double total_gain = 0, max_gain = 0;
  int curved = 0, edges = 0;
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    auto [a, b] = mesh.edge_vertices(e);
    Vec2 mid = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
    if (norm(mesh.edge_node(e) - mid) > 1e-3 * norm(mesh.vertex(b) - mesh.vertex(a))) ++curved;
    double straight = high_precision_edge_length(field, mesh.vertex(a), mesh.vertex(b), field.vertex_log_metric(a),
                                                 field.vertex_log_metric(b), mid);
    double optimized = high_precision_edge_length(field, mesh.vertex(a), mesh.vertex(b), field.vertex_log_metric(a),
                                                  field.vertex_log_metric(b), mesh.edge_node(e));
    double gain = 1 - optimized / straight;
    total_gain += gain;
    max_gain = std::max(max_gain, gain);
    ++edges;
  }
  EXPECT_GT(curved, edges / 20);
  EXPECT_GT(total_gain / edges, 0);
  EXPECT_GT(max_gain, 0.02);
}

TEST(ReinsertionCurving, OutputDoesNotDependOnTheThreadCount) {
  ShearSquare one, three;
  MetricField<2> field(one.mesh, analytic_metric_at_vertices(one.spec, one.mesh));
  ReinsertionOptions options;
  curve_by_reinsertion<2>(one.mesh, field, nullptr, options);
  options.threads = 3;
  curve_by_reinsertion<2>(three.mesh, field, nullptr, options);
  ASSERT_EQ(one.mesh.element_count(), three.mesh.element_count());
  ASSERT_EQ(one.mesh.edge_count(), three.mesh.edge_count());
  for (Index k = 0; k < one.mesh.element_count(); ++k) ASSERT_EQ(one.mesh.element(k), three.mesh.element(k));
  for (Index e = 0; e < one.mesh.edge_count(); ++e) {
    ASSERT_EQ(one.mesh.edge_vertices(e), three.mesh.edge_vertices(e));
    ASSERT_EQ(one.mesh.edge_node(e), three.mesh.edge_node(e)) << "edge " << e;  // bit for bit
  }
}

}  // namespace
}  // namespace hocav
