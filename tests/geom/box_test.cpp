#include "geom/box.hpp"

#include <gtest/gtest.h>

namespace hocav {
namespace {

// The union of boxes, an empty one among them (a process whose piece has no vertex): the others'
// bound, not an infinite box.
TEST(Box, AnEmptyBoxAddsNothingToAUnion) {
  Box<3> some = Box<3>::empty();
  some.add(Vec3{{0, 1, 2}});
  some.add(Vec3{{1, -1, 3}});
  Box<3> whole = Box<3>::empty();
  whole.add(Box<3>::empty());
  EXPECT_TRUE(whole.is_empty());
  whole.add(some);
  whole.add(Box<3>::empty());
  EXPECT_EQ(whole.lower, (Vec3{{0, -1, 2}}));
  EXPECT_EQ(whole.upper, (Vec3{{1, 1, 3}}));
  Box<3> other = Box<3>::empty();
  other.add(Vec3{{-2, 0, 0}});
  whole.add(other);
  EXPECT_EQ(whole.lower, (Vec3{{-2, -1, 0}}));
  EXPECT_EQ(whole.upper, (Vec3{{1, 1, 3}}));
}

}  // namespace
}  // namespace hocav
