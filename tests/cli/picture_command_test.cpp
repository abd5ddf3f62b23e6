// End-to-end tests of `hocav picture`: a 2D mesh drawn whole (one filled path per triangle, curved
// edges as quadratic Bézier pieces), a 3D mesh by a cut (one path per section, the enlarged detail
// clipped), the title and subtitle, and the requests that mean nothing refused with no output.
#include <gtest/gtest.h>

#include "../picture/svg_parse.hpp"
#include "cli_test_support.hpp"

namespace hocav::cli_test {
namespace {

using PictureCli = Cli;
using picture_test::element_count;

// The outline of the first filled path of a document.
std::string first_path(const std::string& svg) {
  const std::size_t start = svg.find("<path d=\"");
  return start == std::string::npos ? "" : svg.substr(start, svg.find('"', start + 9) - start);
}

TEST_F(PictureCli, DrawsA2DMeshWholeOnePathPerTriangle) {
  run_ok("generate square --h 0.25 -o square.mesh");
  const Outcome done = run_ok("picture square.mesh -o square.svg");
  EXPECT_NE(done.out.find("wrote square.svg"), std::string::npos) << done.out;
  const std::string svg = read("square.svg");
  EXPECT_EQ(element_count(picture_test::parsed_svg_outline(svg), "path"),
            std::stoi(stats_json("square.mesh", "d[\"counts\"][\"elements\"]")));
  EXPECT_NE(svg.find(">square.mesh<"), std::string::npos) << "the default title is the file name";
  EXPECT_NE(svg.find("2D P1: 25 vertices"), std::string::npos) << "the subtitle sums the mesh up";
  write("curved.mesh", kShuffledP2Triangle);
  run_ok("convert curved.mesh straight.mesh --order 1");
  run_ok("picture curved.mesh -o curved.svg --title 'one triangle'");
  run_ok("picture straight.mesh -o straight.svg --title 'one triangle'");
  const std::string curved = read("curved.svg");
  EXPECT_NE(curved.find(" Q"), std::string::npos) << "edges are quadratic Bézier pieces";
  EXPECT_NE(curved.find(">one triangle<"), std::string::npos);
  EXPECT_NE(first_path(curved), first_path(read("straight.svg"))) << "the curved edge is drawn curved";
}

TEST_F(PictureCli, DrawsA3DMeshByACut) {
  run_ok("generate cube --h 0.25 -o cube.meshb");
  expect_failure("picture cube.meshb -o z.svg", "--cut z=0: the cut plane meets no element");  // the default: a face of the cube
  run_ok("picture cube.meshb -o z.svg --cut z=0.6");
  run_ok("picture cube.meshb -o x.svg --cut x=0.4 --detail 0.2 0.2 0.5 0.5");
  const std::string z = read("z.svg"), x = read("x.svg");
  EXPECT_NE(z.find(">cube.meshb, cut by the plane z=0.6<"), std::string::npos);
  EXPECT_NE(x.find(">cube.meshb, cut by the plane x=0.4<"), std::string::npos);
  const std::string z_outline = picture_test::parsed_svg_outline(z), x_outline = picture_test::parsed_svg_outline(x);
  // Both planes cross the 4 × 4 cells of the cube, each in two triangles or more.
  EXPECT_GE(element_count(z_outline, "path"), 32) << z_outline;
  EXPECT_GE(element_count(x_outline, "path"), 32) << x_outline;
  EXPECT_EQ(element_count(z_outline, "clipPath"), 0) << z_outline;
  EXPECT_EQ(element_count(x_outline, "clipPath"), 1) << "the enlarged detail: " << x_outline;
}

TEST_F(PictureCli, MeaninglessRequestsFailAndWriteNothing) {
  run_ok("generate cube --h 0.5 -o cube.meshb");
  run_ok("generate square --h 0.5 -o square.mesh");
  for (const char* cut : {"w=1", "z=nan", "z", "z=1x", "z=inf", "=1"})
    expect_failure(std::string("picture cube.meshb -o o.svg --cut ") + cut, "--cut");
  expect_failure("picture cube.meshb -o o.svg --cut z=5", "meets no element");
  expect_failure("picture square.mesh -o o.svg --cut z=0", "2D");
  expect_failure("picture cube.meshb -o o.svg --detail 1 0 0 1", "--detail");
  expect_failure("picture cube.meshb -o o.png", "o.png");
  expect_failure("picture missing.meshb -o o.svg", "missing.meshb");
  EXPECT_EQ(files(), (std::set<std::string>{"cube.meshb", "square.mesh"}));
}

}  // namespace
}  // namespace hocav::cli_test
