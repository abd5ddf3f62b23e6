#include "metric/hessian_metric.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "base/error.hpp"
#include "geom/sym_functions.hpp"
#include "metric/analytic_field.hpp"
#include "metric_test_support.hpp"

namespace hocav {
namespace {

template <int D>
std::vector<SymMat<D>> exact_hessians(const Mesh<D>& mesh, const AnalyticFieldSpec& field) {
  std::vector<SymMat<D>> hessians;
  for (const auto& x : mesh.vertices()) hessians.push_back(analytic_field_hessian<D>(field, x));
  return hessians;
}

template <int D>
void expect_complexity_is_the_target(const Mesh<D>& mesh) {
  auto hessians = exact_hessians(mesh, AnalyticFieldSpec{"tanh-shock", 0.5, 0.05});
  for (double p : {1.0, 2.0, 4.0})
    for (double n : {100.0, 12345.0}) {
      auto metrics = lp_metric(mesh, hessians, {n, p, 1e-4, 2});
      EXPECT_NEAR(metric_complexity(mesh, metrics), n, 1e-12 * n) << "p " << p;
      for (const auto& m : metrics) EXPECT_TRUE(is_spd(m));
    }
}

TEST(HessianMetric, ComplexityOfTheResultIsTheTarget) {
  expect_complexity_is_the_target(metric_test::perturbed_unit_mesh<2>(10, 0.2));
  expect_complexity_is_the_target(metric_test::perturbed_unit_mesh<3>(4, 0.2));
}

TEST(HessianMetric, ComplexityIsTheTargetToQuadratureAccuracyOnAFinerMesh) {
  // The metric of the exact Hessian with the constant D_N of a coarse mesh, measured on a fine one:
  // the two P1 rules differ by the quadrature error only.
  AnalyticFieldSpec shock{"tanh-shock", 0.5, 0.2};
  const LpMetricOptions options{1000, 2, 1e-4, 2};
  Mesh<2> coarse = generate_square(40), fine = generate_square(160);
  auto coarse_metrics = lp_metric(coarse, exact_hessians(coarse, shock), options);
  auto fine_metrics = lp_metric(fine, exact_hessians(fine, shock), options);
  // Same formula, so the fine metric is the coarse one times (I_coarse / I_fine)^{2/d}: compare at a shared vertex.
  double ratio = fine_metrics[0](0, 0) / coarse_metrics[0](0, 0);
  EXPECT_NEAR(ratio, 1, 2e-3);
}

TEST(HessianMetric, ConstantHessianGivesTheConstantMetricOfTheTarget) {
  // M = (N / |Ω|)^{2/d} det(|H|)^{-1/d} |H| whatever p, with |H| from the absolute eigenvalues.
  Mesh<3> mesh = metric_test::perturbed_unit_mesh<3>(3, 0.2);
  AnalyticFieldSpec quadratic{"quadratic"};
  SymMat3 h = analytic_field_hessian<3>(quadratic, Vec3{});
  SymEigen<3> eigen = sym_eigen(h);
  for (int k = 0; k < 3; ++k) eigen.values[k] = std::abs(eigen.values[k]);
  SymMat3 absolute = SymMat3::from_eigen(eigen.vectors, eigen.values);
  const double n = 500;
  SymMat3 expected = std::pow(n, 2.0 / 3) * std::pow(determinant(absolute), -1.0 / 3) * absolute;
  for (double p : {1.0, 3.0}) {
    auto metrics = lp_metric(mesh, exact_hessians(mesh, quadratic), {n, p, 1e-3, 10});
    for (const auto& m : metrics)
      for (int e = 0; e < 6; ++e)
        EXPECT_NEAR(m.entries[static_cast<std::size_t>(e)], expected.entries[static_cast<std::size_t>(e)], 1e-10 * expected(2, 2));
  }
}

TEST(HessianMetric, EigenvaluesOfTheHessianAreClampedBySizes) {
  // A linear field (H = 0) becomes |H| = h_max⁻² I: an isotropic metric of the target complexity.
  Mesh<2> mesh = generate_square(4);
  std::vector<SymMat2> zero(static_cast<std::size_t>(mesh.vertex_count()));
  auto metrics = lp_metric(mesh, zero, {400, 2, 0.01, 1});
  for (const auto& m : metrics) EXPECT_NEAR(1 / std::sqrt(m(0, 0)), 0.05, 1e-14);
  // An anisotropy of |H| beyond (h_max/h_min)² is capped.
  std::vector<SymMat2> stretched(zero.size(), SymMat2::from_diagonal({{1e12, 1e-12}}));
  auto capped = lp_metric(mesh, stretched, {400, 2, 0.01, 1});
  EXPECT_NEAR(capped[0](0, 0) / capped[0](1, 1), 1e4, 1e-6);
}

TEST(HessianMetric, RefusesBadOptions) {
  Mesh<2> mesh = generate_square(2);
  std::vector<SymMat2> hessians(static_cast<std::size_t>(mesh.vertex_count()), SymMat2::identity());
  EXPECT_THROW(lp_metric(mesh, hessians, {0, 2, 0.01, 1}), Error);
  EXPECT_THROW(lp_metric(mesh, hessians, {100, 0, 0.01, 1}), Error);
  EXPECT_THROW(lp_metric(mesh, hessians, {100, 2, 2, 1}), Error);
  EXPECT_THROW(lp_metric(mesh, hessians, {100, 2, 0, 1}), Error);
  hessians.pop_back();
  EXPECT_THROW(lp_metric(mesh, hessians, {100, 2, 0.01, 1}), Error);
}

}  // namespace
}  // namespace hocav
