// End-to-end tests of `hocav stats` on hand-made files: the certified Jacobian figures against the
// exact Jacobian, and the verdict on an invalid mesh (the full report on stdout, one line naming the
// file and the element on stderr, exit code 2).
#include <gtest/gtest.h>

#include <cmath>

#include "cli_test_support.hpp"

namespace hocav::cli_test {
namespace {

// Two P2 unit right triangles side by side, apart, in the Gamma order (corners, then the nodes of
// edges 01, 12, 20); in triangle i the node of edge 01 is moved by d_i along y. Its map is
// x = ξ + 4 λ0 ξ1 d e_y, so J = 1 − 4 d ξ1: min J/|J_straight| = min(1, 1 − 4d), scaled
// min J / max J = min(1, 1 − 4d) / max(1, 1 − 4d).
std::string p2_triangles(double d0, double d1) {
  std::ostringstream file;
  file << "MeshVersionFormatted 2\nDimension 2\nVertices\n12\n";
  for (int i = 0; i < 2; ++i) {
    const double x = 3 * i, d = i == 0 ? d0 : d1;
    file << x << " 0 0\n" << x + 1 << " 0 0\n" << x << " 1 0\n";
    file << x + 0.5 << ' ' << d << " 0\n" << x + 0.5 << " 0.5 0\n" << x << " 0.5 0\n";
  }
  file << "TrianglesP2\n2\n1 2 3 4 5 6 1\n7 8 9 10 11 12 1\nEnd\n";
  return file.str();
}

double exact_min_normalized(double d) { return std::min(1.0, 1 - 4 * d); }
double exact_scaled(double d) { return std::min(1.0, 1 - 4 * d) / std::max(1.0, 1 - 4 * d); }

class StatsCli : public Cli {
 protected:
  double stats_value(const std::string& arguments, const std::string& expression) const {
    return std::stod(stats_json(arguments, expression));
  }
};

TEST_F(StatsCli, CurvedTrianglesGiveTheExactJacobianFigures) {
  write("curved.mesh", p2_triangles(0.1, -0.2));  // inward (min 0.6), outward (max J 1.8)
  EXPECT_NEAR(stats_value("curved.mesh", "d[\"jacobian\"][\"min_normalized\"][\"min\"]"), exact_min_normalized(0.1), 1e-12);
  EXPECT_NEAR(stats_value("curved.mesh", "d[\"jacobian\"][\"min_normalized\"][\"avg\"]"),
              (exact_min_normalized(0.1) + exact_min_normalized(-0.2)) / 2, 1e-12);
  EXPECT_NEAR(stats_value("curved.mesh", "d[\"jacobian\"][\"scaled\"][\"min\"]"), exact_scaled(-0.2), 1e-12);
  EXPECT_NEAR(stats_value("curved.mesh", "d[\"jacobian\"][\"scaled\"][\"max\"]"), exact_scaled(0.1), 1e-12);
  EXPECT_EQ(stats_json("curved.mesh", "d[\"valid\"], d[\"jacobian\"][\"invalid\"], d[\"jacobian\"][\"straight\"]"), "(True, 0, False)");
  // 0.6 and 1 (normalized), 0.6 and 1/1.8 (scaled): the bins (0.5, 0.7] and (0.9, 1].
  EXPECT_EQ(stats_json("curved.mesh",
                       "[(h[\"bin\"], h[\"min_normalized\"], h[\"scaled\"]) for h in d[\"jacobian\"][\"histogram\"] "
                       "if h[\"min_normalized\"] or h[\"scaled\"]]"),
            "[('(0.5, 0.7]', 1, 2), ('(0.9, 1]', 1, 0)]");
  Outcome table = run_ok("stats curved.mesh");
  EXPECT_NE(table.out.find("normalized Jacobian   min 0.6  avg 0.8  max 1"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("  (0.5, 0.7]                   1         2"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("valid                 yes"), std::string::npos) << table.out;
  EXPECT_TRUE(table.err.empty()) << table.err;
}

TEST_F(StatsCli, AFoldedCurvedElementIsReportedThenFailsTheCommand) {
  write("folded.mesh", p2_triangles(0.1, 0.3));  // J = 1 − 1.2 ξ1 < 0 near the vertex 1 of the second
  Outcome json = run("stats --json folded.mesh");
  EXPECT_EQ(json.exit_code, 2);
  EXPECT_EQ(json.err, "hocav: folded.mesh: invalid mesh: 1 element with a non-positive Jacobian (first: element 2)\n");
  write("report.json", json.out);  // the whole report, still one valid JSON object
  EXPECT_EQ(json_value("report.json", "d[\"valid\"], d[\"jacobian\"][\"invalid\"], d[\"jacobian\"][\"first_invalid_element\"]"),
            "(False, 1, 2)");
  EXPECT_NEAR(std::stod(json_value("report.json", "d[\"jacobian\"][\"min_normalized\"][\"min\"]")), exact_min_normalized(0.3), 1e-12);
  EXPECT_EQ(json_value("report.json", "d[\"jacobian\"][\"histogram\"][0][\"min_normalized\"]"), "1");
  EXPECT_EQ(json_value("report.json", "d[\"consistency\"][\"consistent\"]"), "True");  // consistent, yet invalid
  Outcome table = run("stats folded.mesh");
  EXPECT_EQ(table.exit_code, 2);
  EXPECT_NE(table.out.find("invalid elements      1 (first: element 2)"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("valid                 NO: 1 element with a non-positive Jacobian"), std::string::npos) << table.out;
}

TEST_F(StatsCli, AnInvertedStraightElementFailsTheSignCheckAndTheConsistencyCheck) {
  write("inverted.mesh",
        "MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
        "Triangles\n2\n1 2 3 1\n2 3 4 1\nEnd\n");  // the second is clockwise
  Outcome table = run("stats inverted.mesh");
  EXPECT_EQ(table.exit_code, 2);
  EXPECT_EQ(count_lines(table.err), 1) << table.err;
  EXPECT_EQ(table.err.rfind("hocav: inverted.mesh: invalid mesh: 1 element with a non-positive Jacobian (first: element 2); "
                            "consistency: ",
                            0),
            0u)
      << table.err;
  EXPECT_NE(table.out.find("normalized Jacobian   min -1  avg 0  max 1  (straight P1 elements"), std::string::npos) << table.out;
  EXPECT_EQ(table.out.find("Jacobian histogram"), std::string::npos) << "no histogram of straight elements";
}

}  // namespace
}  // namespace hocav::cli_test
