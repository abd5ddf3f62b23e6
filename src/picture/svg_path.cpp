#include "picture/svg_path.hpp"

#include <cstdio>

namespace hocav {

void SvgPath::append(char command, std::initializer_list<Vec2> points) {
  if (!data_.empty()) data_ += ' ';
  data_ += command;
  char number[64];
  for (const Vec2& p : points) {
    std::snprintf(number, sizeof number, "%.2f,%.2f", p[0], p[1]);
    data_ += number;
    if (&p != points.end() - 1) data_ += ' ';
  }
}

SvgPath& SvgPath::move_to(const Vec2& point) {
  append('M', {point});
  return *this;
}

SvgPath& SvgPath::line_to(const Vec2& point) {
  append('L', {point});
  return *this;
}

SvgPath& SvgPath::quadratic_to(const Vec2& control, const Vec2& end) {
  append('Q', {control, end});
  return *this;
}

SvgPath& SvgPath::close() {
  append('Z', {});
  return *this;
}

SvgPath& SvgPath::polyline(std::span<const Vec2> points, bool closed) {
  for (std::size_t i = 0; i < points.size(); ++i) i == 0 ? move_to(points[i]) : line_to(points[i]);
  if (closed && !points.empty()) close();
  return *this;
}

}  // namespace hocav
