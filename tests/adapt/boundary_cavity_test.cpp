// The cavity operator on the boundary: splits and collapses of boundary edges re-star their facets
// (and, in 3D, their feature lines) with the volume; random sequences of them keep the mesh
// consistent, closed and of the same measure, and compaction keeps vertex attributes with their vertices.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <random>

#include "adapt/adaptation_operations.hpp"
#include "adapt/boundary_pieces.hpp"
#include "adapt_test_support.hpp"
#include "base/error.hpp"
#include "cavity/cavity_operations.hpp"
#include "io/mesh_file.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/measure.hpp"
#include "temporary_files.hpp"

namespace hocav {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int kBoundaryOperations = 3000;
#else
constexpr int kBoundaryOperations = 30000;
#endif

template <int D>
double boundary_measure(const Mesh<D>& mesh) {
  double sum = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_removed(f)) continue;
    const auto& v = mesh.facet(f);
    if constexpr (D == 2)
      sum += norm(mesh.vertex(v[1]) - mesh.vertex(v[0]));
    else
      sum += 0.5 * norm(cross(mesh.vertex(v[1]) - mesh.vertex(v[0]), mesh.vertex(v[2]) - mesh.vertex(v[0])));
  }
  return sum;
}

template <int D>
Vec<D> unit_normal(const Mesh<D>& mesh, const typename Mesh<D>::Facet& v) {
  Vec<D> n;
  if constexpr (D == 2)
    n = Vec2{mesh.vertex(v[1])[1] - mesh.vertex(v[0])[1], mesh.vertex(v[0])[0] - mesh.vertex(v[1])[0]};
  else
    n = cross(mesh.vertex(v[1]) - mesh.vertex(v[0]), mesh.vertex(v[2]) - mesh.vertex(v[0]));
  return (1 / norm(n)) * n;
}

// The lines (3D) through both a and b.
std::vector<Index> line_between(const Mesh<3>& mesh, Index a, Index b) {
  std::vector<Index> through, out;
  lines_through(mesh, a, through);
  for (Index l : through)
    if (mesh.line(l)[0] == b || mesh.line(l)[1] == b) out.push_back(l);
  return out;
}

// Splits boundary edge (a, b) at its middle; returns the operator's verdict.
template <int D>
CavityStatus split_boundary_edge(Mesh<D>& mesh, CavityWorkspace<D>& work, Index a, Index b) {
  collect_shell(mesh, a, b, work.cavity);
  std::vector<Index> facets, lines;
  const Index ends[2] = {a, b};
  facets_through<D>(mesh, work.cavity, ends, facets);
  if constexpr (D == 3) lines = line_between(mesh, a, b);
  const Index v = mesh.add_vertex(0.5 * (mesh.vertex(a) + mesh.vertex(b)));
  CavityOptions options;
  options.removed_facets = facets;
  options.removed_lines = lines;
  const CavityStatus status = work.cavity_operator.plan(mesh, work.cavity, v, options);
  if (status == CavityStatus::kAccepted)
    work.cavity_operator.commit(mesh);
  else
    mesh.pop_vertex();
  return status;
}

TEST(BoundaryCavity, SplitOfABoundaryEdgeSplitsItsFacets2D) {
  Mesh<2> mesh = adapt_test::unit_mesh<2>(3);
  CavityWorkspace<2> work;
  const Index facets = mesh.facet_count();
  const auto [a, b] = mesh.facet(0);
  ASSERT_EQ(split_boundary_edge(mesh, work, a, b), CavityStatus::kAccepted);
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_EQ(mesh.facet_count() - facets, 2);  // one removed (waiting for compaction), two new
  mesh.compact();
  EXPECT_EQ(mesh.facet_count(), facets + 1);
  EXPECT_NEAR(boundary_measure(mesh), 4, 1e-12);
  EXPECT_NEAR(total_measure(mesh), 1, 1e-12);
}

