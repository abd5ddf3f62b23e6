// Helpers of the Gamma mesh and solution tests: scratch files (temporary_files.hpp), error messages, and a builder of binary files
// written independently of hocav's writer (it patches NextPos after the fact, the writer computes it
// ahead), so the tests can check the layout against docs/formats.md ("Binary layout") byte by byte.
#pragma once

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "temporary_files.hpp"

namespace hocav::testing_support {

// The message of the Error `action` throws, or "no error".
inline std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

inline std::string write_file(const std::string& name, const std::string& bytes) {
  std::string path = temporary_path(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// Files in `directory` whose name starts with `prefix` (to find leftover temporaries).
inline std::vector<std::string> files_starting_with(const std::string& directory, const std::string& prefix) {
  std::vector<std::string> found;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    if (entry.path().filename().string().rfind(prefix, 0) == 0) found.push_back(entry.path().string());
  return found;
}

class GammaBinaryBuilder {
 public:
  // swap: write every word byte-swapped, as a machine of the other endianness would.
  explicit GammaBinaryBuilder(int version, bool swap = false) : version_(version), swap_(swap) {
    int32(1);
    int32(version);
  }

  void int32(std::int32_t value) { put(value); }
  void int64(std::int64_t value) { put(value); }
  void position(std::int64_t value) { version_ >= 3 ? int64(value) : int32(static_cast<std::int32_t>(value)); }
  void integer(std::int64_t value) { version_ >= 4 ? int64(value) : int32(static_cast<std::int32_t>(value)); }
  void count(std::int64_t value) { integer(value); }
  void real(double value) { version_ == 1 ? put(static_cast<float>(value)) : put(value); }

  // A keyword whose NextPos end_keyword() sets to the size reached (patch_position() to anything).
  void begin_keyword(int code) {
    int32(code);
    next_position_at_ = bytes_.size();
    position(0);
  }
  void end_keyword() { patch_position(next_position_at_, static_cast<std::int64_t>(bytes_.size())); }
  void patch_position(std::size_t at, std::int64_t value) {
    std::string saved = bytes_.substr(at);
    bytes_.resize(at);
    position(value);
    bytes_ += saved.substr(version_ >= 3 ? 8 : 4);
  }
  std::size_t next_position_at() const { return next_position_at_; }

  void dimension(int dimension) {
    begin_keyword(3);
    int32(dimension);
    end_keyword();
  }
  void end() {
    int32(54);
    position(0);
  }

  const std::string& bytes() const { return bytes_; }

 private:
  template <class Word>
  void put(Word value) {
    char raw[sizeof(Word)];
    std::memcpy(raw, &value, sizeof value);
    if (swap_)
      for (std::size_t i = 0; i < sizeof(Word) / 2; ++i) std::swap(raw[i], raw[sizeof(Word) - 1 - i]);
    bytes_.append(raw, sizeof raw);
  }

  int version_;
  bool swap_;
  std::string bytes_;
  std::size_t next_position_at_ = 0;
};

}  // namespace hocav::testing_support
