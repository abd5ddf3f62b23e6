#include "picture/mesh_figure.hpp"

#include <cstdio>

#include "picture/color_bar.hpp"

namespace hocav {
namespace {

constexpr double kPanel = 540, kMargin = 24, kTop = 78, kLegend = 120;
const ShapeStyle kDetailStyle{"none", "#d62728", 1.6};

Rect panel_box(int column) {
  const double left = kMargin + column * (kPanel + kMargin);
  return {{{left, kTop}}, {{left + kPanel, kTop + kPanel}}};
}

}  // namespace

SvgCanvas mesh_figure(const Rect& world, const MeshFigureOptions& options, const PanelDrawing& draw) {
  const int panels = options.detail ? 2 : 1;
  SvgCanvas canvas(kMargin + panels * (kPanel + kMargin) + kLegend, kTop + kPanel + kMargin);
  canvas.text({{kMargin, 32}}, options.title, {20, "start", true});
  canvas.text({{kMargin, 56}}, options.subtitle, {14, "start", false, 0, "#555555"});

  const Rect main = panel_box(0);
  const PageTransform whole(world, {main.lower + Vec2{{6, 6}}, main.upper - Vec2{{6, 6}}});
  draw(canvas, {whole, world, 0.35});
  if (options.detail) {
    canvas.rect(
        {whole({{options.detail->lower[0], options.detail->upper[1]}}), whole({{options.detail->upper[0], options.detail->lower[1]}})},
        kDetailStyle);
    const Rect side = panel_box(1);
    const PageTransform enlarged(*options.detail, side);
    canvas.begin_clip(side);
    draw(canvas, {enlarged, *options.detail, 0.9});
    canvas.end_clip();
    canvas.rect(side, kDetailStyle);
    char zoom[64];
    std::snprintf(zoom, sizeof zoom, "detail (red box), enlarged %.0f times", enlarged.scale() / whole.scale());
    canvas.text({{side.lower[0], side.lower[1] - 8}}, zoom, {13, "start", false, 0, "#d62728"});
  }
  const double bar_left = kMargin + panels * (kPanel + kMargin) + 14;
  draw_color_bar(canvas, {{{bar_left, kTop + 60}}, {{bar_left + 24, kTop + kPanel - 60}}}, options.colors, options.color_title);
  return canvas;
}

}  // namespace hocav
