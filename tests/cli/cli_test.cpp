// End-to-end tests of the `hocav` binary: every command run as a user would, in a scratch folder.
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>

#include "cli_test_support.hpp"
#include "io/mesh_file.hpp"

namespace {

using namespace hocav::cli_test;

TEST_F(Cli, HelpAndVersion) {
  Outcome help = run_ok("--help");
  for (const char* command : {"convert", "stats", "generate"}) EXPECT_NE(help.out.find(command), std::string::npos) << command;
  Outcome generate_help = run_ok("generate --help");
  for (const char* name : {"square", "cube", "annulus", "sphere-shell", "--r-in", "--r-out", "--h", "--order", "--output"})
    EXPECT_NE(generate_help.out.find(name), std::string::npos) << name;
  Outcome case_help = run_ok("generate annulus --help");
  EXPECT_NE(case_help.out.find("--r-out"), std::string::npos);
  Outcome convert_help = run_ok("convert --help");
  for (const char* option : {"--metric", "--metric-out", "--order", "--meshb-version"})
    EXPECT_NE(convert_help.out.find(option), std::string::npos) << option;
  Outcome stats_help = run_ok("stats --help");
  for (const char* option : {"--metric", "--json"}) EXPECT_NE(stats_help.out.find(option), std::string::npos) << option;
  EXPECT_NE(run_ok("--version").out.find("hocav 0."), std::string::npos);
}

TEST_F(Cli, GeneratesEveryCaseAsAConsistentMesh) {
  HOCAV_SKIP_WITHOUT_GMSH();
  const std::map<std::string, std::string> cases{
      {"square", "--h 0.25"}, {"cube", "--h 0.5"}, {"annulus", "--h 0.2"}, {"sphere-shell", "--h 0.4 --r-in 0.4"}};
  for (const auto& [name, options] : cases) {
    SCOPED_TRACE(name);
    Outcome generated = run_ok("generate " + name + " " + options + " -o " + name + ".mesh");
    EXPECT_NE(generated.out.find("wrote " + name + ".mesh"), std::string::npos) << generated.out;
    EXPECT_EQ(stats_json(name + ".mesh", "d[\"consistency\"][\"consistent\"]"), "True");
    EXPECT_EQ(stats_json(name + ".mesh", "d[\"open_boundary_faces\"]"), "0");
  }
  EXPECT_EQ(stats_json("square.mesh", "d[\"counts\"][\"elements\"], d[\"counts\"][\"boundary_facets\"]"), "(32, 16)");
  EXPECT_EQ(stats_json("cube.mesh", "d[\"counts\"][\"elements\"], d[\"dimension\"]"), "(48, 3)");
  EXPECT_EQ(stats_json("annulus.mesh", "sorted(r[\"ref\"] for r in d[\"facet_refs\"])"), "[1, 2]");
  double volume = std::stod(stats_json("sphere-shell.mesh", "d[\"p1_measure\"][\"total\"]"));
  EXPECT_NEAR(volume, 4.0 / 3.0 * std::numbers::pi * (1 - 0.4 * 0.4 * 0.4), 0.25);
}

// The command links no gmsh (it would cost every process 0.12 s at start): it opens its gmsh module
// on demand, and a command without the module beside it fails on a gmsh case only, in one line.
TEST_F(Cli, OpensGmshOnlyForTheCasesThatNeedIt) {
  HOCAV_SKIP_WITHOUT_GMSH();
  ASSERT_EQ(std::system(("ldd '" HOCAV_BINARY "' > '" + path("ldd.txt").string() + "'").c_str()), 0);
  EXPECT_EQ(read("ldd.txt").find("libgmsh"), std::string::npos) << read("ldd.txt");
  fs::copy_file(HOCAV_BINARY, path("lone-hocav"));
  const std::string lone = "cd '" + path("").string() + "' && ./lone-hocav ";
  EXPECT_EQ(std::system((lone + "generate cube --h 0.5 -o cube.meshb > /dev/null").c_str()), 0);
  EXPECT_NE(std::system((lone + "generate annulus --h 0.2 -o annulus.meshb 2> err.txt").c_str()), 0);
  const std::string err = read("err.txt");
  EXPECT_EQ(count_lines(err), 1) << err;
  EXPECT_NE(err.find("hocav-gmsh.so"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(path("annulus.meshb")));
  run_ok("generate annulus --h 0.2 -o annulus.meshb");
}

TEST_F(Cli, GenerateTakesOptionsBeforeOrAfterTheCaseAndIsDeterministic) {
  HOCAV_SKIP_WITHOUT_GMSH();
  run_ok("generate -o a.mesh annulus --r-in 0.3 --h 0.15");
  run_ok("generate annulus --h 0.15 --r-in 0.3 -o b.mesh");
  EXPECT_EQ(read("a.mesh"), read("b.mesh"));
  run_ok("generate sphere-shell --h 0.5 -o c.meshb --order 2");
  EXPECT_EQ(stats_json("c.meshb", "d[\"order\"], d[\"counts\"][\"p2_nodes\"] == d[\"counts\"][\"edges\"]"), "(2, True)");
}

TEST_F(Cli, GenerateWritesTheCadModelThatCurveProjectsOn) {
  HOCAV_SKIP_WITHOUT_GMSH();
  // Radii other than the defaults: the model follows the case's options.
  run_ok("generate cubed-shell --r-in 0.4 --r-out 1.2 --target-tets 3000 -o shell.meshb --cad-out shell.step");
  run_ok("metric shell.meshb --surface 0.03 0.3 --gradation 1.5 -o shell.solb");
  run_ok("curve shell.meshb --metric shell.solb --surface cad:shell.step -o curved.mesh -q");
  const auto curved = std::get<hocav::Mesh<3>>(hocav::read_mesh_file(path("curved.mesh").string()).mesh);
  // Every mid node of a boundary edge is on its sphere (OpenCASCADE's accuracy), or, where the
  // correction could not take the whole proposal, strictly inside it.
  int on_sphere[3] = {0, 0, 0};
  for (hocav::Index f = 0; f < curved.facet_count(); ++f) {
    const int ref = curved.facet_ref(f);
    const double radius = ref == 1 ? 0.4 : 1.2;
    const auto facet = curved.facet(f);
    for (int i = 0; i < 3; ++i) {
      const double node_radius = hocav::norm(curved.edge_node(curved.find_edge(facet[i], facet[(i + 1) % 3])));
      if (std::abs(node_radius - radius) < 1e-9)
        ++on_sphere[ref];
      else
        EXPECT_EQ(node_radius < radius, ref == 2) << "facet " << f << " radius " << node_radius;
    }
  }
  EXPECT_GT(on_sphere[1], 0);
  EXPECT_GT(on_sphere[2], 0);
  // A case without a curved boundary has no model; a CAD file needs a CAD extension. Neither writes anything.
  expect_failure("generate cube --cad-out cube.step -o cube.meshb", "CAD model");
  expect_failure("generate annulus --cad-out annulus.iges -o annulus.meshb", "annulus.iges");
  EXPECT_EQ(files(), (std::set<std::string>{"shell.meshb", "shell.step", "shell.solb", "curved.mesh"}));
}

TEST_F(Cli, ConvertsBetweenEveryFormatWithoutLoss) {
  HOCAV_SKIP_WITHOUT_GMSH();
  run_ok("generate sphere-shell --h 0.5 --order 2 -o shell.mesh");
  run_ok("convert shell.mesh shell.meshb");
  run_ok("convert shell.meshb shell.msh");
  run_ok("convert shell.msh back.mesh");
  run_ok("convert back.mesh back.vtu");
  const std::string figures =
      "d[\"counts\"], [(r[\"ref\"], r[\"count\"]) for r in d[\"facet_refs\"]], round(d[\"p1_measure\"][\"total\"], 12)";
  std::string original = stats_json("shell.mesh", figures);
  EXPECT_EQ(stats_json("shell.meshb", figures), original);
  EXPECT_EQ(stats_json("shell.msh", figures), original);
  EXPECT_EQ(stats_json("back.mesh", figures), original);
  EXPECT_NE(read("back.vtu").find("<VTKFile"), std::string::npos);

  run_ok("convert shell.msh p1.mesh --order 1");
  EXPECT_EQ(stats_json("p1.mesh", "d[\"order\"], d[\"counts\"][\"p2_nodes\"]"), "(1, 0)");
  run_ok("convert p1.mesh p2.meshb --order 2 --meshb-version 4");
  EXPECT_EQ(stats_json("p2.meshb", "d[\"order\"], d[\"counts\"][\"p2_nodes\"] > 0"), "(2, True)");
}

TEST_F(Cli, ConvertCarriesTheMetricToTheOutputNodeOrder) {
  write("tri.mesh", kShuffledP2Triangle);
  write("tri.sol", metric_for_shuffled_triangle(6));
  Outcome converted = run_ok("convert tri.mesh out.mesh --metric tri.sol");
  EXPECT_NE(converted.out.find("out.sol"), std::string::npos) << converted.out;
  auto nodes = gamma_block(read("out.mesh"), "Vertices", 3);
  auto metric = gamma_block(read("out.sol"), "SolAtVertices", 3, 2);
  ASSERT_EQ(nodes.size(), 6u);
  ASSERT_EQ(metric.size(), 6u);
  for (std::size_t i = 0; i < nodes.size(); ++i) EXPECT_DOUBLE_EQ(metric[i][0], encoded_m11(nodes[i][0], nodes[i][1])) << "node " << i + 1;
  // Corners first, then the P2 nodes, so the moved mid node is not among the first three.
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NE(nodes[i][0], 0.6);

  run_ok("convert tri.mesh p1.mesh --metric tri.sol --order 1 --metric-out p1_metric.sol");
  nodes = gamma_block(read("p1.mesh"), "Vertices", 3);
  metric = gamma_block(read("p1_metric.sol"), "SolAtVertices", 3, 2);
  ASSERT_EQ(nodes.size(), 3u);
  ASSERT_EQ(metric.size(), 3u);
  for (std::size_t i = 0; i < nodes.size(); ++i) EXPECT_DOUBLE_EQ(metric[i][0], encoded_m11(nodes[i][0], nodes[i][1]));

  run_ok("convert tri.mesh bin.meshb --metric tri.sol");
  EXPECT_TRUE(fs::exists(path("bin.solb")));
  EXPECT_EQ(stats_json("bin.meshb --metric bin.solb", "d[\"metric\"][\"edges\"], d[\"counts\"][\"p2_nodes\"]"), "(3, 3)");

  run_ok("convert tri.mesh tri.vtu --metric tri.sol");
  EXPECT_NE(read("tri.vtu").find("Name=\"metric\""), std::string::npos);
  EXPECT_EQ(read("tri.sol"), metric_for_shuffled_triangle(6));  // a .vtu carries the metric: no .sol written
}

TEST_F(Cli, StatsReportsEdgeLengthsInTheMetric) {
  run_ok("generate square --h 0.25 -o square.mesh");
  // 25 vertices, metric 16 I: axis edges of length 1, diagonals sqrt 2, all in [1/sqrt 2, sqrt 2].
  std::string sol = "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n25\n1 3\n";
  for (int i = 0; i < 25; ++i) sol += "16 0 16\n";
  write("square.sol", sol + "End\n");
  EXPECT_EQ(stats_json("square.mesh --metric square.sol", "d[\"metric\"][\"edges\"], d[\"metric\"][\"unit_share\"]"), "(56, 1)");
  EXPECT_EQ(stats_json("square.mesh --metric square.sol", "round(d[\"metric\"][\"length\"][\"max\"] ** 2, 12)"), "2.0");
  Outcome table = run_ok("stats square.mesh --metric square.sol");
  EXPECT_NE(table.out.find("unit edges"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("consistency           ok"), std::string::npos) << table.out;
}

TEST_F(Cli, MissingAndMalformedFilesFailCleanly) {
  expect_failure("stats nothere.mesh", "nothere.mesh");
  expect_failure("convert nothere.mesh out.mesh", "nothere.mesh");
  write("broken.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 zero 0\n");
  expect_failure("stats broken.mesh", "broken.mesh");
  expect_failure("convert broken.mesh out.meshb", "broken.mesh");
  write("broken.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1 2\n");
  expect_failure("convert broken.msh out.mesh", "broken.msh");
  EXPECT_EQ(files(), (std::set<std::string>{"broken.mesh", "broken.msh"}));
}

TEST_F(Cli, BadMetricsFailWithoutOutput) {
  write("tri.mesh", kShuffledP2Triangle);
  write("short.sol", metric_for_shuffled_triangle(5));
  expect_failure("convert tri.mesh out.mesh --metric short.sol", "short.sol");
  expect_failure("stats tri.mesh --metric short.sol", "short.sol");
  write("negative.sol", metric_for_shuffled_triangle(6, -2.0));
  expect_failure("convert tri.mesh out.mesh --metric negative.sol", "negative.sol");
  expect_failure("convert tri.mesh out.mesh --metric missing.sol", "missing.sol");
  write("tri.sol", metric_for_shuffled_triangle(6));
  expect_failure("convert tri.mesh out.mesh --metric tri.sol --metric-out out.txt", "out.txt");
  // The metric cannot be written after the mesh was: the mesh goes too.
  expect_failure("convert tri.mesh out.mesh --metric tri.sol --metric-out nowhere/out.sol", "nowhere/out.sol");
  // A P1 mesh made P2 would need metric values at the new nodes.
  run_ok("convert tri.mesh p1.mesh --order 1");
  write("p1.sol", "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n3\n1 3\n1 0 1\n1 0 1\n1 0 1\nEnd\n");
  expect_failure("convert p1.mesh p2.mesh --metric p1.sol --order 2", "--order 2");
  EXPECT_EQ(files(), (std::set<std::string>{"tri.mesh", "short.sol", "negative.sol", "tri.sol", "p1.mesh", "p1.sol"}));
}

TEST_F(Cli, BadCommandLinesExitWithTwo) {
  run_ok("generate square --h 0.5 -o square.mesh");
  for (const char* arguments :
       {"", "frobnicate", "convert square.mesh", "convert square.mesh out.mesh --order 3", "generate annulus", "generate torus -o x.mesh",
        "stats square.mesh --bogus", "convert square.mesh out.mesh --meshb-version 7"}) {
    Outcome result = run(arguments);
    EXPECT_EQ(result.exit_code, 2) << "hocav " << arguments;
    EXPECT_FALSE(result.err.empty()) << "hocav " << arguments;
  }
  expect_failure("generate polar-annulus --r-in 2 -o x.mesh", "r-in");
  expect_failure("generate square --h 0 -o x.mesh", "size h");
  expect_failure("convert square.mesh out.xyz", "out.xyz");
  expect_failure("generate square -o x.stl", "x.stl");
  EXPECT_EQ(files(), (std::set<std::string>{"square.mesh"}));
}

}  // namespace
