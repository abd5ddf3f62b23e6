// The outline of an SVG <path>: straight and quadratic Bézier pieces in page coordinates, written
// with two decimals (a hundredth of a page unit is far below what a screen or a printer shows).
#pragma once

#include <span>
#include <string>

#include "geom/vec.hpp"

namespace hocav {

class SvgPath {
 public:
  SvgPath& move_to(const Vec2& point);
  SvgPath& line_to(const Vec2& point);
  // A quadratic Bézier piece from the current point to `end`, pulled toward `control`.
  SvgPath& quadratic_to(const Vec2& control, const Vec2& end);
  SvgPath& close();
  // move_to the first point, line_to the others, and close() when `closed`.
  SvgPath& polyline(std::span<const Vec2> points, bool closed);

  bool empty() const { return data_.empty(); }
  const std::string& data() const { return data_; }

 private:
  void append(char command, std::initializer_list<Vec2> points);

  std::string data_;
};

}  // namespace hocav
