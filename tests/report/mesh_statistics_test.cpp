#include "report/mesh_statistics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cases/structured.hpp"

namespace hocav {
namespace {

// n x n square, metric (n scale)^2 I at every vertex: axis edges of length scale, diagonals scale sqrt 2.
MeshStatistics square_statistics(int n, double scale) {
  Mesh<2> mesh = generate_square(n);
  double m = n * n * scale * scale;
  std::vector<double> metrics;
  for (Index v = 0; v < mesh.vertex_count(); ++v) metrics.insert(metrics.end(), {m, 0, m});
  return compute_mesh_statistics(mesh, metrics);
}

TEST(MeshStatistics, CountsRefsAndMeasuresOfTheSquare) {
  Mesh<2> mesh = generate_square(4);
  MeshStatistics s = compute_mesh_statistics(mesh);
  EXPECT_EQ(s.dimension, 2);
  EXPECT_EQ(s.order, 1);
  EXPECT_EQ(s.vertices, 25);
  EXPECT_EQ(s.elements, 32);
  EXPECT_EQ(s.boundary_facets, 16);
  EXPECT_EQ(s.edges, 56);  // Euler: V + T - 1
  EXPECT_EQ(s.p2_nodes, 0);
  EXPECT_EQ(s.corners, 4);
  ASSERT_EQ(s.element_refs.size(), 1u);
  EXPECT_EQ(s.element_refs[0].ref, 1);
  EXPECT_EQ(s.element_refs[0].count, 32);
  ASSERT_EQ(s.facet_refs.size(), 4u);
  for (int side = 0; side < 4; ++side) {
    EXPECT_EQ(s.facet_refs[side].ref, side + 1);
    EXPECT_EQ(s.facet_refs[side].count, 4);
  }
  EXPECT_DOUBLE_EQ(s.min_measure, 1.0 / 32);
  EXPECT_DOUBLE_EQ(s.max_measure, 1.0 / 32);
  EXPECT_NEAR(s.total_measure, 1.0, 1e-14);
  EXPECT_EQ(s.non_positive_elements, 0);
  EXPECT_EQ(s.open_boundary_faces, 0);
  EXPECT_TRUE(s.consistency_problems.empty());
  EXPECT_GT(s.memory_bytes, 0u);
  EXPECT_FALSE(s.metric.has_value());
}

TEST(MeshStatistics, P2CubeCountsItsNodesAndStaysConsistent) {
  Mesh<3> mesh = generate_cube(2);
  mesh.make_p2();
  MeshStatistics s = compute_mesh_statistics(mesh);
  EXPECT_EQ(s.order, 2);
  EXPECT_EQ(s.p2_nodes, s.edges);
  EXPECT_EQ(s.lines, 24);
  EXPECT_EQ(s.ridges, 24);
  EXPECT_NEAR(s.total_measure, 1.0, 1e-14);
  EXPECT_TRUE(s.consistency_problems.empty());
}

TEST(MeshStatistics, ReportsInvertedElementsAndOpenFaces) {
  Mesh<2> mesh;
  mesh.add_vertex({{0, 0}});
  mesh.add_vertex({{1, 0}});
  mesh.add_vertex({{0, 1}});
  mesh.add_element({0, 2, 1}, 7);  // clockwise
  mesh.build_topology();
  MeshStatistics s = compute_mesh_statistics(mesh);
  EXPECT_EQ(s.non_positive_elements, 1);
  EXPECT_DOUBLE_EQ(s.min_measure, -0.5);
  EXPECT_EQ(s.open_boundary_faces, 3);
  EXPECT_FALSE(s.consistency_problems.empty());
  EXPECT_EQ(s.element_refs[0].ref, 7);
  // P1: the Jacobian figures are the sign check of straight elements.
  EXPECT_TRUE(s.jacobian.straight);
  EXPECT_EQ(s.jacobian.invalid, 1);
  EXPECT_EQ(s.jacobian.first_invalid_element, 0);
  EXPECT_NEAR(s.jacobian.min_normalized.min, -1, 1e-12);
  EXPECT_NEAR(s.jacobian.scaled.max, -1, 1e-12);
  EXPECT_EQ(s.jacobian.min_normalized.histogram[0], 1);
  EXPECT_FALSE(s.valid());
  EXPECT_EQ(invalidity_summary(s).rfind("1 element with a non-positive Jacobian (first: element 1); consistency: ", 0), 0u)
      << invalidity_summary(s);
}

TEST(MeshStatistics, StraightElementsAreOneAndInTheBinUpToOne) {
  Mesh<3> mesh = generate_cube(2);
  MeshStatistics s = compute_mesh_statistics(mesh);
  EXPECT_TRUE(s.jacobian.straight);
  EXPECT_EQ(s.jacobian.invalid, 0);
  EXPECT_EQ(s.jacobian.first_invalid_element, kNoIndex);
  for (const JacobianFigures* f : {&s.jacobian.min_normalized, &s.jacobian.scaled}) {
    EXPECT_NEAR(f->min, 1, 1e-12);
    EXPECT_NEAR(f->max, 1, 1e-12);
    EXPECT_EQ(f->histogram[kJacobianBinBounds.size() - 1], s.elements);  // (0.9, 1]
  }
  EXPECT_TRUE(s.valid());
  EXPECT_EQ(invalidity_summary(s), "");
  mesh.make_p2();  // straight P2 elements: the same figures, now from the Bézier coefficients
  MeshStatistics p2 = compute_mesh_statistics(mesh);
  EXPECT_FALSE(p2.jacobian.straight);
  EXPECT_NEAR(p2.jacobian.min_normalized.min, 1, 1e-12);
  EXPECT_EQ(p2.jacobian.scaled.histogram[kJacobianBinBounds.size() - 1], p2.elements);
}

// Unit right simplices, each with the mid node of its edge 01 moved by d along y: the map is
// x = ξ + 4 λ0 ξ1 d e_y, so J = 1 − 4 d ξ1 exactly (det(I + e_y ⊗ ∇g) = 1 + ∂g/∂ξ_y): min J/|J_straight|
// = min(1, 1 − 4d), max = max(1, 1 − 4d), both reached at vertices.
template <int D>
Mesh<D> simplices_with_a_curved_edge(const std::vector<double>& displacements) {
  Mesh<D> mesh;
  for (std::size_t i = 0; i < displacements.size(); ++i) {
    typename Mesh<D>::Element element;
    for (int v = 0; v <= D; ++v) {
      Vec<D> x{};
      x[0] = 3.0 * static_cast<double>(i);  // side by side, apart
      if (v > 0) x[v - 1] += 1;
      element[v] = mesh.add_vertex(x);
    }
    mesh.add_element(element);
  }
  mesh.build_topology();
  mesh.make_p2();
  for (std::size_t i = 0; i < displacements.size(); ++i) {
    const auto& element = mesh.element(static_cast<Index>(i));
    mesh.edge_node(mesh.find_edge(element[0], element[1]))[1] += displacements[i];
  }
  return mesh;
}

struct ExactJacobian {
  double min_normalized, scaled;
};

ExactJacobian exact_jacobian_of_curved_edge(double d) {
  const double at_v1 = 1 - 4 * d, low = std::min(1.0, at_v1), high = std::max(1.0, at_v1);
  return {low, low / high};
}

TEST(MeshStatistics, JacobianFiguresOfCurvedTrianglesMatchTheExactJacobian) {
  const std::vector<double> displacements{0.0, 0.1, -0.2, 0.3};  // straight, inward, outward, folded
  Mesh<2> mesh = simplices_with_a_curved_edge<2>(displacements);
  MeshStatistics s = compute_mesh_statistics(mesh);
  std::vector<double> normalized, scaled;
  for (double d : displacements) {
    normalized.push_back(exact_jacobian_of_curved_edge(d).min_normalized);
    scaled.push_back(exact_jacobian_of_curved_edge(d).scaled);
  }
  auto average = [](const std::vector<double>& v) { return (v[0] + v[1] + v[2] + v[3]) / 4; };
  EXPECT_FALSE(s.jacobian.straight);
  EXPECT_NEAR(s.jacobian.min_normalized.min, -0.2, 1e-12);
  EXPECT_NEAR(s.jacobian.min_normalized.max, 1, 1e-12);
  EXPECT_NEAR(s.jacobian.min_normalized.average, average(normalized), 1e-12);
  EXPECT_NEAR(s.jacobian.scaled.min, -0.2, 1e-12);
  EXPECT_NEAR(s.jacobian.scaled.max, 1, 1e-12);
  EXPECT_NEAR(s.jacobian.scaled.average, average(scaled), 1e-12);
  EXPECT_EQ(s.jacobian.invalid, 1);
  EXPECT_EQ(s.jacobian.first_invalid_element, 3);
  // 1, 0.6, 1, −0.2 and 1, 0.6, 1/1.8, −0.2 in the bins (−inf, 0], …, (0.5, 0.7], (0.7, 0.9], (0.9, 1].
  EXPECT_EQ(s.jacobian.min_normalized.histogram, (JacobianHistogram{1, 0, 0, 0, 0, 1, 0, 2, 0}));
  EXPECT_EQ(s.jacobian.scaled.histogram, (JacobianHistogram{1, 0, 0, 0, 0, 2, 0, 1, 0}));
  EXPECT_TRUE(s.consistency_problems.empty());  // a P2 mesh is not held to P1 orientation
  EXPECT_FALSE(s.valid());
  EXPECT_EQ(invalidity_summary(s), "1 element with a non-positive Jacobian (first: element 4)");
}

TEST(MeshStatistics, JacobianFiguresOfCurvedTetrahedraMatchTheExactJacobian) {
  Mesh<3> mesh = simplices_with_a_curved_edge<3>({0.15, -0.1});
  MeshStatistics s = compute_mesh_statistics(mesh);
  const ExactJacobian inward = exact_jacobian_of_curved_edge(0.15), outward = exact_jacobian_of_curved_edge(-0.1);
  EXPECT_NEAR(s.jacobian.min_normalized.min, inward.min_normalized, 1e-12);
  EXPECT_NEAR(s.jacobian.min_normalized.max, outward.min_normalized, 1e-12);
  EXPECT_NEAR(s.jacobian.scaled.min, inward.scaled, 1e-12);   // 0.4
  EXPECT_NEAR(s.jacobian.scaled.max, outward.scaled, 1e-12);  // 1 / 1.4
  EXPECT_NEAR(s.jacobian.scaled.average, (inward.scaled + outward.scaled) / 2, 1e-12);
  EXPECT_EQ(s.jacobian.invalid, 0);
  EXPECT_TRUE(s.valid());
}

TEST(MeshStatistics, JacobianBinsAreClosedOnTheRight) {
  EXPECT_EQ(jacobian_bin(-1.0), 0u);
  EXPECT_EQ(jacobian_bin(0.0), 0u);
  EXPECT_EQ(jacobian_bin(std::nan("")), 0u);
  EXPECT_EQ(jacobian_bin(1e-300), 1u);
  EXPECT_EQ(jacobian_bin(0.01), 1u);
  EXPECT_EQ(jacobian_bin(0.05), 2u);
  EXPECT_EQ(jacobian_bin(0.95), 7u);
  EXPECT_EQ(jacobian_bin(1.0), 7u);
  EXPECT_EQ(jacobian_bin(1 + 1e-14), 7u);  // a straight element, rounded
  EXPECT_EQ(jacobian_bin(1 + 1e-9), 8u);
  EXPECT_EQ(jacobian_bin(15.0), 8u);
}

TEST(MeshStatistics, EdgeLengthsInAUniformMetric) {
  MeshStatistics unit = square_statistics(4, 1.0);
  ASSERT_TRUE(unit.metric.has_value());
  EXPECT_EQ(unit.metric->edge_count, 56);
  EXPECT_NEAR(unit.metric->min, 1.0, 1e-14);
  EXPECT_NEAR(unit.metric->max, std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(unit.metric->mean, (40 + 16 * std::sqrt(2.0)) / 56, 1e-14);
  EXPECT_EQ(unit.metric->histogram[kUnitEdgeBin], 56);
  EXPECT_EQ(unit.metric->unit_share, 1.0);

  MeshStatistics long_edges = square_statistics(4, 2.0);  // axis edges 2, diagonals 2.83
  EXPECT_EQ(long_edges.metric->histogram[4], 40);
  EXPECT_EQ(long_edges.metric->histogram[5], 16);
  EXPECT_EQ(long_edges.metric->unit_share, 0.0);
}

// Right isosceles triangles of legs h in the metric diag(1, k²) (any scale): Σ l² = 2 h² (1 + k²) and
// A_M = k h² / 2, so Q = 4√3 A_M / Σ l² = √3 k / (1 + k²), √3/2 for k = 1.
double right_triangle_quality(double k) { return std::sqrt(3.0) * k / (1 + k * k); }

TEST(MeshStatistics, ElementQualityOfRightTrianglesInAUniformMetric) {
  for (double scale : {1.0, 3.0}) {
    MeshStatistics s = square_statistics(4, scale);
    EXPECT_NEAR(s.metric->quality_min, right_triangle_quality(1), 1e-14);
    EXPECT_NEAR(s.metric->quality_mean, right_triangle_quality(1), 1e-14);
    EXPECT_EQ(s.metric->quality_histogram[4], 32);  // [0.7, 0.9)
    EXPECT_EQ(s.metric->low_quality_share, 0.0);
  }
}

// Vertex metrics diag(1, e^{2t}) give the centroid metric diag(1, k²) with k = e^{mean t}: the
// log-Euclidean mean; the mean of the matrices would give k² = mean e^{2t}.
TEST(MeshStatistics, ElementQualityTakesTheLogEuclideanMetricAtTheCentroid) {
  Mesh<2> mesh = generate_square(1);
  const std::vector<double> t{3.0, 4.0, 8.0, 9.0};
  std::vector<double> metrics;
  for (double tv : t) metrics.insert(metrics.end(), {1, 0, std::exp(2 * tv)});
  std::vector<double> expected;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    double mean_t = 0;
    for (Index v : mesh.element(k)) mean_t += t[static_cast<std::size_t>(v)] / 3;
    expected.push_back(right_triangle_quality(std::exp(mean_t)));
  }
  MeshStatistics s = compute_mesh_statistics(mesh, metrics);
  EXPECT_NEAR(s.metric->quality_min, *std::min_element(expected.begin(), expected.end()), 1e-13);
  EXPECT_NEAR(s.metric->quality_mean, (expected[0] + expected[1]) / 2, 1e-13);
  EXPECT_EQ(s.metric->low_quality_share, 1.0);  // k ≥ e^5: both below 0.1
  EXPECT_EQ(s.metric->quality_histogram[0], 2);
}

TEST(MeshStatistics, QualityBinsAreClosedOnTheLeft) {
  EXPECT_EQ(quality_bin(-1.0), 0u);
  EXPECT_EQ(quality_bin(std::nan("")), 0u);
  EXPECT_EQ(quality_bin(0.0999), 0u);
  EXPECT_EQ(quality_bin(0.1), 1u);
  EXPECT_EQ(quality_bin(0.5), 3u);
  EXPECT_EQ(quality_bin(0.9), 5u);
  EXPECT_EQ(quality_bin(1.0), 5u);
}

TEST(MeshStatistics, MaxAnisotropyIsTheLargestSizeRatio) {
  Mesh<2> mesh = generate_square(2);
  std::vector<double> metrics;
  for (Index v = 0; v < mesh.vertex_count(); ++v) metrics.insert(metrics.end(), {4, 0, 4});
  // Sizes 0.001 and 0.1 along rotated axes at one vertex: M = R diag(1e6, 100) Rᵀ at 30 degrees.
  const double c = std::cos(0.5), s = std::sin(0.5), large = 1e6, small = 100;
  std::copy_n(std::array<double, 3>{c * c * large + s * s * small, c * s * (large - small), s * s * large + c * c * small}.begin(), 3,
              metrics.begin() + 12);
  MeshStatistics statistics = compute_mesh_statistics(mesh, metrics);
  EXPECT_NEAR(statistics.metric->max_anisotropy, 100, 1e-9);
}

// `hocav adapt` measures its P1 output without an edge table (the edges found from the elements):
// the same edges and figures as with the table, on a cube whose metric varies (so that the edge
// lengths differ), and no table built.
TEST(MeshStatistics, P1MetricFiguresNeedNoEdgeTable) {
  Mesh<3> mesh = generate_cube(5);
  std::vector<double> metrics;
  for (const Vec3& x : mesh.vertices()) {
    const double a = 25 * (1 + 3 * x[0] * x[0]), b = 25 * (1 + x[1]), c = 25 * (2 - x[2]);
    metrics.insert(metrics.end(), {a, 0.1 * a, b, 0, 0, c});
  }
  const MetricStatistics without = compute_metric_statistics(mesh, metrics);
  EXPECT_FALSE(mesh.has_edges());
  mesh.build_edges();
  const MetricStatistics with = compute_metric_statistics(mesh, metrics);
  EXPECT_EQ(without.edge_count, mesh.edge_count());
  EXPECT_EQ(without.histogram, with.histogram);
  EXPECT_EQ(without.min, with.min);
  EXPECT_EQ(without.max, with.max);
  EXPECT_NEAR(without.mean, with.mean, 1e-14 * with.mean);
  EXPECT_EQ(without.quality_min, with.quality_min);
  EXPECT_EQ(without.quality_mean, with.quality_mean);
  EXPECT_LT(without.min, 0.9 * without.max);
}

// With la, lb the lengths of e in the end metrics, an isotropic metric whose log varies linearly gives
// the logarithmic mean (lb − la) / log(lb / la).
TEST(MeshStatistics, EdgeLengthIsRiemannianWithTheLogMetricLinearAlongAStraightEdge) {
  Mesh<2> mesh;
  for (Vec2 x : {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{0, 1}}}) mesh.add_vertex(x);
  mesh.add_element({0, 1, 2});
  mesh.build_topology();
  std::vector<double> metrics{1, 0, 1, 16, 0, 16, 1, 0, 1};  // sizes 1, 1/4, 1
  MeshStatistics statistics = compute_mesh_statistics(mesh, metrics);
  const double la = 1, lb = 4, diagonal = std::sqrt(2.0);
  EXPECT_NEAR(statistics.metric->min, 1, 1e-14);  // the edge (0, 2)
  EXPECT_NEAR(statistics.metric->max, diagonal * (lb - la) / std::log(lb / la), 1e-12);
  EXPECT_NEAR(statistics.metric->mean, (1 + 2 * (lb - la) / std::log(lb / la) * (1 + diagonal) / 2) / 3, 1e-12);
}

TEST(MeshStatistics, P2EdgesAreMeasuredAlongTheirCurveWithTheMetricAtTheirNode) {
  Mesh<2> mesh;
  for (Vec2 x : {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{0.5, 0.3}}}) mesh.add_vertex(x);
  mesh.add_element({0, 1, 2});
  mesh.build_topology();
  mesh.make_p2();
  Index bottom = mesh.find_edge(0, 1);
  mesh.edge_node(bottom) = Vec2{{0.5, -0.25}};  // the parabola y = x² − x, the longest edge
  std::vector<double> identity{1, 0, 1, 1, 0, 1, 1, 0, 1};
  std::vector<double> with_nodes = identity;
  for (Index e = 0; e < mesh.edge_count(); ++e) with_nodes.insert(with_nodes.end(), {1, 0, 1});
  // Arc length of y = x² − x on [0, 1]: ∫ sqrt(1 + (2x − 1)²) dx = (sqrt 2 + asinh 1) / 2.
  const double arc = (std::sqrt(2.0) + std::asinh(1.0)) / 2;
  EXPECT_NEAR(compute_mesh_statistics(mesh, identity).metric->max, arc, 1e-9);
  EXPECT_NEAR(compute_mesh_statistics(mesh, with_nodes).metric->max, arc, 1e-9);
  // A metric of 4 I at the bottom node only: log M = φ_M(t) log 4 I along it, |γ'(t)| scaled by 2^{φ_M(t)}.
  with_nodes[9 + 3 * static_cast<std::size_t>(bottom)] = with_nodes[9 + 3 * static_cast<std::size_t>(bottom) + 2] = 4;
  double expected = 0;
  const int steps = 200000;
  for (int i = 0; i < steps; ++i) {
    double t = (i + 0.5) / steps;
    expected += std::sqrt(1 + (2 * t - 1) * (2 * t - 1)) * std::pow(2.0, 4 * t * (1 - t)) / steps;
  }
  EXPECT_NEAR(compute_mesh_statistics(mesh, with_nodes).metric->max, expected, 1e-8);
}

