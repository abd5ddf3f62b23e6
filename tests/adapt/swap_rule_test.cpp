// The swap rule (docs/adaptation.md §The loop): a sweep counts every change since the previous sweep
// began, whatever came between (the end of a pass, its smoothing), and a candidate whose gathered
// cavity holds no element changed since then is not judged again.
#include <gtest/gtest.h>

#include "adapt/adaptation_operations.hpp"
#include "adapt_test_support.hpp"

namespace hocav {
namespace {

// A cube refined by one split pass toward the linear metric's layer: many elements below the swap
// threshold, as after a pass of the loop.
struct SplitCube {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(3);
  AdaptationMetric<3> metric = linear_metric();
  AdaptationMesh<3> am{mesh, metric, nullptr, 45};
  AdaptationLimits limits;
  ThreadPool pool{2};

  static AdaptationMetric<3> linear_metric() {
    AnalyticMetricSpec spec;
    spec.name = "linear";
    spec.h_min = 0.05;
    return AdaptationMetric<3>(spec, {});
  }
  SplitCube() {
    split_long_edges(am, limits, pool);
    mesh.compact();
  }
  // Sweeps as the loop does until a sweep swaps nothing; returns the swaps made.
  Index sweep_until_nothing_changes() {
    Index swaps = 0;
    for (int sweep = 0; sweep < 50; ++sweep) {
      const OperationCount count = swap_for_quality(am, limits, am.start_sweep(), pool);
      if (count.done == 0) return swaps;
      swaps += count.done;
    }
    ADD_FAILURE() << "the sweeps never stopped swapping";
    return swaps;
  }
};

// A candidate is judged when its cavity has changed, and the judgement of a cavity depends on the
// cavity alone: once a sweep finds nothing, a sweep that judges every candidate finds nothing
// either, and one whose candidates are all listed (every vertex marked) but whose cavities hold no
// changed element judges none.
TEST(SwapRule, ACavityThatDidNotChangeIsNotJudgedAgain) {
  SplitCube cube;
  EXPECT_GT(cube.sweep_until_nothing_changes(), 0);
  const OperationCount everything = swap_for_quality(cube.am, cube.limits, 0, cube.pool);
  EXPECT_EQ(everything.done, 0);  // what the rule left out would have been refused
  const Index judged_everything = everything.refused[static_cast<std::size_t>(Refusal::kQuality)];
  EXPECT_GT(judged_everything, 0);
  const int since = cube.am.start_sweep();
  for (Index v = 0; v < cube.mesh.vertex_count(); ++v) cube.am.mark_changed(v);
  const OperationCount unchanged = swap_for_quality(cube.am, cube.limits, since, cube.pool);
  EXPECT_EQ(unchanged.done, 0);
  EXPECT_EQ(unchanged.refused[static_cast<std::size_t>(Refusal::kQuality)], 0) << "of " << judged_everything << " judged before";
}

// The loop's pass k ends with smoothing; the first sweep of pass k + 1 counts those moves, so it
// finds the swaps they made possible (a sweep counting only the changes since its own pass began
// would find none).
TEST(SwapRule, TheNextPassFirstSweepFindsWhatSmoothingMadePossible) {
  SplitCube cube;
  cube.sweep_until_nothing_changes();
  ASSERT_GT(smooth_vertices(cube.am, cube.limits, cube.pool).done, 0);
  cube.mesh.compact();
  const int pass_start = cube.am.start_pass();
  EXPECT_EQ(swap_for_quality(cube.am, cube.limits, pass_start, cube.pool).done, 0);
  const OperationCount first_sweep = swap_for_quality(cube.am, cube.limits, cube.am.start_sweep(), cube.pool);
  EXPECT_GT(first_sweep.done, 0);
  adapt_test::expect_closed_and_consistent(cube.mesh);
}

}  // namespace
}  // namespace hocav
