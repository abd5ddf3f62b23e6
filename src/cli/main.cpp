// The `hocav` command: parses the command line and runs one subcommand. Exit codes: 0 success,
// 2 any error (bad option, bad input file, failed output), with a one-line message on stderr.
#include <CLI/CLI.hpp>

#include <csignal>
#include <iostream>
#include <new>

#include "base/error.hpp"
#include "cli/commands.hpp"

int main(int argc, char** argv) {
  constexpr int kFailure = 2;
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : kFailure;  // --help and --version are "errors" that succeed
  } catch (const std::bad_alloc&) {
    std::cerr << "hocav: out of memory: the job needs more memory than this machine could give\n";
    return kFailure;
  } catch (const hocav::Error& error) {
    std::cerr << "hocav: " << error.what() << '\n';
    return kFailure;
  } catch (const std::exception& error) {
    std::cerr << "hocav: unexpected error: " << error.what() << '\n';
    return kFailure;
  }
  return 0;
}
