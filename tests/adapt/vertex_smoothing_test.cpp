// The smoothing's repair move (docs/adaptation.md §Smoothing): a surface vertex a hair from another
// surface moves off it even where an edge of its ball then gets shorter than the length window
// allows; an inner vertex keeps the window (the thin vertices' collapse and sink are for those).
#include <gtest/gtest.h>

#include <algorithm>

#include "adapt/adaptation_operations.hpp"
#include "adapt_test_support.hpp"

namespace hocav {
namespace {

double worst_quality(const AdaptationMesh<3>& am) {
  double worst = 1;
  for (Index k = 0; k < am.mesh().element_count(); ++k) worst = std::min(worst, am.quality(k));
  return worst;
}

// The face of `element` without `vertex`, as the element orients it.
Mesh<3>::Facet face_without(const Mesh<3>::Element& element, Index vertex) {
  const int local = static_cast<int>(std::find(element.begin(), element.end(), vertex) - element.begin());
  Mesh<3>::Facet face;
  for (int i = 0; i < 3; ++i) face[i] = element[face_vertices<3>(local)[i]];
  return face;
}

// One smoothing sweep in the uniform metric of size 1 on a mesh whose worst element is below 0.1:
// whether `v` moved, how far it came toward `near`, and the worst quality before and after.
struct Sweep {
  bool moved;
  double before, after, near_distance_before, near_distance_after;
};

Sweep smooth_once(Mesh<3>& mesh, Index v, Index near) {
  const AdaptationMetric<3> metric = adapt_test::uniform_metric<3>(1);
  AdaptationMesh<3> am(mesh, metric, nullptr, 45);
  const Vec3 start = mesh.vertex(v);
  Sweep sweep{false, worst_quality(am), 0, norm(mesh.vertex(near) - start), 0};
  ThreadPool pool(1);
  smooth_vertices(am, AdaptationLimits{}, pool);
  sweep.moved = mesh.vertex(v) != start;
  sweep.after = worst_quality(am);
  sweep.near_distance_after = norm(mesh.vertex(near) - mesh.vertex(v));
  return sweep;
}

// A vertex of the side x = 0, 0.002 from its edge along y = 1 and halfway between that edge's two
// vertices, under a roof of six faces; one face (r1, r2, q) lies on the side y = 1, so the
// element over it is a needle. The ball's shortest edge (0.54) goes to the roof's inner vertex u,
// and every way off the edge y = 1 along the side comes closer to u: the length window alone
// refuses it. The repair lifts the vertex off, and the worst element gains several times over.
TEST(VertexSmoothing, ASurfaceVertexsRepairMayShortenAnEdgeBeyondTheBallsShortest) {
  Mesh<3> mesh;
  for (const Vec3& x : {Vec3{{0, 1, -0.6}}, Vec3{{0, 1, 0.6}}, Vec3{{0, 0.2, 0.6}}, Vec3{{0, 0.2, -0.6}}, Vec3{{0.7, 1, 0}},
                        Vec3{{0.3, 0.55, 0}}, Vec3{{0, 0.998, 0}}})
    mesh.add_vertex(x);
  constexpr Index r1 = 0, r2 = 1, p3 = 2, p4 = 3, q = 4, u = 5, v = 6;
  const std::vector<std::array<Index, 3>> roof{{r1, q, r2}, {r2, q, u}, {r1, u, q}, {r2, u, p3}, {p3, u, p4}, {p4, u, r1}};
  for (const auto& [a, b, c] : roof) mesh.add_element({a, b, c, v}, 1);
  ASSERT_TRUE(adapt_test::every_element_positive(mesh));
  for (Index k = 0; k < mesh.element_count(); ++k) mesh.add_facet(face_without(mesh.element(k), v), k == 0 ? 3 : 2);
  for (const auto& [k, far] : {std::pair{Index{0}, q}, {3, u}, {4, u}, {5, u}}) mesh.add_facet(face_without(mesh.element(k), far), 1);
  mesh.build_topology();
  adapt_test::expect_closed_and_consistent(mesh);
  const Sweep sweep = smooth_once(mesh, v, u);
  ASSERT_LT(sweep.before, 0.1);
  EXPECT_TRUE(sweep.moved);
  EXPECT_GT(sweep.after, 3 * sweep.before);
  EXPECT_LT(sweep.near_distance_after, sweep.near_distance_before);
  EXPECT_EQ(mesh.vertex(v)[0], 0);  // on its side
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_TRUE(adapt_test::every_element_positive(mesh));
}

// An inner vertex 0.01 above the floor of a flat pyramid (the unit square under an apex 0.35 high):
// the elements over the floor are needles, and every way off the floor comes closer to the apex than
// the ball's shortest edge (0.41). It keeps the length window, and does not move.
TEST(VertexSmoothing, AnInnerVertexsRepairKeepsTheLengthWindow) {
  const std::vector<Vec3> points{Vec3{{0, 0, 0}}, Vec3{{1, 0, 0}},        Vec3{{1, 1, 0}},
                                 Vec3{{0, 1, 0}}, Vec3{{0.5, 0.5, 0.35}}, Vec3{{2.0 / 3, 1.0 / 3, 0.01}}};
  constexpr Index a = 0, b = 1, c = 2, d = 3, apex = 4, v = 5;
  Mesh<3> mesh = adapt_test::star_of<3>(points, {{a, b, c}, {a, c, d}, {a, b, apex}, {b, c, apex}, {c, d, apex}, {d, a, apex}});
  ASSERT_TRUE(adapt_test::every_element_positive(mesh));
  const Sweep sweep = smooth_once(mesh, v, apex);
  ASSERT_LT(sweep.before, 0.1);
  EXPECT_GE(sweep.near_distance_after, sweep.near_distance_before);
}

}  // namespace
}  // namespace hocav
