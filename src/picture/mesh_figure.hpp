// The frame of a mesh picture: a title, the mesh's extent drawn in a square panel, an optional
// enlarged view of a detail beside it (its box outlined in the main panel), and a colour bar for
// the values the cells are filled by. What is drawn in the panels comes from the caller, in world
// coordinates through the panel's transform.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "picture/color_map.hpp"
#include "picture/svg_canvas.hpp"

namespace hocav {

struct MeshFigureOptions {
  std::string title, subtitle;
  ColorScale colors;
  std::string color_title;
  std::optional<Rect> detail;  // world box of the enlarged view
};

// One panel: where the world lands on the page, the part of the world it shows (what lies outside
// needs not be drawn), and the stroke width of a cell edge there (page units).
struct PanelView {
  PageTransform transform;
  Rect visible;
  double line_width = 1;
};

// Draws the world content of a panel.
using PanelDrawing = std::function<void(SvgCanvas& canvas, const PanelView& view)>;

SvgCanvas mesh_figure(const Rect& world, const MeshFigureOptions& options, const PanelDrawing& draw);

}  // namespace hocav
