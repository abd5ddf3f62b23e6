// The third-party test files of ../shared/data beside the repository (mmg's torus, the UGAWG linear
// case). A bare clone has none: the tests that read them skip, naming the missing file. The
// environment variable HOCAV_SHARED_DATA_DIR points the tests elsewhere (at a missing folder, to
// check the skips).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <string>

namespace hocav::testing_support {

inline std::string shared_data_path(const std::string& relative) {
  const char* overridden = std::getenv("HOCAV_SHARED_DATA_DIR");
  return std::string(overridden != nullptr ? overridden : HOCAV_SHARED_DATA_DIR) + "/" + relative;
}

// Why a test cannot run ("missing <path> ..."), or empty when every file is there. Use as
//   if (auto missing = missing_shared_data({path}); !missing.empty()) GTEST_SKIP() << missing;
inline std::string missing_shared_data(std::initializer_list<std::string> paths) {
  for (const std::string& path : paths)
    if (!std::filesystem::exists(path)) return "missing " + path + " (../shared/data is not beside the repository)";
  return "";
}

}  // namespace hocav::testing_support
