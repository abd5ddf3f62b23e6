// Inner vertices a hair above the boundary (docs/adaptation.md §Collapse, "Thin vertices"): the
// collapse removes them, or they sink onto the boundary, which no other operator of the loop does.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "adapt/adaptation_operations.hpp"
#include "adapt_test_support.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

// The structured cube's inner vertex at (1/4, 1/4, 1/4) lowered to `height` above the side z = 0.
Index lower_an_inner_vertex(Mesh<3>& mesh, double height) {
  Index v = 0;
  while (mesh.vertex(v) != Vec3{{0.25, 0.25, 0.25}}) ++v;
  mesh.vertex(v)[2] = height;
  return v;
}

TEST(ThinVertices, AnInnerVertexAHairAboveASideIsCollapsedOntoIt) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(4);
  const Index v = lower_an_inner_vertex(mesh, 1e-6);
  ASSERT_TRUE(adapt_test::every_element_positive(mesh));
  const AdaptationMetric<3> metric = adapt_test::uniform_metric<3>(0.25);  // 1e-6 is 4e-6 of the size across
  AdaptationMesh<3> am(mesh, metric, nullptr, 45);
  const OperationCount count = collapse_thin_vertices(am, AdaptationLimits{});
  EXPECT_EQ(count.done, 1);
  EXPECT_TRUE(mesh.vertex_removed(v));
  mesh.compact();
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_TRUE(adapt_test::every_element_positive(mesh));
}

// The structured cube in a metric 10,000 times finer along the side z = 0 than across it: the elements
// on that side are needles in the metric (quality far below 0.01), but their inner vertices lie a
// quarter of the size across above it.
TEST(ThinVertices, APoorElementsVertexWellAboveASideStays) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(4);
  mesh.build_topology();
  SymMat<3> needles;
  needles(0, 0) = needles(1, 1) = 1e8;  // sizes 1e-4 along the side
  needles(2, 2) = 1;                    // size 1 across it
  const MetricField<3> field(mesh, std::vector<SymMat<3>>(static_cast<std::size_t>(mesh.vertex_count()), needles));
  const AdaptationMetric<3> metric(field, SizeBounds{});
  AdaptationMesh<3> am(mesh, metric, nullptr, 45);
  Index poor = 0;
  for (Index k = 0; k < mesh.element_count(); ++k) poor += am.quality(k) < 1e-2;
  ASSERT_GT(poor, 0);
  const OperationCount count = collapse_thin_vertices(am, AdaptationLimits{});
  EXPECT_EQ(count.done + count.refused_total(), 0);
}

// The facets of ref 1 (the bottom), and whether each of them lies on the bottom.
template <int D>
std::pair<int, bool> bottom_facets(const Mesh<D>& mesh) {
  int count = 0;
  bool on_bottom = true;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_ref(f) != 1) continue;
    ++count;
    for (Index v : mesh.facet(f)) on_bottom = on_bottom && mesh.vertex(v)[D - 1] == 0;
  }
  return {count, on_bottom};
}

// Runs the thin vertices' sweep on the star of `mesh` from its last vertex, in the uniform metric
// of size 1: that vertex is gone, one new vertex took its place on the bottom (`vertices_after` in
// all), whose facets are `bottom_facets_after` and all on the bottom, and the mesh is consistent.
template <int D>
void expect_sunk(Mesh<D>& mesh, Index vertices_after, int bottom_facets_after) {
  const Index thin = mesh.vertex_count() - 1;
  ASSERT_TRUE(adapt_test::every_element_positive(mesh));
  const AdaptationMetric<D> metric = adapt_test::uniform_metric<D>(1);
  AdaptationMesh<D> am(mesh, metric, nullptr, 45);
  const OperationCount count = collapse_thin_vertices(am, AdaptationLimits{});
  EXPECT_EQ(count.done, 1);
  EXPECT_TRUE(mesh.vertex_removed(thin));
  mesh.compact();
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_TRUE(adapt_test::every_element_positive(mesh));
  EXPECT_EQ(mesh.vertex_count(), vertices_after);
  EXPECT_EQ(bottom_facets(mesh), std::make_pair(bottom_facets_after, true));
}

// A vertex 1e-6 above the bottom of a slab whose four bottom facets and four top facets share no
// vertex: a collapse onto any vertex would flatten the elements over the bottom or top facets
// without it, so none removes it. It sinks onto the bottom, at its foot.
TEST(ThinVertices, AVertexOverSeveralFacetsSinksOntoThem3D) {
  // Bottom a b c e f g (z = 0: the parallelogram a c g e, its strip of four triangles), top the same
  // at z = 1, the thin vertex last.
  std::vector<Vec3> points;
  for (double z : {0.0, 1.0})
    for (const Vec3& p : {Vec3{{0, 0, 0}}, Vec3{{1, 0, 0}}, Vec3{{2, 0, 0}}, Vec3{{0.5, 1, 0}}, Vec3{{1.5, 1, 0}}, Vec3{{2.5, 1, 0}}})
      points.push_back(Vec3{{p[0], p[1], z}});
  points.push_back(Vec3{{1.25, 0.5, 1e-6}});
  constexpr Index a = 0, b = 1, c = 2, e = 3, f = 4, g = 5, top = 6;
  std::vector<std::array<Index, 3>> faces;
  for (Index z : {Index{0}, top})
    for (const std::array<Index, 3>& t : {std::array<Index, 3>{a, b, e}, {b, f, e}, {b, c, f}, {c, g, f}})
      faces.push_back({t[0] + z, t[1] + z, t[2] + z});
  // The four sides, each quad (p, q, q', p') as two triangles.
  for (const auto& [p, q] : {std::pair{a, b}, {b, c}, {e, f}, {f, g}, {a, e}, {c, g}}) {
    faces.push_back({p, q, q + top});
    faces.push_back({p, q + top, p + top});
  }
  Mesh<3> mesh = adapt_test::star_of<3>(points, faces);
  ASSERT_EQ(bottom_facets(mesh), std::make_pair(4, true));
  // The bottom becomes the fan of its rim of six edges from the foot, every facet still of ref 1.
  expect_sunk<3>(mesh, 13, 6);
  const Vec3 foot{{1.25, 0.5, 0}};
  EXPECT_TRUE(std::any_of(mesh.vertices().begin(), mesh.vertices().end(), [&](const Vec3& x) { return x == foot; }));
}

// The 2D counterpart: a vertex 1e-6 above the bottom edge, under a chimney of the boundary whose
// walls pass either side of it, so that every collapse turns an element over.
TEST(ThinVertices, AVertexThatNoCollapseRemovesSinksOntoTheEdgeBelow2D) {
  const std::vector<Vec2> points{Vec2{{1, 0}},    Vec2{{2, 0}},      Vec2{{2, 1}}, Vec2{{1.55, 0.5}}, Vec2{{1.55, 1}},
                                 Vec2{{1.45, 1}}, Vec2{{1.45, 0.5}}, Vec2{{1, 1}}, Vec2{{1.5, 1e-6}}};
  Mesh<2> mesh = adapt_test::star_of<2>(points, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 0}});
  expect_sunk<2>(mesh, 9, 2);
}

}  // namespace
}  // namespace hocav
