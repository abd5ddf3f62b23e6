#include "metric/metric_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "base/error.hpp"
#include "cases/structured.hpp"
#include "geom/sym_functions.hpp"

namespace hocav {
namespace {

template <int D>
SymMat<D> random_symmetric(std::mt19937& random, double scale) {
  std::uniform_real_distribution<double> entry(-scale, scale);
  SymMat<D> s;
  for (double& e : s.entries) e = entry(random);
  return s;
}

// A log-metric affine in x: log-Euclidean interpolation on any mesh reproduces it exactly, inside
// the mesh and (affine extension) just outside.
template <int D>
void expect_affine_log_metric_is_reproduced(const Mesh<D>& mesh) {
  std::mt19937 random(11);
  SymMat<D> base = random_symmetric<D>(random, 4);
  std::array<SymMat<D>, D> slope;
  for (auto& s : slope) s = random_symmetric<D>(random, 2);
  auto exact = [&](const Vec<D>& x) {
    SymMat<D> value = base;
    for (int i = 0; i < D; ++i) value += x[i] * slope[i];
    return value;
  };
  std::vector<SymMat<D>> metrics;
  for (const auto& p : mesh.vertices()) metrics.push_back(exp_sym(exact(p)));
  MetricField<D> field(mesh, metrics);
  std::uniform_real_distribution<double> coordinate(-0.01, 1.01);
  for (int trial = 0; trial < 500; ++trial) {
    Vec<D> x;
    for (int i = 0; i < D; ++i) x[i] = coordinate(random);
    auto sample = field.sample(x);
    EXPECT_LT(frobenius_norm(sample.log_metric - exact(x)), 1e-9) << "trial " << trial;
    auto gradient = field.log_metric_gradient(sample.where.element);
    for (int i = 0; i < D; ++i) EXPECT_LT(frobenius_norm(gradient[i] - slope[i]), 1e-9);
  }
}

TEST(MetricField, ReproducesAnAffineLogMetricIn2D) { expect_affine_log_metric_is_reproduced(generate_square(7)); }
TEST(MetricField, ReproducesAnAffineLogMetricIn3D) { expect_affine_log_metric_is_reproduced(generate_cube(4)); }

TEST(MetricField, InterpolationIsLogEuclideanNotLinear) {
  // Two vertex metrics diag(1, 1e8) and diag(1e8, 1): the log-Euclidean mean at the midpoint is
  // 1e4·I (a linear mean would be about 5e7·I).
  Mesh<2> mesh;
  mesh.add_vertex({{0, 0}});
  mesh.add_vertex({{1, 0}});
  mesh.add_vertex({{0, 1}});
  mesh.add_element({0, 1, 2});
  mesh.build_topology();
  SymMat<2> a = SymMat<2>::from_diagonal({{1, 1e8}}), b = SymMat<2>::from_diagonal({{1e8, 1}});
  MetricField<2> field(mesh, {a, b, b});
  SymMat<2> middle = exp_sym(field.log_metric_at({{0.5, 0.25}}));
  // λ = (0.25, 0.5, 0.25): exp(0.25 log a + 0.75 log b) = diag(1e6, 1e2).
  EXPECT_NEAR(middle(0, 0) / 1e6, 1, 1e-12);
  EXPECT_NEAR(middle(1, 1) / 1e2, 1, 1e-12);
  EXPECT_NEAR(middle(0, 1), 0, 1e-9);
}

// One thin simplex (height 0.01 over its base) whose apex asks 1e4·I and base 1·I. A point four
// heights above the apex: the affine extension runs away (λ_apex = 5: 1e20·I); sample_within pulls
// the barycentrics toward the centroid until the lowest is −kMostExtension, so the apex's weight
// (1 minus the base's) is at most 1 + D·kMostExtension. Within that reach the two agree bit for bit.
template <int D>
void expect_sample_within_to_stay_in_reach() {
  Mesh<D> mesh;
  for (int i = 0; i < D; ++i) {
    Vec<D> corner{};
    if (i > 0) corner[i - 1] = 1;
    mesh.add_vertex(corner);
  }
  Vec<D> apex{};
  for (int i = 0; i < D - 1; ++i) apex[i] = 0.25;
  apex[D - 1] = 0.01;
  mesh.add_vertex(apex);
  typename Mesh<D>::Element element;
  for (int i = 0; i <= D; ++i) element[i] = i;
  mesh.add_element(element);
  mesh.build_topology();
  const SymMat<D> top = 1e4 * SymMat<D>::identity();
  std::vector<SymMat<D>> metrics(D + 1, SymMat<D>::identity());
  metrics[D] = top;
  MetricField<D> field(mesh, metrics);
  const double reach = MetricField<D>::kMostExtension, top_norm = frobenius_norm(log_spd(top));
  Vec<D> above = apex;
  above[D - 1] = 0.05;
  EXPECT_GT(frobenius_norm(field.sample(above).log_metric), 4 * top_norm);  // the runaway
  const auto far = field.sample_within(above);
  EXPECT_LT(*std::min_element(far.where.barycentrics.begin(), far.where.barycentrics.end()), -reach);
  EXPECT_LE(frobenius_norm(far.log_metric), (1 + D * reach) * top_norm * (1 + 1e-12));
  EXPECT_GT(frobenius_norm(far.log_metric), top_norm);  // still extended, as far as the reach
  Vec<D> near = apex;
  near[D - 1] = 0.011;  // a tenth of the height above the apex: the base's barycentrics sum to −0.1
  EXPECT_EQ(field.sample_within(near).log_metric.entries, field.sample(near).log_metric.entries);
  EXPECT_GT(frobenius_norm(field.sample(near).log_metric), top_norm);
}

TEST(MetricField, SampleWithinExtendsNoFartherThanItsReach2D) { expect_sample_within_to_stay_in_reach<2>(); }
TEST(MetricField, SampleWithinExtendsNoFartherThanItsReach3D) { expect_sample_within_to_stay_in_reach<3>(); }

TEST(MetricField, RefusesNonSpdMetricsAndWrongCounts) {
  Mesh<2> mesh = generate_square(1);
  std::vector<SymMat<2>> metrics(4, SymMat<2>::identity());
  metrics[2](1, 1) = -1;
  try {
    MetricField<2> field(mesh, metrics);
    FAIL() << "accepted a non-SPD metric";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("vertex 3"), std::string::npos);
  }
  metrics.pop_back();
  EXPECT_THROW(MetricField<2>(mesh, metrics), Error);
}

// A field remade on another's back mesh (with_metrics) samples as one made from the mesh itself,
// bit for bit; is_on tells the mesh it was made from from a moved copy.
TEST(MetricField, AnotherFieldOnTheSameBackMeshSamplesAsItsOwn) {
  const Mesh<3> mesh = generate_cube(3);
  std::mt19937 random(5);
  std::vector<SymMat<3>> first, second;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    first.push_back(exp_sym(random_symmetric<3>(random, 2)));
    second.push_back(exp_sym(random_symmetric<3>(random, 2)));
  }
  const MetricField<3> field(mesh, first);
  ASSERT_TRUE(field.is_on(mesh));
  const MetricField<3> shared = field.with_metrics(second), own(mesh, second);
  EXPECT_EQ(&shared.back_mesh(), &field.back_mesh());
  std::uniform_real_distribution<double> coordinate(-0.05, 1.05);
  for (int i = 0; i < 200; ++i) {
    const Vec<3> x{coordinate(random), coordinate(random), coordinate(random)};
    EXPECT_EQ(shared.log_metric_at(x).entries, own.log_metric_at(x).entries) << i;
  }
  Mesh<3> moved = mesh;
  moved.vertex(5)[0] += 1e-9;
  EXPECT_FALSE(field.is_on(moved));
  second[7](0, 0) = -1;
  EXPECT_THROW(field.with_metrics(second), Error);
}

}  // namespace
}  // namespace hocav
