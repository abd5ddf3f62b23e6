// A histogram as an SVG bar chart: the bins of a ValueSummary (mesh_quality.hpp) over its range,
// with axes, round ticks, labels, and a line of figures (count, min / avg / max, values outside).
#pragma once

#include <optional>
#include <string>

#include "bezier/mesh_quality.hpp"
#include "picture/color_map.hpp"
#include "picture/svg_canvas.hpp"

namespace hocav {

struct HistogramLabels {
  std::string title, x_label, y_label;
  // Bars take the colour of their bin's middle value on this scale (e.g. the one of a mesh
  // picture they go with); one plain colour without it.
  std::optional<ColorScale> bar_colors;
  // Counts on a logarithmic axis (powers of ten), so that bins of a few values in a long tail show.
  bool log_counts = false;
};

SvgCanvas histogram_chart(const ValueSummary& summary, const HistogramLabels& labels);

}  // namespace hocav
