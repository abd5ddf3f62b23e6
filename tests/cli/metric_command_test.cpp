// End-to-end tests of `hocav metric` and of the metric figures of `hocav stats`, third-party data included.
#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "cli_test_support.hpp"
#include "shared_data.hpp"

namespace {

using namespace hocav::cli_test;

class MetricCli : public Cli {
 protected:
  // The metric rows of a .sol file written by hocav (3 or 6 columns).
  std::vector<std::vector<double>> metric_rows(const std::string& name, int dimension) const {
    return gamma_block(read(name), "SolAtVertices", dimension == 2 ? 3 : 6, 2);
  }
};

const std::string kUgawgMesh = hocav::testing_support::shared_data_path("ugawg-linear/linear.mesh");
const std::string kUgawgMetric = hocav::testing_support::shared_data_path("ugawg-linear/linear.sol");

double max_relative_difference(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b) {
  EXPECT_EQ(a.size(), b.size());
  double difference = 0;
  for (std::size_t row = 0; row < std::min(a.size(), b.size()); ++row) {
    double scale = 0;
    for (double value : b[row]) scale = std::max(scale, std::abs(value));
    for (std::size_t c = 0; c < b[row].size(); ++c) difference = std::max(difference, std::abs(a[row][c] - b[row][c]) / scale);
  }
  return difference;
}

TEST_F(MetricCli, HelpListsSourcesAndOptions) {
  EXPECT_NE(run_ok("--help").out.find("metric"), std::string::npos);
  Outcome help = run_ok("metric --help");
  for (const char* option :
       {"--analytic", "--implied", "--surface", "--hessian", "--input", "--gradation", "--h-min", "--h-max", "--axis", "--center",
        "--radius", "--width", "--origin", "--complexity", "--norm", "--from", "--from-metric", "shear-circle", "tanh-shock"})
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
}

// mmg adapted the UGAWG cube to this metric: measured 94.9% of the 60751 edges in [1/√2, √2], and the
// largest anisotropy at a vertex 99.92 (100 at z = 0.5, where no vertex lies exactly).
TEST_F(MetricCli, StatsOfTheUgawgLinearCaseShowAUnitMeshOfAnisotropyAbout100) {
  if (auto missing = hocav::testing_support::missing_shared_data({kUgawgMesh, kUgawgMetric}); !missing.empty()) GTEST_SKIP() << missing;
  std::string figures = stats_json("'" + kUgawgMesh + "' --metric '" + kUgawgMetric + "'",
                                   "d[\"metric\"][\"edges\"], d[\"metric\"][\"unit_share\"], d[\"metric\"][\"max_anisotropy\"]");
  std::istringstream in(figures.substr(1));
  long edges = 0;
  double unit_share = 0, anisotropy = 0;
  char comma = 0;
  in >> edges >> comma >> unit_share >> comma >> anisotropy;
  EXPECT_EQ(edges, 60751);
  EXPECT_GT(unit_share, 0.94);
  EXPECT_GT(anisotropy, 99.5);
  EXPECT_LE(anisotropy, 100 * (1 + 1e-12));
  Outcome table = run_ok("stats '" + kUgawgMesh + "' --metric '" + kUgawgMetric + "'");
  EXPECT_NE(table.out.find("max anisotropy        99.9"), std::string::npos) << table.out;
}

// The same mesh's element qualities in its metric, through the JSON: measured mean 0.85, min 0.46,
// no element below 0.1, and a histogram that counts every element.
TEST_F(MetricCli, StatsJsonCarriesTheElementQualitiesOfTheUgawgCase) {
  if (auto missing = hocav::testing_support::missing_shared_data({kUgawgMesh, kUgawgMetric}); !missing.empty()) GTEST_SKIP() << missing;
  const std::string q = "d[\"metric\"][\"quality\"]";
  std::string figures = stats_json("'" + kUgawgMesh + "' --metric '" + kUgawgMetric + "'",
                                   q + "[\"mean\"], " + q + "[\"min\"], " + q + "[\"low_share\"], sum(b[\"count\"] for b in " + q +
                                       "[\"histogram\"]), d[\"counts\"][\"elements\"]");
  std::istringstream in(figures.substr(1));
  double mean = 0, min = 0, low_share = 1;
  long binned = 0, elements = -1;
  char comma = 0;
  in >> mean >> comma >> min >> comma >> low_share >> comma >> binned >> comma >> elements;
  EXPECT_GT(mean, 0.8);
  EXPECT_LT(mean, 1);
  EXPECT_GT(min, 0.3);
  EXPECT_LT(min, mean);
  EXPECT_EQ(low_share, 0);
  EXPECT_EQ(binned, elements);
  EXPECT_EQ(elements, 48720);
}

TEST_F(MetricCli, AnalyticLinearReproducesTheUgawgMetric) {
  if (auto missing = hocav::testing_support::missing_shared_data({kUgawgMesh, kUgawgMetric}); !missing.empty()) GTEST_SKIP() << missing;
  Outcome result = run_ok("metric '" + kUgawgMesh + "' --analytic linear -o linear.sol");
  EXPECT_NE(result.out.find("wrote linear.sol: 9476 metrics"), std::string::npos) << result.out;
  auto expected = gamma_block(read_text(kUgawgMetric), "SolAtVertices", 6, 2);
  EXPECT_LT(max_relative_difference(metric_rows("linear.sol", 3), expected), 1e-14);
  // The same field spelled out: hz = 0.001 + 2 (0.1 − 0.001) |z − 0.5|, hx = hy = 0.1.
  run_ok("metric '" + kUgawgMesh + "' --analytic linear --axis z --center 0.5 --h-min 0.001 --h-max 0.1 -o explicit.solb");
  run_ok("convert '" + kUgawgMesh + "' copy.mesh --metric explicit.solb --metric-out explicit.sol");
  EXPECT_LT(max_relative_difference(metric_rows("explicit.sol", 3), expected), 1e-14);
}

// The shuffled P2 triangle lists its mid nodes first: every row must go to its own file node. The
// linear field along x with h = 0.1 + 1.8 |x| makes m11 a function of the node's x.
TEST_F(MetricCli, RowsFollowTheFileNodeNumberingIncludingP2Nodes) {
  write("tri.mesh", kShuffledP2Triangle);
  run_ok("metric tri.mesh --analytic linear --axis x --center 0 --h-min 0.1 --h-max 1 -o exact.sol");
  const double node_x[6] = {0.5, 0.6, 0, 0, 1, 0};
  auto rows = metric_rows("exact.sol", 2);
  ASSERT_EQ(rows.size(), 6u);
  for (int node = 0; node < 6; ++node) {
    double h = 0.1 + 1.8 * node_x[node];
    EXPECT_NEAR(rows[node][0], 1 / (h * h), 1e-12 / (h * h)) << "node " << node + 1;
    EXPECT_NEAR(rows[node][2], 1, 1e-15);
  }
  // Graded, the mid nodes take the log-Euclidean mean of their edge's ends (for diagonal metrics,
  // the geometric mean of each entry): the node 2 of edge (5, 6), node 1 of (4, 5), node 3 of (6, 4).
  run_ok("metric tri.mesh --analytic linear --axis x --center 0 --h-min 0.1 --h-max 1 --gradation 3 -o graded.sol");
  auto graded = metric_rows("graded.sol", 2);
  const int ends[3][3] = {{1, 4, 5}, {0, 3, 4}, {2, 5, 3}};
  for (const auto& [mid, a, b] : ends)
    for (int c : {0, 2}) EXPECT_NEAR(graded[mid][c], std::sqrt(graded[a][c] * graded[b][c]), 1e-12 * graded[mid][c]) << mid;
}

TEST_F(MetricCli, ImpliedMetricOfAStructuredMeshMakesItAUnitMesh) {
  run_ok("generate square --h 0.25 -o square.mesh");
  run_ok("metric square.mesh --implied -o implied.sol");
  EXPECT_EQ(stats_json("square.mesh --metric implied.sol",
                       "round(d[\"metric\"][\"length\"][\"min\"], 12), round(d[\"metric\"][\"length\"][\"max\"], 12), "
                       "d[\"metric\"][\"unit_share\"]"),
            "(1.0, 1.0, 1)");
}

TEST_F(MetricCli, SurfaceMetricIsGradedIntoTheVolume) {
  run_ok("generate cube --h 0.25 -o cube.mesh");
  run_ok("metric cube.mesh --surface 0.01,0.2 --gradation 1.5 -o surface.sol");
  auto vertices = gamma_block(read("cube.mesh"), "Vertices", 4);
  auto rows = metric_rows("surface.sol", 3);
  ASSERT_EQ(rows.size(), vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const auto& x = vertices[v];
    if (x[0] == 0.5 && x[1] == 0.5 && x[2] == 0) {  // on the face z = 0: h_n = 0.01 along z
      EXPECT_NEAR(rows[v][5], 1e4, 1e-8);
      EXPECT_NEAR(rows[v][0], 25, 1e-10);
    }
    if (x[0] == 0.5 && x[1] == 0.5 && x[2] == 0.5) {  // the centre, 0.5 from every face: graded from h = √3 down
      double size = 1 / std::sqrt(rows[v][0]);
      EXPECT_LT(size, 0.2 + 0.5 * std::log(1.5));
      EXPECT_GT(size, 0.01);
    }
  }
  // Grading a graded metric changes nothing.
  run_ok("metric cube.mesh --input surface.sol --gradation 1.5 -o again.sol");
  EXPECT_EQ(read("again.sol"), read("surface.sol"));
}

TEST_F(MetricCli, HessianOfAFieldFileMatchesTheAnalyticHessian) {
  run_ok("generate square --h 0.1 -o square.mesh");
  // u = x² + xy − 4y² at the vertices (the analytic "quadratic"): the fit recovers its Hessian exactly.
  auto vertices = gamma_block(read("square.mesh"), "Vertices", 3);
  std::ostringstream field;
  field.precision(17);
  field << "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n" << vertices.size() << "\n1 1\n";
  for (const auto& x : vertices) field << x[0] * x[0] + x[0] * x[1] - 4 * x[1] * x[1] << "\n";
  write("u.sol", field.str() + "End\n");
  Outcome result = run_ok("metric square.mesh --hessian u.sol --complexity 500 --norm 1 -o recovered.sol");
  EXPECT_NE(result.out.find("complexity 500 "), std::string::npos) << result.out;
  run_ok("metric square.mesh --hessian analytic:quadratic --complexity 500 --norm 1 -o exact.sol");
  EXPECT_LT(max_relative_difference(metric_rows("recovered.sol", 2), metric_rows("exact.sol", 2)), 1e-9);
  // A constant |H| gives the constant metric N det(|H|)^{-1/2} |H| on the unit square: det |H| = 17.
  auto rows = metric_rows("exact.sol", 2);
  EXPECT_NEAR(rows[0][0] * rows[0][2] - rows[0][1] * rows[0][1], 500.0 * 500.0, 1e-3);
  run_ok("metric square.mesh --hessian analytic:tanh-shock --radius 0.5 --width 0.1 --complexity 2000 -o shock.sol");
  EXPECT_GT(std::stod(stats_json("square.mesh --metric shock.sol", "d[\"metric\"][\"max_anisotropy\"]")), 3);
}

// The unit square in two triangles with the metric diag(e^{2x+y}, e^{−x+3y}) at its corners: its log is
// affine, so the log-Euclidean interpolation reproduces it exactly anywhere in the square.
double affine_log_entry(double x, double y, int entry) {
  return entry == 0 ? std::exp(2 * x + y) : entry == 2 ? std::exp(-x + 3 * y) : 0.0;
}

std::string affine_log_back_metric() {
  const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::ostringstream sol;
  sol.precision(17);
  sol << "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n4\n1 3\n";
  for (const auto& c : corners) sol << affine_log_entry(c[0], c[1], 0) << " 0 " << affine_log_entry(c[0], c[1], 2) << "\n";
  sol << "End\n";
  return sol.str();
}

constexpr const char* kTwoTriangleSquare =
    "MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
    "Triangles\n2\n1 2 3 1\n1 3 4 1\nEnd\n";

TEST_F(MetricCli, FromInterpolatesABackMeshMetricLogEuclidean) {
  write("back.mesh", kTwoTriangleSquare);
  write("back.sol", affine_log_back_metric());
  run_ok("generate square --h 0.2 -o square.mesh");
  Outcome result = run_ok("metric square.mesh --from back.mesh --from-metric back.sol -o at-square.sol");
  EXPECT_NE(result.out.find("wrote at-square.sol: 36 metrics"), std::string::npos) << result.out;
  auto vertices = gamma_block(read("square.mesh"), "Vertices", 3);
  auto rows = metric_rows("at-square.sol", 2);
  ASSERT_EQ(rows.size(), vertices.size());
  for (std::size_t v = 0; v < rows.size(); ++v)
    for (int entry = 0; entry < 3; ++entry)
      EXPECT_NEAR(rows[v][entry], affine_log_entry(vertices[v][0], vertices[v][1], entry), 1e-12 * std::exp(3.0)) << v;
}

// mmg's torus and its metric, interpolated onto the torus itself: each vertex gets its own row back.
TEST_F(MetricCli, FromOntoTheBackMeshItselfGivesBackItsMetric) {
  const std::string torus = hocav::testing_support::shared_data_path("mmg-torus/torus");
  if (auto missing = hocav::testing_support::missing_shared_data({torus + ".mesh", torus + "-met.sol"}); !missing.empty())
    GTEST_SKIP() << missing;
  run_ok("metric '" + torus + ".mesh' --from '" + torus + ".mesh' --from-metric '" + torus + "-met.sol' -o self.sol");
  EXPECT_LT(max_relative_difference(metric_rows("self.sol", 3), gamma_block(read_text(torus + "-met.sol"), "SolAtVertices", 6, 2)), 1e-12);
}

TEST_F(MetricCli, BadRequestsFailWithOneLineAndNoOutput) {
  run_ok("generate square --h 0.5 -o square.mesh");
  write("tri.mesh", kShuffledP2Triangle);
  write("tri.sol", metric_for_shuffled_triangle(6));
  expect_failure("metric square.mesh -o m.sol", "exactly one metric source");
  expect_failure("metric square.mesh --implied --analytic uniform -o m.sol", "exactly one metric source");
  expect_failure("metric square.mesh --analytic spiral -o m.sol", "spiral");
  expect_failure("metric square.mesh --analytic shear-sphere -o m.sol", "shear-sphere");
  expect_failure("metric square.mesh --implied --h 0.1 -o m.sol", "--h");
  expect_failure("metric square.mesh --implied --complexity 10 -o m.sol", "--complexity");
  expect_failure("metric square.mesh --hessian analytic:quadratic -o m.sol", "--complexity");
  expect_failure("metric square.mesh --hessian analytic:sine --complexity 10 -o m.sol", "sine");
  expect_failure("metric square.mesh --hessian nothere.sol --complexity 10 -o m.sol", "nothere.sol");
  expect_failure("metric square.mesh --hessian tri.sol --complexity 10 -o m.sol", "tri.sol");
  expect_failure("metric square.mesh --surface 0.1,0.2 -o m.sol", "--gradation");
  expect_failure("metric square.mesh --implied --gradation 1 -o m.sol", "growth");
  expect_failure("metric square.mesh --analytic shear-circle --origin 1,2,3 -o m.sol", "--origin");
  expect_failure("metric square.mesh --implied -o m.mesh", "m.mesh");
  expect_failure("metric nothere.mesh --implied -o m.sol", "nothere.mesh");
  expect_failure("metric square.mesh --input tri.sol -o m.sol", "tri.sol");
  expect_failure("metric square.mesh --implied -o nowhere/m.sol", "nowhere/m.sol");
  expect_failure("metric square.mesh --from square.mesh -o m.sol", "--from-metric");
  expect_failure("metric square.mesh --implied --from-metric tri.sol -o m.sol", "--from-metric");
  expect_failure("metric square.mesh --from tri.mesh --from-metric tri.sol --implied -o m.sol", "exactly one metric source");
  for (const char* arguments :
       {"metric square.mesh --implied", "metric --implied -o m.sol", "metric square.mesh --surface 0.1 --gradation 2 -o m.sol",
        "metric square.mesh --analytic linear --axis w -o m.sol"}) {
    Outcome result = run(arguments);
    EXPECT_EQ(result.exit_code, 2) << "hocav " << arguments;
    EXPECT_FALSE(result.err.empty()) << "hocav " << arguments;
  }
  EXPECT_EQ(files(), (std::set<std::string>{"square.mesh", "tri.mesh", "tri.sol"}));
}

}  // namespace
