#include "mesh/mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

#include "base/error.hpp"
#include "cases/structured.hpp"
#include "inner_facet_meshes.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/consistency.hpp"
#include "mesh/measure.hpp"
#include "pinched_mesh.hpp"
#include "turned_facets.hpp"

namespace hocav {
namespace {

TEST(Mesh, CubeCountsAndConsistency) {
  Mesh<3> mesh = generate_cube(3);
  EXPECT_EQ(mesh.vertex_count(), 64);
  EXPECT_EQ(mesh.element_count(), 6 * 27);
  EXPECT_EQ(mesh.facet_count(), 6 * 9 * 2);
  EXPECT_EQ(mesh.line_count(), 12 * 3);
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  EXPECT_EQ(check_consistency(mesh, options), std::vector<std::string>{});
  double volume = 0;
  for (Index k = 0; k < mesh.element_count(); ++k) volume += element_measure(mesh, k);
  EXPECT_NEAR(volume, 1.0, 1e-12);
}

TEST(Mesh, SquareCountsAndConsistency) {
  Mesh<2> mesh = generate_square(4);
  EXPECT_EQ(mesh.element_count(), 32);
  EXPECT_EQ(mesh.facet_count(), 16);
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  EXPECT_EQ(check_consistency(mesh, options), std::vector<std::string>{});
}

// The generated meshes' facets are outward; turned and oriented again, each is as it was (3D: up to
// a rotation, the same vertices in the same cyclic order).
template <int D>
void expect_facets_oriented_outward(const Mesh<D>& mesh) {
  Mesh<D> turned = mesh_test::with_facets_turned(mesh, 2);
  const auto cyclic = [](auto facet) {  // 3D: the rotation that starts at the smallest vertex (2D: as it is)
    if constexpr (D == 3) std::rotate(facet.begin(), std::min_element(facet.begin(), facet.end()), facet.end());
    return facet;
  };
  Index differing = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) differing += cyclic(turned.facet(f)) != cyclic(mesh.facet(f));
  EXPECT_EQ(differing, (mesh.facet_count() + 1) / 2);
  turned.orient_boundary_facets_outward();
  for (Index f = 0; f < mesh.facet_count(); ++f) EXPECT_EQ(cyclic(turned.facet(f)), cyclic(mesh.facet(f))) << "facet " << f;
  EXPECT_TRUE(check_consistency(turned).empty());
}

// link_facets after build_topology links the facets added since as build_topology does: the same
// element face for each (the smaller element across an inner facet), also at a non-manifold edge,
// where the walk around a vertex sees one cube only.
template <int D>
void expect_linked_as_built(const Mesh<D>& built) {
  Mesh<D> linked;
  for (Index v = 0; v < built.vertex_count(); ++v) linked.add_vertex(built.vertex(v));
  for (Index k = 0; k < built.element_count(); ++k) linked.add_element(built.element(k), built.element_ref(k));
  linked.build_topology();
  for (Index f = 0; f < built.facet_count(); ++f) linked.add_facet(built.facet(f), built.facet_ref(f));
  linked.link_facets();
  for (Index f = 0; f < built.facet_count(); ++f) EXPECT_EQ(linked.facet_element_face(f), built.facet_element_face(f)) << f;
  for (Index k = 0; k < built.element_count(); ++k)
    for (int face = 0; face <= D; ++face) EXPECT_EQ(linked.element_face_facet(k, face), built.element_face_facet(k, face)) << k;
}

TEST(Mesh, LinkFacetsLinksAsBuildTopologyDoes) {
  expect_linked_as_built(mesh_test::four_refs_by_quadrant<3>(4));
  expect_linked_as_built(mesh_test::four_refs_by_quadrant<2>(5));
  Mesh<3> cubes = mesh_test::cubes_sharing_an_edge(2);
  cubes.build_topology();
  expect_linked_as_built(cubes);
  Mesh<3> wrong = generate_cube(2);
  wrong.build_topology();
  wrong.add_facet({0, 1, 26}, 1);  // no face of any element
  EXPECT_THROW(wrong.link_facets(), Error);
}

TEST(Mesh, BoundaryFacetsAreOrientedOutward) {
  expect_facets_oriented_outward(generate_square(3));
  expect_facets_oriented_outward(generate_cube(2));
}

// A baffle given with its facets either way is oriented like its first facet: every side (edge in
// 3D, vertex in 2D) two of its facets share is given opposite directions by them.
template <int D>
void expect_baffle_oriented_alike() {
  Mesh<D> mesh = mesh_test::with_facets_turned(mesh_test::baffle_across_the_middle<D>(4), 2);
  std::vector<Index> baffle;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (mesh.facet_ref(f) == 9) baffle.push_back(f);
  const typename Mesh<D>::Facet first = mesh.facet(baffle.front());
  const auto directed_sides = [&] {
    std::map<std::pair<Index, Index>, int> sides;  // (from, to) -> how many facets give it (2D: (v, ±1))
    for (Index f : baffle) {
      const auto& facet = mesh.facet(f);
      if constexpr (D == 2) {
        ++sides[{facet[0], -1}];
        ++sides[{facet[1], +1}];
      } else {
        for (int i = 0; i < 3; ++i) ++sides[{facet[i], facet[(i + 1) % 3]}];
      }
    }
    return sides;
  };
  const auto repeated = [&] {
    const auto sides = directed_sides();
    return std::count_if(sides.begin(), sides.end(), [](const auto& side) { return side.second > 1; });
  };
  ASSERT_GT(repeated(), 0) << "the input must give some shared side one direction twice";
  mesh.orient_boundary_facets_outward();
  EXPECT_EQ(repeated(), 0);
  EXPECT_EQ(mesh.facet(baffle.front()), first);
  EXPECT_TRUE(check_consistency(mesh).empty());
}

TEST(Mesh, BafflePatchesAreOrientedAlike) {
  expect_baffle_oriented_alike<2>();
  expect_baffle_oriented_alike<3>();
}

TEST(Mesh, EulerCharacteristicOfTheEdgeTable) {
  Mesh<3> mesh = generate_cube(4);
  mesh.make_p2();
  // V - E + F - T = 1 for a ball; count interior faces from the adjacency.
  Index faces = 0;
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int f = 0; f < 4; ++f) faces += (mesh.neighbor(k, f) == kNoIndex || mesh.neighbor(k, f) > k) ? 1 : 0;
  EXPECT_EQ(mesh.vertex_count() - mesh.edge_count() + faces - mesh.element_count(), 1);
  EXPECT_EQ(check_consistency(mesh), std::vector<std::string>{});
}

