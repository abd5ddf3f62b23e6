// A feature line with no facet along it (a Gamma Edges entry inside the volume) is never swapped or
// split away: the loop keeps every one of its edges as an element edge.
#include <gtest/gtest.h>

#include <unordered_set>

#include "adapt/adaptation_loop.hpp"
#include "adapt/adaptation_operations.hpp"
#include "adapt_test_support.hpp"

namespace hocav {
namespace {

AdaptationMetric<3> linear_metric(double h_min) {
  AnalyticMetricSpec spec;
  spec.name = "linear";
  spec.h_min = h_min;
  return AdaptationMetric<3>(spec, {});
}

bool on_boundary(const Vec<3>& x) {
  for (int i = 0; i < 3; ++i)
    if (x[i] < 1e-12 || x[i] > 1 - 1e-12) return true;
  return false;
}

// Puts a feature line on every element edge whose ends are both inside the domain; returns how
// many.
Index line_every_interior_edge(Mesh<3>& mesh) {
  std::unordered_set<std::uint64_t> seen;
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < i; ++j) {
        const Index a = mesh.element(k)[i], b = mesh.element(k)[j];
        if (!on_boundary(mesh.vertex(a)) && !on_boundary(mesh.vertex(b)) && seen.insert(Mesh<3>::edge_key(a, b)).second)
          mesh.add_line({a, b});
      }
  return static_cast<Index>(seen.size());
}

Index line_count(const Mesh<3>& mesh) {
  Index count = 0;
  for (Index l = 0; l < mesh.line_count(); ++l) count += mesh.line_removed(l) ? 0 : 1;
  return count;
}

// The loop in a metric that splits, collapses and swaps all over the cube: the interior lines come
// out whole (check_consistency finds every line edge among the element edges), and untouched.
TEST(InteriorLine, TheLoopKeepsALineThatLiesOnNoFacet) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(4);
  const Index lines_before = line_count(mesh);
  const Index interior = line_every_interior_edge(mesh);
  ASSERT_GT(interior, 10);
  const AdaptationRun run = adapt_to_metric<3>(mesh, linear_metric(0.02), nullptr, {});
  ASSERT_GT(run.passes.front().splits.done, 0);
  adapt_test::expect_closed_and_consistent(mesh);
  // The cube's own edges are split (more lines), the interior ones are not.
  Index interior_after = 0;
  for (Index l = 0; l < mesh.line_count(); ++l)
    interior_after += !on_boundary(mesh.vertex(mesh.line(l)[0])) && !on_boundary(mesh.vertex(mesh.line(l)[1]));
  EXPECT_EQ(interior_after, interior);
  EXPECT_GT(line_count(mesh), lines_before + interior);
}

// Swap sweeps alone, after a split pass made many poor elements: every swap refused on an interior
// line is one that the same sweeps make without the lines.
TEST(InteriorLine, SwapsLeaveALineThatLiesOnNoFacet) {
  const auto swaps_on = [](bool with_lines) {
    Mesh<3> mesh = adapt_test::unit_mesh<3>(3);
    const AdaptationMetric<3> metric = linear_metric(0.05);
    AdaptationMesh<3> am{mesh, metric, nullptr, 45};
    AdaptationLimits limits;
    ThreadPool pool{2};
    split_long_edges(am, limits, pool);
    mesh.compact();
    const Index lines = with_lines ? line_every_interior_edge(mesh) : 0;
    Index swaps = 0;
    for (int sweep = 0; sweep < 5; ++sweep) swaps += swap_for_quality(am, limits, am.start_sweep(), pool).done;
    mesh.compact();
    adapt_test::expect_closed_and_consistent(mesh);
    if (with_lines) {
      EXPECT_GT(lines, 50);
    }
    return swaps;
  };
  const Index free_swaps = swaps_on(false), swaps_with_lines = swaps_on(true);
  EXPECT_GT(free_swaps, 0);
  EXPECT_LT(swaps_with_lines, free_swaps);
}

}  // namespace
}  // namespace hocav
