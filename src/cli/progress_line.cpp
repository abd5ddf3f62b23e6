#include "cli/progress_line.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <utility>

namespace hocav {
namespace {

// 1234567 -> "1,234,567"
std::string with_thousands(double value) {
  const std::string digits = std::to_string(std::llround(std::max(value, 0.0)));
  std::string text;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) text += ',';
    text += digits[i];
  }
  return text;
}

// 42 -> "42 s", 125 -> "2 min 5 s", 3720 -> "1 h 2 min"
std::string duration_text(double seconds) {
  const long long whole = std::llround(seconds);
  if (whole < 60) return std::to_string(whole) + " s";
  if (whole < 3600) return std::to_string(whole / 60) + " min " + std::to_string(whole % 60) + " s";
  return std::to_string(whole / 3600) + " h " + std::to_string(whole % 3600 / 60) + " min";
}

}  // namespace

bool stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

std::string progress_text(const std::string& phase, const std::string& unit, double done, double total, double seconds) {
  const double percent = total > 0 ? std::floor(100 * done / total) : 100;
  std::string text = phase + ": " + with_thousands(done) + "/" + with_thousands(total) + " " + unit + " (" +
                     std::to_string(static_cast<int>(percent)) + "%)";
  if (done > 0 && seconds > 0) {
    const double rate = done / seconds;
    text += ", " + with_thousands(rate) + "/s, " + duration_text(std::max(total - done, 0.0) / rate) + " left";
  }
  return text;
}

ProgressLine::ProgressLine(std::ostream& out, std::string phase, std::string unit, double total)
    : out_(out), phase_(std::move(phase)), unit_(std::move(unit)), total_(total) {}

void ProgressLine::update(double done) {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // "\r" returns to the line's start, "\x1b[K" erases what a longer previous text left.
  out_ << '\r' << progress_text(phase_, unit_, done, total_, seconds) << "\x1b[K" << std::flush;
  drawn_ = true;
}

void ProgressLine::finish() {
  if (drawn_) out_ << '\n' << std::flush;
  drawn_ = false;
}

void ProgressLine::complete() {
  update(total_);
  finish();
}

}  // namespace hocav
