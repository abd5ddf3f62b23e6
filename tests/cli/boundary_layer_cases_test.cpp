// End to end, issue 5's hard case: the cubed-sphere shell with boundary layers on both spheres that
// meet in the middle, coarse along the walls, curved in its implied metric with the P3 surrogate. The
// walls' chords sag by more than the first layer is thick, so the P2 cavity operator must correct
// (pull nodes back); every element still ends above the Jacobian floor and the output reads back.
#include <gtest/gtest.h>

#include "cli_test_support.hpp"

namespace hocav::cli_test {
namespace {

TEST_F(Cli, BoundaryLayersMeetingNeedCorrectionsAndEndValid) {
  const Outcome generated = run_ok("generate cubed-shell-bl-both --target-tets 3000 -o shell.meshb");
  EXPECT_NE(generated.out.find("3168 tetrahedra"), std::string::npos) << generated.out;  // n = 2, 22 layers
  run_ok("metric shell.meshb --implied -o shell.solb");
  run_ok("curve shell.meshb --metric shell.solb --surface p3 -o curved.meshb --report report.json -q");
  auto value = [this](const std::string& expression) { return std::stod(json_value("report.json", expression)); };
  EXPECT_GT(value("d[\"cavities\"][\"corrections\"]"), 0);
  EXPECT_EQ(value("d[\"cavities\"][\"tried\"] - d[\"cavities\"][\"accepted\"]"), 0);
  EXPECT_GT(value("d[\"max_anisotropy\"]"), 10);
  EXPECT_EQ(value("d[\"normalized_jacobian\"][\"invalid\"]"), 0);
  // The reported minimum is a lower bound refined to 1e-6: an element certified just above the
  // floor 0.01 may read a little below it.
  EXPECT_GE(value("d[\"normalized_jacobian\"][\"min\"]"), 0.01 - 1e-6);
  EXPECT_GT(value("d[\"average_gain\"]"), 0);
  EXPECT_EQ(stats_json("curved.meshb", "d[\"consistency\"][\"consistent\"], d[\"order\"], d[\"open_boundary_faces\"]"), "(True, 2, 0)");
}

TEST_F(Cli, GeneratesTheStructuredCasesAtAGivenSize) {
  for (const char* name : {"cubed-shell", "cubed-shell-bl-inner", "cubed-shell-bl-both"}) {
    SCOPED_TRACE(name);
    run_ok(std::string("generate ") + name + " --target-tets 2e4 -o shell.meshb");
    EXPECT_EQ(stats_json("shell.meshb",
                         "d[\"consistency\"][\"consistent\"], sorted(r[\"ref\"] for r in d[\"facet_refs\"]), "
                         "abs(d[\"counts\"][\"elements\"] / 2e4 - 1) < 0.3"),
              "(True, [1, 2], True)");
  }
  run_ok("generate shear-circle -o annulus.mesh");
  EXPECT_EQ(stats_json("annulus.mesh", "d[\"consistency\"][\"consistent\"], d[\"dimension\"], d[\"counts\"][\"elements\"]"),
            "(True, 2, 1824)");
  run_ok("generate polar-annulus-bl-both --target-triangles 500 --first-layer 0.004 --growth 1.5 --layers 3 -o layers.mesh");
  expect_failure("generate cubed-shell-bl-inner --growth 0.5 -o x.mesh", "growth");
  expect_failure("generate cubed-shell --target-tets 1e12 -o x.mesh", "target-tets");
  expect_failure("generate cubed-shell-bl-both --layers 2.5 -o x.mesh", "layers");
  expect_failure("generate shear-circle --radius 2 -o x.mesh", "radius");
}

}  // namespace
}  // namespace hocav::cli_test
