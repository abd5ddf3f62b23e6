// End-to-end tests of `hocav bench`: a small case at two thread counts, each run in its own
// process; the rows hold the Table-1 figures, the same output on both thread counts, and memory.
#include <gtest/gtest.h>

#include "cli_test_support.hpp"

namespace hocav::cli_test {
namespace {

class BenchCli : public Cli {
 protected:
  double row_value(int row, const std::string& member) const {
    return std::stod(json_value("bench.json", "d[\"rows\"][" + std::to_string(row) + "][\"" + member + "\"]"));
  }
};

TEST_F(BenchCli, SmallCubeOnOneAndTwoThreadsGivesTheSameOutput) {
  Outcome result = run_ok("bench --cases cube-shear --sizes 3k --threads 1,2 --repeat 2 --json bench.json --markdown bench.md");
  EXPECT_EQ(json_value("bench.json", "len(d[\"rows\"])"), "2");
  for (int row = 0; row < 2; ++row) {
    EXPECT_EQ(row_value(row, "elements"), 6 * 8 * 8 * 8);  // the cube of 8 cells per side is nearest 3k
    EXPECT_EQ(row_value(row, "threads"), row + 1);
    EXPECT_GE(std::stod(json_value("bench.json", "d[\"rows\"][" + std::to_string(row) + "][\"normalized_jacobian\"][\"min\"]")), 0.01);
    EXPECT_GT(row_value(row, "average_gain"), 0);
    EXPECT_EQ(row_value(row, "rejections"), 0);
    EXPECT_GT(row_value(row, "seconds_without_io"), 0);
    EXPECT_GT(row_value(row, "cpu_seconds"), 0);
    EXPECT_GT(row_value(row, "peak_rss_bytes"), 1 << 20);
    // Short runs are repeated: the median of two is the slower.
    EXPECT_EQ(json_value("bench.json", "len(d[\"rows\"][" + std::to_string(row) + "][\"run_seconds\"])"), "2");
  }
  EXPECT_EQ(json_value("bench.json", "d[\"rows\"][1][\"same_output_as_one_thread\"]"), "True");
  EXPECT_EQ(json_value("bench.json", "d[\"rows\"][0][\"output_hash\"] == d[\"rows\"][1][\"output_hash\"]"), "True");
  EXPECT_NE(json_value("bench.json", "d[\"machine\"][\"cpu\"]"), "");
  EXPECT_EQ(read("bench.md"), result.out);
  EXPECT_NE(result.out.find("| cube-shear | 3,072 |"), std::string::npos) << result.out;
}

TEST_F(BenchCli, BadOptionsGiveOneLineAndNoOutput) {
  expect_failure("bench --cases nowhere --json bench.json", "nowhere");
  expect_failure("bench --sizes 12q --json bench.json", "12q");
  expect_failure("bench --sizes 0 --json bench.json", "0");
  EXPECT_TRUE(files().empty());
}

}  // namespace
}  // namespace hocav::cli_test
