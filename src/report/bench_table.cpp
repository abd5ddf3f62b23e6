#include "report/bench_table.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <sstream>
#include <thread>

#include "report/json_writer.hpp"

namespace hocav {

BenchFigures bench_figures(const CurvingReport& report) {
  BenchFigures figures;
  figures.dimension = report.dimension;
  figures.elements = report.elements;
  figures.points_before = report.points_before;
  figures.points_after = report.points_after;
  figures.max_anisotropy = report.max_anisotropy;
  figures.seconds = report.seconds;
  figures.edges_optimized_per_second = report.edges_optimized_per_second;
  figures.normalized_jacobian_min = report.normalized_jacobian.min;
  figures.normalized_jacobian_avg = report.normalized_jacobian.average;
  figures.normalized_jacobian_max = report.normalized_jacobian.max;
  figures.scaled_jacobian_min = report.scaled_jacobian.min;
  figures.average_gain = report.average_gain;
  figures.max_gain = report.max_gain;
  const P2CavityCounters& counters = report.counters;
  figures.cavities = counters.cavities;
  figures.accepted = counters.accepted;
  figures.rejections = counters.rejected_topology + counters.rejected_curving;
  figures.corrections = counters.corrections;
  figures.edges_optimized = counters.edges_optimized;
  figures.optimizer_iterations = counters.optimizer_iterations;
  figures.edges_kept_optimal = counters.edges_kept_optimal;
  figures.elements_certified = counters.elements_certified;
  figures.certificates_kept = counters.certificates_kept;
  return figures;
}

MachineInfo this_machine() {
  MachineInfo machine;
  machine.cores = static_cast<int>(std::thread::hardware_concurrency());
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.starts_with("model name")) {
      machine.cpu = line.substr(line.find(':') + 2);
      break;
    }
  std::ifstream("/proc/loadavg") >> machine.load_average;
  std::ifstream meminfo("/proc/meminfo");
  std::string name;
  long long kib = 0;
  if (meminfo >> name >> kib && name == "MemTotal:") machine.memory_bytes = kib * 1024;
  return machine;
}

namespace {

// 1234567 -> "1,234,567"
std::string grouped(long long value) {
  std::string digits = std::to_string(value < 0 ? -value : value), text;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) text += ',';
    text += digits[i];
  }
  return value < 0 ? "-" + text : text;
}

std::string formatted(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// Whether two runs curved the same mesh into the same output (times aside).
bool same_output(const BenchFigures& a, const BenchFigures& b) {
  return a.output_hash == b.output_hash && a.elements == b.elements && a.points_after == b.points_after &&
         a.normalized_jacobian_min == b.normalized_jacobian_min && a.average_gain == b.average_gain && a.corrections == b.corrections &&
         a.rejections == b.rejections;
}

// "yes"/"no" against the one-thread row of the same case and size; "" when there is none.
std::string thread_check(const BenchRow& row, const std::vector<BenchRow>& rows) {
  if (row.threads == 1) return "";
  for (const BenchRow& other : rows)
    if (other.threads == 1 && other.case_name == row.case_name && other.target == row.target)
      return same_output(row.figures, other.figures) ? "yes" : "no";
  return "";
}

double median_of(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0 : values[values.size() / 2];
}

}  // namespace

