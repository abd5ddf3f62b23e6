// The careful user: every command that writes files run with failing, colliding, long and odd
// outputs, every reader given bad files, every floating option given values that mean nothing,
// meshes with defects, and a kill in the middle. The checks run over tables: a new command that
// reads a mesh (and a metric) and writes files is one more row of kWritingCommands.
#include <csignal>
#include <string>
#include <vector>

#include "cli_test_support.hpp"

namespace hocav::cli_test {
namespace {

const std::vector<std::string> kMeshAndMetric{"square.mesh", "square.sol"};

struct WritingCommand {
  std::string name;
  std::string command;        // everything but the outputs; the inputs are those of prepare_inputs()
  std::string output_option;  // "-o " or "" for a positional output
  std::string output_extension;
  std::vector<std::pair<std::string, std::string>> secondary;  // option, a good file name for it
  std::vector<std::string> inputs;
};

const std::vector<WritingCommand> kWritingCommands{
    {"curve", "curve square.mesh --metric square.sol -q", "-o ", ".meshb", {{"--report", "r.json"}, {"--vtu", "v.vtu"}}, kMeshAndMetric},
    {"adapt", "adapt square.mesh --metric square.sol -q", "-o ", ".meshb", {{"--report", "r.json"}, {"--vtu", "v.vtu"}}, kMeshAndMetric},
    {"convert", "convert square.mesh --metric square.sol", "", ".meshb", {{"--metric-out", "m.solb"}}, kMeshAndMetric},
    {"metric", "metric square.mesh --input square.sol", "-o ", ".solb", {}, kMeshAndMetric},
    {"picture", "picture square.mesh", "-o ", ".svg", {}, {"square.mesh"}},
    // With gmsh, the gmsh-meshed annulus and its CAD model (a second output); without, a structured case.
    HOCAV_WITH_GMSH ? WritingCommand{"generate", "generate annulus --h 0.4", "-o ", ".meshb", {{"--cad-out", "a.step"}}, {}}
                    : WritingCommand{"generate", "generate polar-annulus --target-triangles 200", "-o ", ".meshb", {}, {}},
};

class CarefulUser : public Cli {
 protected:
  void prepare_inputs() const {
    run_ok("generate square --h 0.25 -o square.mesh");
    run_ok("metric square.mesh --analytic uniform --h 0.25 -o square.sol");
  }

  static std::string main_output(const WritingCommand& row, const std::string& path) { return row.output_option + path; }

  // No temporary of an output left behind (today's names, and the OUT.tmp-PID of earlier versions).
  void expect_no_temporaries() const {
    for (const std::string& name : files())
      EXPECT_TRUE(name.find(".hocav-") == std::string::npos && name.find(".tmp") == std::string::npos) << "left behind: " << name;
  }

