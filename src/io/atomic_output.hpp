// Output files appear whole or not at all: data goes to a temporary name beside the target and is
// renamed over it only when commit() is called; otherwise the temporary is removed.
#pragma once

#include <fstream>
#include <string>

namespace hocav {

class AtomicOutput {
 public:
  // Opens "<path>.tmp-<pid>" for writing (binary mode). Throws Error when it cannot.
  explicit AtomicOutput(std::string path);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  std::ofstream& stream() { return stream_; }
  // Flushes, checks for write errors, and renames the temporary to the target. Throws Error.
  void commit();

 private:
  std::string path_, temporary_path_;
  std::ofstream stream_;
  bool committed_ = false;
};

}  // namespace hocav
