#include "mesh/harmonic_extension.hpp"

#include <gtest/gtest.h>

#include <random>

#include "../metric/metric_test_support.hpp"
#include "cases/structured.hpp"
#include "geom/barycentric.hpp"
#include "mesh/boundary_vertices.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

// Every boundary vertex fixed with the move f(x).
template <int D, typename Field>
void fix_boundary(const Mesh<D>& mesh, Field f, std::vector<char>& fixed, std::vector<Vec<D>>& moves) {
  const std::vector<bool> on_boundary = boundary_vertex_flags(mesh);
  fixed.assign(static_cast<std::size_t>(mesh.vertex_count()), 0);
  moves.assign(fixed.size(), Vec<D>{});
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (on_boundary[v]) {
      fixed[v] = 1;
      moves[v] = f(mesh.vertex(v));
    }
}

// Every boundary vertex moved by `linear`: every vertex is, exactly.
template <int D, typename Field>
void expect_linear_move_extended_exactly(const Mesh<D>& mesh, Field linear) {
  std::vector<char> fixed;
  std::vector<Vec<D>> moves;
  fix_boundary(mesh, linear, fixed, moves);
  const HarmonicExtension<D> extension = harmonic_extension<D>(mesh, fixed, moves, 1e9);
  EXPECT_GT(extension.free_vertices, 0);
  // (The solver stops at a residual of 1e-10 of the start.)
  for (Index v = 0; v < mesh.vertex_count(); ++v) EXPECT_LT(norm(extension.moves[v] - linear(mesh.vertex(v))), 1e-10) << v;
}

TEST(HarmonicExtension, ExtendsALinearMoveExactly) {
  expect_linear_move_extended_exactly(metric_test::perturbed_unit_mesh<3>(4, 0.2), [](const Vec3& x) {
    return Vec3{{0.01 * x[0] + 0.02 * x[1], -0.03 * x[2], 0.01 + 0.02 * x[0]}};
  });
  expect_linear_move_extended_exactly(metric_test::perturbed_unit_mesh<2>(5, 0.2), [](const Vec2& x) {
    return Vec2{{0.02 - 0.01 * x[1], 0.03 * x[0]}};
  });
}

// The Dirichlet energy Σ_k |k| |∇u|² of the moves, coordinate by coordinate.
template <int D>
double dirichlet_energy(const Mesh<D>& mesh, const std::vector<Vec<D>>& moves) {
  double energy = 0;
  for (const auto& element : mesh.elements()) {
    SimplexPoints<D> points;
    for (int i = 0; i <= D; ++i) points[i] = mesh.vertex(element[i]);
    const auto gradient = barycentric_gradients<D>(points);
    for (int c = 0; c < D; ++c) {
      Vec<D> g{};
      for (int i = 0; i <= D; ++i) g = g + moves[element[i]][c] * gradient[i];
      energy += std::abs(signed_measure<D>(points)) * dot(g, g);
    }
  }
  return energy;
}

TEST(HarmonicExtension, MinimizesTheDirichletEnergyOverTheFreeVertices) {
  const Mesh<2> mesh = metric_test::perturbed_unit_mesh<2>(4, 0.2);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.06, 0.06);
  std::vector<char> fixed;
  std::vector<Vec2> moves;
  fix_boundary(
      mesh,
      [&](const Vec2&) {
        return Vec2{{jitter(random), jitter(random)}};
      },
      fixed, moves);
  const HarmonicExtension<2> extension = harmonic_extension<2>(mesh, fixed, moves, 1e9);
  const double least = dirichlet_energy(mesh, extension.moves);
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (fixed[v]) continue;
    for (int c = 0; c < 2; ++c)
      for (double step : {-1e-4, 1e-4}) {
        std::vector<Vec2> other = extension.moves;
        other[v][c] += step;
        EXPECT_GT(dirichlet_energy(mesh, other), least) << v << " " << c << " " << step;
      }
  }
}

TEST(HarmonicExtension, MovesNothingBeyondTheReach) {
  const Mesh<2> mesh = generate_square(10);  // spacing 0.1
  std::vector<char> fixed;
  std::vector<Vec2> moves;
  fix_boundary(
      mesh, [](const Vec2&) { return Vec2{}; }, fixed, moves);
  Index moved = kNoIndex;
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (norm(mesh.vertex(v) - Vec2{{0.5, 0}}) < 1e-12) moved = v;
  ASSERT_NE(moved, kNoIndex);
  moves[moved] = Vec2{{0, 0.01}};
  const HarmonicExtension<2> extension = harmonic_extension<2>(mesh, fixed, moves, 25);  // reach 0.25
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (fixed[v]) continue;
    const double distance = norm(mesh.vertex(v) - mesh.vertex(moved));
    if (distance > 0.25 + 1e-9) {  // a path along the edges is no shorter
      EXPECT_EQ(norm(extension.moves[v]), 0) << v;
    } else if (distance < 0.15) {
      EXPECT_GT(extension.moves[v][1], 0) << v;
    }
  }
  EXPECT_GT(extension.free_vertices, 0);
  EXPECT_LT(extension.free_vertices, 20);
}

}  // namespace
}  // namespace hocav
