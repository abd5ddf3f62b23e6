#include "picture/color_bar.hpp"

#include "picture/axis_ticks.hpp"

namespace hocav {

void draw_color_bar(SvgCanvas& canvas, const Rect& bar, const ColorScale& scale, std::string_view title) {
  constexpr int kSteps = 64;  // bands, each a shade: fine enough to look continuous
  const double band = bar.height() / kSteps;
  for (int step = 0; step < kSteps; ++step) {
    const double value = scale.lower + (scale.upper - scale.lower) * (step + 0.5) / kSteps;
    const double top = bar.upper[1] - (step + 1) * band;
    // Each band overlaps the next by a little so no hairline of background shows between them.
    canvas.rect({{{bar.lower[0], top - 0.3}}, {{bar.upper[0], top + band}}}, {scale(value).hex(), "none", 0});
  }
  canvas.rect(bar, {"none", "#444444", 0.8});
  for (double tick : round_ticks(scale.lower, scale.upper, 5)) {
    const double y = bar.upper[1] - scale.fraction(tick) * bar.height();
    canvas.line({{bar.upper[0], y}}, {{bar.upper[0] + 5, y}}, {"none", "#444444", 0.8});
    canvas.text({{bar.upper[0] + 8, y + 4.5}}, tick_label(tick), {13, "start"});
  }
  canvas.text({{bar.upper[0] + 56, 0.5 * (bar.lower[1] + bar.upper[1])}}, title, {14, "middle", false, -90});
}

}  // namespace hocav
