#include "picture/histogram_chart.hpp"

#include <gtest/gtest.h>

#include "svg_parse.hpp"

namespace hocav {
namespace {

TEST(HistogramChart, OneBarPerBinWithAxesAndLabels) {
  const std::vector<double> values{0.1, 0.1, 0.35, 0.9, 1.2};
  const ValueSummary summary = summarize_values(values, 4, 0, 1);
  const SvgCanvas chart = histogram_chart(summary, {"Title", "value", "count", ColorScale{0, 1}});
  const std::string document = chart.document();
  // Background + 4 bars; lines: 2 axes, 3 count ticks (0, 1, 2) with grid lines, 11 value ticks
  // (0, 0.1, ..., 1); texts: title, 2 axis labels, figures, 3 + 11 tick labels.
  EXPECT_EQ(picture_test::parsed_svg_outline(document), "svg defs=1 line=19 rect=5 text=18");
  for (const char* text : {">Title<", ">value<", ">count<", "5 values, min 0.1, avg 0.53, max 1.2, 1 above 1<"})
    EXPECT_NE(document.find(text), std::string::npos) << text;
  // The tallest bar (2 values in [0, 0.25)) reaches the top tick, coloured as its bin's middle.
  EXPECT_NE(document.find("fill=\"" + viridis(0.125).hex() + "\""), std::string::npos);
}

}  // namespace
}  // namespace hocav
