// The outputs of one command, written all or none. A command registers its inputs and outputs
// before any work: each output is checked then (its folder exists and is writable, it is not a
// folder or a device, it names no input and no other output, also through symlinks, hard links
// and ./ forms), so a bad path fails in a moment rather than after the work. Writers (AtomicOutput,
// or any code given temporary_for) write to temporaries beside the targets; commit() renames them
// all into place at the end. Until then no target is touched, and the destructor (or SIGINT/SIGTERM)
// removes the temporaries.
#pragma once

#include <string>
#include <vector>

namespace hocav {

class OutputSet {
 public:
  // Becomes the process's active set, the one AtomicOutput writes through (one at a time).
  OutputSet();
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // `option` names the path in messages: "-o", "--report", "input mesh", ...
  void add_input(const std::string& path, const std::string& option);
  // Throws Error when the output cannot be written or collides with an input or another output.
  void add_output(const std::string& path, const std::string& option);

  // A new temporary for registered output `path`, renamed onto it by commit(). Throws Error for a
  // path that was not registered (a command that forgot to declare an output).
  std::string temporary_for(const std::string& path);
  // The temporary written for registered output `path` so far, or empty.
  const std::string& written_temporary(const std::string& path) const;
  // Renames every temporary onto its target. Throws Error naming the first that fails.
  void commit();

  // The active set, or nullptr (library use: AtomicOutput then renames on its own).
  static OutputSet* active();

 private:
  struct Entry {
    std::string path, option, identity;
    bool is_output = false;
    std::string temporary;  // empty until written
  };
  void add(const std::string& path, const std::string& option, bool is_output);

  std::vector<Entry> entries_;
  OutputSet* previous_ = nullptr;
};

}  // namespace hocav