// Two tetrahedra that share only vertex 0: the walk from vertex 0's element sees one of them, yet
// a feature line on the other's edge is an element edge; a line on no element's edge is named.
TEST(Mesh, ConsistencyFindsALineAtAVertexWhereTwoPartsMeet) {
  Mesh<3> mesh = mesh_test::pinched_tetrahedra();
  ASSERT_GT(signed_measure(mesh.vertex(0), mesh.vertex(5), mesh.vertex(4), mesh.vertex(6)), 0);
  mesh.add_line({0, 1});
  mesh.add_line({0, 4});
  mesh.build_topology();
  std::vector<Index> ball;
  collect_ball(mesh, 0, ball);
  ASSERT_EQ(ball.size(), 1u);  // the walk sees one part
  EXPECT_EQ(check_consistency(mesh), std::vector<std::string>{});
  mesh.add_line({1, 4});
  EXPECT_EQ(check_consistency(mesh), std::vector<std::string>{"edge (line) 3 (2, 5) is no element edge"});
}

TEST(Mesh, P2NodesAreFoundFromVerticesAndFromLocalEdges) {
  Mesh<3> mesh = generate_cube(2);
  mesh.make_p2();
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int e = 0; e < 6; ++e) {
      Index a = mesh.element(k)[edge_vertices<3>(e)[0]], b = mesh.element(k)[edge_vertices<3>(e)[1]];
      Index edge = mesh.element_edge(k, e);
      EXPECT_EQ(mesh.find_edge(a, b), edge);
      EXPECT_EQ(mesh.find_edge(b, a), edge);
      Vec3 mid = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
      EXPECT_EQ(mesh.edge_node(edge), mid);
    }
  EXPECT_EQ(mesh.find_edge(0, mesh.vertex_count() - 1), kNoIndex);  // the cube's long diagonal is no edge at n = 2
}

