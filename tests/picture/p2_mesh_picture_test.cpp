#include "picture/p2_mesh_picture.hpp"

#include <gtest/gtest.h>

#include "cases/structured.hpp"
#include "picture/section_picture.hpp"
#include "svg_parse.hpp"

namespace hocav {
namespace {

TEST(P2MeshPicture, EdgesAreQuadraticBeziersThroughTheirMidNodes) {
  P2Element<2> element;
  element.nodes = {Vec2{{0, 0}}, Vec2{{4, 0}}, Vec2{{0, 4}}, Vec2{{2, 1}}, Vec2{{2, 2}}, Vec2{{0, 2}}};
  // Identity-like page map: world [0, 4]² onto page [0, 4]² (y flipped).
  const PageTransform transform({{{0, 0}}, {{4, 4}}}, {{{0, 0}}, {{4, 4}}});
  // Edge 01 with mid node (2, 1): control point 2 (2, 1) − ((0, 0) + (4, 0)) / 2 = (2, 2), page (2, 2).
  // Edge 12 is straight: control (2, 2), page (2, 2). Edge 20: control (0, 2), page (0, 2).
  EXPECT_EQ(p2_triangle_path(element, transform).data(), "M0.00,4.00 Q2.00,2.00 4.00,4.00 Q2.00,2.00 0.00,0.00 Q0.00,2.00 0.00,4.00 Z");
}

TEST(P2MeshPicture, OnePathPerTriangleInEachPanelItShows) {
  Mesh<2> mesh = generate_square(2);  // 8 triangles
  mesh.make_p2();
  const std::vector<double> values(8, 0.5);
  MeshFigureOptions options{"square", "straight", ColorScale{0, 1}, "value", std::nullopt};
  const std::string outline = picture_test::parsed_svg_outline(p2_mesh_picture(mesh, values, options).document());
  EXPECT_NE(outline.find(" path=8 "), std::string::npos) << outline;
  // The detail shows the lower left cell's two triangles: only those are drawn again.
  options.detail = Rect{{{0, 0}}, {{0.4, 0.4}}};
  const std::string with_detail = picture_test::parsed_svg_outline(p2_mesh_picture(mesh, values, options).document());
  EXPECT_NE(with_detail.find(" path=10 "), std::string::npos) << with_detail;
  EXPECT_NE(with_detail.find("clipPath=1"), std::string::npos) << with_detail;
}

TEST(SectionPicture, OnePathPerSection) {
  Mesh<3> mesh = generate_cube(2);
  mesh.make_p2();
  const std::vector<CutCell> cells = cut_p2_mesh(mesh, CutPlane{{{0, 0, 0.3}}}, 4);
  const std::vector<double> values(static_cast<std::size_t>(mesh.element_count()), 1.0);
  const std::string outline = picture_test::parsed_svg_outline(
      section_picture(cells, values, {"cube", "cut", ColorScale{0, 1}, "value", std::nullopt}).document());
  EXPECT_NE(outline.find(" path=" + std::to_string(cells.size()) + " "), std::string::npos) << outline;
  EXPECT_GT(cells.size(), 8u);
}

}  // namespace
}  // namespace hocav
