// The subcommands of `hocav`. Each adds itself to the application with its options and runs from
// its callback; failures are thrown as Error and reported by main.
#pragma once

#include <CLI/CLI.hpp>

namespace hocav {

void add_convert_command(CLI::App& app);
void add_stats_command(CLI::App& app);
void add_generate_command(CLI::App& app);
void add_curve_command(CLI::App& app);
void add_adapt_command(CLI::App& app);
void add_metric_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_demo_command(CLI::App& app);
void add_picture_command(CLI::App& app);

}  // namespace hocav
