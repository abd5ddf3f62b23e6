#include "metric/gradation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "base/error.hpp"
#include "curve/quadrature.hpp"
#include "geom/sym_functions.hpp"
#include "mesh/vertex_graph.hpp"
#include "metric_test_support.hpp"

namespace hocav {
namespace {

TEST(Gradation, FactorShrinksTheMetricBySizeGrowthOnePlusLengthLogBeta) {
  EXPECT_EQ(gradation_factor(0, 2), 1);
  EXPECT_DOUBLE_EQ(gradation_factor(1, std::exp(1.0)), 0.25);
  EXPECT_DOUBLE_EQ(gradation_factor(3, 1.5), std::pow(1 + 3 * std::log(1.5), -2));
}

TEST(Gradation, LargestRelativeEigenvalueIsTheLoewnerBound) {
  EXPECT_DOUBLE_EQ(largest_relative_eigenvalue(SymMat2::from_diagonal({{4, 1}}), SymMat2::from_diagonal({{1, 2}})), 4);
  std::mt19937_64 random(3);
  for (int trial = 0; trial < 100; ++trial) {
    SymMat3 a = metric_test::random_metric<3>(random, 0.01, 100), b = metric_test::random_metric<3>(random, 0.01, 100);
    double mu = largest_relative_eigenvalue(a, b);
    // B^{-1/2} A B^{-1/2} from the spectral functions, independently.
    SymMat3 inverse_root = pow_spd(b, -0.5);
    Mat3 root;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) root(i, j) = inverse_root(i, j);
    EXPECT_NEAR(mu, spd_eigen(congruence(root, a)).values[2], 1e-9 * mu);
    EXPECT_NEAR(largest_relative_eigenvalue(b, b), 1, 1e-12);
  }
}

// A strip of 2 × n triangles along x, cells of width dx and height dx / 2.
Mesh<2> strip(int cells, double dx) {
  Mesh<2> mesh;
  for (int i = 0; i <= cells; ++i) {
    mesh.add_vertex({{i * dx, 0}});
    mesh.add_vertex({{i * dx, dx / 2}});
  }
  for (Index i = 0; i < cells; ++i) {
    mesh.add_element({2 * i, 2 * i + 2, 2 * i + 3});
    mesh.add_element({2 * i, 2 * i + 3, 2 * i + 1});
  }
  return mesh;
}

TEST(Gradation, ASmallSizeSpreadsGrowingByBetaPerUnitLengthAlongALine) {
  const double dx = 0.05, h0 = 0.01, coarse = 1, beta = 2;
  Mesh<2> mesh = strip(40, dx);
  std::vector<SymMat2> metrics(static_cast<std::size_t>(mesh.vertex_count()), SymMat2::identity());
  metrics[0] = metrics[1] = (1 / (h0 * h0)) * SymMat2::identity();
  grade_metrics(mesh, metrics, {beta, 1e-12});
  // h(x) = h0 + x log β, up to the coarse size.
  std::vector<double> sizes;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const SymMat2& m = metrics[static_cast<std::size_t>(v)];
    EXPECT_NEAR(m(1, 0), 0, 1e-9 * m(0, 0));
    EXPECT_NEAR(m(0, 0), m(1, 1), 1e-9 * m(0, 0));
    double expected = std::min(coarse, h0 + mesh.vertex(v)[0] * std::log(beta));
    EXPECT_NEAR(1 / std::sqrt(m(0, 0)), expected, 1e-9 * expected) << "at x = " << mesh.vertex(v)[0];
    if (v % 2 == 0) sizes.push_back(1 / std::sqrt(m(0, 0)));
  }
  // The same, read as geometric growth: from one vertex to the next the size is multiplied by β^ℓ,
  // ℓ the edge's length in the graded field (sizes linear along the edge), as long as it grows.
  const QuadratureRule& rule = high_precision_rule();
  for (std::size_t i = 0; i + 1 < sizes.size() && sizes[i + 1] < coarse; ++i) {
    double length = 0;
    for (std::size_t q = 0; q < rule.nodes.size(); ++q)
      length += rule.weights[q] * dx / ((1 - rule.nodes[q]) * sizes[i] + rule.nodes[q] * sizes[i + 1]);
    EXPECT_NEAR(sizes[i + 1] / sizes[i], std::pow(beta, length), 1e-12);
  }
}