TEST(MeshStatistics, BinsAreClosedTowardsTheUnitBin) {
  EXPECT_EQ(edge_length_bin(0.0), 0u);
  EXPECT_EQ(edge_length_bin(0.3), 1u);
  EXPECT_EQ(edge_length_bin(0.5), 2u);
  EXPECT_EQ(edge_length_bin(1 / std::sqrt(2.0)), kUnitEdgeBin);
  EXPECT_EQ(edge_length_bin(1.0), kUnitEdgeBin);
  EXPECT_EQ(edge_length_bin(std::sqrt(2.0)), kUnitEdgeBin);
  // Quadrature rounding does not push a unit mesh's diagonals out of the unit bin.
  EXPECT_EQ(edge_length_bin(std::sqrt(2.0) * (1 + 1e-14)), kUnitEdgeBin);
  EXPECT_EQ(edge_length_bin(std::sqrt(0.5) * (1 - 1e-14)), kUnitEdgeBin);
  EXPECT_EQ(edge_length_bin(std::sqrt(2.0) * (1 + 1e-9)), 4u);
  EXPECT_EQ(edge_length_bin(1.5), 4u);
  EXPECT_EQ(edge_length_bin(2.0), 4u);
  EXPECT_EQ(edge_length_bin(3.0), 5u);
  EXPECT_EQ(edge_length_bin(3.5), 6u);
}

