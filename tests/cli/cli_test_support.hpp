// The scratch-folder fixture of the end-to-end tests of the `hocav` binary, and the test inputs
// several command test files share.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "gmsh_requirement.hpp"
#include "temporary_files.hpp"

namespace hocav::cli_test {

namespace fs = std::filesystem;

struct Outcome {
  int exit_code = -1;
  std::string out, err;
};

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline int count_lines(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n' ? 1 : 0;
  return lines;
}

// A P2 triangle whose file lists the three mid nodes before the corners, the mid node of the long
// edge moved off its straight midpoint. Readers must renumber; writers put corners first.
inline constexpr const char* kShuffledP2Triangle =
    "MeshVersionFormatted 2\nDimension 2\nVertices\n6\n"
    "0.5 0 0\n0.6 0.6 0\n0 0.5 0\n0 0 0\n1 0 0\n0 1 0\n"
    "TrianglesP2\n1\n4 5 6 1 2 3 1\nEnd\n";

// A metric that encodes its node's position: m11 = 1 + x + 10 y, so a row read back can be matched to
// the coordinates of the node it is written for.
inline double encoded_m11(double x, double y) { return 1 + x + 10 * y; }

inline std::string metric_for_shuffled_triangle(int rows, double first_m11_override = 0) {
  const double nodes[6][2] = {{0.5, 0}, {0.6, 0.6}, {0, 0.5}, {0, 0}, {1, 0}, {0, 1}};
  std::ostringstream sol;
  sol << "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n" << rows << "\n1 3\n";
  for (int i = 0; i < rows; ++i) {
    double m11 = i == 0 && first_m11_override != 0 ? first_m11_override : encoded_m11(nodes[i % 6][0], nodes[i % 6][1]);
    sol << m11 << " 0 1\n";
  }
  sol << "End\n";
  return sol.str();
}

// The rows of the first block `keyword` of a Gamma ASCII file: `columns` numbers per row.
inline std::vector<std::vector<double>> gamma_block(const std::string& text, const std::string& keyword, int columns,
                                                    int header_numbers = 0) {
  std::istringstream in(text);
  std::string token;
  while (in >> token && token != keyword) {
  }
  std::size_t count = 0;
  in >> count;
  for (int i = 0; i < header_numbers; ++i) in >> token;
  std::vector<std::vector<double>> rows(count, std::vector<double>(static_cast<std::size_t>(columns)));
  for (auto& row : rows)
    for (double& value : row) in >> value;
  return rows;
}

// The text of a .mesh file without its block `keyword` (the facets).
inline std::string without_block(const std::string& text, const std::string& keyword) {
  std::istringstream in(text);
  std::ostringstream out;
  std::string line;
  int to_skip = 0;  // lines of the block left: its count's, then its entries'
  while (std::getline(in, line)) {
    if (line == keyword) {
      std::getline(in, line);
      to_skip = std::stoi(line);
      continue;
    }
    if (to_skip > 0) {
      --to_skip;
      continue;
    }
    out << line << '\n';
  }
  return out.str();
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = testing_support::temporary_folder(); }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(directory_);
  }

  // Runs `hocav <arguments>` in the scratch folder.
  Outcome run(const std::string& arguments) const {
    std::string command = "cd '" + directory_.string() + "' && '" HOCAV_BINARY "' " + arguments + " > stdout.txt 2> stderr.txt";
    int status = std::system(command.c_str());
    Outcome result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_text(directory_ / "stdout.txt");
    result.err = read_text(directory_ / "stderr.txt");
    fs::remove(directory_ / "stdout.txt");
    fs::remove(directory_ / "stderr.txt");
    return result;
  }

  Outcome run_ok(const std::string& arguments) const {
    Outcome result = run(arguments);
    EXPECT_EQ(result.exit_code, 0) << "hocav " << arguments << "\n" << result.err;
    return result;
  }

  // Expects exit code 2 and one line "hocav: ..." naming `named` on stderr.
  void expect_failure(const std::string& arguments, const std::string& named) const {
    Outcome result = run(arguments);
    EXPECT_EQ(result.exit_code, 2) << "hocav " << arguments;
    EXPECT_EQ(count_lines(result.err), 1) << result.err;
    EXPECT_EQ(result.err.rfind("hocav: ", 0), 0u) << result.err;
    EXPECT_NE(result.err.find(named), std::string::npos) << "message does not name " << named << ": " << result.err;
  }

  fs::path path(const std::string& name) const { return directory_ / name; }
  void write(const std::string& name, const std::string& text) const { std::ofstream(path(name)) << text; }
  std::string read(const std::string& name) const { return read_text(path(name)); }

  std::set<std::string> files() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory_)) names.insert(entry.path().filename().string());
    return names;
  }

  // Evaluates a Python expression over the JSON document `d` printed by `hocav stats --json`:
  // an independent, strict parser checks the output is one valid JSON object.
  std::string stats_json(const std::string& arguments, const std::string& expression) const {
    Outcome result = run_ok("stats --json " + arguments);
    write("stats.json", result.out);
    std::string value = json_value("stats.json", expression);
    fs::remove(path("stats.json"));
    return value;
  }

  // Evaluates a Python expression over the JSON document `d` in file `name` of the scratch folder.
  std::string json_value(const std::string& name, const std::string& expression) const {
    std::string command = "/usr/bin/python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print((" + expression + "))' '" +
                          path(name).string() + "'";
    std::string value;
    if (FILE* pipe = popen(command.c_str(), "r")) {
      char buffer[4096];
      while (fgets(buffer, sizeof buffer, pipe)) value += buffer;
      EXPECT_EQ(pclose(pipe), 0) << "not valid JSON or no " << expression << ":\n" << read(name);
    }
    while (!value.empty() && value.back() == '\n') value.pop_back();
    return value;
  }

  fs::path directory_;
};

}  // namespace hocav::cli_test
