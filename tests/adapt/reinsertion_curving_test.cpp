#include "adapt/reinsertion_curving.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "bezier/jacobian_bounds.hpp"
#include "bezier/mesh_quality.hpp"
#include "bezier/p2_element.hpp"
#include "cases/structured.hpp"
#include "curve/edge_optimizer.hpp"
#include "mesh/consistency.hpp"
#include "metric/analytic_metric.hpp"
#include "report/curving_report.hpp"

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

// Edges with a vertex that is reinserted: the edges the passes optimize.
template <int D>
long long reinserted_edge_count(const Mesh<D>& mesh) {
  std::vector<bool> reinserted(static_cast<std::size_t>(mesh.vertex_count()), false);
  for (Index v : volume_vertices(mesh)) reinserted[v] = true;
  long long count = 0;
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    auto [a, b] = mesh.edge_vertices(e);
    if (a != kNoIndex && (reinserted[a] || reinserted[b])) ++count;
  }
  return count;
}

TEST(ReinsertionCurving, WorkNotRedoneOptimizesEachEdgeOnceAndChangesLittle) {
  ShearSquare reusing, redoing;
  MetricField<2> field(reusing.mesh, analytic_metric_at_vertices(reusing.spec, reusing.mesh));
  ReinsertionOptions options;
  const auto reused = curve_by_reinsertion<2>(reusing.mesh, field, nullptr, options).counters;
  options.reuse_results = false;
  const auto redone = curve_by_reinsertion<2>(redoing.mesh, field, nullptr, options).counters;

  // Every reinsertion recreates the same inner edges either way: each is optimized or kept.
  EXPECT_EQ(redone.edges_kept_optimal, 0);
  EXPECT_EQ(redone.certificates_kept, 0);
  EXPECT_EQ(reused.edges_optimized + reused.edges_kept_optimal, redone.edges_optimized);
  // Each edge is recreated once from each reinserted end; it is optimized about once (again only
  // after a correction pulled it back or the optimizer did not converge).
  const long long edges = reinserted_edge_count(reusing.mesh);
  EXPECT_GT(redone.edges_optimized, 3 * edges / 2);
  EXPECT_LE(reused.edges_optimized, edges + edges / 10);
  // Most new elements are unchanged copies of the elements they replace.
  EXPECT_GT(reused.certificates_kept, reused.elements_certified - reusing.mesh.element_count());
  EXPECT_LT(reused.elements_certified, redone.elements_certified);

  // Validity as before, and the same mesh up to the few edges whose second optimization, from the
  // other end, would have found another optimum (mostly edges the first one left straight).
  const double floor = options.cavity.jacobian_floor;
  EXPECT_GT(summarize_jacobian_quality(mesh_jacobian_quality(reusing.mesh)).min_normalized_jacobian.min, floor);
  ASSERT_EQ(reusing.mesh.edge_count(), redoing.mesh.edge_count());
  for (Index k = 0; k < reusing.mesh.element_count(); ++k) ASSERT_EQ(reusing.mesh.element(k), redoing.mesh.element(k));
  int moved = 0;
  for (Index e = 0; e < reusing.mesh.edge_count(); ++e) {
    auto [a, b] = reusing.mesh.edge_vertices(e);
    const double size = norm(reusing.mesh.vertex(b) - reusing.mesh.vertex(a));
    if (norm(reusing.mesh.edge_node(e) - redoing.mesh.edge_node(e)) > 1e-9 * size) ++moved;
  }
  EXPECT_LE(moved, reusing.mesh.edge_count() / 25);
  auto average = [](const std::vector<double>& values) {
    double sum = 0;
    for (double value : values) sum += value;
    return sum / static_cast<double>(values.size());
  };
  const double reused_gain = average(volume_edge_gains(reusing.mesh, field));
  const double redone_gain = average(volume_edge_gains(redoing.mesh, field));
  EXPECT_NEAR(reused_gain, redone_gain, 0.05 * redone_gain);
}

// The output's measures (each element's Jacobians, each volume edge's gain) are the same, bit for
// bit and in the same order, on one thread and on three; and the gains are those of the edges,
// measured one by one.
TEST(ReinsertionCurving, OutputMeasuresDoNotDependOnTheThreadCount) {
  ShearSquare square;
  MetricField<2> field(square.mesh, analytic_metric_at_vertices(square.spec, square.mesh));
  curve_by_reinsertion<2>(square.mesh, field, nullptr, ReinsertionOptions{});
  const std::vector<double> gains = volume_edge_gains(square.mesh, field, 1);
  EXPECT_EQ(volume_edge_gains(square.mesh, field, 3), gains);
  const auto one = mesh_jacobian_quality(square.mesh, kReportedRefinement, 1),
             three = mesh_jacobian_quality(square.mesh, kReportedRefinement, 3);
  ASSERT_EQ(one.size(), three.size());
  for (std::size_t k = 0; k < one.size(); ++k) {
    EXPECT_EQ(one[k].min_normalized_jacobian, three[k].min_normalized_jacobian) << "element " << k;
    EXPECT_EQ(one[k].scaled_jacobian, three[k].scaled_jacobian) << "element " << k;
  }
  // The volume edges, in order: not both ends on the boundary.
  std::vector<bool> on_boundary(static_cast<std::size_t>(square.mesh.vertex_count()), false);
  for (Index f = 0; f < square.mesh.facet_count(); ++f)
    for (Index v : square.mesh.facet(f)) on_boundary[v] = true;
  std::size_t next = 0;
  int curved = 0;
  for (Index e = 0; e < square.mesh.edge_count(); ++e) {
    const auto [a, b] = square.mesh.edge_vertices(e);
    if (on_boundary[a] && on_boundary[b]) continue;
    ASSERT_LT(next, gains.size());
    const Vec2 middle = 0.5 * (square.mesh.vertex(a) + square.mesh.vertex(b));
    const auto length = [&](const Vec2& node) {
      return high_precision_edge_length(field, square.mesh.vertex(a), square.mesh.vertex(b), field.vertex_log_metric(a),
                                        field.vertex_log_metric(b), node, field.back_mesh().vertex_element(a));
    };
    const double expected = square.mesh.edge_node(e) == middle ? 0 : 1 - length(square.mesh.edge_node(e)) / length(middle);
    EXPECT_EQ(gains[next++], expected) << "edge " << e;
    curved += expected != 0;
  }
  EXPECT_EQ(next, gains.size());
  EXPECT_GT(curved, 100);
}

