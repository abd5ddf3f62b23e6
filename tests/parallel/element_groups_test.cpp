// Groups of neighbouring elements (src/parallel/element_groups.hpp), the vertices of the coarser
// graph PT-Scotch cuts: every element in one group, each group joined through faces, and a few
// elements to a group.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "cases/structured.hpp"
#include "parallel/element_groups.hpp"

namespace hocav {
namespace {

// Whether the elements of each group are joined through their faces (a walk inside the group from
// its first element reaches all of them), and the size of every group.
template <int D>
std::vector<Index> joined_group_sizes(const Mesh<D>& mesh, const ElementGroups& groups) {
  std::vector<Index> sizes(static_cast<std::size_t>(groups.count), 0), reached(sizes.size(), 0);
  for (Index g : groups.group_of) ++sizes.at(static_cast<std::size_t>(g));
  std::vector<char> seen(groups.group_of.size(), 0);
  for (Index start = 0; start < mesh.element_count(); ++start) {
    const Index g = groups.group_of[start];
    if (reached[g] > 0) continue;
    std::vector<Index> stack{start};
    seen[start] = 1;
    while (!stack.empty()) {
      const Index k = stack.back();
      stack.pop_back();
      ++reached[g];
      for (int face = 0; face <= D; ++face)
        if (const Index other = mesh.neighbor(k, face); other != kNoIndex && groups.group_of[other] == g && !seen[other]) {
          seen[other] = 1;
          stack.push_back(other);
        }
    }
  }
  return reached == sizes ? sizes : std::vector<Index>{};
}

template <int D>
void expect_grouped(const Mesh<D>& mesh) {
  const ElementGroups groups = neighbouring_element_groups(mesh);
  ASSERT_EQ(groups.group_of.size(), static_cast<std::size_t>(mesh.element_count()));
  const std::vector<Index> sizes = joined_group_sizes(mesh, groups);
  ASSERT_EQ(sizes.size(), static_cast<std::size_t>(groups.count)) << "a group is not joined through its faces";
  // Every element has a neighbour here, so no group is alone; a star starts with at most D + 2.
  EXPECT_GE(*std::min_element(sizes.begin(), sizes.end()), 2);
  EXPECT_LE(2 * groups.count, mesh.element_count());
  EXPECT_GE((D + 3) * groups.count, mesh.element_count());
}

TEST(ElementGroups, NeighbouringElementsMakeJoinedGroupsOfAFew) {
  Mesh<2> square = generate_square(8);
  square.build_topology();
  expect_grouped(square);
  Mesh<3> cube = generate_cube(4);
  cube.build_topology();
  expect_grouped(cube);
}

TEST(ElementGroups, SingleElementGroupsAreTheElements) {
  const ElementGroups groups = single_element_groups(5);
  EXPECT_EQ(groups.count, 5);
  EXPECT_EQ(groups.group_of, (std::vector<Index>{0, 1, 2, 3, 4}));
}

}  // namespace
}  // namespace hocav
