// The `hocav` command: parses the command line and runs one subcommand. Exit codes: 0 success,
// 2 any error (bad option, bad input file, failed output), with a one-line message on stderr.
#include <CLI/CLI.hpp>

#include <chrono>
#include <csignal>
#include <iostream>
#include <new>
#include <string>
#include <string_view>
#include <thread>

#include "base/error.hpp"
#include "cli/commands.hpp"
#include "parallel/communicator.hpp"

namespace {

// Under mpirun with several processes only `adapt`, `curve`, `metric` (--implied) and `convert` (of
// Gamma meshes) are distributed (docs/distributed.md).
bool runs_on_several_processes(int argc, char** argv) {
  if (argc < 2) return false;
  const std::string_view command = argv[1];
  return command == "adapt" || command == "curve" || command == "metric" || command == "convert";
}

// The message of an error on one of several processes, before they all stop.
int fail(const std::string& message) {
  constexpr int kFailure = 2;
  if (hocav::process_count() == 1) {
    std::cerr << message << '\n';
    return kFailure;
  }
  if (hocav::process_rank() == 0) {
    std::cerr << message << '\n';
  } else {
    // An error every process meets (a missing or malformed input that each reads a piece of) is said
    // once, by rank 0, whose abort ends this process while it waits.
    std::this_thread::sleep_for(std::chrono::seconds(1));
    std::cerr << "(rank " << hocav::process_rank() << ") " << message << '\n';
  }
  hocav::abort_processes(kFailure);
}

}  // namespace

int main(int argc, char** argv) {
  constexpr int kFailure = 2;
  hocav::MpiSession mpi(argc, argv);
  if (hocav::process_count() > 1 && !runs_on_several_processes(argc, argv)) {
    if (hocav::process_rank() == 0)
      std::cerr << "hocav: only `hocav adapt`, `hocav curve`, `hocav metric --implied` and `hocav convert` run on several processes "
                   "(docs/distributed.md)\n";
    return kFailure;
  }
  std::signal(SIGXFSZ, SIG_IGN);  // a file-size limit (ulimit -f) is a write error, reported and cleaned up, not a kill
  CLI::App app{"hocav: curved (P2) metric-based mesh adaptation", "hocav"};
  app.set_version_flag("--version", std::string("hocav ") + HOCAV_VERSION + " (commit " + HOCAV_GIT_COMMIT + ")");
  app.require_subcommand(1);
  hocav::add_convert_command(app);
  hocav::add_stats_command(app);
  hocav::add_generate_command(app);
  hocav::add_metric_command(app);
  hocav::add_curve_command(app);
  hocav::add_adapt_command(app);
  hocav::add_bench_command(app);
  hocav::add_demo_command(app);
  hocav::add_picture_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : kFailure;  // --help and --version are "errors" that succeed
  } catch (const std::bad_alloc&) {
    return fail("hocav: out of memory: the job needs more memory than this machine could give");
  } catch (const hocav::Error& error) {
    return fail(std::string("hocav: ") + error.what());
  } catch (const std::exception& error) {
    return fail(std::string("hocav: unexpected error: ") + error.what());
  }
  return 0;
}
