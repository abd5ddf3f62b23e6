// The progress of a long run as one line on a terminal, redrawn in place:
//   curving: 41,200/100,000 vertices (41%), 23,400/s, 3 s left
// Commands draw it on stderr only when stderr is a terminal and the user did not ask for quiet: a
// log or a pipe would fill with partial lines.
#pragma once

#include <chrono>
#include <iosfwd>
#include <string>

namespace hocav {

bool stderr_is_terminal();

// The text of the line after `seconds` of work: phase, done/total unit, percent, then (once some
// work is done) the rate and the time left at that rate.
std::string progress_text(const std::string& phase, const std::string& unit, double done, double total, double seconds);

class ProgressLine {
 public:
  ProgressLine(std::ostream& out, std::string phase, std::string unit, double total);
  ~ProgressLine() { finish(); }  // an error's message then starts on a line of its own
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // Redraws the line with `done` of the total.
  void update(double done);
  // Ends the line (if one was drawn); later updates start a new one.
  void finish();
  // Redraws the line with all of the total done, and ends it.
  void complete();

 private:
  std::ostream& out_;
  std::string phase_, unit_;
  double total_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  bool drawn_ = false;
};

}  // namespace hocav
