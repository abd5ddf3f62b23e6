#include "bench/bench_run.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <iostream>
#include <memory>
#include <type_traits>

#include "adapt/curving_run.hpp"
#include "base/error.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

// FNV-1a over the bytes of a range of trivially copyable values.
template <class T>
void hash_values(std::uint64_t& hash, std::span<const T> values) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
  for (std::size_t i = 0; i < values.size_bytes(); ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ull;
}

// What fixes the output: vertices, elements and P2 nodes, bit for bit.
template <int D>
std::uint64_t output_hash(const Mesh<D>& mesh) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  hash_values(hash, mesh.vertices());
  hash_values(hash, mesh.elements());
  for (Index e = 0; e < mesh.edge_count(); ++e) hash_values(hash, std::span<const Vec<D>>(&mesh.edge_node(e), 1));
  return hash;
}

// The case's run on its generated mesh: metric (not timed, as reading a .sol is not), then what
// `hocav curve` does between reading and writing.
template <int D>
BenchFigures curve_generated(Mesh<D>& mesh, const BenchCase& bench_case, int threads) {
  std::vector<SymMat<D>> metrics = bench_metric(bench_case.metric, mesh);
  const auto setup_start = std::chrono::steady_clock::now();
  const MetricField<D> field(mesh, metrics);
  metrics = {};
  std::unique_ptr<P3Surrogate<D>> surrogate;
  if (bench_case.surface == "p3") surrogate = std::make_unique<P3Surrogate<D>>(mesh);
  const double setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_start).count();
  ReinsertionOptions reinsertion;
  reinsertion.threads = threads;
  const CurvingRun run = curve_with_boundary<D>(mesh, field, surrogate.get(), reinsertion);
  BenchFigures figures = bench_figures(run.report);
  figures.setup_seconds = setup_seconds + run.proposal_seconds;
  figures.cpu_seconds = run.cpu_seconds;
  figures.output_hash = output_hash(mesh);
  return figures;
}

// What a child process sends back through its pipe.
struct ChildMessage {
  bool ok = false;
  BenchFigures figures;
  char error[480] = {};
};
static_assert(std::is_trivially_copyable_v<ChildMessage>);

ChildMessage run_in_this_process(const BenchCase& bench_case, double target, int threads) {
  ChildMessage message;
  try {
    AnyMesh generated = generate_case(find_case(bench_case.generator), bench_case.options_for_target(target));
    message.figures = std::visit([&](auto& mesh) { return curve_generated(mesh, bench_case, threads); }, generated);
    message.ok = true;
  } catch (const std::exception& error) {
    std::strncpy(message.error, error.what(), sizeof message.error - 1);
  }
  return message;
}

struct ChildResult {
  ChildMessage message;
  long long peak_rss_bytes = 0;
};

// One run in a child process: its peak resident memory (getrusage of the child) is the run's own.
ChildResult run_in_child(const BenchCase& bench_case, double target, int threads) {
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) throw Error("bench: cannot create a pipe");
  std::cout.flush();
  std::cerr.flush();
  const pid_t child = fork();
  if (child < 0) throw Error("bench: cannot fork");
  if (child == 0) {
    close(pipe_ends[0]);
    const ChildMessage message = run_in_this_process(bench_case, target, threads);
    const auto* bytes = reinterpret_cast<const char*>(&message);
    for (std::size_t sent = 0; sent < sizeof message;) {
      const ssize_t written = write(pipe_ends[1], bytes + sent, sizeof message - sent);
      if (written <= 0) _exit(1);
      sent += static_cast<std::size_t>(written);
    }
    _exit(0);
  }
  close(pipe_ends[1]);
  ChildResult result;
  auto* bytes = reinterpret_cast<char*>(&result.message);
  std::size_t received = 0;
  while (received < sizeof result.message) {
    const ssize_t got = read(pipe_ends[0], bytes + received, sizeof result.message - received);
    if (got <= 0) break;
    received += static_cast<std::size_t>(got);
  }
  close(pipe_ends[0]);
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  if (received != sizeof result.message || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error("bench: the run of " + bench_case.name + " died (" +
                (WIFSIGNALED(status) ? "signal " + std::to_string(WTERMSIG(status)) : "no result") + ")");
  if (!result.message.ok) throw Error("bench: " + bench_case.name + ": " + result.message.error);
  result.peak_rss_bytes = static_cast<long long>(usage.ru_maxrss) * 1024;  // Linux gives KiB
  return result;
}

}  // namespace

BenchRow run_bench_case(const BenchCase& bench_case, double target, const BenchRunOptions& options) {
  BenchRow row;
  row.case_name = bench_case.name;
  row.target = target;
  row.threads = options.threads;
  std::vector<BenchFigures> runs;
  do {
    ChildResult result = run_in_child(bench_case, target, options.threads);
    runs.push_back(result.message.figures);
    row.run_seconds.push_back(result.message.figures.seconds);
    row.peak_rss_bytes = std::max(row.peak_rss_bytes, result.peak_rss_bytes);
  } while (static_cast<int>(runs.size()) < options.repeat && runs.front().seconds < options.repeat_below_seconds);
  std::sort(runs.begin(), runs.end(), [](const BenchFigures& a, const BenchFigures& b) { return a.seconds < b.seconds; });
  row.figures = runs[runs.size() / 2];
  return row;
}

}  // namespace hocav
