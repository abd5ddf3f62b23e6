// Output files appear whole or not at all: data goes to a short temporary name beside the target
// (see temporary_files.hpp). Inside a command's OutputSet, commit() checks the write and leaves the
// temporary for the set to rename with the command's other outputs; without one (library use),
// commit() renames it at once. A temporary not committed is removed.
#pragma once

#include <fstream>
#include <string>

namespace hocav {

class AtomicOutput {
 public:
  // Opens the temporary for writing (binary mode). Throws Error when it cannot.
  explicit AtomicOutput(std::string path);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  std::ofstream& stream() { return stream_; }
  // Flushes and checks for write errors, then renames or hands over to the OutputSet. Throws Error.
  void commit();

 private:
  std::string path_, temporary_path_;
  std::ofstream stream_;
  bool in_output_set_ = false;
  bool committed_ = false;
};

}  // namespace hocav
