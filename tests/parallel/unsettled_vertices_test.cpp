// The vertices a part's loop left unadapted (src/parallel/unsettled_vertices.hpp): the ends of the
// element edges longer than kUnsettledEdgeLength in the metric, found against every element's
// edges measured one by one.
#include "parallel/unsettled_vertices.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "../adapt/adapt_test_support.hpp"
#include "cases/structured.hpp"

namespace hocav {
namespace {

// Per vertex, the longest edge at it in the uniform metric of size h, the edges listed element by
// element.
std::vector<double> longest_edge_at(const Mesh<3>& mesh, double h) {
  std::vector<double> longest(static_cast<std::size_t>(mesh.vertex_count()), 0);
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (Index a : mesh.element(k))
      for (Index b : mesh.element(k)) longest[a] = std::max(longest[a], norm(mesh.vertex(a) - mesh.vertex(b)) / h);
  return longest;
}

// Cells of 0.25 in a metric of size 0.125: their sides 2 long, their faces' diagonals 2.83, their
// own diagonals 3.46, so only the ends of the cells' diagonals are unsettled.
TEST(UnsettledVertices, AreTheEndsOfTheEdgesLongerThanTheBound) {
  const Mesh<3> mesh = generate_cube(4);
  const std::vector<char> flags = unsettled_vertex_flags(mesh, adapt_test::uniform_metric<3>(0.125), 1);
  const std::vector<double> longest = longest_edge_at(mesh, 0.125);
  ASSERT_EQ(flags.size(), longest.size());
  for (std::size_t v = 0; v < flags.size(); ++v) EXPECT_EQ(flags[v] != 0, longest[v] > kUnsettledEdgeLength) << "vertex " << v;
  const auto flagged = std::count(flags.begin(), flags.end(), 1);
  EXPECT_GT(flagged, 0);
  EXPECT_LT(flagged, mesh.vertex_count());  // a cube's corners off its cells' diagonals are not
}

TEST(UnsettledVertices, NoneWhereEveryEdgeIsShort) {
  const Mesh<3> mesh = generate_cube(4);
  const std::vector<char> flags = unsettled_vertex_flags(mesh, adapt_test::uniform_metric<3>(0.25), 1);
  EXPECT_EQ(std::count(flags.begin(), flags.end(), 1), 0);
}

TEST(UnsettledVertices, TheSameOnAnyThreadCount) {
  const Mesh<3> mesh = generate_cube(6);
  const AdaptationMetric<3> metric = adapt_test::uniform_metric<3>(0.05);
  EXPECT_EQ(unsettled_vertex_flags(mesh, metric, 1), unsettled_vertex_flags(mesh, metric, 2));
}

}  // namespace
}  // namespace hocav
