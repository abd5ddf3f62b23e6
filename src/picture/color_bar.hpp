// The legend of a colour scale: a vertical bar of its colours, round values marked on its right
// and a title beside them (about 70 page units right of the bar in all).
#pragma once

#include <string_view>

#include "picture/color_map.hpp"
#include "picture/svg_canvas.hpp"

namespace hocav {

// Draws the bar in `bar` (page units): `scale.upper` at the top, `scale.lower` at the bottom.
void draw_color_bar(SvgCanvas& canvas, const Rect& bar, const ColorScale& scale, std::string_view title);

}  // namespace hocav
