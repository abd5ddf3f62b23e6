// End-to-end test of `hocav demo` on a coarse sphere shell: every file is written, the mesh reads
// back as a valid P2 mesh, the report's figures hold, and the pictures are well-formed SVG.
#include <gtest/gtest.h>

#include "../picture/svg_parse.hpp"
#include "cli_test_support.hpp"

namespace hocav::cli_test {
namespace {

using DemoCli = Cli;
using picture_test::element_count;

TEST_F(DemoCli, WritesTheCurvedMeshTheReportAndThePictures) {
  HOCAV_SKIP_WITHOUT_GMSH();
  Outcome demo = run_ok("demo --h 0.4 --threads 2 -o results");
  const std::vector<std::string> names{"sphere-shell-p2.meshb", "sphere-shell-p2.vtu", "sphere-shell-report.json", "sphere-shell-cut.svg",
                                       "shear-circle-p2.svg",   "edge-gains.svg",      "normalized-jacobians.svg"};
  for (const std::string& name : names) {
    EXPECT_TRUE(fs::is_regular_file(path("results/" + name))) << name;
    EXPECT_NE(demo.out.find("results/" + name), std::string::npos) << "not listed: " << name << "\n" << demo.out;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(path("results")), fs::directory_iterator()), 7);
  for (const char* row : {"tetrahedra", "normalized Jacobian min/avg/max", "gain avg / max", "edges optimized per second"})
    EXPECT_NE(demo.out.find(row), std::string::npos) << row;
  EXPECT_NE(demo.err.find("demo: adapting: pass 1"), std::string::npos) << "no progress on stderr: " << demo.err;

  EXPECT_EQ(stats_json("results/sphere-shell-p2.meshb", "d[\"consistency\"][\"consistent\"], d[\"order\"], d[\"dimension\"]"),
            "(True, 2, 3)");
  const std::string report = "results/sphere-shell-report.json";
  EXPECT_EQ(json_value(report, "d[\"curving\"][\"normalized_jacobian\"][\"invalid\"]"), "0");
  EXPECT_GE(std::stod(json_value(report, "d[\"curving\"][\"normalized_jacobian\"][\"min\"]")), 0.01 - 1e-12);
  EXPECT_GT(std::stod(json_value(report, "d[\"curving\"][\"max_gain\"]")), 0);
  // The pipeline adapts first: a unit mesh of the surface metric, far finer than the input.
  EXPECT_GE(std::stod(json_value(report, "d[\"edge_length\"][\"unit_share\"]")), 0.85);
  EXPECT_GT(std::stod(json_value(report, "d[\"output_elements\"]")), 3 * std::stod(json_value(report, "d[\"input_elements\"]")));

  // The cut: one filled section per cut element, a colour bar. The 2D mesh: curved edges as
  // quadratic Bézier pieces. The histograms: bars over axes.
  const std::string cut = picture_test::parsed_svg_outline(read("results/sphere-shell-cut.svg"));
  EXPECT_GT(element_count(cut, "path"), 100) << cut;
  EXPECT_EQ(element_count(cut, "clipPath"), 1) << cut;  // the enlarged detail
  const std::string shear_circle_svg = read("results/shear-circle-p2.svg");
  EXPECT_GT(element_count(picture_test::parsed_svg_outline(shear_circle_svg), "path"), 1000);
  EXPECT_NE(shear_circle_svg.find(" Q"), std::string::npos);
  for (const char* histogram : {"results/edge-gains.svg", "results/normalized-jacobians.svg"})
    EXPECT_GE(element_count(picture_test::parsed_svg_outline(read(histogram)), "rect"), 20) << histogram;
}

TEST_F(DemoCli, BadOptionsFailAndWriteNothing) {
  // Command-line mistakes: the parser's message names the option (and a line pointing to --help).
  for (const char* option : {"--h 0", "--threads 0"}) {
    Outcome bad = run(std::string("demo ") + option);
    EXPECT_EQ(bad.exit_code, 2) << option;
    EXPECT_NE(bad.err.find(std::string(option).substr(0, std::string(option).find(' '))), std::string::npos) << bad.err;
  }
  write("taken", "a file, not a folder");
  expect_failure("demo --h 0.4 -o taken", "taken");
  EXPECT_EQ(files(), (std::set<std::string>{"taken"}));
  Outcome help = run_ok("demo --help");
  for (const char* option : {"--output", "--threads", "--h"}) EXPECT_NE(help.out.find(option), std::string::npos) << option;
}

}  // namespace
}  // namespace hocav::cli_test
