#include "picture/color_map.hpp"

#include <gtest/gtest.h>

namespace hocav {
namespace {

TEST(ColorMap, ViridisRunsFromPurpleToYellowAndClamps) {
  EXPECT_EQ(viridis(0).hex(), "#440154");
  EXPECT_EQ(viridis(0.5).hex(), "#21908c");
  EXPECT_EQ(viridis(1).hex(), "#fde725");
  EXPECT_EQ(viridis(-3).hex(), "#440154");
  EXPECT_EQ(viridis(7).hex(), "#fde725");
  // Lightness grows along the map (what makes it readable in grey).
  double previous = -1;
  for (int i = 0; i <= 20; ++i) {
    const Color c = viridis(i / 20.0);
    const double luma = 0.299 * c.red + 0.587 * c.green + 0.114 * c.blue;
    EXPECT_GT(luma, previous) << i;
    previous = luma;
  }
}

TEST(ColorMap, ScaleMapsItsRangeOntoTheMap) {
  const ColorScale scale{0.5, 1.5};
  EXPECT_DOUBLE_EQ(scale.fraction(1), 0.5);
  EXPECT_DOUBLE_EQ(scale.fraction(0), 0);
  EXPECT_DOUBLE_EQ(scale.fraction(2), 1);
  EXPECT_EQ(scale(1).hex(), viridis(0.5).hex());
}

}  // namespace
}  // namespace hocav
