#include "metric/surface_metric.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../mesh/inner_facet_meshes.hpp"
#include "../mesh/turned_facets.hpp"
#include "base/error.hpp"
#include "mesh/boundary_mesh.hpp"
#include "metric_test_support.hpp"

namespace hocav {
namespace {

using metric_test::vertex_at;

template <int D>
void expect_near_vector(const Vec<D>& actual, const Vec<D>& expected) {
  for (int i = 0; i < D; ++i) EXPECT_NEAR(actual[i], expected[i], 1e-14);
}

TEST(SurfaceMetric, NormalsOfTheSquareAreOutwardAndAreaWeighted) {
  Mesh<2> mesh = generate_square(4);
  auto normals = boundary_vertex_normals(mesh);
  expect_near_vector(normals[vertex_at(mesh, Vec2{{0.5, 0}})], Vec2{{0, -1}});
  expect_near_vector(normals[vertex_at(mesh, Vec2{{1, 0.25}})], Vec2{{1, 0}});
  expect_near_vector(normals[vertex_at(mesh, Vec2{{0.75, 1}})], Vec2{{0, 1}});
  expect_near_vector(normals[vertex_at(mesh, Vec2{{0, 0.5}})], Vec2{{-1, 0}});
  expect_near_vector(normals[vertex_at(mesh, Vec2{{1, 1}})], Vec2{{std::sqrt(0.5), std::sqrt(0.5)}});
  expect_near_vector(normals[vertex_at(mesh, Vec2{{0.5, 0.5}})], Vec2{});
}

TEST(SurfaceMetric, NormalsOfTheCubeAreOutwardWhateverTheFacetOrientation) {
  // Every third facet of the cube listed in the other orientation.
  Mesh<3> mesh = mesh_test::with_facets_turned(generate_cube(2), 3);
  auto normals = boundary_vertex_normals(mesh);
  expect_near_vector(normals[vertex_at(mesh, Vec3{{0.5, 0.5, 0}})], Vec3{{0, 0, -1}});
  expect_near_vector(normals[vertex_at(mesh, Vec3{{1, 0.5, 0.5}})], Vec3{{1, 0, 0}});
  expect_near_vector(normals[vertex_at(mesh, Vec3{{0.5, 1, 0.5}})], Vec3{{0, 1, 0}});
  expect_near_vector(normals[vertex_at(mesh, Vec3{{0.5, 0.5, 0.5}})], Vec3{});
  // On a cube edge, the two faces count by their facets' areas around the vertex.
  Vec3 edge_normal = normals[vertex_at(mesh, Vec3{{0.5, 0, 0}})];
  EXPECT_LT(edge_normal[0], 1e-14);
  EXPECT_LT(edge_normal[1], 0);
  EXPECT_LT(edge_normal[2], 0);
  EXPECT_NEAR(norm(edge_normal), 1, 1e-14);
}

TEST(SurfaceMetric, SizesAlongTheNormalInTheTangentPlaneAndInside) {
  Mesh<3> mesh = generate_cube(2);
  SurfaceSizes sizes{0.01, 0.2, 3};
  auto metrics = surface_metric_at_vertices(mesh, sizes);
  const SymMat3& face = metrics[vertex_at(mesh, Vec3{{0.5, 0.5, 0}})];
  EXPECT_NEAR(quadratic_form(face, Vec3{{0, 0, 0.01}}), 1, 1e-12);
  EXPECT_NEAR(quadratic_form(face, Vec3{{0.2, 0, 0}}), 1, 1e-12);
  EXPECT_NEAR(quadratic_form(face, Vec3{{0, 0.2, 0}}), 1, 1e-12);
  EXPECT_NEAR(face(2, 0), 0, 1e-12);
  const SymMat3& inside = metrics[vertex_at(mesh, Vec3{{0.5, 0.5, 0.5}})];
  EXPECT_EQ(inside, (1 / 9.0) * SymMat3::identity());
  // At a corner the normal is the diagonal of the three faces.
  Vec3 diagonal{{1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}};
  EXPECT_NEAR(quadratic_form(metrics[vertex_at(mesh, Vec3{{1, 1, 1}})], 0.01 * diagonal), 1, 1e-12);

  Mesh<2> square = generate_square(2);
  auto square_metrics = surface_metric_at_vertices(square, sizes);
  const SymMat2& side = square_metrics[vertex_at(square, Vec2{{0, 0.5}})];
  EXPECT_NEAR(side(0, 0), 1e4, 1e-8);
  EXPECT_NEAR(side(1, 1), 25, 1e-12);
  EXPECT_NEAR(side(1, 0), 0, 1e-12);
}

TEST(SurfaceMetric, OpposedFacetsLeaveTheSmallSizeInEveryDirection) {
  // A bow tie: two triangles touching at vertex 0 only, whose boundary edges there face opposite ways.
  Mesh<2> mesh;
  for (Vec2 x : {Vec2{{0, 0}}, Vec2{{-1, -1}}, Vec2{{-1, 1}}, Vec2{{1, 1}}, Vec2{{1, -1}}}) mesh.add_vertex(x);
  mesh.add_element({0, 2, 1});
  mesh.add_element({0, 4, 3});
  for (Mesh<2>::Facet facet :
       {Mesh<2>::Facet{0, 2}, Mesh<2>::Facet{2, 1}, Mesh<2>::Facet{1, 0}, Mesh<2>::Facet{0, 4}, Mesh<2>::Facet{4, 3}, Mesh<2>::Facet{3, 0}})
    mesh.add_facet(facet);
  mesh.build_topology();
  auto metrics = surface_metric_at_vertices(mesh, SurfaceSizes{0.5, 1, 1});
  EXPECT_EQ(boundary_vertex_normals(mesh)[0], Vec2{});
  EXPECT_EQ(metrics[0], 4 * SymMat2::identity());
  expect_near_vector(boundary_vertex_normals(mesh)[1], Vec2{{-std::sqrt(0.5), -std::sqrt(0.5)}});
}

// The metric from the boundary alone (its facets oriented outward) against the mesh's, vertex by
// vertex; the number of vertices where they differ by more than rounding.
template <int D>
int boundary_metric_differences(Mesh<D> mesh, bool oriented) {
  if (oriented) mesh.orient_boundary_facets_outward();
  const SurfaceSizes sizes{0.01, 0.2, 3};
  const std::vector<SymMat<D>> whole = surface_metric_at_vertices(mesh, sizes);
  const std::vector<SymMat<D>> boundary = surface_metric_at_boundary(boundary_mesh_of(mesh), sizes);
  EXPECT_EQ(boundary.size(), whole.size());
  int differences = 0;
  for (std::size_t v = 0; v < whole.size(); ++v)
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j)
        if (std::abs(boundary[v](i, j) - whole[v](i, j)) > 1e-9 * (1 + std::abs(whole[v](i, j)))) {
          ++differences;
          i = j = D;
        }
  return differences;
}

TEST(SurfaceMetric, TheBoundaryAloneGivesTheMeshsMetricOnceItsFacetsFaceOutward) {
  EXPECT_EQ(boundary_metric_differences(mesh_test::with_facets_turned(generate_square(5), 3), true), 0);
  EXPECT_EQ(boundary_metric_differences(mesh_test::with_facets_turned(generate_cube(3), 3), true), 0);
  // Facets that face either way cancel in the sums of the boundary alone.
  EXPECT_GT(boundary_metric_differences(mesh_test::with_facets_turned(generate_cube(3), 3), false), 0);
}

// An inner surface's facets add up to its normal whichever element each is linked to and however it
// is turned: the interface's as the faces of the smaller ref's side (x < 0.5: the normal +x), a
// baffle's all one way (fails with each facet's normal taken away from its linked element).
TEST(SurfaceMetric, AnInnerSurfacesNormalsAgree) {
  for (const bool baffle : {false, true}) {
    const Mesh<3> mesh = mesh_test::elements_shuffled(baffle ? mesh_test::baffle_across_the_middle<3>(4)
                                                             : mesh_test::two_refs_across_an_interface<3>(4));
    const std::vector<Vec3> normals = boundary_vertex_normals(mesh);
    std::vector<double> signs;
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
      const Vec3& x = mesh.vertex(v);
      if (x[0] != 0.5 || x[1] <= 0 || x[1] >= 1 || x[2] <= 0 || x[2] >= 1) continue;  // inside the surface
      EXPECT_NEAR(std::abs(normals[v][0]), 1, 1e-12) << "vertex " << v << (baffle ? " of the baffle" : " of the interface");
      signs.push_back(normals[v][0]);
    }
    ASSERT_EQ(signs.size(), 9u);
    for (double sign : signs) EXPECT_EQ(sign, baffle ? signs.front() : 1.0);
  }
}

TEST(SurfaceMetric, RefusesNonPositiveSizes) {
  Mesh<2> mesh = generate_square(1);
  EXPECT_THROW(surface_metric_at_vertices(mesh, SurfaceSizes{0, 1, 1}), Error);
  EXPECT_THROW(surface_metric_at_vertices(mesh, SurfaceSizes{1, -1, 1}), Error);
  EXPECT_THROW(surface_metric_at_vertices(mesh, SurfaceSizes{1, 1, std::nan("")}), Error);
}

}  // namespace
}  // namespace hocav
