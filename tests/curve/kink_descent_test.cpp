#include "curve/kink_descent.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "../metric/metric_test_support.hpp"
#include "cases/structured.hpp"
#include "curve/edge_optimizer.hpp"
#include "geom/orthonormal_complement.hpp"
#include "metric/analytic_metric.hpp"

namespace hocav {
namespace {

// Unit vectors spanning the bisector plane (line in 2D) of the edge direction m.
template <int D>
std::vector<Vec<D>> plane_directions(const Vec<D>& m, int count) {
  std::vector<Vec<D>> directions;
  const auto basis = orthonormal_complement(m);
  if constexpr (D == 2) {
    directions = {basis[0], -basis[0]};
  } else {
    const Vec3 &e1 = basis[0], &e2 = basis[1];
    for (int k = 0; k < count; ++k) {
      const double angle = 2 * std::numbers::pi * k / count;
      directions.push_back(std::cos(angle) * e1 + std::sin(angle) * e2);
    }
  }
  return directions;
}

// The edge (pa, pb) with its straight midpoint X on a kink of ℓ. Finite-difference slopes over 1e-6 |AB|
// (round-off ~1e-9 ℓ/|AB| there; shorter steps along directions grazing a face stay within the locator's
// tolerance band, which extends one element's metric) check the analysis to 1e-5 ℓ/|AB|, where a wrongly oriented ray, a missed
// sector or a wrong sector gradient shows errors of order ℓ/|AB|:
// - no direction of the bisector plane (into the domain, where only its side is analysed) descends more
//   steeply than s*, and d* descends at s*;
// - d* enters the element returned (X + εd* has no negative barycentric there).
// Counts strict minima (s* > 0) and descents (s* < 0).
struct KinkCounts {
  int analysed = 0, minima = 0, descents = 0, domain_side_only = 0;
};
template <int D>
void check_kink(const MetricField<D>& field, const Vec<D>& pa, const Vec<D>& pb, Index hint, KinkCounts& counts) {
  const Vec<D> midpoint = 0.5 * (pa + pb);
  const double size = norm(pb - pa);
  const Vec<D> direction = (1 / size) * (pb - pa);
  const EdgeLengthFunction<D> function(pa, pb, field.log_metric_at(pa, hint), field.log_metric_at(pb, hint), default_optimizer_rule());
  const auto sample = field.sample(midpoint, hint);
  ASSERT_TRUE(on_back_mesh_face(sample.where));
  const auto log_gradient = field.log_metric_gradient(sample.where.element);
  const auto value = function.evaluate(midpoint, sample.log_metric, log_gradient, EdgeLengthFunction<D>::Order::kGradient);
  // The gradient parts add up to the gradient of the element found.
  for (int i = 0; i < D; ++i)
    EXPECT_NEAR(value.node_gradient[i] + frobenius_dot(value.log_node_gradient, log_gradient[i]), value.gradient[i],
                1e-12 * value.length / size);
  const KinkDescent<D> kink = steepest_descent_on_kink(field, sample.where, direction, value);
  if (!kink.analysed) return;
  const double unit = value.length / size, tolerance = 1e-5 * unit, step = 1e-6 * size;
  // One-sided differences over h and 2h, extrapolated (Richardson): the O(h) curvature term cancels, which
  // at anisotropy 300 is up to ~1e-4 ℓ/|AB|.
  auto slope_along = [&](const Vec<D>& d) {
    auto difference = [&](double h) {
      const Vec<D> node = midpoint + h * d;
      return (function.length(node, field.log_metric_at(node, sample.where.element)) - value.length) / h;
    };
    return 2 * difference(step) - difference(2 * step);
  };
  EXPECT_NEAR(norm(kink.direction), 1, 1e-12);
  EXPECT_NEAR(dot(kink.direction, direction), 0, 1e-12);
  EXPECT_NEAR(slope_along(kink.direction), kink.slope, tolerance);
  for (const Vec<D>& d : plane_directions<D>(direction, 48)) {
    // Into the domain: clearly so, 1e-3 |AB| away.
    if (kink.whole_plane || field.sample(midpoint + 1e-3 * size * d, hint).where.inside) {
      EXPECT_GT(slope_along(d), kink.slope - tolerance);
    }
  }
  const auto corners = field.locator().element_points(kink.element);
  const auto lambda = barycentric_coordinates<D>(barycentric_gradients<D>(corners), corners[0], midpoint + 1e-6 * size * kink.direction);
  for (double l : lambda) EXPECT_GT(l, -1e-9);
  ++counts.analysed;
  counts.domain_side_only += !kink.whole_plane;
  counts.minima += kink.whole_plane && kink.slope > 1e-8 * unit;
  counts.descents += kink.slope < -1e-8 * unit;
}

// Every edge of the back mesh starts at its midpoint, on a back-mesh edge (3D) or face (2D): the analysis
// must also decide, a good share of the edges being strict minima and a good share descending; the boundary
// edges get the domain's side.
template <int D>
void check_back_mesh_edges(int cells, int min_minima, int min_descents) {
  Mesh<D> mesh = metric_test::unit_mesh<D>(cells);
  const MetricField<D> field = metric_test::shear_layer_field<D>(mesh);
  mesh.build_edges();
  KinkCounts counts;
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    const auto [a, b] = mesh.edge_vertices(e);
    SCOPED_TRACE("edge " + std::to_string(e));
    check_kink<D>(field, mesh.vertex(a), mesh.vertex(b), mesh.vertex_element(a), counts);
  }
  EXPECT_GE(counts.minima, min_minima);
  EXPECT_GE(counts.descents, min_descents);
  EXPECT_GT(counts.domain_side_only, 0);
}

TEST(KinkDescent, SteepestDescentOnBackMeshEdgesMatchesFiniteDifferences3D) { check_back_mesh_edges<3>(8, 200, 200); }
TEST(KinkDescent, SteepestDescentOnBackMeshEdgesMatchesFiniteDifferences2D) { check_back_mesh_edges<2>(40, 200, 200); }

// 3D, X inside a back-mesh face (two half planes; one at the boundary): edges of random directions through a
// random point of every face. No strict minimum exists there (the slopes along the face line are opposite);
// most descend.
TEST(KinkDescent, SteepestDescentInsideBackMeshFacesMatchesFiniteDifferences) {
  Mesh<3> mesh = generate_cube(6);
  const MetricField<3> field = metric_test::shear_layer_field<3>(mesh);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> gauss;
  KinkCounts counts;
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face < 4; ++face) {
      const Index other = mesh.neighbor(k, face);
      if (other != kNoIndex && other < k) continue;  // each face once
      const auto corners = field.locator().element_points(k);
      std::array<double, 3> weights = {unit(random) + 0.2, unit(random) + 0.2, unit(random) + 0.2};
      const double total = weights[0] + weights[1] + weights[2];
      Vec3 x{};
      for (int i = 0, j = 0; i < 4; ++i)
        if (i != face) x += (weights[static_cast<std::size_t>(j++)] / total) * corners[static_cast<std::size_t>(i)];
      const Vec3 m{{gauss(random), gauss(random), gauss(random)}};
      const Vec3 half = (0.5 / (6.0 * norm(m))) * m;  // an edge about one back element long
      SCOPED_TRACE("element " + std::to_string(k) + " face " + std::to_string(face));
      check_kink<3>(field, x - half, x + half, k, counts);
    }
  EXPECT_GT(counts.analysed, 200);
  EXPECT_GT(counts.domain_side_only, 20);
  EXPECT_EQ(counts.minima, 0);
  EXPECT_GT(counts.descents, counts.analysed / 2);
}