// The gains of a curved mesh whose vertices are numbered otherwise than the field's back mesh (the
// curved passes of adapt --curved renumber them): each edge's gain is the same as before, its ends'
// metrics sampled where they are instead of read by vertex id.
TEST(ReinsertionCurving, GainsDoNotDependOnTheVertexNumbering) {
  ShearSquare square;
  MetricField<2> field(square.mesh, analytic_metric_at_vertices(square.spec, square.mesh));
  curve_by_reinsertion<2>(square.mesh, field, nullptr, ReinsertionOptions{});
  Mesh<2> renumbered = square.mesh;
  // Shifted by a third (a reversal would map the square onto itself through the centre, where the
  // shear circle's metric is the same).
  const Index n = renumbered.vertex_count();
  std::vector<Index> shifted(static_cast<std::size_t>(n)), same(static_cast<std::size_t>(renumbered.element_count()));
  for (Index v = 0; v < n; ++v) shifted[static_cast<std::size_t>(v)] = (v + n / 3) % n;
  for (Index k = 0; k < renumbered.element_count(); ++k) same[static_cast<std::size_t>(k)] = k;
  renumbered.renumber(shifted, same);
  const std::vector<double> gains = volume_edge_gains(square.mesh, field), renumbered_gains = volume_edge_gains(renumbered, field);
  ASSERT_EQ(renumbered_gains.size(), gains.size());
  Index curved = 0;
  for (std::size_t e = 0; e < gains.size(); ++e) {
    EXPECT_NEAR(renumbered_gains[e], gains[e], 1e-9 + 1e-9 * std::abs(gains[e])) << "edge " << e;
    curved += gains[e] > 1e-3;
  }
  EXPECT_GT(curved, 10);
}

TEST(ReinsertionCurving, CertificatesAreKeptOnlyWhenEveryInputElementIsAboveTheFloor) {
  ShearSquare square;
  MetricField<2> field(square.mesh, analytic_metric_at_vertices(square.spec, square.mesh));
  ReinsertionOptions options;
  curve_by_reinsertion<2>(square.mesh, field, nullptr, options);  // a valid P2 mesh

  // Curving it again: the input is certified once, then unchanged elements keep their certificates.
  Mesh<2> valid = square.mesh;
  const auto again = curve_by_reinsertion<2>(valid, field, nullptr, options).counters;
  EXPECT_GE(again.elements_certified, valid.element_count());
  EXPECT_GT(again.certificates_kept, 0);

  // One element pushed below the floor (an edge node moved across the element): no certificate is
  // taken on trust.
  Mesh<2> invalid = square.mesh;
  const Index k = invalid.element_count() / 2;
  const Index e = invalid.element_edge(k, 0);
  auto [a, b] = invalid.edge_vertices(e);
  const Vec2 midpoint = 0.5 * (invalid.vertex(a) + invalid.vertex(b));
  Vec2 opposite{};
  for (Index v : invalid.element(k))
    if (v != a && v != b) opposite = invalid.vertex(v);
  invalid.edge_node(e) = midpoint + 1.5 * (opposite - midpoint);
  ASSERT_FALSE(certify_min_normalized_jacobian_above(gather_p2_element(invalid, k), options.cavity.jacobian_floor));
  const auto from_invalid = curve_by_reinsertion<2>(invalid, field, nullptr, options).counters;
  EXPECT_EQ(from_invalid.certificates_kept, 0);
  EXPECT_GT(from_invalid.edges_kept_optimal, 0);
}

TEST(ReinsertionCurving, ARegionLimitsTheReinsertionToItsVertices) {
  ShearSquare square;
  Mesh<2>& mesh = square.mesh;
  const MetricField<2> field(mesh, analytic_metric_at_vertices(square.spec, mesh));
  mesh.build_topology();
  const std::vector<Index> volume = volume_vertices(mesh);
  std::vector<char> region(static_cast<std::size_t>(mesh.vertex_count()), 0);
  for (std::size_t i = 0; i < volume.size(); i += 3) region[volume[i]] = 1;
  region[0] = 1;  // a corner of the square: flagged, but on the boundary, so not reinserted
  ReinsertionOptions options;
  options.region = region;
  const ReinsertionResult result = curve_by_reinsertion<2>(mesh, field, nullptr, options);
  EXPECT_EQ(result.counters.cavities, static_cast<long long>((volume.size() + 2) / 3));
  // An edge no reinserted vertex touches keeps its straight node.
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    const auto [a, b] = mesh.edge_vertices(e);
    if (region[a] || region[b]) continue;
    EXPECT_EQ(mesh.edge_node(e), 0.5 * (mesh.vertex(a) + mesh.vertex(b))) << a << ' ' << b;
  }
}

}  // namespace
}  // namespace hocav
