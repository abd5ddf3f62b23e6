#include "picture/axis_ticks.hpp"

#include <gtest/gtest.h>

namespace hocav {
namespace {

TEST(AxisTicks, RoundStepsCoverTheRange) {
  EXPECT_EQ(round_ticks(0, 1, 5), (std::vector<double>{0, 0.2, 0.4, 0.6000000000000001, 0.8, 1}));
  EXPECT_EQ(round_ticks(0, 1234, 5), (std::vector<double>{0, 200, 400, 600, 800, 1000, 1200}));
  EXPECT_EQ(round_ticks(-0.03, 0.26, 4), (std::vector<double>{0, 0.1, 0.2}));
  EXPECT_EQ(round_ticks(0, 2, 5), (std::vector<double>{0, 0.5, 1, 1.5, 2}));
  EXPECT_EQ(round_ticks(2, 2, 5), (std::vector<double>{2}));
  EXPECT_TRUE(round_ticks(1, 0, 5).empty());
}

TEST(AxisTicks, LabelsAreShort) {
  EXPECT_EQ(tick_label(0.6000000000000001), "0.6");
  EXPECT_EQ(tick_label(1200), "1200");
  EXPECT_EQ(tick_label(-1e-17), "0");
  EXPECT_EQ(tick_label(2.5e-5), "2.5e-05");
}

}  // namespace
}  // namespace hocav
