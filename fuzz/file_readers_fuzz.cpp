// Feeds arbitrary bytes to every file reader: each must either read the file or throw
// hocav::Error; a crash, a sanitizer report, a hang or any other exception is a bug.
// The first byte picks the format; the rest is the file.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "base/error.hpp"
#include "io/mesh_file.hpp"
#include "io/solution_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const kExtensions[] = {".mesh", ".meshb", ".msh", ".sol", ".solb"};
  if (size == 0) return 0;
  const char* extension = kExtensions[data[0] % 5];
  static const std::string stem = "/tmp/hocav-fuzz-" + std::to_string(::getpid());
  std::string path = stem + extension;
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    if (data[0] % 5 < 3)
      hocav::read_mesh_file(path);
    else
      hocav::read_solution_file(path);
  } catch (const hocav::Error&) {
  }
  std::remove(path.c_str());
  return 0;
}
