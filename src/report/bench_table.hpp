// The rows of `hocav bench`: one curving run per case, size and thread count, in the columns of the
// paper's Table 1 (docs/method.md §11) plus time per tetrahedron, peak memory, the runs
// the median came from, and a fingerprint of the output to check thread independence.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "report/curving_report.hpp"

namespace hocav {

// The figures of one run: plain numbers only, so a child process can hand them over as bytes.
struct BenchFigures {
  int dimension = 3;
  Index elements = 0, points_before = 0, points_after = 0;
  double max_anisotropy = 0;
  double seconds = 0;        // curving, no I/O (the reinsertion passes, as `hocav curve` reports)
  double cpu_seconds = 0;    // processor time of the curving, all threads (shows a loaded machine)
  double setup_seconds = 0;  // metric field, boundary surrogate and its proposals, before the passes
  double edges_optimized_per_second = 0;
  double normalized_jacobian_min = 0, normalized_jacobian_avg = 0, normalized_jacobian_max = 0;
  double scaled_jacobian_min = 0;
  double average_gain = 0, max_gain = 0;
  long long cavities = 0, accepted = 0, rejections = 0, corrections = 0, edges_optimized = 0, optimizer_iterations = 0;
  long long edges_kept_optimal = 0, elements_certified = 0, certificates_kept = 0;
  std::uint64_t output_hash = 0;  // of the curved mesh's vertices, elements and nodes
};

BenchFigures bench_figures(const CurvingReport& report);

struct BenchRow {
  std::string case_name;
  double target = 0;  // the element count asked for
  int threads = 1;
  BenchFigures figures;             // of the run of median time
  std::vector<double> run_seconds;  // every run, in order
  long long peak_rss_bytes = 0;     // largest over the runs, each in its own process
};

struct MachineInfo {
  std::string cpu;          // model name from /proc/cpuinfo
  int cores = 0;            // hardware threads
  double load_average = 0;  // 1-minute load average when the bench started
  long long memory_bytes = 0;
};
MachineInfo this_machine();

// Table 1 as Markdown, with the machine above it; rows with more than one thread say whether the
// output matches the one-thread row of the same case and size.
void write_bench_markdown(std::ostream& out, const MachineInfo& machine, const std::vector<BenchRow>& rows);
void write_bench_json(std::ostream& out, const MachineInfo& machine, const std::vector<BenchRow>& rows);

}  // namespace hocav
