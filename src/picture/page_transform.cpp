#include "picture/page_transform.hpp"

#include <algorithm>

#include "base/error.hpp"

namespace hocav {

Rect bounding_rect(std::span<const Vec2> points) {
  if (points.empty()) return {};
  Rect box{points.front(), points.front()};
  for (const Vec2& p : points)
    for (int i = 0; i < 2; ++i) {
      box.lower[i] = std::min(box.lower[i], p[i]);
      box.upper[i] = std::max(box.upper[i], p[i]);
    }
  return box;
}

PageTransform::PageTransform(const Rect& world, const Rect& page)
    : world_center_(0.5 * (world.lower + world.upper)), page_center_(0.5 * (page.lower + page.upper)) {
  if (!(world.width() > 0 || world.height() > 0)) throw Error("internal error: a picture of an empty world box");
  scale_ = std::min(world.width() > 0 ? page.width() / world.width() : page.height() / world.height(),
                    world.height() > 0 ? page.height() / world.height() : page.width() / world.width());
}

Vec2 PageTransform::operator()(const Vec2& world) const {
  const Vec2 offset = world - world_center_;
  return {{page_center_[0] + scale_ * offset[0], page_center_[1] - scale_ * offset[1]}};
}

}  // namespace hocav
