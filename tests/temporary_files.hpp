// Scratch files and folders of the unit tests. They lie in a folder of the test process under
// GoogleTest's temporary directory, named after the running test, so that tests run side by side
// (ctest -j, two checkouts at once) never share one; the folder goes when the process's tests end,
// unless one failed (its files are then there to look at).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace hocav::testing_support {

// The test process's scratch folder.
inline std::filesystem::path scratch_root() {
  return std::filesystem::path(::testing::TempDir()) / ("hocav_" + std::to_string(::getpid()));
}

// Removes the scratch folder after the process's tests, unless one failed.
class ScratchCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    if (!::testing::UnitTest::GetInstance()->Failed()) std::filesystem::remove_all(scratch_root());
  }
};

inline ::testing::Environment* const scratch_cleanup = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

// "<suite>_<test>", the running test's name in scratch names ('/' of parameterized names made '_').
inline std::string running_test_name() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = test ? std::string(test->test_suite_name()) + "_" + test->name() : "outside_tests";
  std::replace(name.begin(), name.end(), '/', '_');
  return name;
}

// A path for the running test's scratch file `name` (it may name a folder below, which the caller
// makes).
inline std::string temporary_path(const std::string& name) {
  std::filesystem::create_directories(scratch_root());
  return (scratch_root() / (running_test_name() + "_" + name)).string();
}

// A new empty scratch folder for the running test.
inline std::filesystem::path temporary_folder() {
  const std::filesystem::path folder = scratch_root() / running_test_name();
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

}  // namespace hocav::testing_support
