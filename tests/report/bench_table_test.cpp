#include "report/bench_table.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace hocav {
namespace {

BenchRow row(int threads, std::uint64_t hash, double target = 1e6) {
  BenchRow r;
  r.case_name = "cube-shear";
  r.target = target;
  r.threads = threads;
  r.figures.elements = 1234567;
  r.figures.points_before = 1000;
  r.figures.points_after = 2500;
  r.figures.seconds = 2.5;
  r.figures.cpu_seconds = 4;
  r.figures.normalized_jacobian_min = 0.01;
  r.figures.average_gain = 0.0123;
  r.figures.max_gain = 0.5;
  r.figures.output_hash = hash;
  r.run_seconds = {2.5};
  r.peak_rss_bytes = 3LL << 20;
  return r;
}

std::string markdown(const std::vector<BenchRow>& rows) {
  std::ostringstream out;
  write_bench_markdown(out, MachineInfo{"Test CPU", 2, 0.5, 4LL << 30}, rows);
  return out.str();
}

TEST(BenchTable, MarkdownRowsHaveTheTableOneColumnsAndTheThreadCheck) {
  const std::string text = markdown({row(1, 7), row(2, 7), row(2, 8, 1e5), row(1, 9, 1e5)});
  EXPECT_NE(text.find("Machine: Test CPU, 2 hardware threads, 4.0 GiB; load average 0.50"), std::string::npos) << text;
  // Counts grouped by thousands, time per element in microseconds, memory in MiB.
  EXPECT_NE(text.find("| cube-shear | 1,234,567 | 1,000 / 2,500 |"), std::string::npos) << text;
  EXPECT_NE(text.find("| 2.50 s | 2.03 | 4.00 s |"), std::string::npos) << text;
  EXPECT_NE(text.find("| 1.23% / 50% |"), std::string::npos) << text;
  EXPECT_NE(text.find("| 3 MiB | yes |"), std::string::npos) << text;  // same hash as its 1-thread row
  EXPECT_NE(text.find("| 3 MiB | no |"), std::string::npos) << text;   // another hash at 1e5
  EXPECT_NE(text.find("| 3 MiB |  |"), std::string::npos) << text;     // 1-thread rows check nothing
}

TEST(BenchTable, JsonHoldsEveryRunAndTheMachine) {
  BenchRow slow = row(1, 7);
  slow.run_seconds = {3, 1, 2};
  std::ostringstream out;
  write_bench_json(out, MachineInfo{"Test CPU", 2, 0.5, 4LL << 30}, {slow, row(2, 8)});
  const std::string text = out.str();
  EXPECT_NE(text.find("\"cpu\": \"Test CPU\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"median_of_runs\": 2"), std::string::npos) << text;
  EXPECT_NE(text.find("\"same_output_as_one_thread\": false"), std::string::npos) << text;
  EXPECT_NE(text.find("\"output_hash\": \"7\""), std::string::npos) << text;
}

TEST(BenchTable, ThisMachineHasACpuAndCores) {
  const MachineInfo machine = this_machine();
  EXPECT_GT(machine.cores, 0);
  EXPECT_GT(machine.memory_bytes, 0);
}

}  // namespace
}  // namespace hocav
