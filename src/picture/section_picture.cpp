#include "picture/section_picture.hpp"

#include "picture/polyline_simplification.hpp"

namespace hocav {
namespace {

// How far (page units) a drawn outline may stray from the sampled one: a twentieth of a pixel.
constexpr double kPageTolerance = 0.05;

}  // namespace

SvgCanvas section_picture(const std::vector<CutCell>& cells, std::span<const double> element_values, const MeshFigureOptions& options) {
  std::vector<Vec2> all_points;
  for (const CutCell& cell : cells) all_points.insert(all_points.end(), cell.outline.begin(), cell.outline.end());
  return mesh_figure(bounding_rect(all_points), options, [&](SvgCanvas& canvas, const PanelView& view) {
    std::vector<Vec2> page;
    for (const CutCell& cell : cells) {
      if (!view.visible.intersects(bounding_rect(cell.outline))) continue;
      page.clear();
      for (const Vec2& point : cell.outline) page.push_back(view.transform(point));
      canvas.path(SvgPath().polyline(simplified_polyline(page, kPageTolerance, true), true),
                  {options.colors(element_values[cell.element]).hex(), "#1a1a1a", view.line_width});
    }
  });
}

}  // namespace hocav
