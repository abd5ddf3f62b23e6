#include "picture/histogram_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "picture/axis_ticks.hpp"

namespace hocav {
namespace {

constexpr double kWidth = 720, kHeight = 440;
// The plot area: room on the left for the count labels, below for the value labels.
constexpr Rect kPlot{{{90, 60}}, {{kWidth - 30, kHeight - 90}}};
const ShapeStyle kAxisStyle{"none", "#444444", 1};

std::string figures_line(const ValueSummary& summary) {
  char text[200];
  std::snprintf(text, sizeof text, "%lld values, min %.3g, avg %.3g, max %.3g", static_cast<long long>(summary.count), summary.min,
                summary.average, summary.max);
  std::string line = text;
  if (summary.below > 0) line += ", " + std::to_string(summary.below) + " below " + tick_label(summary.histogram_lower);
  if (summary.above > 0) line += ", " + std::to_string(summary.above) + " above " + tick_label(summary.histogram_upper);
  return line;
}

// Count ticks from 0 (linear) or 1 (powers of ten) to the first tick at or above `tallest`.
std::vector<double> count_axis_ticks(double tallest, bool logarithmic) {
  std::vector<double> ticks;
  if (logarithmic) {
    for (double tick = 1; ticks.empty() || ticks.back() < tallest; tick *= 10) ticks.push_back(tick);
    return ticks;
  }
  ticks = round_ticks(0, tallest, 5);
  if (ticks.back() < tallest) ticks.push_back(ticks.back() + (ticks[1] - ticks[0]));
  std::erase_if(ticks, [](double tick) { return tick != std::floor(tick); });  // counts are whole
  return ticks;
}

}  // namespace

SvgCanvas histogram_chart(const ValueSummary& summary, const HistogramLabels& labels) {
  SvgCanvas canvas(kWidth, kHeight);
  canvas.text({{kWidth / 2, 30}}, labels.title, {18, "middle", true});

  const double lower = summary.histogram_lower, upper = summary.histogram_upper;
  const Index tallest = summary.histogram.empty() ? 0 : *std::max_element(summary.histogram.begin(), summary.histogram.end());
  const std::vector<double> count_ticks = count_axis_ticks(static_cast<double>(std::max<Index>(tallest, 1)), labels.log_counts);
  // Bar heights: linear from 0, or logarithmic from half a value (a bin of one value still shows).
  auto height = [&](double count) { return labels.log_counts ? std::log10(std::max(count, 0.5) / 0.5) : count; };
  const double count_top = height(count_ticks.back());
  auto page_x = [&](double value) { return kPlot.lower[0] + (value - lower) / (upper - lower) * kPlot.width(); };
  auto page_y = [&](double count) { return kPlot.upper[1] - height(count) / count_top * kPlot.height(); };

  for (double tick : count_ticks)  // grid lines behind the bars
    canvas.line({{kPlot.lower[0], page_y(tick)}}, {{kPlot.upper[0], page_y(tick)}}, {"none", "#dddddd", 0.6});
  const auto bins = static_cast<double>(summary.histogram.size());
  for (std::size_t bin = 0; bin < summary.histogram.size(); ++bin) {
    const double from = lower + (upper - lower) * static_cast<double>(bin) / bins;
    const double to = lower + (upper - lower) * static_cast<double>(bin + 1) / bins;
    const std::string color = labels.bar_colors ? (*labels.bar_colors)(0.5 * (from + to)).hex() : "#3b528b";
    canvas.rect({{{page_x(from), page_y(static_cast<double>(summary.histogram[bin]))}}, {{page_x(to), kPlot.upper[1]}}},
                {color, "white", 0.6});
  }

  canvas.line(kPlot.lower, {{kPlot.lower[0], kPlot.upper[1]}}, kAxisStyle);
  canvas.line({{kPlot.lower[0], kPlot.upper[1]}}, kPlot.upper, kAxisStyle);
  for (double tick : count_ticks) {
    const double y = page_y(tick);
    canvas.line({{kPlot.lower[0] - 5, y}}, {{kPlot.lower[0], y}}, kAxisStyle);
    canvas.text({{kPlot.lower[0] - 8, y + 4.5}}, tick_label(tick), {13, "end"});
  }
  for (double tick : round_ticks(lower, upper, 8)) {
    const double x = page_x(tick);
    canvas.line({{x, kPlot.upper[1]}}, {{x, kPlot.upper[1] + 5}}, kAxisStyle);
    canvas.text({{x, kPlot.upper[1] + 20}}, tick_label(tick), {13, "middle"});
  }
  canvas.text({{(kPlot.lower[0] + kPlot.upper[0]) / 2, kPlot.upper[1] + 44}}, labels.x_label, {15, "middle"});
  canvas.text({{28, (kPlot.lower[1] + kPlot.upper[1]) / 2}}, labels.y_label, {15, "middle", false, -90});
  canvas.text({{(kPlot.lower[0] + kPlot.upper[0]) / 2, kHeight - 18}}, figures_line(summary), {13, "middle", false, 0, "#555555"});
  return canvas;
}

}  // namespace hocav
