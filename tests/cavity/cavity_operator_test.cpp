#include "cavity/cavity_operator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "../mesh/inner_facet_meshes.hpp"
#include "../mesh/turned_facets.hpp"
#include "adapt/boundary_pieces.hpp"
#include "cases/structured.hpp"
#include "cavity/cavity_operations.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/consistency.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int kOperations = 60000;  // the sanitizer build runs ~10x slower
#else
constexpr int kOperations = 600000;
#endif

template <int D>
void expect_consistent(const Mesh<D>& mesh, double measure, int operation) {
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  ASSERT_EQ(check_consistency(mesh, options), std::vector<std::string>{}) << "after operation " << operation;
  ASSERT_NEAR(total_measure(mesh), measure, 1e-9) << "after operation " << operation;
}

// Random reinsertions, insertions, collapses and swaps, with the checker run along the way.
template <int D>
void run_random_operations(Mesh<D> mesh, std::uint32_t seed) {
  mesh.make_p2();  // keeps the edge table (and straight P2 nodes) up to date through every operation
  const double measure = total_measure(mesh);
  const Index facets = mesh.facet_count();
  std::vector<bool> on_boundary(static_cast<std::size_t>(mesh.vertex_count()), false);
  for (const auto& facet : mesh.facets())
    for (Index v : facet) on_boundary[v] = true;

  CavityWorkspace<D> work;
  CavityOptions options;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Index> shell;
  int accepted[4] = {}, tried[4] = {};
  for (int operation = 0; operation < kOperations; ++operation) {
    int kind = static_cast<int>(random() % 4);
    Index k = static_cast<Index>(random() % static_cast<unsigned>(mesh.element_count()));
    const auto element = mesh.element(k);
    Index a = element[random() % (D + 1)], b = a;
    while (b == a) b = element[random() % (D + 1)];
    CavityStatus status = CavityStatus::kNotStarShaped;
    if (kind == 0) {
      status = reinsert_vertex(mesh, work, a, options);
      ASSERT_EQ(status, CavityStatus::kAccepted) << "a vertex can always be reinserted in its own ball";
    } else if (kind == 1) {
      Vec<D> x;
      for (int i = 0; i < D; ++i) x[i] = 0.02 + 0.96 * unit(random);
      SymMat<D> metric = SymMat<D>::identity();
      metric(0, 0) = 1 + 20 * unit(random);  // an anisotropic Delaunay criterion now and then
      Index before = mesh.vertex_count(), inserted = kNoIndex;
      status = insert_vertex(mesh, work, x, k, metric, options, &inserted);
      if (status == CavityStatus::kAccepted) {
        ASSERT_EQ(inserted, before);
        on_boundary.push_back(false);
      } else {
        ASSERT_EQ(mesh.vertex_count(), before);
      }
    } else if (kind == 2) {
      if (on_boundary[a]) continue;
      status = collapse_edge(mesh, work, a, b, options);
      if (status == CavityStatus::kAccepted) {
        ASSERT_EQ(mesh.vertex_element(a), kNoIndex);
      }
    } else {
      collect_shell(mesh, a, b, shell);
      // A boundary edge stays (its boundary face is starred again): swap interior edges only.
      bool boundary_edge = false;
      for (Index s : shell)
        for (int face = 0; face <= D; ++face) {
          int holds = 0;
          for (int i = 0; i < D; ++i) {
            Index v = mesh.element(s)[face_vertices<D>(face)[i]];
            holds += v == a || v == b;
          }
          boundary_edge = boundary_edge || (holds == 2 && mesh.neighbor(s, face) == kNoIndex);
        }
      if (boundary_edge) continue;
      Index apex = kNoIndex;
      const auto& other = mesh.element(shell[random() % shell.size()]);
      for (Index v : other)
        if (v != a && v != b) apex = v;
      status = swap_edge(mesh, work, a, b, apex, options);
      if (status == CavityStatus::kAccepted) {
        ASSERT_EQ(mesh.find_edge(a, b), kNoIndex) << "the swapped edge is gone";
      }
    }
    ++tried[kind];
    accepted[kind] += status == CavityStatus::kAccepted;
    if (operation % 5000 == 0) expect_consistent(mesh, measure, operation);
    if (::testing::Test::HasFatalFailure()) return;
  }
  expect_consistent(mesh, measure, kOperations);
  EXPECT_EQ(mesh.facet_count(), facets);
  // Every kind of operation must have happened many times, not just been tried.
  for (int kind = 0; kind < 4; ++kind) EXPECT_GT(accepted[kind], tried[kind] / 50) << "operation kind " << kind;
  std::printf("%dD: accepted reinsert %d/%d insert %d/%d collapse %d/%d swap %d/%d; %d elements\n", D, accepted[0], tried[0], accepted[1],
              tried[1], accepted[2], tried[2], accepted[3], tried[3], mesh.element_count());
}