// In a uniform metric ℓ is smooth and stationary at the midpoint: the slopes are round-off, neither a
// strict minimum nor a descent (the optimizer's Newton step decides).
TEST(KinkDescent, UniformMetricIsStationary) {
  Mesh<3> mesh = generate_cube(4);
  AnalyticMetricSpec uniform;
  uniform.h = 0.25;
  const MetricField<3> field(mesh, analytic_metric_at_vertices(uniform, mesh));
  mesh.build_edges();
  int analysed = 0;
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    const auto [a, b] = mesh.edge_vertices(e);
    const Vec3 pa = mesh.vertex(a), pb = mesh.vertex(b), midpoint = 0.5 * (pa + pb);
    const EdgeLengthFunction<3> function(pa, pb, field.vertex_log_metric(a), field.vertex_log_metric(b), default_optimizer_rule());
    const auto sample = field.sample(midpoint, mesh.vertex_element(a));
    const auto value = function.evaluate(midpoint, sample.log_metric, field.log_metric_gradient(sample.where.element),
                                         EdgeLengthFunction<3>::Order::kGradient);
    const KinkDescent<3> kink = steepest_descent_on_kink(field, sample.where, (1 / norm(pb - pa)) * (pb - pa), value);
    if (!kink.analysed) continue;  // boundary edges: an open ring
    ++analysed;
    EXPECT_LT(std::abs(kink.slope), 1e-8 * value.length / norm(pb - pa)) << e;
  }
  EXPECT_GT(analysed, 50);
}

// Off every face (inside an element) there is no kink to test.
TEST(KinkDescent, InsideAnElementIsNoKink) {
  Mesh<3> mesh = generate_cube(4);
  const MetricField<3> field = metric_test::shear_layer_field<3>(mesh);
  const auto points = field.locator().element_points(5);
  const Vec3 centroid = 0.25 * (points[0] + points[1] + points[2] + points[3]);
  EXPECT_FALSE(on_back_mesh_face(field.sample(centroid, 5).where));
  EXPECT_TRUE(on_back_mesh_face(field.sample(0.5 * (points[0] + points[1]), 5).where));
}

}  // namespace
}  // namespace hocav
