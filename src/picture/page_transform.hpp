// Where a picture's world (mesh coordinates, y up) lands on an SVG page (y down): a world box scaled
// uniformly to fit a page box and centred in it, so circles stay circles.
#pragma once

#include <span>

#include "geom/vec.hpp"

namespace hocav {

// An axis-aligned rectangle of the plane: a picture's box in the world or its area on the page.
struct Rect {
  Vec2 lower, upper;  // lower.x ≤ upper.x, lower.y ≤ upper.y

  double width() const { return upper[0] - lower[0]; }
  double height() const { return upper[1] - lower[1]; }
  bool contains(const Vec2& p) const { return p[0] >= lower[0] && p[0] <= upper[0] && p[1] >= lower[1] && p[1] <= upper[1]; }
  bool intersects(const Rect& other) const {
    return other.lower[0] <= upper[0] && lower[0] <= other.upper[0] && other.lower[1] <= upper[1] && lower[1] <= other.upper[1];
  }
};

// The smallest box holding every point (a box at the origin for none).
Rect bounding_rect(std::span<const Vec2> points);

class PageTransform {
 public:
  // `world` must have a positive width or height; `page` is in page units (its lower corner is the
  // top left of the page area).
  PageTransform(const Rect& world, const Rect& page);

  Vec2 operator()(const Vec2& world) const;
  // Page units per world unit.
  double scale() const { return scale_; }

 private:
  Vec2 world_center_, page_center_;
  double scale_ = 1;
};

}  // namespace hocav
