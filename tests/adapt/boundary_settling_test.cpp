#include "adapt/boundary_settling.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "adapt/adaptation_loop.hpp"
#include "adapt/metric_measures.hpp"
#include "adapt_test_support.hpp"
#include "cases/structured.hpp"

namespace hocav {
namespace {

using metric_test::vertex_at;

template <int D>
std::vector<SymMat<D>> unit_metrics(const Mesh<D>& mesh) {
  SymMat<D> identity;
  for (int i = 0; i < D; ++i) identity(i, i) = 1;
  return std::vector<SymMat<D>>(static_cast<std::size_t>(mesh.vertex_count()), identity);
}

template <int D>
std::vector<double> qualities(const Mesh<D>& mesh, const std::vector<SymMat<D>>& metrics) {
  std::vector<double> out;
  for (const auto& element : mesh.elements()) {
    SimplexPoints<D> points;
    std::array<SymMat<D>, D + 1> at;
    for (int i = 0; i <= D; ++i) {
      points[i] = mesh.vertex(element[i]);
      at[i] = metrics[element[i]];
    }
    out.push_back(mean_metric_ratio<D>(points, at));
  }
  return out;
}

// Every element keeps 70% of its quality, and 0.1 if it had it (the settling's floor).
void expect_floors_kept(const std::vector<double>& before, const std::vector<double>& after) {
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t k = 0; k < before.size(); ++k) EXPECT_GE(after[k], std::max(0.7 * before[k], std::min(before[k], kPoorQuality))) << k;
}

TEST(BoundarySettling, PutsSurfaceAndRidgeVerticesBackOntoTheirSides) {
  Mesh<3> mesh = generate_cube(6);
  mesh.build_topology();
  // Inside the side z = 0, every other vertex 0.01 off it (as a split that could not use its point on
  // the geometry leaves it, on the facets before); on the edge x = y = 0, one vertex off it too.
  Index off = 0;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    Vec3& x = mesh.vertex(v);
    const bool inside_bottom = x[2] == 0 && x[0] > 0 && x[0] < 1 && x[1] > 0 && x[1] < 1;
    if (inside_bottom && std::lround(6 * (x[0] + x[1])) % 2 == 1) {
      x[2] = 0.01;
      ++off;
    }
  }
  const Index on_edge = vertex_at<3>(mesh, {{0, 0, 0.5}});
  ASSERT_NE(on_edge, kNoIndex);
  mesh.vertex(on_edge) = Vec3{{0.01, 0.02, 0.5}};
  const std::vector<SymMat<3>> metrics = unit_metrics(mesh);
  const std::vector<double> before = qualities(mesh, metrics);
  const BoundarySettling settling = settle_boundary<3>(mesh, metrics, adapt_test::unit_box_sides<3>(), 45);
  EXPECT_EQ(settling.off_geometry, off + 1);
  EXPECT_EQ(settling.settled, off + 1);
  EXPECT_EQ(settling.partly + settling.blocked, 0);
  EXPECT_GT(settling.inner_vertices_moved, 0);
  for (const auto& facet : mesh.facets())
    for (Index v : facet)
      EXPECT_NEAR(std::min({mesh.vertex(v)[0], mesh.vertex(v)[1], mesh.vertex(v)[2], 1 - mesh.vertex(v)[0], 1 - mesh.vertex(v)[1],
                            1 - mesh.vertex(v)[2]}),
                  0, 1e-12)
          << v;
  EXPECT_LT(norm(mesh.vertex(on_edge) - Vec3{{0, 0, 0.5}}), 1e-9);
  adapt_test::expect_closed_and_consistent(mesh);
  expect_floors_kept(before, qualities(mesh, metrics));
}

TEST(BoundarySettling, MovesAVertexOnlyAsFarAsItsElementsAllow) {
  // The bottom side's geometry 0.1 below the mesh's: its vertices go down with their columns, but
  // next to the corners, which stay, the elements would lose more than 30% of their quality.
  Mesh<2> mesh = generate_square(10);
  mesh.build_topology();
  AnalyticBoundary<2> sides = adapt_test::unit_box_sides<2>();
  sides.add(1, AnalyticSurface<2>::plane(Vec2{{0, -0.1}}, Vec2{{0, 1}}));
  const std::vector<SymMat<2>> metrics = unit_metrics(mesh);
  const std::vector<double> before = qualities(mesh, metrics);
  const BoundarySettling settling = settle_boundary<2>(mesh, metrics, sides, 45);
  EXPECT_EQ(settling.off_geometry, 9);
  EXPECT_NEAR(settling.largest_distance, 0.1, 1e-12);
  EXPECT_GT(settling.settled, 0);
  EXPECT_GT(settling.partly + settling.blocked, 0);
  EXPECT_EQ(settling.settled + settling.partly + settling.blocked, 9);
  EXPECT_GT(settling.rounds, 0);
  EXPECT_GT(settling.largest_distance_left, 0);
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (mesh.vertex(v)[1] < 1e-12) {
      EXPECT_GE(mesh.vertex(v)[1], -0.1 - 1e-12) << v;
    }
  const std::vector<double> after = qualities(mesh, metrics);
  expect_floors_kept(before, after);
}

TEST(BoundarySettling, LeavesAMeshOnItsGeometryUnchanged) {
  Mesh<3> mesh = generate_cube(4);
  mesh.build_topology();
  const Mesh<3> start = mesh;
  const BoundarySettling settling = settle_boundary<3>(mesh, unit_metrics(mesh), adapt_test::unit_box_sides<3>(), 45);
  EXPECT_EQ(settling.off_geometry, 0);
  for (Index v = 0; v < mesh.vertex_count(); ++v) EXPECT_EQ(mesh.vertex(v), start.vertex(v)) << v;
}

}  // namespace
}  // namespace hocav
