// Boundary-only elements (docs/adaptation.md §Split): poor elements whose vertices all lie on the
// boundary are cut through an inner edge, since swaps and smoothing cannot mend them.
#include <gtest/gtest.h>

#include <algorithm>

#include "adapt/adaptation_operations.hpp"
#include "adapt_test_support.hpp"

namespace hocav {
namespace {

template <int D>
Index poor_boundary_only(const AdaptationMesh<D>& am) {
  Index count = 0;
  for (Index k = 0; k < am.mesh().element_count(); ++k) {
    const auto& e = am.mesh().element(k);
    if (am.quality(k) < 0.2 && std::none_of(e.begin(), e.end(), [&](Index v) { return am.vertex_class(v) == VertexClass::kInterior; }))
      ++count;
  }
  return count;
}

// One cell of the structured square or cube, squashed across the one inner edge that all its
// elements hold (the diagonal) into needles along it: every vertex is on the boundary, every
// element is poor, and one split at the diagonal's middle cuts them all into better ones.
template <int D>
void expect_cut() {
  Mesh<D> mesh = adapt_test::unit_mesh<D>(1);
  std::vector<Index> diagonal(mesh.element(0).begin(), mesh.element(0).end());
  for (const auto& element : mesh.elements())
    std::erase_if(diagonal, [&](Index v) { return std::find(element.begin(), element.end(), v) == element.end(); });
  ASSERT_EQ(diagonal.size(), 2u);
  const Vec<D> start = mesh.vertex(diagonal[0]), along = mesh.vertex(diagonal[1]) - start;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const Vec<D> offset = mesh.vertex(v) - start;
    const Vec<D> on_diagonal = (dot(offset, along) / dot(along, along)) * along;
    mesh.vertex(v) = start + on_diagonal + 0.1 * (offset - on_diagonal);
  }
  const AdaptationMetric<D> metric = adapt_test::uniform_metric<D>(1);
  AdaptationMesh<D> am(mesh, metric, nullptr, 45);
  ASSERT_EQ(poor_boundary_only(am), mesh.element_count());
  const Index before = mesh.vertex_count();
  const OperationCount count = cut_boundary_only_elements(am, AdaptationLimits{});
  EXPECT_EQ(count.done, 1);
  EXPECT_EQ(poor_boundary_only(am), 0);
  ASSERT_EQ(mesh.vertex_count(), before + 1);
  EXPECT_EQ(am.vertex_class(before), VertexClass::kInterior);
  mesh.compact();
  adapt_test::expect_closed_and_consistent(mesh);
}

TEST(BoundaryOnlyElements, PoorOnesAreCutThroughTheirInnerEdge) {
  expect_cut<2>();
  expect_cut<3>();
}

// Elements near the regular one in their metric are left alone, boundary-only or not.
TEST(BoundaryOnlyElements, GoodOnesAreLeftAlone) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(1);
  const AdaptationMetric<3> metric = adapt_test::uniform_metric<3>(1);
  AdaptationMesh<3> am(mesh, metric, nullptr, 45);
  EXPECT_EQ(cut_boundary_only_elements(am, AdaptationLimits{}).done, 0);
  EXPECT_EQ(mesh.element_count(), 6);
}

}  // namespace
}  // namespace hocav
