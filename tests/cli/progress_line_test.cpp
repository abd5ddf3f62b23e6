// The progress line of long runs: its text (counts, percent, rate, time left) and how it is drawn
// (redrawn in place, ended by one newline).
#include "cli/progress_line.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

namespace hocav {
namespace {

TEST(ProgressText, CountsPercentRateAndTimeLeft) {
  // 41,200 in 2 s: 20,600 per second, 58,800 left: 2.85 s.
  EXPECT_EQ(progress_text("curving", "vertices", 41200, 100000, 2.0), "curving: 41,200/100,000 vertices (41%), 20,600/s, 3 s left");
  EXPECT_EQ(progress_text("curving", "vertices", 100000, 100000, 4.0), "curving: 100,000/100,000 vertices (100%), 25,000/s, 0 s left");
}

TEST(ProgressText, NoRateBeforeAnyWork) {
  EXPECT_EQ(progress_text("curving", "vertices", 0, 1234567, 0.5), "curving: 0/1,234,567 vertices (0%)");
  EXPECT_EQ(progress_text("curving", "vertices", 10, 100, 0), "curving: 10/100 vertices (10%)");
}

TEST(ProgressText, LongTimesInMinutesAndHours) {
  EXPECT_EQ(progress_text("adapting", "passes", 50, 200, 50), "adapting: 50/200 passes (25%), 1/s, 2 min 30 s left");
  // 100 per second, 999,000 left: 9,990 s.
  EXPECT_EQ(progress_text("curving", "vertices", 1000, 1000000, 10), "curving: 1,000/1,000,000 vertices (0%), 100/s, 2 h 46 min left");
}

TEST(ProgressLine, RedrawsOneLineAndEndsItOnce) {
  std::ostringstream out;
  {
    ProgressLine line(out, "curving", "vertices", 100);
    line.update(0);
    line.update(50);
    line.finish();
    line.finish();  // nothing more
  }
  const std::string text = out.str();
  EXPECT_EQ(text.find("\rcurving: 0/100 vertices (0%)\x1b[K"), 0u) << text;
  EXPECT_NE(text.find("\rcurving: 50/100 vertices (50%)"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\r'), 2);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
  EXPECT_EQ(text.back(), '\n');
}

TEST(ProgressLine, CompleteDrawsTheWholeTotal) {
  std::ostringstream out;
  ProgressLine line(out, "curving", "vertices", 2500);
  line.update(1000);
  line.complete();
  const std::string text = out.str();
  EXPECT_NE(text.find("\rcurving: 2,500/2,500 vertices (100%)"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
}

TEST(ProgressLine, EndsItsLineWhenDestroyedAndDrawsNothingUnused) {
  std::ostringstream drawn, unused;
  {
    ProgressLine line(drawn, "curving", "vertices", 100);
    line.update(10);
  }
  { ProgressLine line(unused, "curving", "vertices", 100); }
  EXPECT_EQ(drawn.str().back(), '\n');
  EXPECT_EQ(unused.str(), "");
}

}  // namespace
}  // namespace hocav
