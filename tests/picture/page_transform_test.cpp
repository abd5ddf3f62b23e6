#include "picture/page_transform.hpp"

#include <gtest/gtest.h>

namespace hocav {
namespace {

TEST(PageTransform, FitsTheWorldUniformlyCentredAndFlipsY) {
  // A 4 x 1 world into a 100 x 100 page: the width limits the scale to 25.
  const PageTransform transform({{{-2, 0}}, {{2, 1}}}, {{{0, 0}}, {{100, 100}}});
  EXPECT_DOUBLE_EQ(transform.scale(), 25);
  const Vec2 center = transform({{0, 0.5}});
  EXPECT_DOUBLE_EQ(center[0], 50);
  EXPECT_DOUBLE_EQ(center[1], 50);
  const Vec2 top_right = transform({{2, 1}});  // world y up is page y down
  EXPECT_DOUBLE_EQ(top_right[0], 100);
  EXPECT_DOUBLE_EQ(top_right[1], 37.5);
  const Vec2 bottom_left = transform({{-2, 0}});
  EXPECT_DOUBLE_EQ(bottom_left[0], 0);
  EXPECT_DOUBLE_EQ(bottom_left[1], 62.5);
}

TEST(PageTransform, TallWorldIsLimitedByItsHeight) {
  const PageTransform transform({{{0, 0}}, {{1, 10}}}, {{{10, 20}}, {{110, 70}}});
  EXPECT_DOUBLE_EQ(transform.scale(), 5);
  const Vec2 corner = transform({{1, 10}});
  EXPECT_DOUBLE_EQ(corner[0], 62.5);
  EXPECT_DOUBLE_EQ(corner[1], 20);
}

TEST(PageTransform, BoundingBoxHoldsEveryPoint) {
  const std::vector<Vec2> points{{{1, -2}}, {{-3, 4}}, {{0.5, 0.5}}};
  const Rect box = bounding_rect(points);
  EXPECT_EQ(box.lower, (Vec2{{-3, -2}}));
  EXPECT_EQ(box.upper, (Vec2{{1, 4}}));
  for (const Vec2& p : points) EXPECT_TRUE(box.contains(p));
  EXPECT_FALSE(box.contains({{1.5, 0}}));
}

}  // namespace
}  // namespace hocav
