#include "parallel/file_in_runs.hpp"

#include <vector>

#include "io/output_set.hpp"
#include "parallel/communicator.hpp"

namespace hocav {

std::string file_begun_on_rank_0(const std::string& path) {
  std::string file;
  if (process_rank() == 0) {
    const OutputSet* outputs = OutputSet::active();
    file = outputs ? outputs->written_temporary(path) : path;
  }
  std::vector<char> name(file.begin(), file.end());
  broadcast_values(name);
  return {name.begin(), name.end()};
}

}  // namespace hocav
