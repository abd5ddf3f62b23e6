// One row of `hocav bench`: a case generated at a target size, its metric computed, then curved by
// the paper's algorithm (as `hocav curve` does, without files) in a child process of its own, so
// that the process's peak resident memory is this run's alone. Runs are repeated while they are
// short, and the row keeps the run of median time.
#pragma once

#include "bench/bench_cases.hpp"
#include "report/bench_table.hpp"

namespace hocav {

struct BenchRunOptions {
  int threads = 1;
  int repeat = 3;                    // runs when the first one is short
  double repeat_below_seconds = 10;  // a first run at least this long is not repeated
};

// Throws Error (with the child's message) when the case fails.
BenchRow run_bench_case(const BenchCase& bench_case, double target, const BenchRunOptions& options);

}  // namespace hocav
