// `hocav --version` against CHANGELOG.md, and the defaults in every command's --help: an option that
// takes a value shows its default (CLI11's `=VALUE`, or "default ..." in its text) unless it is
// listed below as having none (leaving it out means "not done" or "not given").
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <thread>

#include "cli_test_support.hpp"

namespace hocav::cli_test {
namespace {

// One option of a help text: its first column ("--order INT:{1,2}=1") and its description.
struct HelpOption {
  std::string name, signature, text;
};

// The lines of a help text from `heading` to the next blank line.
std::vector<std::string> section(const std::string& help, const std::string& heading) {
  std::istringstream in(help);
  std::vector<std::string> lines;
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (inside && line.empty()) break;
    if (inside) lines.push_back(line);
    inside = inside || line == heading;
  }
  return lines;
}

std::vector<HelpOption> options_of(const std::string& help) {
  std::vector<HelpOption> options;
  for (const std::string& line : section(help, "Options:")) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == 2 && line[2] == '-') {
      const std::size_t gap = line.find("  ", start);
      HelpOption option;
      option.signature = line.substr(start, gap == std::string::npos ? std::string::npos : gap - start);
      option.text = gap == std::string::npos ? "" : line.substr(gap);
      const std::string names = option.signature.substr(0, option.signature.find(' '));
      option.name = names.substr(names.rfind(',') + 1);
      options.push_back(option);
    } else if (!options.empty()) {
      options.back().text += line;  // the description continues
    }
  }
  return options;
}

std::vector<std::string> subcommands_of(const std::string& help) {
  std::vector<std::string> names;
  for (const std::string& line : section(help, "Subcommands:")) names.push_back(line.substr(2, line.find(' ', 2) - 2));
  return names;
}

bool takes_value(const HelpOption& option) { return option.signature.find(' ') != std::string::npos; }
bool shows_default(const HelpOption& option) {
  return option.signature.find('=') != std::string::npos || option.text.find("default") != std::string::npos;
}

// Options without a default, per command.
const std::map<std::string, std::set<std::string>> kWithoutDefault = {
    {"convert", {"--metric"}},
    {"stats", {"--metric"}},
    {"generate", {"--cad-out"}},
    {"metric", {"--analytic", "--surface", "--hessian", "--input", "--from", "--from-metric", "--gradation", "--complexity"}},
    {"curve", {"--report", "--vtu"}},
    {"adapt",
     {"--metric", "--analytic", "--hessian", "--complexity", "--surface-sizes", "--hmin", "--hmax", "--hgrad", "--report", "--vtu"}},
    {"bench", {"--markdown", "--json"}},
    {"demo", {}},
    {"picture", {"--detail"}},
};

class HelpCli : public Cli {
 protected:
  // Checks every option of `command`'s help; returns the help's options.
  std::vector<HelpOption> expect_defaults_shown(const std::string& command, const std::set<std::string>& without_default) {
    const std::string help = run_ok(command + " --help").out;
    const std::vector<HelpOption> options = options_of(help);
    EXPECT_GE(options.size(), 2u) << "no options parsed from:\n" << help;
    for (const HelpOption& option : options) {
      if (!takes_value(option) || option.signature.find("REQUIRED") != std::string::npos) continue;
      if (without_default.contains(option.name)) {
        EXPECT_FALSE(shows_default(option)) << command << " " << option.name << " has a default: drop it from kWithoutDefault";
        continue;
      }
      EXPECT_TRUE(shows_default(option)) << command << " " << option.name << " does not show its default: " << option.signature
                                         << option.text;
    }
    return options;
  }
};

TEST_F(HelpCli, EveryCommandShowsTheDefaultsOfItsOptions) {
  const std::vector<std::string> commands = subcommands_of(run_ok("--help").out);
  EXPECT_EQ(commands.size(), kWithoutDefault.size());
  for (const std::string& command : commands) {
    auto listed = kWithoutDefault.find(command);
    if (listed == kWithoutDefault.end()) {
      ADD_FAILURE() << "new command " << command << ": list its options without default in kWithoutDefault";
      continue;
    }
    expect_defaults_shown(command, listed->second);
  }
  for (const std::string& generated_case : subcommands_of(run_ok("generate --help").out))
    expect_defaults_shown("generate " + generated_case, {});
}

TEST_F(HelpCli, ThreadsDefaultToEveryCore) {
  const std::string cores = std::to_string(std::max(1u, std::thread::hardware_concurrency()));
  const std::map<std::string, std::string> shown = {
      {"curve", "=" + cores}, {"adapt", "=" + cores}, {"demo", "=" + cores}, {"bench", "=[" + cores + "]"}};
  for (const auto& [command, default_shown] : shown) {
    const std::vector<HelpOption> options = options_of(run_ok(command + " --help").out);
    auto threads = std::find_if(options.begin(), options.end(), [](const HelpOption& o) { return o.name == "--threads"; });
    ASSERT_NE(threads, options.end()) << command;
    EXPECT_TRUE(threads->signature.ends_with(default_shown) || threads->signature.ends_with(default_shown + " ..."))
        << command << ": " << threads->signature;
  }
}

// The version `hocav --version` prints is the top entry of CHANGELOG.md, and a commit is named.
TEST_F(HelpCli, VersionIsTheChangelogsTopEntry) {
  // Plain string parsing: std::regex trips GCC 12's uninitialized-use warnings in the sanitizer build.
  const std::string changelog = read_text(HOCAV_SOURCE_DIR "/CHANGELOG.md");
  const std::size_t heading = changelog.find("\n## ");
  ASSERT_NE(heading, std::string::npos) << "no version heading";
  const std::size_t start = heading + 4, end = changelog.find_first_not_of("0123456789.", start);
  const std::string version = changelog.substr(start, end - start);
  ASSERT_EQ(std::count(version.begin(), version.end(), '.'), 2) << "not a version: " << version;
  const std::string printed = run_ok("--version").out;
  const std::string prefix = "hocav " + version + " (commit ";
  ASSERT_EQ(printed.rfind(prefix, 0), 0u) << printed;
  ASSERT_TRUE(printed.ends_with(")\n")) << printed;
  const std::string commit = printed.substr(prefix.size(), printed.size() - prefix.size() - 2);
  EXPECT_TRUE(commit == "unknown" ||
              (commit.size() >= 4 && commit.size() <= 40 && commit.find_first_not_of("0123456789abcdef") == std::string::npos))
      << printed;
}

}  // namespace
}  // namespace hocav::cli_test