void write_bench_markdown(std::ostream& out, const MachineInfo& machine, const std::vector<BenchRow>& rows) {
  out << "Machine: " << machine.cpu << ", " << machine.cores << " hardware threads, "
      << formatted("%.1f", static_cast<double>(machine.memory_bytes) / (1 << 30)) << " GiB; load average "
      << formatted("%.2f", machine.load_average) << " at the start.\n\n";
  out << "| case | elements | points ini / end | max aniso | edges opt./s | time (no I/O) | µs per element | CPU (curving) | setup "
         "| min / avg / max norm. Jacobian | min scaled Jacobian | avg / max gain | rejections | corrections "
         "| threads | runs | peak RSS | same output as 1 thread |\n";
  out << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchRow& row : rows) {
    const BenchFigures& f = row.figures;
    out << "| " << row.case_name << " | " << grouped(f.elements) << " | " << grouped(f.points_before) << " / " << grouped(f.points_after)
        << " | " << formatted("%.3g", f.max_anisotropy) << " | " << grouped(static_cast<long long>(f.edges_optimized_per_second)) << " | "
        << formatted("%.2f s", f.seconds) << " | " << formatted("%.2f", 1e6 * f.seconds / static_cast<double>(f.elements)) << " | "
        << formatted("%.2f s", f.cpu_seconds) << " | " << formatted("%.2f s", f.setup_seconds) << " | "
        << formatted("%.2g", f.normalized_jacobian_min) << " / " << formatted("%.2f", f.normalized_jacobian_avg) << " / "
        << formatted("%.3g", f.normalized_jacobian_max) << " | " << formatted("%.2g", f.scaled_jacobian_min) << " | "
        << formatted("%.2f%%", 100 * f.average_gain) << " / " << formatted("%.0f%%", 100 * f.max_gain) << " | " << grouped(f.rejections)
        << " | " << grouped(f.corrections) << " | " << row.threads << " | " << row.run_seconds.size() << " | "
        << formatted("%.0f MiB", static_cast<double>(row.peak_rss_bytes) / (1 << 20)) << " | " << thread_check(row, rows) << " |\n";
  }
}

void write_bench_json(std::ostream& out, const MachineInfo& machine, const std::vector<BenchRow>& rows) {
  JsonWriter json(out);
  json.begin_object();
  json.key("machine").begin_object();
  json.member("cpu", machine.cpu).member("hardware_threads", machine.cores);
  json.member("memory_bytes", machine.memory_bytes).member("load_average_at_start", machine.load_average);
  json.end_object();
  json.key("rows").begin_array();
  for (const BenchRow& row : rows) {
    const BenchFigures& f = row.figures;
    json.begin_object();
    json.member("case", row.case_name).member("target", row.target).member("threads", row.threads);
    json.member("dimension", f.dimension).member("elements", f.elements);
    json.member("points_before", f.points_before).member("points_after", f.points_after);
    json.member("max_anisotropy", f.max_anisotropy);
    json.member("edges_optimized_per_second", f.edges_optimized_per_second);
    json.member("seconds_without_io", f.seconds).member("cpu_seconds", f.cpu_seconds);
    json.member("setup_seconds", f.setup_seconds);
    json.member("median_of_runs", median_of(row.run_seconds));
    json.key("run_seconds").begin_array();
    for (double seconds : row.run_seconds) json.value(seconds);
    json.end_array();
    json.key("normalized_jacobian").begin_object();
    json.member("min", f.normalized_jacobian_min).member("avg", f.normalized_jacobian_avg).member("max", f.normalized_jacobian_max);
    json.end_object();
    json.member("scaled_jacobian_min", f.scaled_jacobian_min);
    json.member("average_gain", f.average_gain).member("max_gain", f.max_gain);
    json.member("cavities", f.cavities).member("accepted", f.accepted).member("rejections", f.rejections);
    json.member("corrections", f.corrections).member("edges_optimized", f.edges_optimized);
    json.member("optimizer_iterations", f.optimizer_iterations).member("edges_kept_optimal", f.edges_kept_optimal);
    json.member("elements_certified", f.elements_certified).member("certificates_kept", f.certificates_kept);
    json.member("peak_rss_bytes", row.peak_rss_bytes);
    json.member("output_hash", std::to_string(f.output_hash));
    if (std::string check = thread_check(row, rows); !check.empty()) json.member("same_output_as_one_thread", check == "yes");
    json.end_object();
  }
  json.end_array();
  json.end_object();
  out << '\n';
}

}  // namespace hocav