// For every edge pq both ways: η(ℓ_p(pq)) M_p ≤ (1 + slack) M_q.
template <int D>
void expect_graded(const Mesh<D>& mesh, const std::vector<SymMat<D>>& metrics, double beta, double slack) {
  VertexGraph graph = vertex_graph(mesh);
  for (Index p = 0; p < mesh.vertex_count(); ++p)
    for (Index q : graph.neighbors_of(p)) {
      const SymMat<D>& mp = metrics[static_cast<std::size_t>(p)];
      double length = std::sqrt(quadratic_form(mp, mesh.vertex(q) - mesh.vertex(p)));
      EXPECT_LE(largest_relative_eigenvalue(gradation_factor(length, beta) * mp, metrics[static_cast<std::size_t>(q)]), 1 + slack)
          << p << " -> " << q;
    }
}

template <int D>
void expect_gradation_reaches_an_idempotent_fixed_point(int cells) {
  Mesh<D> mesh = metric_test::perturbed_unit_mesh<D>(cells, 0.2);
  std::mt19937_64 random(5);
  std::vector<SymMat<D>> original;
  for (Index v = 0; v < mesh.vertex_count(); ++v) original.push_back(metric_test::random_metric<D>(random, 0.002, 100));
  const GradationOptions options{1.5, 1e-3};
  std::vector<SymMat<D>> graded = original;
  GradationReport first = grade_metrics(mesh, graded, options);
  EXPECT_GT(first.updates, 0);
  expect_graded(mesh, graded, options.growth, options.tolerance + 1e-12);
  // Metrics only grow.
  for (std::size_t v = 0; v < graded.size(); ++v) EXPECT_LE(largest_relative_eigenvalue(original[v], graded[v]), 1 + 1e-12);
  std::vector<SymMat<D>> twice = graded;
  EXPECT_EQ(grade_metrics(mesh, twice, options).updates, 0);
  EXPECT_EQ(twice, graded);
}

TEST(Gradation, ReachesAFixedPointWhereEveryEdgeIsGradedAndGradingAgainChangesNothing) {
  expect_gradation_reaches_an_idempotent_fixed_point<2>(12);
  expect_gradation_reaches_an_idempotent_fixed_point<3>(5);
}

TEST(Gradation, KeepsTheAnisotropyOfWhatItSpreads) {
  // A layer of small sizes across x at x = 0 (h_x = 0.001, h_y = 0.1) in a field of size 1: along x
  // both sizes grow by the same factor 1 + ℓ log β per edge, so h_x = 0.001 + x log β and h_y = 100 h_x.
  const double dx = 0.0005, beta = 1.5;
  Mesh<2> mesh = strip(40, dx);
  std::vector<SymMat2> metrics(static_cast<std::size_t>(mesh.vertex_count()), SymMat2::identity());
  metrics[0] = metrics[1] = SymMat2::from_diagonal({{1e6, 100}});
  grade_metrics(mesh, metrics, {beta, 1e-12});
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const SymMat2& m = metrics[static_cast<std::size_t>(v)];
    double hx = 1 / std::sqrt(m(0, 0)), hy = 1 / std::sqrt(m(1, 1));
    EXPECT_NEAR(hx, 0.001 + mesh.vertex(v)[0] * std::log(beta), 1e-9) << v;
    EXPECT_NEAR(hy / hx, 100, 1e-6) << v;
    EXPECT_NEAR(m(1, 0), 0, 1e-9 * m(1, 1));
  }
}

TEST(Gradation, RefusesBadOptionsAndMetrics) {
  Mesh<2> mesh = generate_square(2);
  std::vector<SymMat2> metrics(static_cast<std::size_t>(mesh.vertex_count()), SymMat2::identity());
  EXPECT_THROW(grade_metrics(mesh, metrics, {1.0, 1e-3}), Error);
  EXPECT_THROW(grade_metrics(mesh, metrics, {0.5, 1e-3}), Error);
  EXPECT_THROW(grade_metrics(mesh, metrics, {1.5, -1}), Error);
  metrics[3] = -SymMat2::identity();
  EXPECT_THROW(grade_metrics(mesh, metrics, {1.5, 1e-3}), Error);
  metrics.pop_back();
  EXPECT_THROW(grade_metrics(mesh, metrics, {1.5, 1e-3}), Error);
}

}  // namespace
}  // namespace hocav