TEST(CavityOperator, RandomOperationsKeepTheTriangleMeshConsistent) { run_random_operations(generate_square(10), 1); }
TEST(CavityOperator, RandomOperationsKeepTheTetrahedralMeshConsistent) { run_random_operations(generate_cube(4), 2); }

TEST(CavityOperator, RefusedPlansLeaveNoTrace) {
  Mesh<3> mesh = generate_cube(3);
  CavityOperator<3> op;
  // Starring a ball from a vertex outside it folds the mesh: refused by the measure check.
  std::vector<Index> ball;
  collect_ball(mesh, 21, ball);  // an interior vertex of the 4x4x4 grid
  CavityOptions options;
  EXPECT_NE(op.plan(mesh, ball, 0, options), CavityStatus::kAccepted);
  // A cavity whose elements carry different refs is refused.
  Mesh<2> square = generate_square(2);
  std::vector<Index> two = {0, 1};
  Mesh<2> copy = square;
  copy.set_element(1, copy.element(1), 7);
  CavityOperator<2> op2;
  EXPECT_EQ(op2.plan(copy, two, copy.element(0)[0], options), CavityStatus::kMixedRefs);
}

// A facet inside the domain (an interface between two element refs) has an element on each side: a
// cavity on one side that re-stars it would leave the other side's face unmatched, so the plan is
// refused. The same cavity re-starring a facet of the domain's hull is accepted.
TEST(CavityOperator, AnInterfaceFacetIsNotReStarredFromOneSide) {
  Mesh<2> mesh;
  for (const Vec2 x : {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{1, 1}}, Vec2{{0, 1}}, Vec2{{0.5, 0.5}}, Vec2{{0.5, 0}}}) mesh.add_vertex(x);
  mesh.add_element({0, 1, 2}, 1);
  mesh.add_element({0, 2, 3}, 2);
  for (const std::array<Index, 2> hull : {std::array<Index, 2>{0, 1}, {1, 2}, {2, 3}, {3, 0}}) mesh.add_facet(hull, 1);
  const Index interface = mesh.add_facet({0, 2}, 9);
  mesh.build_topology();
  const std::vector<Index> cavity{0};
  CavityOperator<2> op;
  CavityOptions options;
  const std::array<Index, 1> on_interface{interface};
  options.removed_facets = on_interface;
  EXPECT_EQ(op.plan(mesh, cavity, 4, options), CavityStatus::kCrossesBoundary);  // vertex 4 on the interface
  const std::array<Index, 1> on_hull{0};
  options.removed_facets = on_hull;
  EXPECT_EQ(op.plan(mesh, cavity, 5, options), CavityStatus::kAccepted);  // vertex 5 on the hull edge (0, 1)
  op.commit(mesh);
  EXPECT_EQ(check_consistency(mesh), std::vector<std::string>{});
}

// The same interface re-starred from a vertex on it, with the cavity on both of its sides: each new
// element keeps its side's ref, and the interface is split into two facets of its ref.
TEST(CavityOperator, AnInterfaceFacetIsReStarredWithBothOfItsSides) {
  Mesh<2> mesh;
  for (const Vec2 x : {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{1, 1}}, Vec2{{0, 1}}, Vec2{{0.5, 0.5}}}) mesh.add_vertex(x);
  mesh.add_element({0, 1, 2}, 1);
  mesh.add_element({0, 2, 3}, 2);
  for (const std::array<Index, 2> hull : {std::array<Index, 2>{0, 1}, {1, 2}, {2, 3}, {3, 0}}) mesh.add_facet(hull, 1);
  const Index interface = mesh.add_facet({0, 2}, 9);
  mesh.build_topology();
  mesh.orient_boundary_facets_outward();
  const Vec2 direction = mesh.vertex(mesh.facet(interface)[1]) - mesh.vertex(mesh.facet(interface)[0]);
  const std::vector<Index> both{0, 1};
  CavityOperator<2> op;
  CavityOptions options;
  EXPECT_EQ(op.plan(mesh, both, 4, options), CavityStatus::kMixedRefs);  // the interface kept inside: refused
  const std::array<Index, 1> on_interface{interface};
  options.removed_facets = on_interface;
  ASSERT_EQ(op.plan(mesh, both, 4, options), CavityStatus::kAccepted);
  op.commit(mesh);
  ConsistencyOptions checks;
  checks.require_boundary_facets = true;
  EXPECT_EQ(check_consistency(mesh, checks), std::vector<std::string>{});
  ASSERT_EQ(mesh.element_count(), 4);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    Vec2 centroid{};
    for (Index v : mesh.element(k)) centroid = centroid + (1.0 / 3) * mesh.vertex(v);
    EXPECT_EQ(mesh.element_ref(k), centroid[0] > centroid[1] ? 1 : 2) << "element " << k;
  }
  std::vector<std::array<Index, 2>> interface_facets;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_removed(f) || mesh.facet_ref(f) != 9) continue;
    const auto& facet = mesh.facet(f);
    EXPECT_GT(dot(mesh.vertex(facet[1]) - mesh.vertex(facet[0]), direction), 0) << "facet " << f << " turned around";
    interface_facets.push_back({std::min(facet[0], facet[1]), std::max(facet[0], facet[1])});
  }
  std::sort(interface_facets.begin(), interface_facets.end());
  EXPECT_EQ(interface_facets, (std::vector<std::array<Index, 2>>{{0, 4}, {2, 4}}));
}

