// The defects of a consistent mesh: open boundary faces, non-manifold vertices and edges, overlaps.
#include "mesh/mesh_defects.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cases/structured.hpp"
#include "pinched_mesh.hpp"

namespace hocav {
namespace {

TEST(MeshDefects, AGeneratedMeshHasNone) {
  Mesh<3> cube = generate_cube(2);
  EXPECT_TRUE(find_mesh_defects(cube).none()) << find_mesh_defects(cube).summary();
  EXPECT_EQ(find_mesh_defects(cube).summary(), "");
}

TEST(MeshDefects, NamesOpenBoundaryFaces) {
  Mesh<2> square;
  for (const Vec2& p : {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{1, 1}}, Vec2{{0, 1}}}) square.add_vertex(p);
  square.add_element({0, 1, 2});
  square.add_element({0, 2, 3});
  square.add_facet({0, 1});  // three of the four sides have no facet
  square.build_topology();
  const MeshDefects defects = find_mesh_defects(square, 2);
  EXPECT_EQ(defects.open_faces, 3);
  EXPECT_EQ(defects.examples.size(), 2u);
  EXPECT_NE(defects.summary().find("3 open boundary faces"), std::string::npos) << defects.summary();
  EXPECT_NE(defects.summary().find("has no boundary facet"), std::string::npos) << defects.summary();
}

TEST(MeshDefects, NamesAVertexWhereTwoPartsMeet) {
  Mesh<2> bowtie;
  for (const Vec2& p : {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{1, 1}}, Vec2{{-1, 0}}, Vec2{{-1, -1}}}) bowtie.add_vertex(p);
  bowtie.add_element({0, 1, 2});
  bowtie.add_element({0, 3, 4});
  using Side = Mesh<2>::Facet;
  for (const Side& side : {Side{0, 1}, Side{1, 2}, Side{2, 0}, Side{0, 3}, Side{3, 4}, Side{4, 0}}) bowtie.add_facet(side);
  bowtie.build_topology();
  const MeshDefects defects = find_mesh_defects(bowtie);
  EXPECT_EQ(defects.open_faces, 0);
  EXPECT_EQ(defects.non_manifold_vertices, 1);
  EXPECT_NE(defects.summary().find("vertex 1 joins parts"), std::string::npos) << defects.summary();
}

TEST(MeshDefects, NamesAnEdgeWithFourBoundaryFaces) {
  Mesh<3> pair;
  for (const Vec3& p : {Vec3{{0, 0, 0}}, Vec3{{0, 0, 1}}, Vec3{{1, 0, 0}}, Vec3{{0, 1, 0}}, Vec3{{-1, 0, 0}}, Vec3{{0, -1, 0}}})
    pair.add_vertex(p);
  pair.add_element({0, 1, 2, 3});
  pair.add_element({0, 1, 4, 5});
  pair.build_topology();
  const MeshDefects defects = find_mesh_defects(pair);
  EXPECT_EQ(defects.non_manifold_edges, 1);
  EXPECT_EQ(defects.open_faces, 8);
}

TEST(MeshDefects, NamesAnInnerVertexWhoseElementsTurnTwice) {
  // A pentagram fan: five positive triangles around vertex 1, each turning 144 degrees, 720 in all.
  Mesh<2> star;
  star.add_vertex({{0, 0}});
  for (int i = 0; i < 5; ++i) {
    const double angle = i * 0.8 * std::numbers::pi;
    star.add_vertex({{std::cos(angle), std::sin(angle)}});
  }
  for (Index i = 0; i < 5; ++i) {
    star.add_element({0, 1 + i, 1 + (i + 1) % 5});
    star.add_facet({1 + i, 1 + (i + 1) % 5});
  }
  star.build_topology();
  const MeshDefects defects = find_mesh_defects(star);
  EXPECT_EQ(defects.overlap_vertices, 1);
  EXPECT_EQ(defects.non_manifold_vertices + defects.open_faces, 0);
  EXPECT_NE(defects.summary().find("inner vertex 1 overlap"), std::string::npos) << defects.summary();
}

TEST(NonManifoldPlaces, AreThePinchedVerticesAndTheEdgesWithMoreThanTwoBoundaryFaces) {
  Mesh<3> pinched = mesh_test::pinched_tetrahedra();
  pinched.build_topology();
  EXPECT_EQ(non_manifold_places(pinched).vertices, std::vector<Index>{0});
  EXPECT_TRUE(non_manifold_places(pinched).edges.empty());

  Mesh<3> cubes = mesh_test::cubes_sharing_an_edge(2);
  cubes.build_topology();
  const NonManifoldPlaces places = non_manifold_places(cubes);
  ASSERT_EQ(places.vertices.size(), 3u);  // the shared edge's vertices, at z = 0, 0.5, 1
  for (Index v : places.vertices) {
    EXPECT_EQ(cubes.vertex(v)[0], 1);
    EXPECT_EQ(cubes.vertex(v)[1], 1);
  }
  ASSERT_EQ(places.edges.size(), 2u);
  for (const std::uint64_t key : places.edges) {
    const Index a = static_cast<Index>(key >> 32), b = static_cast<Index>(key & 0xffffffffu);
    EXPECT_EQ(std::abs(cubes.vertex(a)[2] - cubes.vertex(b)[2]), 0.5);
  }
  EXPECT_EQ(places.every_vertex(), places.vertices);
  EXPECT_EQ(find_mesh_defects(cubes).non_manifold_edges, 2);
  Mesh<3> cube = generate_cube(2);
  cube.build_topology();
  EXPECT_TRUE(non_manifold_places(cube).vertices.empty());
  EXPECT_TRUE(non_manifold_places(cube).edges.empty());
}

}  // namespace
}  // namespace hocav
