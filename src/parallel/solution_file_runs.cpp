#include "parallel/solution_file_runs.hpp"

#include <cstdint>
#include <fstream>

#include "base/error.hpp"
#include "io/output_set.hpp"
#include "parallel/communicator.hpp"

namespace hocav {
namespace {

// Where rank 0 wrote the file's keywords: the file, and its rows' layout.
struct Skeleton {
  std::string file;
  SolutionRowsLayout layout;
};

Skeleton skeleton_from_rank_0(const std::string& path, const SolutionField& run, Index count) {
  Skeleton skeleton;
  if (process_rank() == 0) {
    skeleton.layout = write_solution_skeleton(path, run.dimension, count, {run.kind});
    const OutputSet* outputs = OutputSet::active();
    skeleton.file = outputs ? outputs->written_temporary(path) : path;
  }
  std::vector<SolutionRowsLayout> layout{skeleton.layout};
  broadcast_values(layout);
  std::vector<char> file(skeleton.file.begin(), skeleton.file.end());
  broadcast_values(file);
  return {std::string(file.begin(), file.end()), layout.at(0)};
}

}  // namespace

void write_solution_runs(const std::string& path, const SolutionField& run, Index first_row, Index count) {
  const Skeleton skeleton = skeleton_from_rank_0(path, run, count);
  if (static_cast<std::uint64_t>(run.components()) * sizeof(double) != skeleton.layout.row_bytes || first_row + run.count() > count)
    throw Error(path + ": the rows of a distributed solution file do not fit its layout");
  std::fstream out(skeleton.file, std::ios::in | std::ios::out | std::ios::binary);
  out.seekp(
      static_cast<std::streamoff>(skeleton.layout.first_row_offset + skeleton.layout.row_bytes * static_cast<std::uint64_t>(first_row)));
  out.write(reinterpret_cast<const char*>(run.values.data()), static_cast<std::streamsize>(run.values.size() * sizeof(double)));
  out.close();
  if (!out) throw Error(path + ": cannot write rows " + one_based(first_row) + " on (rank " + std::to_string(process_rank()) + ")");
  all_gather_value(0);  // every run is in place before rank 0 commits the file
}

}  // namespace hocav