TEST(Mesh, BallAndShellAgreeWithBruteForce) {
  Mesh<3> mesh = generate_cube(3);
  mesh.build_edges();
  std::vector<Index> ball, shell;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    collect_ball(mesh, v, ball);
    std::set<Index> expected;
    for (Index k = 0; k < mesh.element_count(); ++k)
      if (local_vertex(mesh, k, v) >= 0) expected.insert(k);
    EXPECT_EQ(std::set<Index>(ball.begin(), ball.end()), expected) << "vertex " << v;
    EXPECT_EQ(ball.size(), expected.size());
  }
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    auto [a, b] = mesh.edge_vertices(e);
    collect_shell(mesh, a, b, shell);
    std::set<Index> expected;
    for (Index k = 0; k < mesh.element_count(); ++k)
      if (local_vertex(mesh, k, a) >= 0 && local_vertex(mesh, k, b) >= 0) expected.insert(k);
    EXPECT_EQ(std::set<Index>(shell.begin(), shell.end()), expected);
  }
}

TEST(Mesh, CheckerFindsBrokenInvariants) {
  Mesh<2> mesh;
  mesh.add_vertex({{0, 0}});
  mesh.add_vertex({{1, 0}});
  mesh.add_vertex({{0, 1}});
  mesh.add_vertex({{1, 1}});
  mesh.add_element({0, 1, 2});
  mesh.add_element({1, 2, 3});  // clockwise: inverted and inconsistently oriented with its neighbour
  mesh.build_topology();
  auto problems = check_consistency(mesh);
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems[0].find("element 2"), std::string::npos);
  ConsistencyOptions no_orientation;
  no_orientation.require_positive_orientation = false;
  problems = check_consistency(mesh, no_orientation);
  ASSERT_EQ(problems.size(), 2u);  // seen from each side of the shared edge
  for (const auto& problem : problems) EXPECT_NE(problem.find("not consistently oriented"), std::string::npos);
}

TEST(Mesh, NonManifoldFaceIsAnError) {
  Mesh<2> mesh;
  for (Vec2 p : {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{0, 1}}, Vec2{{0, -1}}, Vec2{{-1, 0}}}) mesh.add_vertex(p);
  mesh.add_element({0, 1, 2});
  mesh.add_element({1, 0, 3});
  mesh.add_element({0, 1, 4});  // a third triangle on edge (0, 1)
  EXPECT_THROW(mesh.build_topology(), Error);
}

TEST(Mesh, OutOfRangeVertexIsRefused) {
  Mesh<2> mesh;
  mesh.add_vertex({{0, 0}});
  EXPECT_THROW(mesh.add_element({0, 1, 2}), Error);
  EXPECT_THROW(mesh.add_facet({0, -1}), Error);
}

TEST(IndexHashMap, MatchesAStandardMapUnderRandomInsertAndErase) {
  IndexHashMap map;
  std::map<std::uint64_t, Index> reference;
  std::mt19937_64 random(7);
  for (int step = 0; step < 200000; ++step) {
    std::uint64_t key = random() % 5000;
    if (random() % 3 == 0) {
      EXPECT_EQ(map.erase(key), reference.erase(key) == 1);
    } else {
      Index value = static_cast<Index>(random() % 1000);
      Index stored = map.insert(key, value);
      auto [it, inserted] = reference.emplace(key, value);
      EXPECT_EQ(stored, it->second);
    }
  }
  EXPECT_EQ(map.size(), reference.size());
  for (std::uint64_t key = 0; key < 5000; ++key) {
    auto it = reference.find(key);
    EXPECT_EQ(map.find(key), it == reference.end() ? kNoIndex : it->second);
  }
}

}  // namespace
}  // namespace hocav
