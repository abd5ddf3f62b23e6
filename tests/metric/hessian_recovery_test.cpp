#include "metric/hessian_recovery.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "base/error.hpp"
#include "metric/analytic_field.hpp"
#include "metric_test_support.hpp"

namespace hocav {
namespace {

template <int D>
std::vector<double> values_at_vertices(const Mesh<D>& mesh, const AnalyticFieldSpec& field) {
  std::vector<double> values;
  for (const auto& x : mesh.vertices()) values.push_back(analytic_field<D>(field, x));
  return values;
}

template <int D>
void expect_quadratic_recovered_exactly(const Mesh<D>& mesh) {
  AnalyticFieldSpec quadratic{"quadratic"};
  auto hessians = recover_hessians(mesh, values_at_vertices(mesh, quadratic));
  SymMat<D> exact = analytic_field_hessian<D>(quadratic, Vec<D>{});
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    for (int e = 0; e < SymMat<D>::kEntryCount; ++e)
      EXPECT_NEAR(hessians[static_cast<std::size_t>(v)].entries[static_cast<std::size_t>(e)], exact.entries[static_cast<std::size_t>(e)],
                  1e-8)
          << "vertex " << v;
}

TEST(HessianRecovery, RecoversAQuadraticExactlyAtEveryVertex) {
  expect_quadratic_recovered_exactly(metric_test::perturbed_unit_mesh<2>(8, 0.2));
  expect_quadratic_recovered_exactly(metric_test::perturbed_unit_mesh<3>(4, 0.2));
  // Shifted and stretched 100:1, the fit stays exact: its round-off is that of the data, about
  // eps·|u| / h², and the scaled, equilibrated QR adds nothing to it.
  Mesh<2> stretched = metric_test::perturbed_unit_mesh<2>(6, 0.2);
  for (Index v = 0; v < stretched.vertex_count(); ++v) {
    Vec2& x = stretched.vertex(v);
    x = Vec2{{1 + x[0], -2 + 0.01 * x[1]}};
  }
  expect_quadratic_recovered_exactly(stretched);
}

// Two strips along the axes joined at (2, 2): the corners (0, 0) and (2, 2) have 2 neighbours, their
// 2-rings lie on two lines through them (xy = 0 there: no xy term), and only the 3-ring, 5 vertices
// with (2, 2) or (0, 0), determines the quadratic.
TEST(HessianRecovery, GrowsTheStencilToTheThirdRing) {
  Mesh<2> cross;
  for (Vec2 x : {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{2, 0}}, Vec2{{0, 1}}, Vec2{{0, 2}}, Vec2{{2, 2}}}) cross.add_vertex(x);
  for (std::array<Index, 3> t : {std::array<Index, 3>{0, 1, 3}, {1, 2, 3}, {3, 2, 4}, {2, 5, 4}}) cross.add_element(t);
  expect_quadratic_recovered_exactly(cross);
}

// The largest error of the recovered Hessian of u = exp(x) sin(2y) over the vertices away from the boundary.
double interior_error(int cells) {
  Mesh<2> mesh = metric_test::perturbed_unit_mesh<2>(cells, 0.15);
  std::vector<double> values;
  for (const auto& x : mesh.vertices()) values.push_back(std::exp(x[0]) * std::sin(2 * x[1]));
  auto hessians = recover_hessians(mesh, values);
  double error = 0;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const Vec2& x = mesh.vertex(v);
    if (x[0] < 0.2 || x[0] > 0.8 || x[1] < 0.2 || x[1] > 0.8) continue;
    double u = std::exp(x[0]), s = std::sin(2 * x[1]), c = std::cos(2 * x[1]);
    SymMat2 exact;
    exact(0, 0) = u * s;
    exact(1, 0) = 2 * u * c;
    exact(1, 1) = -4 * u * s;
    error = std::max(error, frobenius_norm(hessians[static_cast<std::size_t>(v)] - exact));
  }
  return error;
}

TEST(HessianRecovery, ConvergesOnASmoothField) {
  double coarse = interior_error(10), fine = interior_error(40);
  EXPECT_LT(fine, 0.5);
  EXPECT_LT(fine, coarse / 3);
}

TEST(HessianRecovery, RefusesTooFewNeighboursAndWrongSizes) {
  Mesh<2> triangle;
  for (Vec2 x : {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{0, 1}}}) triangle.add_vertex(x);
  triangle.add_element({0, 1, 2});
  EXPECT_THROW(recover_hessians(triangle, std::vector<double>{1, 2, 3}), Error);
  Mesh<2> square = generate_square(3);
  EXPECT_THROW(recover_hessians(square, std::vector<double>(3, 0.0)), Error);
}

}  // namespace
}  // namespace hocav
