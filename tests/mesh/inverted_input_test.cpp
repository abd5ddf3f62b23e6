#include "mesh/inverted_input.hpp"

#include <gtest/gtest.h>

#include <utility>

#include "../metric/metric_test_support.hpp"
#include "mesh/consistency.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

// A copy of `mesh` whose first `turned_below` elements list two vertices the other way round.
template <int D>
Mesh<D> with_elements_turned(const Mesh<D>& mesh, Index turned_below) {
  Mesh<D> copy = mesh;
  for (Index k = 0; k < turned_below; ++k) {
    auto vertices = copy.element(k);
    std::swap(vertices[0], vertices[1]);
    copy.set_element(k, vertices, copy.element_ref(k));
  }
  copy.build_topology();
  return copy;
}

template <int D>
void expect_all_inverted_reoriented() {
  const Mesh<D> mesh = metric_test::unit_mesh<D>(D == 2 ? 3 : 2);
  Mesh<D> inverted = with_elements_turned(mesh, mesh.element_count());
  const std::string warning = reorient_inverted_mesh(inverted, "in.mesh");
  EXPECT_EQ(warning, "in.mesh: every one of its " + std::to_string(mesh.element_count()) +
                         " elements is negatively oriented (the other convention): reoriented");
  for (Index k = 0; k < inverted.element_count(); ++k) EXPECT_GT(element_measure(inverted, k), 0) << k;
  EXPECT_TRUE(check_consistency(inverted).empty());

  // One element inverted is a defect, not a convention: left for the consistency check to name.
  Mesh<D> mixed = with_elements_turned(mesh, 1);
  EXPECT_EQ(reorient_inverted_mesh(mixed, "in.mesh"), "");
  EXPECT_EQ(mixed.element(0), with_elements_turned(mesh, 1).element(0));
  EXPECT_FALSE(check_consistency(mixed).empty());
  // A positive mesh is left as it is.
  Mesh<D> positive = mesh;
  EXPECT_EQ(reorient_inverted_mesh(positive, "in.mesh"), "");
  EXPECT_EQ(std::vector(positive.elements().begin(), positive.elements().end()),
            std::vector(mesh.elements().begin(), mesh.elements().end()));
}

TEST(InvertedInput, AMeshGivenAllInvertedIsReorientedAndOneWithSomeInvertedIsNot2D) { expect_all_inverted_reoriented<2>(); }
TEST(InvertedInput, AMeshGivenAllInvertedIsReorientedAndOneWithSomeInvertedIsNot3D) { expect_all_inverted_reoriented<3>(); }

}  // namespace
}  // namespace hocav