// A 3D interface edge split with both sides: the shell of an edge on the plane x = 1/2 between two
// element refs, starred from its middle, the facets through it re-starred.
TEST(CavityOperator, AnInterfaceEdgeIsSplitWithBothOfItsSides3D) {
  // Every facet turned around (the interface's normal −x): orient_boundary_facets_outward must
  // orient the interface back as faces of side 1 (normal +x), as the new facets are checked below.
  Mesh<3> mesh = mesh_test::with_facets_turned(mesh_test::two_refs_across_an_interface<3>(2), 1);
  mesh.orient_boundary_facets_outward();
  const auto interface_facets = std::count(mesh.facet_refs().begin(), mesh.facet_refs().end(), 9);
  ASSERT_EQ(interface_facets, 8);  // the plane's four squares, two triangles each
  // An edge of the interface from the cube's centre.
  Index a = kNoIndex, b = kNoIndex;
  for (Index f = 0; f < mesh.facet_count() && a == kNoIndex; ++f) {
    if (mesh.facet_ref(f) != 9) continue;
    for (Index v : mesh.facet(f))
      if (std::abs(mesh.vertex(v)[1] - 0.5) < 1e-12 && std::abs(mesh.vertex(v)[2] - 0.5) < 1e-12) a = v;
    for (Index v : mesh.facet(f))
      if (a != kNoIndex && v != a && b == kNoIndex) b = v;
  }
  ASSERT_NE(a, kNoIndex);
  std::vector<Index> shell, facets;
  collect_shell(mesh, a, b, shell);
  const Index ends[2] = {a, b};
  facets_through<3>(mesh, shell, ends, facets);
  ASSERT_EQ(facets.size(), 2u);
  const Index middle = mesh.add_vertex(0.5 * (mesh.vertex(a) + mesh.vertex(b)));
  CavityOperator<3> op;
  CavityOptions options;
  options.removed_facets = facets;
  ASSERT_EQ(op.plan(mesh, shell, middle, options), CavityStatus::kAccepted);
  op.commit(mesh);
  ConsistencyOptions checks;
  checks.require_boundary_facets = true;
  EXPECT_EQ(check_consistency(mesh, checks), std::vector<std::string>{});
  EXPECT_NEAR(total_measure(mesh), 1, 1e-12);
  double area = 0;
  Index count = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_removed(f) || mesh.facet_ref(f) != 9) continue;
    const auto& t = mesh.facet(f);
    for (Index v : t) EXPECT_NEAR(mesh.vertex(v)[0], 0.5, 1e-12);
    // Oriented as the old ones: its normal along +x, from side 1 (x < 1/2) to side 2.
    area += 0.5 * cross(mesh.vertex(t[1]) - mesh.vertex(t[0]), mesh.vertex(t[2]) - mesh.vertex(t[0]))[0];
    ++count;
  }
  EXPECT_EQ(count, interface_facets + 2);
  EXPECT_NEAR(area, 1, 1e-12);
  for (Index k = 0; k < mesh.element_count(); ++k)
    EXPECT_EQ(mesh.element_ref(k), mesh_test::centroid_x(mesh, k) < 0.5 ? 1 : 2) << "element " << k;
}

