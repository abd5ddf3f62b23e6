// `hocav --version` against CHANGELOG.md.
#include <gtest/gtest.h>

#include <regex>

#include "cli_test_support.hpp"

namespace hocav::cli_test {
namespace {

// The version `hocav --version` prints is the top entry of CHANGELOG.md, and a commit is named.
TEST_F(Cli, VersionIsTheChangelogsTopEntry) {
  const std::string changelog = read_text(HOCAV_SOURCE_DIR "/CHANGELOG.md");
  std::smatch top;
  ASSERT_TRUE(std::regex_search(changelog, top, std::regex("\n## ([0-9]+\\.[0-9]+\\.[0-9]+)"))) << "no version heading";
  const std::string version = std::regex_replace(top[1].str(), std::regex("\\."), "\\.");
  const std::string printed = run_ok("--version").out;
  EXPECT_TRUE(std::regex_match(printed, std::regex("hocav " + version + " \\(commit ([0-9a-f]{4,40}|unknown)\\)\n"))) << printed;
}

}  // namespace
}  // namespace hocav::cli_test
