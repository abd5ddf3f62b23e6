#include "io/atomic_output.hpp"

#include <unistd.h>

#include <cstdio>

#include "base/error.hpp"

namespace hocav {

AtomicOutput::AtomicOutput(std::string path)
    : path_(std::move(path)), temporary_path_(path_ + ".tmp-" + std::to_string(::getpid())) {
  stream_.open(temporary_path_, std::ios::binary | std::ios::trunc);
  if (!stream_) throw Error(path_ + ": cannot open for writing");
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    stream_.close();
    std::remove(temporary_path_.c_str());
  }
}

void AtomicOutput::commit() {
  stream_.flush();
  bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written || stream_.fail()) throw Error(path_ + ": write failed (disk full?)");
  if (std::rename(temporary_path_.c_str(), path_.c_str()) != 0) throw Error(path_ + ": cannot rename the temporary file into place");
  committed_ = true;
}

}  // namespace hocav
