#include "picture/svg_canvas.hpp"

#include <gtest/gtest.h>

#include "svg_parse.hpp"

namespace hocav {
namespace {

TEST(SvgCanvas, WritesAWellFormedDocumentOfWhatWasDrawn) {
  SvgCanvas canvas(200, 100);
  canvas.path(SvgPath().move_to({{0, 0}}).line_to({{10, 0}}).quadratic_to({{15, 5}}, {{10, 10}}).close(), {"#ff0000", "black", 1});
  canvas.begin_clip({{{0, 0}}, {{50, 50}}});
  canvas.rect({{{1, 2}}, {{3, 4}}}, {"blue", "none", 0});
  canvas.end_clip();
  canvas.line({{0, 0}}, {{5, 5}}, {"none", "black", 0.5});
  canvas.text({{10, 20}}, "a < b & \"c\"", {12, "middle", true, -90});
  canvas.path(SvgPath(), {});  // nothing to draw: no element
  // The root holds the background rect, the clip rect and its clipPath, the group, and the rest.
  EXPECT_EQ(picture_test::parsed_svg_outline(canvas.document()), "svg clipPath=1 defs=1 g=1 line=1 path=1 rect=3 text=1");
  const std::string document = canvas.document();
  EXPECT_NE(document.find("d=\"M0.00,0.00 L10.00,0.00 Q15.00,5.00 10.00,10.00 Z\""), std::string::npos) << document;
  EXPECT_NE(document.find(">a &lt; b &amp; &quot;c&quot;</text>"), std::string::npos) << document;
  EXPECT_NE(document.find("width=\"200.00\" height=\"100.00\""), std::string::npos);
}

TEST(SvgPath, PolylineClosesOnlyWhenAsked) {
  const std::vector<Vec2> points{{{0, 0}}, {{1, 0}}, {{1, 1}}};
  EXPECT_EQ(SvgPath().polyline(points, true).data(), "M0.00,0.00 L1.00,0.00 L1.00,1.00 Z");
  EXPECT_EQ(SvgPath().polyline(points, false).data(), "M0.00,0.00 L1.00,0.00 L1.00,1.00");
  EXPECT_TRUE(SvgPath().polyline({}, true).empty());
}

}  // namespace
}  // namespace hocav
