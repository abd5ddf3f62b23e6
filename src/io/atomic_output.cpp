#include "io/atomic_output.hpp"

#include <cstdio>

#include "base/error.hpp"
#include "io/output_set.hpp"
#include "io/temporary_files.hpp"

namespace hocav {

AtomicOutput::AtomicOutput(std::string path) : path_(std::move(path)), in_output_set_(OutputSet::active() != nullptr) {
  temporary_path_ = in_output_set_ ? OutputSet::active()->temporary_for(path_) : new_temporary_path(path_);
  stream_.open(temporary_path_, std::ios::binary | std::ios::trunc);
  if (!stream_) throw Error(path_ + ": cannot open for writing");
}

AtomicOutput::~AtomicOutput() {
  if (!committed_ && !in_output_set_) {
    stream_.close();
    remove_temporary(temporary_path_);
  }
}

void AtomicOutput::commit() {
  stream_.flush();
  bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written || stream_.fail()) throw Error(path_ + ": write failed (disk full?)");
  if (!in_output_set_) {
    if (std::rename(temporary_path_.c_str(), path_.c_str()) != 0) throw Error(path_ + ": cannot rename the temporary file into place");
    forget_temporary(temporary_path_);
  }
  committed_ = true;
}

}  // namespace hocav
