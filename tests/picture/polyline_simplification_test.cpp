#include "picture/polyline_simplification.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace hocav {
namespace {

TEST(PolylineSimplification, StraightRunsShrinkToTheirEnds) {
  std::vector<Vec2> square;  // the unit square's outline, 8 points a side
  for (int side = 0; side < 4; ++side)
    for (int i = 0; i < 8; ++i) {
      const double t = i / 8.0;
      const Vec2 corners[4] = {{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}};
      square.push_back((1 - t) * corners[side] + t * corners[(side + 1) % 4]);
    }
  EXPECT_EQ(simplified_polyline(square, 1e-9, true), (std::vector<Vec2>{{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}}));
}

TEST(PolylineSimplification, CurvesKeepEnoughPointsToStayWithinTheTolerance) {
  std::vector<Vec2> arc;  // a quarter of the unit circle
  for (int i = 0; i <= 200; ++i) arc.push_back({{std::cos(i * M_PI / 400), std::sin(i * M_PI / 400)}});
  for (double tolerance : {1e-2, 1e-4}) {
    const std::vector<Vec2> kept = simplified_polyline(arc, tolerance, false);
    EXPECT_EQ(kept.front(), arc.front());
    EXPECT_EQ(kept.back(), arc.back());
    EXPECT_LT(kept.size(), arc.size() / 2);
    // Every dropped point lies within the tolerance of the chord that replaces it.
    std::size_t piece = 0;
    for (const Vec2& p : arc) {
      while (std::atan2(kept[piece + 1][1], kept[piece + 1][0]) < std::atan2(p[1], p[0])) ++piece;
      const Vec2 a = kept[piece], chord = kept[piece + 1] - a;
      const double along = std::clamp(dot(p - a, chord) / dot(chord, chord), 0.0, 1.0);
      EXPECT_LE(norm(p - (a + along * chord)), tolerance);
    }
  }
  EXPECT_EQ(simplified_polyline(std::vector<Vec2>{{{0, 0}}, {{1, 1}}}, 1, false).size(), 2u);
}

}  // namespace
}  // namespace hocav