TEST(BoundaryCavity, SplitOfARidgeEdgeSplitsItsLineAndBothFacets3D) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(2);
  CavityWorkspace<3> work;
  const Index line = mesh.ridges().front();
  const auto [a, b] = mesh.line(line);
  const Index lines = mesh.line_count(), facets = mesh.facet_count(), ridges = static_cast<Index>(mesh.ridges().size());
  ASSERT_EQ(split_boundary_edge(mesh, work, a, b), CavityStatus::kAccepted);
  adapt_test::expect_closed_and_consistent(mesh);
  mesh.compact();
  EXPECT_EQ(mesh.line_count(), lines + 1);
  EXPECT_EQ(static_cast<Index>(mesh.ridges().size()), ridges + 1);  // both halves are ridges
  EXPECT_EQ(mesh.facet_count(), facets + 2);                        // two facets, each split in two
  EXPECT_NEAR(boundary_measure(mesh), 6, 1e-12);
  EXPECT_NEAR(total_measure(mesh), 1, 1e-12);
}

TEST(BoundaryCavity, CollapseOfASurfaceVertexAlongItsSurface3D) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(2);
  // The vertex at the centre of the face z = 0, collapsed onto a neighbour on that face.
  Index center = kNoIndex, neighbor = kNoIndex;
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (norm(mesh.vertex(v) - Vec3{0.5, 0.5, 0}) < 1e-12) center = v;
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (norm(mesh.vertex(v) - Vec3{0.5, 0, 0}) < 1e-12) neighbor = v;
  ASSERT_NE(center, kNoIndex);
  const Index facets_before = mesh.facet_count();
  CavityWorkspace<3> work;
  collect_ball(mesh, center, work.cavity);
  std::vector<Index> facets;
  const Index through[1] = {center};
  facets_through<3>(mesh, work.cavity, through, facets);
  CavityOptions options;
  options.removable_vertex = center;
  options.removed_facets = facets;
  ASSERT_EQ(work.cavity_operator.plan(mesh, work.cavity, neighbor, options), CavityStatus::kAccepted);
  work.cavity_operator.commit(mesh);
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_TRUE(mesh.vertex_removed(center));
  // Until compacted, no writer takes it: the removed vertex would be written as if it were there.
  const std::string path = testing_support::temporary_path("uncompacted.meshb");
  EXPECT_THROW(write_mesh_file(path, mesh), Error);
  EXPECT_FALSE(std::filesystem::exists(path));
  const Index vertices = mesh.vertex_count();
  mesh.compact();
  EXPECT_EQ(mesh.vertex_count(), vertices - 1);
  // The fan around the face's centre is re-starred from its neighbour: the two triangles through
  // the collapsed edge go.
  EXPECT_GE(facets.size(), 4u);
  EXPECT_EQ(mesh.facet_count(), facets_before - 2);
  EXPECT_NEAR(boundary_measure(mesh), 6, 1e-12);
  EXPECT_NEAR(total_measure(mesh), 1, 1e-12);
  adapt_test::expect_closed_and_consistent(mesh);
}

TEST(BoundaryCavity, ABoundaryCollapseWithoutItsFacetsIsRefused) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(2);
  Index center = kNoIndex, neighbor = kNoIndex;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (norm(mesh.vertex(v) - Vec3{0.5, 0.5, 0}) < 1e-12) center = v;
    if (norm(mesh.vertex(v) - Vec3{0.5, 0, 0}) < 1e-12) neighbor = v;
  }
  CavityWorkspace<3> work;
  EXPECT_NE(collapse_edge(mesh, work, center, neighbor, {}), CavityStatus::kAccepted);
  adapt_test::expect_closed_and_consistent(mesh);
}

