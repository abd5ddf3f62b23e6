#include "parallel/file_in_runs.hpp"

#include <cstdint>
#include <fstream>
#include <vector>

#include "base/error.hpp"
#include "io/atomic_output.hpp"
#include "io/output_set.hpp"
#include "parallel/communicator.hpp"

namespace hocav {
namespace {

// Where each of this process's segments begins in the file, from every process's sizes.
std::vector<std::uint64_t> segment_starts(const std::vector<std::string>& segments) {
  std::vector<std::uint64_t> own;
  for (const std::string& segment : segments) own.push_back(segment.size());
  const std::vector<std::vector<std::uint64_t>> sizes = all_gather_values(own);  // per process, per segment
  std::vector<std::uint64_t> starts;
  std::uint64_t at = 0;
  for (std::size_t i = 0; i < segments.size(); ++i)
    for (std::size_t r = 0; r < sizes.size(); ++r) {
      if (sizes[r].size() != segments.size()) throw std::logic_error("write_segments_in_runs: processes with different segment counts");
      if (static_cast<int>(r) == process_rank()) starts.push_back(at);
      at += sizes[r][i];
    }
  return starts;
}

void write_at(std::ostream& out, const std::vector<std::string>& segments, const std::vector<std::uint64_t>& starts) {
  for (std::size_t i = 0; i < segments.size(); ++i)
    if (!segments[i].empty()) {
      out.seekp(static_cast<std::streamoff>(starts[i]));
      out.write(segments[i].data(), static_cast<std::streamsize>(segments[i].size()));
    }
}

}  // namespace

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

void write_segments_in_runs(const std::string& path, const std::vector<std::string>& segments) {
  const std::vector<std::uint64_t> starts = segment_starts(segments);
  if (process_rank() == 0) {
    AtomicOutput begun(path);
    write_at(begun.stream(), segments, starts);
    begun.commit();
  }
  const std::string file = file_begun_on_rank_0(path);
  if (process_rank() != 0) {
    std::fstream out(file, std::ios::in | std::ios::out | std::ios::binary);
    write_at(out, segments, starts);
    out.close();
    if (!out) throw Error(path + ": cannot write the records of rank " + std::to_string(process_rank()));
  }
  all_gather_value(0);  // every run is in place before rank 0 commits the file
}

}  // namespace hocav
