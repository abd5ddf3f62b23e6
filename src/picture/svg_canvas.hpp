// An SVG document being drawn: shapes and text in page units (y down), optionally clipped to a box,
// written out as one self-contained SVG 1.1 file (no scripts, no external resources).
#pragma once

#include <sstream>
#include <string>
#include <string_view>

#include "picture/page_transform.hpp"
#include "picture/svg_path.hpp"

namespace hocav {

struct ShapeStyle {
  std::string fill = "none";  // an SVG colour, e.g. "#21908c", or "none"
  std::string stroke = "none";
  double stroke_width = 1;
};

struct TextStyle {
  double size = 14;
  std::string anchor = "start";  // start, middle, end: where `at` is along the text
  bool bold = false;
  double rotation = 0;  // degrees, clockwise, about `at` (−90: reads bottom to top)
  std::string fill = "#222222";
};

class SvgCanvas {
 public:
  SvgCanvas(double width, double height);

  double width() const { return width_; }
  double height() const { return height_; }

  void path(const SvgPath& path, const ShapeStyle& style);
  void rect(const Rect& box, const ShapeStyle& style);
  void line(const Vec2& from, const Vec2& to, const ShapeStyle& style);
  // `text` is escaped for XML (xml_escape.hpp).
  void text(const Vec2& at, std::string_view text, const TextStyle& style);
  // What is drawn until end_clip() shows only inside `box`.
  void begin_clip(const Rect& box);
  void end_clip();

  // The complete document.
  std::string document() const;

 private:
  double width_, height_;
  int clips_ = 0;
  std::ostringstream definitions_, body_;
};

// Writes the canvas to `path` whole or not at all (atomic_output.hpp). Throws Error.
void write_svg(const std::string& path, const SvgCanvas& canvas);

}  // namespace hocav
