// hocav bench [--cases LIST] [--sizes LIST] [--threads LIST] [--repeat N] [--markdown F.md] [--json F.json]
// Generates every case at every size, curves it as `hocav curve` would (each run in its own
// process), and prints the rows of the paper's Table 1 with time per element and peak memory.
#include <cmath>
#include <iostream>
#include <memory>

#include "base/error.hpp"
#include "base/thread_pool.hpp"
#include "bench/bench_run.hpp"
#include "cli/command_support.hpp"
#include "cli/commands.hpp"
#include "io/atomic_output.hpp"
#include "io/output_set.hpp"

namespace hocav {
namespace {

struct BenchOptions {
  std::vector<std::string> cases, sizes{"100k"};
  std::vector<int> threads{every_core()};
  int repeat = 3;
  std::string markdown, json;
};

// "100k" -> 1e5, "1M" -> 1e6, "2500" -> 2500.
double parse_size(const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  const std::string suffix = text.substr(used);
  const double scale = suffix.empty() ? 1 : suffix == "k" ? 1e3 : suffix == "M" ? 1e6 : 0;
  if (used == 0 || scale == 0 || !std::isfinite(value) || !(value * scale >= 1))
    throw Error("--sizes: '" + text + "' is not an element count such as 100k, 1M or 2500");
  return value * scale;
}

void run_bench(const BenchOptions& options) {
  OutputSet outputs;
  if (!options.markdown.empty()) outputs.add_output(options.markdown, "--markdown");
  if (!options.json.empty()) outputs.add_output(options.json, "--json");
  std::vector<const BenchCase*> cases;
  if (options.cases.empty())
    for (const BenchCase& bench_case : bench_cases()) cases.push_back(&bench_case);
  for (const std::string& name : options.cases) cases.push_back(&find_bench_case(name));
  std::vector<double> targets;
  for (const std::string& size : options.sizes) targets.push_back(parse_size(size));

  const MachineInfo machine = this_machine();
  std::vector<BenchRow> rows;
  for (const BenchCase* bench_case : cases)
    for (double target : targets) {
      if (target > bench_case->largest_target) {
        std::cerr << "bench: " << bench_case->name << " skipped at " << target << " elements (its generator stops at "
                  << bench_case->largest_target << ")\n";
        continue;
      }
      for (int threads : options.threads) {
        std::cerr << "bench: " << bench_case->name << " at " << target << " elements, " << threads << " thread(s)\n";
        rows.push_back(run_bench_case(*bench_case, target, {threads, options.repeat}));
      }
    }
  if (!options.markdown.empty()) {
    AtomicOutput out(options.markdown);
    write_bench_markdown(out.stream(), machine, rows);
    out.commit();
  }
  if (!options.json.empty()) {
    AtomicOutput out(options.json);
    write_bench_json(out.stream(), machine, rows);
    out.commit();
  }
  outputs.commit();
  write_bench_markdown(std::cout, machine, rows);
}

std::string bench_cases_footer() {
  std::string footer = "Cases:\n";
  for (const BenchCase& bench_case : bench_cases()) footer += "  " + bench_case.name + ": " + bench_case.description + "\n";
  return footer;
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* command = app.add_subcommand("bench",
                                         "Curve every benchmark case at every size and print the paper's Table-1 rows (Markdown, JSON)");
  command->add_option("--cases", options->cases, "cases to run, comma-separated (default: all)")->delimiter(',');
  command->add_option("--sizes", options->sizes, "element counts to aim at, comma-separated: 100k, 1M, 5M, 20M, ...")
      ->delimiter(',')
      ->capture_default_str();
  command->add_option("--threads", options->threads, "thread counts to run each case with, comma-separated (default: every core)")
      ->delimiter(',')
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  command->add_option("--repeat", options->repeat, "runs of a case whose first run takes under 10 s; the median is kept")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  command->add_option("--markdown", options->markdown, "also write the table to this file");
  command->add_option("--json", options->json, "write the rows, every run's time and the machine as JSON");
  command->footer(bench_cases_footer());
  command->callback([options] { run_bench(*options); });
}

}  // namespace hocav