TEST(MeshStatistics, TableAndJsonCarryTheFigures) {
  MeshStatistics s = square_statistics(2, 1.0);
  std::ostringstream table, json;
  write_statistics_table(table, s, "square.mesh", "square.sol");
  write_statistics_json(json, s, "square.mesh", "square.sol");
  EXPECT_NE(table.str().find("consistency           ok"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("elements              8 triangles"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("unit edges            100.0% in [0.707, 1.41]"), std::string::npos) << table.str();
  EXPECT_NE(json.str().find("\"elements\": 8,"), std::string::npos) << json.str();
  EXPECT_NE(json.str().find("\"consistent\": true"), std::string::npos) << json.str();
  EXPECT_NE(json.str().find("\"unit_share\": 1"), std::string::npos) << json.str();
  EXPECT_NE(json.str().find("\"file\": \"square.sol\""), std::string::npos) << json.str();
  EXPECT_NE(table.str().find("element quality       min 0.866025  mean 0.866025"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("  [0.7, 0.9)                   8   100.0%"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("poor elements         0.0% with quality below 0.1"), std::string::npos) << table.str();
  const std::size_t quality = json.str().find("\"quality\": {");
  ASSERT_NE(quality, std::string::npos) << json.str();
  for (const char* member : {"\"min\": 0.8660254", "\"mean\": 0.8660254", "\"low_share\": 0,", "\"low_bound\": 0.1,",
                             "\"bin\": \"[0.7, 0.9)\",", "\"count\": 8"})
    EXPECT_NE(json.str().find(member, quality), std::string::npos) << member << '\n' << json.str();
  EXPECT_NE(table.str().find("valid                 yes"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("invalid elements      0"), std::string::npos) << table.str();
  EXPECT_NE(json.str().find("\"valid\": true"), std::string::npos) << json.str();
  EXPECT_NE(json.str().find("\"straight\": true"), std::string::npos) << json.str();
  EXPECT_EQ(json.str().back(), '\n');
}

}  // namespace
}  // namespace hocav