TEST(CavityOperator, BoundaryEdgesOfAPlanAreFoundByTheirVertices) {
  Mesh<3> mesh = generate_cube(3);
  mesh.make_p2();
  CavityOperator<3> op;
  std::vector<Index> ball;
  const Index vertex = 21;  // an interior vertex of the 4x4x4 grid
  collect_ball(mesh, vertex, ball);
  ASSERT_EQ(op.plan(mesh, ball, vertex, CavityOptions{}), CavityStatus::kAccepted);
  ASSERT_FALSE(op.boundary_edges().empty());
  for (Index e : op.boundary_edges()) {
    const auto [a, b] = mesh.edge_vertices(e);
    EXPECT_EQ(e, mesh.find_edge(a, b));
    EXPECT_EQ(op.boundary_edge(a, b), e);
    EXPECT_EQ(op.boundary_edge(b, a), e);
  }
  // The edges through the reinserted vertex are inner edges, not on the hole's boundary.
  ASSERT_EQ(op.new_inner_edges().size(), 14u);
  for (const auto& [a, b] : op.new_inner_edges()) EXPECT_EQ(op.boundary_edge(a, b), kNoIndex);
}

// Two elements of the mesh that share exactly one vertex.
template <int D>
std::vector<Index> elements_touching_at_one_vertex(const Mesh<D>& mesh) {
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (Index j = k + 1; j < mesh.element_count(); ++j) {
      int shared = 0;
      for (Index v : mesh.element(k)) shared += local_vertex(mesh, j, v) >= 0;
      if (shared == 1) return {k, j};
    }
  return {};
}

// A cavity whose boundary touches itself at a vertex is no ball: its star would wrap two fans around
// one new edge. With the measure test on, only rounding on near-flat elements lets such a star
// through; with it off, the topology alone must refuse it.
template <int D>
void expect_pinched_cavity_refused(const Mesh<D>& structured) {
  Mesh<D> mesh = structured;
  const std::vector<Index> cavity = elements_touching_at_one_vertex(mesh);
  ASSERT_EQ(cavity.size(), 2u);
  Vec<D> centre{};
  for (Index k : cavity)
    for (Index v : mesh.element(k)) centre = centre + (1.0 / (2 * (D + 1))) * mesh.vertex(v);
  const Index vertex = mesh.add_vertex(centre);
  CavityOptions options;
  options.check_straight_measure = false;
  CavityOperator<D> op;
  EXPECT_EQ(op.plan(mesh, cavity, vertex, options), CavityStatus::kNotStarShaped);
  // Each element alone is a ball.
  EXPECT_EQ(op.plan(mesh, std::span<const Index>(cavity).first(1), vertex, options), CavityStatus::kAccepted);
}

// (In 2D the pairing of the new faces through the vertex refuses it too: the pinched vertex is the
// key of four of them.)
TEST(CavityOperator, ACavityPinchedAtAVertexIsRefused2D) { expect_pinched_cavity_refused(generate_square(3)); }
TEST(CavityOperator, ACavityPinchedAtAVertexIsRefused3D) { expect_pinched_cavity_refused(generate_cube(3)); }

// A star whose new edge already joins its ends through an element outside the cavity folds over
// the mesh (a face would get three elements). The P2 operator finds such an edge in its edge table;
// a P1 mesh has none, and is searched around the vertex.
template <int D>
void expect_folding_star_refused(const Mesh<D>& structured) {
  Mesh<D> mesh = structured;
  // An element, and a vertex outside it joined by an edge to one of its vertices.
  const Index k = 0;
  std::vector<Index> ball;
  collect_ball(mesh, mesh.element(k)[0], ball);
  Index vertex = kNoIndex;
  for (Index j : ball)
    for (Index v : mesh.element(j))
      if (local_vertex(mesh, k, v) < 0) vertex = v;
  ASSERT_NE(vertex, kNoIndex);
  CavityOptions options;
  options.check_straight_measure = false;
  CavityOperator<D> op;
  const Index cavity[1] = {k};
  EXPECT_EQ(op.plan(mesh, cavity, vertex, options), CavityStatus::kNotStarShaped);
  // A new vertex at the same place has no edges yet: its star folds over nothing.
  const Index fresh = mesh.add_vertex(mesh.vertex(vertex));
  EXPECT_EQ(op.plan(mesh, cavity, fresh, options), CavityStatus::kAccepted);
}

TEST(CavityOperator, AStarThatFoldsOverTheMeshIsRefused2D) { expect_folding_star_refused(generate_square(3)); }
TEST(CavityOperator, AStarThatFoldsOverTheMeshIsRefused3D) { expect_folding_star_refused(generate_cube(3)); }

}  // namespace
}  // namespace hocav
