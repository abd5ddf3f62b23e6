#include "io/output_set.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "base/error.hpp"
#include "io/temporary_files.hpp"

namespace hocav {
namespace {

namespace fs = std::filesystem;

OutputSet* active_set = nullptr;

// What makes two paths the same file: the device and inode of an existing file (hard links,
// symlinks), otherwise the resolved path (symlinked folders, ./ and ../ forms).
std::string file_identity(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) return "inode " + std::to_string(status.st_dev) + ":" + std::to_string(status.st_ino);
  std::error_code error;
  return "path " + fs::weakly_canonical(fs::absolute(path), error).string();
}

std::string folder_of(const std::string& path) {
  const fs::path folder = fs::path(path).parent_path();
  return folder.empty() ? "." : folder.string();
}

void check_writable(const std::string& path, const std::string& option) {
  if (path.empty()) throw Error(option + ": empty output path");
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode))
    throw Error(path + ": " + option + " names " + (S_ISDIR(status.st_mode) ? "a folder" : "something other than a file"));
  const std::string folder = folder_of(path);
  if (::stat(folder.c_str(), &status) != 0 || !S_ISDIR(status.st_mode)) throw Error(path + ": " + option + ": no folder " + folder);
  if (::access(folder.c_str(), W_OK | X_OK) != 0) throw Error(path + ": " + option + ": folder " + folder + " is not writable");
}

}  // namespace

OutputSet::OutputSet() : previous_(active_set) { active_set = this; }

OutputSet::~OutputSet() {
  for (const Entry& entry : entries_)
    if (!entry.temporary.empty()) remove_temporary(entry.temporary);
  active_set = previous_;
}

OutputSet* OutputSet::active() { return active_set; }

void OutputSet::add_input(const std::string& path, const std::string& option) { add(path, option, false); }

void OutputSet::add_output(const std::string& path, const std::string& option) {
  check_writable(path, option);
  add(path, option, true);
}

void OutputSet::add(const std::string& path, const std::string& option, bool is_output) {
  Entry entry{path, option, file_identity(path), is_output, {}};
  for (const Entry& other : entries_)
    if (other.identity == entry.identity && (is_output || other.is_output))
      throw Error(path + ": " + option + " names the same file as " + other.option + " (" + other.path + ")");
  entries_.push_back(std::move(entry));
}

std::string OutputSet::temporary_for(const std::string& path) {
  for (Entry& entry : entries_)
    if (entry.is_output && entry.path == path) {
      if (!entry.temporary.empty()) remove_temporary(entry.temporary);
      entry.temporary = new_temporary_path(path);
      return entry.temporary;
    }
  throw Error("internal error: output " + path + " was not declared before the work");
}

const std::string& OutputSet::written_temporary(const std::string& path) const {
  for (const Entry& entry : entries_)
    if (entry.is_output && entry.path == path) return entry.temporary;
  throw Error("internal error: output " + path + " was not declared before the work");
}

void OutputSet::commit() {
  for (Entry& entry : entries_) {
    if (entry.temporary.empty()) continue;
    if (std::rename(entry.temporary.c_str(), entry.path.c_str()) != 0)
      throw Error(entry.path + ": cannot rename the temporary file into place");
    forget_temporary(entry.temporary);
    entry.temporary.clear();
  }
}

}  // namespace hocav
