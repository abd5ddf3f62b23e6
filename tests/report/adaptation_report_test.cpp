#include "report/adaptation_report.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace hocav {
namespace {

// A run of two passes over 10,000 vertices whose last split `splits` edges, its settling having
// put `settled` vertices on the geometry and left `partly` part of the way.
AdaptationReport run_ending_with(Index splits, Index settled, Index partly) {
  AdaptationReport report;
  AdaptationPass pass;
  pass.vertices = 10000;
  pass.splits.done = 5000;
  report.run.passes.push_back(pass);
  pass.splits.done = splits;
  pass.settled = settled;
  pass.partly_settled = partly;
  report.run.passes.push_back(pass);
  return report;
}

TEST(NonConvergenceSummary, IsEmptyForAConvergedRun) {
  AdaptationReport report = run_ending_with(3, 0, 0);
  report.run.converged = true;
  EXPECT_EQ(non_convergence_summary(report), "");
}

// 25 changes of 10,000 vertices are below the loop's bar of 0.25%: only the settling kept it going;
// 26 are above it: the metric may ask for what the geometry does not allow.
TEST(NonConvergenceSummary, SaysWhetherTheSettlingOrTheMetricKeptTheLoopGoing) {
  const std::string counts = "not converged after 2 passes (the last split ";
  const std::vector<std::pair<Index, std::string>> cases{
      {25, counts + "25 and collapsed 0 edges): few enough to stop, but the boundary's settling was still getting further (2 "
                    "vertices put on the geometry, 3 left part of the way); raise --iterations to let it finish"},
      {26, counts + "26 and collapsed 0 edges); raise --iterations, or check that the metric asks for sizes the geometry allows"}};
  for (const auto& [splits, text] : cases) {
    const AdaptationReport report = run_ending_with(splits, 2, 3);
    EXPECT_EQ(changed_little(report.run.passes.back()), splits == 25);
    EXPECT_EQ(non_convergence_summary(report), text);
  }
}

}  // namespace
}  // namespace hocav
