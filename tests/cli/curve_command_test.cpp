// End-to-end tests of `hocav curve`: generated cases with a shear metric, curved with the P3
// surrogate of their boundary; every element certified, gains positive, the output reads back.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_test_support.hpp"

namespace hocav::cli_test {
namespace {

class CurveCli : public Cli {
 protected:
  double report_value(const std::string& expression) const { return std::stod(json_value("report.json", expression)); }

  // Curves MESH in METRIC with the P3 surrogate and checks what every run must give.
  void curve_and_check(const std::string& mesh, const std::string& metric, const std::string& extra = "") {
    run_ok("curve " + mesh + " --metric " + metric + " --surface p3 -o curved.meshb --report report.json -q " + extra);
    EXPECT_EQ(report_value("d[\"cavities\"][\"tried\"] - d[\"cavities\"][\"accepted\"]"), 0);
    EXPECT_GT(report_value("d[\"normalized_jacobian\"][\"min\"]"), 0.01);  // the default floor, on every element
    EXPECT_EQ(report_value("d[\"normalized_jacobian\"][\"invalid\"]"), 0);
    EXPECT_GT(report_value("d[\"average_gain\"]"), 0);
    EXPECT_GT(report_value("d[\"max_gain\"]"), 0.02);
    EXPECT_GT(report_value("d[\"cavities\"][\"boundary_nodes_applied\"]"), 0);
    // A proposal stays only when the Jacobian floor held its node back, in the cavities and in the
    // last pass over the proposals they left (docs/curving.md): a few, never many.
    EXPECT_LE(report_value("d[\"boundary_proposals_left\"]"), 0.01 * report_value("d[\"cavities\"][\"boundary_nodes_applied\"]"));
    EXPECT_EQ(report_value("d[\"boundary_proposals_left\"]"),
              report_value("d[\"boundary_completion\"][\"pulled_back\"] + d[\"boundary_completion\"][\"blocked\"]"));
    // Work not redone: an edge recreated at its optimum keeps it, so there is about one optimization
    // per edge (points after − points before), and unchanged recreated elements keep their certificates.
    EXPECT_GT(report_value("d[\"cavities\"][\"edges_kept_optimal\"]"), 0);
    EXPECT_LE(report_value("d[\"cavities\"][\"edges_optimized\"]"), 1.1 * report_value("d[\"points_after\"] - d[\"points_before\"]"));
    EXPECT_GT(report_value("d[\"cavities\"][\"certificates_kept\"]"), 0);
    // The output reads back as a consistent P2 mesh.
    EXPECT_EQ(stats_json("curved.meshb", "d[\"consistency\"][\"consistent\"], d[\"order\"]"), "(True, 2)");
  }
};

// A mesh given without its boundary facets gets facets of ref 0 on its open faces, with a warning,
// and curves as with them (the same Jacobian figures); before, that boundary stayed straight.
TEST_F(CurveCli, AMeshWithoutItsFacetsGetsThemAndCurvesItsBoundary) {
  run_ok("generate polar-annulus --target-triangles 400 -o whole.mesh");
  write("bare.mesh", without_block(read("whole.mesh"), "Edges"));
  run_ok("metric whole.mesh --analytic shear-circle -o metric.sol");
  run_ok("curve whole.mesh --metric metric.sol -o whole_curved.meshb --report whole.json -q");
  const auto bare = run("curve bare.mesh --metric metric.sol -o bare_curved.meshb --report report.json");
  ASSERT_EQ(bare.exit_code, 0) << bare.err;
  EXPECT_NE(bare.err.find("bare.mesh: "), std::string::npos) << bare.err;
  EXPECT_NE(bare.err.find(" boundary faces had no facet: facets of ref 0 made for them"), std::string::npos) << bare.err;
  EXPECT_GT(report_value("d[\"cavities\"][\"boundary_nodes_applied\"]"), 0);
  const std::string jacobian = "d[\"normalized_jacobian\"][\"min\"], d[\"normalized_jacobian\"][\"avg\"]";
  EXPECT_EQ(json_value("report.json", jacobian), json_value("whole.json", jacobian));
}

TEST_F(CurveCli, AnnulusInACircularShearLayer) {
  HOCAV_SKIP_WITHOUT_GMSH();
  run_ok("generate annulus --h 0.05 -o annulus.meshb");
  run_ok("metric annulus.meshb --analytic shear-circle --radius 0.75 --width 0.05 --h-min 0.005 --h-max 0.05 -o annulus.solb");
  curve_and_check("annulus.meshb", "annulus.solb");
}

TEST_F(CurveCli, SphereShellInASphericalShearLayerOnTwoThreads) {
  HOCAV_SKIP_WITHOUT_GMSH();
  run_ok("generate sphere-shell --h 0.2 -o shell.meshb");
  run_ok("metric shell.meshb --analytic shear-sphere --radius 0.75 --width 0.1 --h-min 0.02 --h-max 0.2 -o shell.solb");
  curve_and_check("shell.meshb", "shell.solb", "--threads 2");
  // The thread count changes nothing.
  run_ok("curve shell.meshb --metric shell.solb -o one-thread.meshb -q --threads 1");
  EXPECT_EQ(read("curved.meshb"), read("one-thread.meshb"));
}

// A mesh large enough to show progress: one line redrawn on a terminal (stderr of `script`'s
// pseudo-terminal, stdout to a file), nothing in a log or with --quiet.
TEST_F(CurveCli, ProgressLineOnlyOnATerminal) {
  run_ok("generate square --h 0.007 -o square.meshb");  // 144 x 144 vertices, 142 x 142 inside
  run_ok("metric square.meshb --analytic uniform --h 0.007 -o square.solb");
  auto on_terminal = [this](const std::string& options) {
    const std::string command = "cd '" + directory_.string() +
                                "' && script -qec \"'" HOCAV_BINARY "' curve square.meshb --metric square.solb -o curved.meshb " + options +
                                " > stdout.txt\" /dev/null > terminal.txt";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return read("terminal.txt");
  };
  const std::string drawn = on_terminal("");
  EXPECT_NE(drawn.find("\rcurving: 20,164/20,164 vertices (100%), "), std::string::npos) << drawn;
  EXPECT_NE(drawn.find("/s, 0 s left"), std::string::npos) << drawn;
  EXPECT_GE(std::count(drawn.begin(), drawn.end(), '\r'), 10);  // redrawn, ...
  EXPECT_EQ(count_lines(drawn), 1) << drawn;                    // ... on one line
  EXPECT_NE(read("stdout.txt").find("curved square.meshb"), std::string::npos);
  EXPECT_EQ(on_terminal("--quiet"), "");
  EXPECT_EQ(run_ok("curve square.meshb --metric square.solb -o curved.meshb").err, "");
}

TEST_F(CurveCli, BadInputGivesOneLineAndNoOutput) {
  run_ok("generate square --h 0.25 -o square.mesh");
  run_ok("metric square.mesh --analytic uniform --h 0.25 -o square.sol");
  run_ok("generate square --h 0.5 -o coarse.mesh");
  expect_failure("curve square.mesh --metric missing.sol -o out.meshb", "missing.sol");
  expect_failure("curve coarse.mesh --metric square.sol -o out.meshb", "square.sol");  // wrong row count
  expect_failure("curve square.mesh --metric square.sol --surface bezier -o out.meshb", "bezier");
  expect_failure("curve square.mesh --metric square.sol --surface cad:missing.step -o out.meshb", "missing.step");
  EXPECT_EQ(files(), (std::set<std::string>{"coarse.mesh", "square.mesh", "square.sol"}));
  Outcome help = run_ok("curve --help");
  for (const char* option : {"--metric", "--surface", "--jacobian-floor", "--passes", "--threads", "--quadrature", "--report", "--vtu"})
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
}

}  // namespace
}  // namespace hocav::cli_test