// The surface link condition: four tetrahedra, (u, w, x, p) and (u, w, x, q) on either side of the
// inner triangle (u, w, x) and one more on each of their faces (u, x, p) and (u, x, q), out to c and
// d. The triangle's three edges are on the boundary, so u and w share the surface neighbour x
// though (u, w, x) is no facet: collapsing u onto w would flatten the triangle onto the edge (w, x)
// and leave that edge four facets (the domain pinched along it), though the tetrahedra it makes are
// positive and none of the facets it makes is one already.
TEST(BoundaryCavity, ACollapseThatPinchesTheSurfaceIsRefused3D) {
  constexpr Index u = 0, w = 1, x = 2, p = 3, q = 4, c = 5, d = 6;
  Mesh<3> mesh;
  for (const Vec3& point : {Vec3{{0, 0, 0}}, Vec3{{0.5, 0.9, 0}}, Vec3{{1, 0, 0}}, Vec3{{0.5, 0.3, -0.8}}, Vec3{{0.5, 0.3, 0.8}},
                            Vec3{{0.5, -0.8, -0.6}}, Vec3{{0.5, -0.8, 0.6}}})
    mesh.add_vertex(point);
  const auto positive = [&](const Mesh<3>::Element& e) {
    return signed_measure(mesh.vertex(e[0]), mesh.vertex(e[1]), mesh.vertex(e[2]), mesh.vertex(e[3])) > 0;
  };
  for (const Mesh<3>::Element& element : {Mesh<3>::Element{u, w, x, p}, {w, u, x, q}, {u, x, c, p}, {x, u, d, q}}) {
    ASSERT_TRUE(positive(element));
    mesh.add_element(element, 1);
  }
  // A facet, oriented outward, on every face of one element only.
  const auto face = [&](Index k, int f) {
    Mesh<3>::Facet vertices;
    for (int i = 0; i < 3; ++i) vertices[i] = mesh.element(k)[face_vertices<3>(f)[i]];
    return vertices;
  };
  const auto sorted = [](Mesh<3>::Facet vertices) {
    std::sort(vertices.begin(), vertices.end());
    return vertices;
  };
  std::map<Mesh<3>::Facet, int> elements_on;
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int f = 0; f < 4; ++f) ++elements_on[sorted(face(k, f))];
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int f = 0; f < 4; ++f)
      if (elements_on[sorted(face(k, f))] == 1) mesh.add_facet(face(k, f), 1);
  mesh.build_topology();
  ASSERT_EQ(mesh.facet_count(), 10);

  // Whether a facet holds all these vertices.
  const auto on_a_facet = [&](std::initializer_list<Index> vertices) {
    return std::any_of(mesh.facets().begin(), mesh.facets().end(), [&](const Mesh<3>::Facet& facet) {
      return std::all_of(vertices.begin(), vertices.end(),
                         [&](Index v) { return std::find(facet.begin(), facet.end(), v) != facet.end(); });
    });
  };
  ASSERT_TRUE(on_a_facet({u, w}));
  ASSERT_TRUE(on_a_facet({u, x}));
  ASSERT_TRUE(on_a_facet({w, x}));
  ASSERT_FALSE(on_a_facet({u, w, x}));
  // What the collapse makes from u's elements and facets without w (u moved onto w): positive
  // tetrahedra, and facets not there already.
  const auto moves = [&](const auto& vertices) {
    return std::find(vertices.begin(), vertices.end(), u) != vertices.end() &&
           std::find(vertices.begin(), vertices.end(), w) == vertices.end();
  };
  const auto moved = [&](auto vertices) {
    std::replace(vertices.begin(), vertices.end(), u, w);
    return vertices;
  };
  for (const Mesh<3>::Element& element : mesh.elements()) {
    if (!moves(element)) continue;
    ASSERT_TRUE(positive(moved(element)));
  }
  for (const Mesh<3>::Facet& facet : mesh.facets()) {
    if (!moves(facet)) continue;
    const Mesh<3>::Facet made = moved(facet);
    ASSERT_FALSE(on_a_facet({made[0], made[1], made[2]}));
  }

  const AdaptationMetric<3> metric = adapt_test::uniform_metric<3>(1);
  AdaptationMesh<3> am(mesh, metric, nullptr, 180);  // one facet ref, a feature angle of 180°: no ridges
  ASSERT_EQ(am.vertex_class(u), VertexClass::kSurface);
  ASSERT_EQ(am.vertex_class(w), VertexClass::kSurface);
  AdaptationLimits limits;  // no length or turn refuses it first
  limits.collapse_new_length = 1e9;
  limits.cos_feature_angle = -1;
  CollapseScratch<3> scratch;
  const Refusal refusal = collapse_edge(am, u, w, limits, scratch);
  EXPECT_EQ(refusal, Refusal::kTopology) << to_string(refusal);
  EXPECT_FALSE(mesh.vertex_removed(u));
  EXPECT_EQ(mesh.element_count(), 4);
  adapt_test::expect_closed_and_consistent(mesh);
}