  // Exit 2 and a last line "hocav: ..." naming `named`; at most `lines` lines, none with a control
  // or non-ASCII byte, none long.
  void expect_clean_failure(const std::string& arguments, const std::string& named, int lines = 1) const {
    const Outcome result = run(arguments);
    EXPECT_EQ(result.exit_code, 2) << "hocav " << arguments << "\n" << result.err;
    EXPECT_GE(count_lines(result.err), 1);
    EXPECT_LE(count_lines(result.err), lines) << result.err;
    const std::size_t last_line = result.err.rfind('\n', result.err.size() - 2) + 1;
    EXPECT_EQ(result.err.compare(last_line, 7, "hocav: "), 0) << result.err;
    EXPECT_NE(result.err.find(named), std::string::npos) << "message does not name " << named << ": " << result.err;
    for (unsigned char byte : result.err) EXPECT_TRUE(byte == '\n' || (byte >= 0x20 && byte < 0x7f)) << "raw byte " << int(byte);
    EXPECT_LT(result.err.size(), 300u * static_cast<std::size_t>(lines)) << result.err;
  }
};

TEST_F(CarefulUser, EveryCommandWritesAllItsOutputsAndNoTemporary) {
  prepare_inputs();
  for (const WritingCommand& row : kWritingCommands) {
    SCOPED_TRACE(row.name);
    std::string arguments = row.command + " " + main_output(row, "out" + row.output_extension);
    for (const auto& [option, name] : row.secondary) arguments += " " + option + " " + name;
    run_ok(arguments);
    EXPECT_TRUE(fs::exists(path("out" + row.output_extension)));
    for (const auto& secondary : row.secondary) EXPECT_TRUE(fs::exists(path(secondary.second))) << secondary.first;
    expect_no_temporaries();
  }
}

TEST_F(CarefulUser, AFailingSecondaryOutputReplacesNothing) {
  prepare_inputs();
  for (const WritingCommand& row : kWritingCommands)
    for (const auto& [option, name] : row.secondary)
      for (const std::string folder : {"/nonexistent/", "missing/"}) {
        SCOPED_TRACE(row.name + " " + option + " " + folder);
        const std::string output = "old" + row.output_extension;
        write(output, "the old file");
        expect_clean_failure(row.command + " " + main_output(row, output) + " " + option + " " + folder + name, folder);
        EXPECT_EQ(read(output), "the old file");
        expect_no_temporaries();
      }
}

TEST_F(CarefulUser, AnOutputNamingAnInputOrAnotherOutputIsRefusedInEveryForm) {
  prepare_inputs();
  fs::create_symlink(path("square.mesh"), path("link.mesh"));
  for (const WritingCommand& row : kWritingCommands) {
    SCOPED_TRACE(row.name);
    const std::string output = "out" + row.output_extension;
    for (const std::string& input : row.inputs)
      for (const std::string& alias : {input, "./" + input}) {
        const std::string before = read(input);
        expect_clean_failure(row.command + " " + main_output(row, alias), alias);
        for (const auto& secondary : row.secondary)
          expect_clean_failure(row.command + " " + main_output(row, output) + " " + secondary.first + " " + alias, alias);
        EXPECT_EQ(read(input), before);
      }
    if (!row.inputs.empty()) expect_clean_failure(row.command + " " + main_output(row, "link.mesh"), "link.mesh");
    for (const auto& secondary : row.secondary)
      expect_clean_failure(row.command + " " + main_output(row, output) + " " + secondary.first + " ./" + output, "./" + output);
    EXPECT_FALSE(fs::exists(path(output)));
    expect_no_temporaries();
  }
}

TEST_F(CarefulUser, AWriteThatFailsForLackOfSpaceReplacesNothing) {
  prepare_inputs();
  for (const WritingCommand& row : kWritingCommands) {
    SCOPED_TRACE(row.name);
    const std::string output = "old" + row.output_extension;
    write(output, "the old file");
    std::string arguments = row.command + " " + main_output(row, output);
    for (const auto& [option, name] : row.secondary) arguments += " " + option + " " + name;
    // ulimit -f 0: no byte can go to a file, as on a full disk; stderr goes through a pipe, which the limit spares.
    const std::string command = "cd '" + directory_.string() + "' || exit 1; (ulimit -f 0; exec '" HOCAV_BINARY "' " + arguments +
                                " 2>&1 > /dev/null) | cat > stderr.txt";
    ASSERT_EQ(std::system(command.c_str()), 0);
    const std::string message = read("stderr.txt");
    fs::remove(path("stderr.txt"));
    EXPECT_NE(message.find("hocav: " + output + ": write failed"), std::string::npos) << message;
    EXPECT_EQ(read(output), "the old file");
    for (const auto& secondary : row.secondary) EXPECT_FALSE(fs::exists(path(secondary.second))) << secondary.first;
    expect_no_temporaries();
  }
}

TEST_F(CarefulUser, OutputNamesOfTheLongestLegalLengthAndOddCharactersWork) {
  prepare_inputs();
  for (const WritingCommand& row : kWritingCommands) {
    SCOPED_TRACE(row.name);
    const std::string longest = std::string(255 - row.output_extension.size(), 'a') + row.output_extension;  // 255 bytes
    run_ok(row.command + " " + main_output(row, longest));
    EXPECT_TRUE(fs::exists(path(longest)));
    run_ok(row.command + " " + main_output(row, "'odd name é -x'" + row.output_extension));
    EXPECT_TRUE(fs::exists(path("odd name é -x" + row.output_extension)));
    fs::create_directory(path("folder" + row.output_extension));
    expect_clean_failure(row.command + " " + main_output(row, "folder" + row.output_extension), "folder");
    expect_clean_failure(row.command + " " + main_output(row, "/dev/null"), "/dev/null");
    expect_clean_failure(row.command + " " + main_output(row, "out.txt"), "out.txt");  // no such format
    expect_no_temporaries();
  }
}

TEST_F(CarefulUser, AKilledCommandLeavesNoTemporaryAndNoPartialOutput) {
  // SIGTERM while generating or writing 750k tetrahedra (SIGINT, which a shell's background jobs
  // ignore, is tested in output_set_test). Either nothing is left, or the output was committed
  // whole before the signal landed (it may land between the rename and the exit): then it reads back.
  const std::string command = "cd '" + directory_.string() +
                              "' || exit 1; '" HOCAV_BINARY
                              "' generate cube --h 0.02 -o big.meshb > /dev/null 2>&1 & pid=$!; sleep 0.3; kill -TERM $pid; wait $pid";
  const int status = std::system(command.c_str());
  const bool finished_first = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (finished_first || fs::exists(path("big.meshb"))) run_ok("stats big.meshb");
  expect_no_temporaries();
}

// Bad input files: a row per format and defect. Each must fail at once with a short, escaped line.
struct BadFile {
  std::string name, bytes, named;  // `named`: a fragment of the message
};

std::string repeated(const std::string& text, int times) {
  std::string result;
  for (int i = 0; i < times; ++i) result += text;
  return result;
}

const std::vector<BadFile> kBadMeshes{
    {"empty.mesh", "", "empty.mesh"},
    {"escape.mesh", "Dimension 3\n\033[2J\033[31mX\n", "\\x1b[2J"},
    {"long-token.mesh", "Dimension 3\n" + std::string(1 << 20, 'x') + "\n", "bytes)"},
    {"garbage.mesh", repeated(std::string("\x01\x7f\xfe\x1b[0m G\n", 9), 400), "garbage.mesh"},
    {"negative.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n-3\n", "negative count"},
    {"truncated.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 0 0\n", "truncated.mesh"},
    {"index.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\nTriangles\n1\n1 2 9 0\nEnd\n", "9"},
    {"nan.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\nnan 0 0\n0 1 0\nTriangles\n1\n1 2 3 0\nEnd\n", "finite"},
    {"garbage.meshb", std::string("\x01\0\0\0\x02\0\0\0", 8) + repeated("\xff\x13", 50), "garbage.meshb"},
    {"header.meshb", std::string("\x01\0\0\0", 4), "header.meshb"},
    {"old.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", "2.2"},
    {"truncated.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n", "truncated.msh"},
};

// `command` with every mention of input `input` replaced by `replacement`.
std::string with_input(std::string command, const std::string& input, const std::string& replacement) {
  for (std::size_t at = command.find(input); at != std::string::npos; at = command.find(input, at + replacement.size()))
    command.replace(at, input.size(), replacement);
  return command;
}

TEST_F(CarefulUser, BadMeshFilesFailAtOnceWithAShortEscapedLine) {
  prepare_inputs();
  for (const BadFile& file : kBadMeshes) {
    SCOPED_TRACE(file.name);
    write(file.name, file.bytes);
    expect_clean_failure("stats " + file.name, file.named, 2);  // a warning may come first
    for (const WritingCommand& row : kWritingCommands)
      if (!row.inputs.empty())
        expect_clean_failure(with_input(row.command, "square.mesh", file.name) + " " + main_output(row, "out" + row.output_extension),
                             file.named, 2);
  }
  expect_no_temporaries();
}

TEST_F(CarefulUser, TruncatedBinaryFilesAreRefused) {
  run_ok("generate cube --h 0.5 -o cube.meshb");
  run_ok("metric cube.meshb --analytic uniform --h 0.5 -o cube.solb");
  const std::string mesh = read("cube.meshb"), metric = read("cube.solb");
  // 2860 bytes end on a block boundary of this file: every block read whole, only End missing.
  for (std::size_t size : {std::size_t{2860}, mesh.size() / 2, mesh.size() - 1}) {
    write("cut.meshb", mesh.substr(0, size));
    expect_clean_failure("stats cut.meshb", "cut.meshb");
  }
  write("cut.solb", metric.substr(0, metric.size() - 4));  // the End keyword's NextPos cut
  expect_clean_failure("curve cube.meshb --metric cut.solb -o out.meshb", "cut.solb");
  EXPECT_FALSE(fs::exists(path("out.meshb")));
}

const std::vector<BadFile> kBadMetrics{
    {"rows.sol", "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n2\n1 3\n1 0 1\n1 0 1\nEnd\n", "rows.sol"},
    {"nan.sol", "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n1\n1 3\nnan 0 1\nEnd\n", "nan.sol"},
    {"empty.sol", "", "empty.sol"},
    {"escape.sol", "\033]0;title\007", "escape.sol"},
};

TEST_F(CarefulUser, BadMetricFilesFailAtOnceWithAShortEscapedLine) {
  prepare_inputs();
  for (const BadFile& file : kBadMetrics)
    for (const WritingCommand& row : kWritingCommands)
      if (row.command.find("square.sol") != std::string::npos) {
        SCOPED_TRACE(row.name + " " + file.name);
        write(file.name, file.bytes);
        const std::string output = "out" + row.output_extension;
        expect_clean_failure(with_input(row.command, "square.sol", file.name) + " " + main_output(row, output), file.named, 2);
        EXPECT_FALSE(fs::exists(path(output)));
      }
  expect_no_temporaries();
}

// Options that mean nothing: NaN and infinities, empty size ranges, options of another source, jobs
// too large to build. Each refused before any work.
const std::vector<std::pair<std::string, std::string>> kMeaninglessOptions{
    {"curve square.mesh --metric square.sol -o o.meshb --jacobian-floor nan", "nan"},
    {"curve square.mesh --metric square.sol -o o.meshb --jacobian-floor inf", "inf"},
    {"metric square.mesh --analytic linear --h-min 1 --h-max 0.5 -o o.sol", "--h-max"},
    {"metric square.mesh --analytic shear-circle --h-min 0.2 --h-max 0.1 -o o.sol", "--h-max"},
    {"metric square.mesh --analytic uniform --center 0.3 -o o.sol", "--center"},
    {"metric square.mesh --analytic uniform --h-min 0.01 -o o.sol", "--h-min"},
    {"metric square.mesh --analytic linear --h 0.1 -o o.sol", "--h"},
    {"metric square.mesh --analytic uniform --h nan -o o.sol", "nan"},
    {"metric square.mesh --analytic uniform --h 0.1 --gradation inf -o o.sol", "inf"},
    {"metric square.mesh --analytic shear-circle --radius nan -o o.sol", "nan"},
    {"metric square.mesh --analytic shear-circle --origin 0,nan -o o.sol", "nan"},
    {"generate square --h nan -o o.mesh", "nan"},
    {"generate annulus --r-out inf -o o.mesh", "inf"},
    {"generate cube --h 0.0005 -o o.mesh", "elements"},
    {"demo --h nan -o demo", "nan"},
    {"picture square.mesh -o o.svg --detail 0 0 nan 1", "nan"},
    {"bench --sizes inf", "inf"},
};

TEST_F(CarefulUser, MeaninglessOptionsAreRefusedBeforeAnyWork) {
  prepare_inputs();
  for (const auto& [arguments, named] : kMeaninglessOptions) {
    SCOPED_TRACE(arguments);
    const Outcome result = run(arguments);
    EXPECT_EQ(result.exit_code, 2) << result.out;
    EXPECT_NE(result.err.find(named), std::string::npos) << result.err;
  }
  EXPECT_EQ(files(), (std::set<std::string>{"square.mesh", "square.sol"}));
}

// A square whose boundary is given twice on one side (a duplicated boundary edge): inconsistent.
constexpr const char* kDuplicatedFacet =
    "MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
    "Triangles\n2\n1 2 3 1\n1 3 4 1\nEdges\n5\n1 2 1\n2 3 1\n3 4 1\n4 1 1\n1 2 1\nEnd\n";
// The same square with two sides left without boundary edges: consistent, but open.
constexpr const char* kOpenBoundary =
    "MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
    "Triangles\n2\n1 2 3 1\n1 3 4 1\nEdges\n2\n1 2 1\n2 3 1\nEnd\n";
constexpr const char* kUnitMetric = "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n4\n1 3\n4 0 4\n4 0 4\n4 0 4\n4 0 4\nEnd\n";

TEST_F(CarefulUser, CurveRefusesAnInconsistentMeshAsStatsDoesAndNamesTheProblem) {
  write("duplicated.mesh", kDuplicatedFacet);
  write("unit.sol", kUnitMetric);
  EXPECT_EQ(run("stats duplicated.mesh").exit_code, 2);
  expect_clean_failure("curve duplicated.mesh --metric unit.sol -o out.meshb", "duplicated.mesh: inconsistent mesh");
  EXPECT_FALSE(fs::exists(path("out.meshb")));
}

// The square with both triangles listed clockwise (a mesh written with the other orientation
// convention), and with one of them only (a defect).
constexpr const char* kInvertedSquare =
    "MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
    "Triangles\n2\n1 3 2 1\n1 4 3 1\nEdges\n4\n1 2 1\n2 3 1\n3 4 1\n4 1 1\nEnd\n";
constexpr const char* kHalfInvertedSquare =
    "MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
    "Triangles\n2\n1 3 2 1\n1 3 4 1\nEdges\n4\n1 2 1\n2 3 1\n3 4 1\n4 1 1\nEnd\n";
constexpr const char* kSquare =
    "MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
    "Triangles\n2\n1 2 3 1\n1 3 4 1\nEdges\n4\n1 2 1\n2 3 1\n3 4 1\n4 1 1\nEnd\n";

TEST_F(CarefulUser, AMeshGivenAllInvertedIsReorientedAsMmgDoesAndAHalfInvertedOneRefused) {
  write("inverted.mesh", kInvertedSquare);
  write("half.mesh", kHalfInvertedSquare);
  write("square.mesh", kSquare);
  write("unit.sol", kUnitMetric);
  const std::string warning =
      "hocav: warning: inverted.mesh: every one of its 2 elements is negatively oriented (the other convention): reoriented";
  for (const char* command : {"adapt", "curve"}) {
    SCOPED_TRACE(command);
    const Outcome turned = run_ok(std::string(command) + " inverted.mesh --metric unit.sol -o turned.meshb -q");
    EXPECT_NE(turned.err.find(warning), std::string::npos) << turned.err;
    run_ok(std::string(command) + " square.mesh --metric unit.sol -o straight.meshb -q");
    EXPECT_EQ(read("turned.meshb"), read("straight.meshb"));
    expect_clean_failure(std::string(command) + " half.mesh --metric unit.sol -o half.meshb", "half.mesh: inconsistent mesh");
    EXPECT_FALSE(fs::exists(path("half.meshb")));
  }
}

TEST_F(CarefulUser, CurveAndStatsNameTheDefectsOfAnOpenMesh) {
  write("open.mesh", kOpenBoundary);
  write("unit.sol", kUnitMetric);
  // curve gives the open faces facets of ref 0 (so that their boundary curves too) and says so.
  const Outcome curved = run_ok("curve open.mesh --metric unit.sol -o out.meshb -q");
  EXPECT_NE(curved.err.find("hocav: warning: open.mesh: 2 boundary faces had no facet: facets of ref 0 made for them"), std::string::npos)
      << curved.err;
  EXPECT_EQ(stats_json("out.meshb", "d[\"open_boundary_faces\"], d[\"counts\"][\"boundary_facets\"]"), "(0, 4)");
  const Outcome stats = run_ok("stats open.mesh");
  EXPECT_NE(stats.out.find("yes, but with defects: 2 open boundary faces"), std::string::npos) << stats.out;
  EXPECT_EQ(stats_json("open.mesh", "d[\"defects\"][\"summary\"].startswith(\"2 open\")"), "True");
}

TEST_F(CarefulUser, ThirdPartyChatterStaysOffStandardOutput) {
  HOCAV_SKIP_WITHOUT_GMSH();
  const Outcome generated = run_ok("generate annulus --h 0.4 -o a.mesh --cad-out a.step");
  EXPECT_EQ(count_lines(generated.out), 2) << generated.out;
  EXPECT_EQ(generated.out.find('\033'), std::string::npos);
  run_ok("metric a.mesh --analytic uniform --h 0.4 -o a.sol");
  const Outcome curved = run_ok("curve a.mesh --metric a.sol --surface cad:a.step -o c.mesh -q");
  EXPECT_EQ(curved.out, "");
}

}  // namespace
}  // namespace hocav::cli_test
