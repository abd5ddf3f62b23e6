#include "metric/implied_metric.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "base/error.hpp"
#include "geom/sym_functions.hpp"
#include "mesh/measure.hpp"
#include "metric_test_support.hpp"

namespace hocav {
namespace {

template <int D>
SimplexPoints<D> element_points(const Mesh<D>& mesh, Index k) {
  SimplexPoints<D> points;
  for (int i = 0; i <= D; ++i) points[static_cast<std::size_t>(i)] = mesh.vertex(mesh.element(k)[i]);
  return points;
}

// (A Aᵀ)⁻¹ = A⁻ᵀ A⁻¹: the metric of the map x ↦ A x, in which A applied to unit vectors has unit length.
template <int D>
SymMat<D> map_metric(const Mat<D>& a) {
  return pow_spd(congruence(a, SymMat<D>::identity()), -1.0);
}

template <int D>
void expect_close(const SymMat<D>& actual, const SymMat<D>& expected, double relative) {
  double scale = frobenius_norm(expected);
  for (int e = 0; e < SymMat<D>::kEntryCount; ++e)
    EXPECT_NEAR(actual.entries[static_cast<std::size_t>(e)], expected.entries[static_cast<std::size_t>(e)], relative * scale);
}

// The vertices x ↦ A x + b of a mesh, each element kept positive.
template <int D>
Mesh<D> mapped(const Mesh<D>& pattern, const Mat<D>& a, const Vec<D>& b) {
  Mesh<D> mesh;
  for (const auto& x : pattern.vertices()) mesh.add_vertex(a * x + b);
  for (auto element : pattern.elements()) {
    Index k = mesh.add_element(element, 1);
    if (element_measure(mesh, k) < 0) {
      std::swap(element[0], element[1]);
      mesh.set_element(k, element, 1);
    }
  }
  return mesh;
}

// Equilateral triangles of unit edges tiling a parallelogram.
Mesh<2> equilateral_lattice(int n) {
  Mesh<2> mesh;
  const Vec2 first{{1, 0}}, second{{0.5, std::sqrt(3.0) / 2}};
  auto id = [n](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.add_vertex(double(i) * first + double(j) * second);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.add_element({id(i, j), id(i + 1, j), id(i, j + 1)}, 1);
      mesh.add_element({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}, 1);
    }
  return mesh;
}

// Four regular tetrahedra of unit edges around the common edge from (0, 0, −½) to (0, 0, ½), each
// the previous one turned by the dihedral angle acos(1/3) (regular tetrahedra do not tile space).
Mesh<3> regular_tetrahedra_fan() {
  Mesh<3> mesh;
  mesh.add_vertex({{0, 0, -0.5}});
  mesh.add_vertex({{0, 0, 0.5}});
  const double angle = std::acos(1.0 / 3), radius = std::sqrt(3.0) / 2;
  for (int k = 0; k <= 4; ++k) mesh.add_vertex({{radius * std::cos(k * angle), radius * std::sin(k * angle), 0}});
  for (Index k = 0; k < 4; ++k) mesh.add_element({0, 1, k + 2, k + 3}, 1);
  return mesh;
}

template <int D>
void expect_implied_metric_of_map(const Mesh<D>& regular_pattern, const Mat<D>& a, const Vec<D>& b) {
  for (Index k = 0; k < regular_pattern.element_count(); ++k)
    for (const auto& [i, j] : Simplex<D>::kEdgeLocalVertices)
      ASSERT_NEAR(norm(regular_pattern.vertex(regular_pattern.element(k)[i]) - regular_pattern.vertex(regular_pattern.element(k)[j])), 1.0,
                  1e-14);
  Mesh<D> mesh = mapped(regular_pattern, a, b);
  SymMat<D> expected = map_metric(a);
  for (const SymMat<D>& metric : implied_metric_at_vertices(mesh)) expect_close(metric, expected, 1e-13);
}

TEST(ImpliedMetric, IsTheMetricOfTheAffineMapOfARegularPattern) {
  expect_implied_metric_of_map(equilateral_lattice(5), Mat<2>{{2.0, 0.5, -0.3, 0.07}}, Vec2{{3, -1}});
  expect_implied_metric_of_map(equilateral_lattice(3), Mat<2>{{1e-3, 0, 0, 10}}, Vec2{});
  expect_implied_metric_of_map(regular_tetrahedra_fan(), Mat<3>{{1.5, 0.2, -0.4, 0.1, 0.02, 0.3, -0.2, 0.5, 4}}, Vec3{{1, 2, 3}});
}

template <int D>
void expect_unit_edges_in_element_metrics(const Mesh<D>& mesh) {
  for (Index k = 0; k < mesh.element_count(); ++k) {
    SimplexPoints<D> points = element_points(mesh, k);
    SymMat<D> metric = element_implied_metric<D>(points);
    EXPECT_TRUE(is_spd(metric));
    for (const auto& [i, j] : Simplex<D>::kEdgeLocalVertices)
      EXPECT_NEAR(quadratic_form(metric, points[static_cast<std::size_t>(i)] - points[static_cast<std::size_t>(j)]), 1.0, 1e-12);
    // The edges do not depend on the orientation, nor does the metric.
    std::swap(points[0], points[1]);
    expect_close(element_implied_metric<D>(points), metric, 1e-14);
  }
}

TEST(ImpliedMetric, EveryEdgeHasUnitLengthInItsElementMetric) {
  expect_unit_edges_in_element_metrics(metric_test::perturbed_unit_mesh<2>(6, 0.2));
  expect_unit_edges_in_element_metrics(metric_test::perturbed_unit_mesh<3>(4, 0.2));
  // A thin sliver: long edges and a tiny height.
  Mesh<3> sliver;
  for (Vec3 x : {Vec3{{0, 0, 0}}, Vec3{{1, 0, 0}}, Vec3{{0, 1, 0}}, Vec3{{0.4, 0.4, 1e-4}}}) sliver.add_vertex(x);
  sliver.add_element({0, 1, 2, 3});
  expect_unit_edges_in_element_metrics(sliver);
}

TEST(ImpliedMetric, VertexMetricIsTheVolumeWeightedLogEuclideanMean) {
  // Two triangles of areas 1/2 and 3/2 sharing the edge (1, 2).
  Mesh<2> mesh;
  for (Vec2 x : {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{0, 1}}, Vec2{{3, 1}}}) mesh.add_vertex(x);
  mesh.add_element({0, 1, 2});
  mesh.add_element({1, 3, 2});
  auto metrics = implied_metric_at_vertices(mesh);
  SymMat2 first = element_implied_metric<2>(element_points(mesh, 0));
  SymMat2 second = element_implied_metric<2>(element_points(mesh, 1));
  expect_close(metrics[0], first, 1e-14);
  expect_close(metrics[3], second, 1e-14);
  SymMat2 mean = exp_sym(0.25 * log_spd(first) + 0.75 * log_spd(second));
  expect_close(metrics[1], mean, 1e-14);
  expect_close(metrics[2], mean, 1e-14);
}

TEST(ImpliedMetric, FlatElementsAndUnusedVerticesAreRefused) {
  Mesh<2> flat;
  for (Vec2 x : {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{2, 0}}}) flat.add_vertex(x);
  flat.add_element({0, 1, 2});
  EXPECT_THROW(implied_metric_at_vertices(flat), Error);
  Mesh<2> unused = equilateral_lattice(1);
  unused.add_vertex({{5, 5}});
  EXPECT_THROW(implied_metric_at_vertices(unused), Error);
}

}  // namespace
}  // namespace hocav