// Random splits and collapses of boundary and interior edges, the checker run after each accepted
// one; measures stay, the boundary stays closed, and a vertex attribute written as the vertex's own
// coordinates follows it through compaction.
template <int D>
void run_random_boundary_operations(unsigned seed) {
  Mesh<D> mesh = adapt_test::unit_mesh<D>(3);
  const int attribute = mesh.add_vertex_attribute(D);
  const auto write_position = [&](Index v) {
    for (int i = 0; i < D; ++i) mesh.vertex_attribute(attribute, v)[static_cast<std::size_t>(i)] = mesh.vertex(v)[i];
  };
  for (Index v = 0; v < mesh.vertex_count(); ++v) write_position(v);
  CavityWorkspace<D> work;
  std::mt19937 random(seed);
  int accepted[2] = {};
  for (int operation = 0; operation < kBoundaryOperations; ++operation) {
    const Index k = static_cast<Index>(random() % static_cast<unsigned>(mesh.element_count()));
    const auto element = mesh.element(k);
    const Index a = element[random() % (D + 1)];
    Index b = a;
    while (b == a) b = element[random() % (D + 1)];
    if (random() % 2 == 0) {
      if (split_boundary_edge(mesh, work, a, b) == CavityStatus::kAccepted) {
        ++accepted[0];
        write_position(mesh.vertex_count() - 1);
      }
    } else {
      // Collapse a onto b with a's facets, when no line passes through a (3D ridges stay put here).
      collect_ball(mesh, a, work.cavity);
      std::vector<Index> facets, lines;
      const Index through[1] = {a};
      facets_through<D>(mesh, work.cavity, through, facets);
      if constexpr (D == 3) lines_through(mesh, a, lines);
      if (!lines.empty()) continue;
      CavityOptions options;
      options.removable_vertex = a;
      options.removed_facets = facets;
      if (work.cavity_operator.plan(mesh, work.cavity, b, options) == CavityStatus::kAccepted) {
        // On the boundary, only along it (else the boundary moves inward: allowed by topology, not by us).
        const bool along = facets.empty() || std::any_of(facets.begin(), facets.end(), [&](Index f) {
                             const auto& v = mesh.facet(f);
                             return std::find(v.begin(), v.end(), b) != v.end();
                           });
        const auto& plan = work.cavity_operator;
        const bool flat = std::all_of(plan.new_facets().begin(), plan.new_facets().end(), [&](const auto& facet) {
          return norm(unit_normal<D>(mesh, facet.vertices) - unit_normal<D>(mesh, mesh.facet(facet.replaced))) < 1e-9;
        });
        if (along && flat) {
          work.cavity_operator.commit(mesh);
          ++accepted[1];
        }
      }
    }
    if (operation % 500 == 0) {
      adapt_test::expect_closed_and_consistent(mesh);
      ASSERT_NEAR(total_measure(mesh), 1, 1e-9) << "after operation " << operation;
      mesh.compact();
      for (Index v = 0; v < mesh.vertex_count(); ++v)
        for (int i = 0; i < D; ++i) ASSERT_EQ(mesh.vertex_attribute(attribute, v)[static_cast<std::size_t>(i)], mesh.vertex(v)[i]);
    }
  }
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_GT(accepted[0], kBoundaryOperations / 20);
  EXPECT_GT(accepted[1], kBoundaryOperations / 50);
}

TEST(BoundaryCavity, RandomBoundarySplitsAndCollapses2D) { run_random_boundary_operations<2>(11); }
TEST(BoundaryCavity, RandomBoundarySplitsAndCollapses3D) { run_random_boundary_operations<3>(12); }

}  // namespace
}  // namespace hocav
