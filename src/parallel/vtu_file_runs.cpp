#include "parallel/vtu_file_runs.hpp"

#include <fstream>

#include "base/error.hpp"
#include "io/atomic_output.hpp"
#include "parallel/communicator.hpp"
#include "parallel/file_in_runs.hpp"

namespace hocav {
namespace {

// Per array (in block order) the bytes of each process's run, process by process.
std::vector<std::vector<std::uint64_t>> runs_bytes(const std::vector<VtuArray>& arrays) {
  std::vector<std::uint64_t> own;
  for (const VtuArray& array : arrays) own.push_back(array.bytes);
  return all_gather_values(own);
}

}  // namespace

template <int D>
void write_vtu_runs(const std::string& path, const Mesh<D>& mesh, const VtuData& data) {
  if (!mesh.is_compact()) throw std::logic_error("write_vtu_runs: a mesh that is not compact");
  const Index nodes = mesh.vertex_count() + (mesh.is_p2() ? mesh.edge_count() : 0);
  const CountOffset points = offset_over_processes(nodes), cells = offset_over_processes(mesh.element_count());
  const VtuArrays<D> arrays(path, mesh, data, points.before, cells.before);
  const std::vector<VtuArray>& block = arrays.in_block_order();
  const std::vector<std::vector<std::uint64_t>> runs = runs_bytes(block);
  std::vector<std::uint64_t> totals(block.size(), 0);
  for (const std::vector<std::uint64_t>& process : runs)
    for (std::size_t i = 0; i < totals.size(); ++i) totals[i] += process.at(i);
  std::vector<std::uint64_t> start{0};  // where the appended block begins
  if (process_rank() == 0) {
    AtomicOutput head(path);
    arrays.write_head(head.stream(), points.total, cells.total, totals);
    start[0] = static_cast<std::uint64_t>(head.stream().tellp());
    std::uint64_t end = start[0];
    for (std::uint64_t total : totals) end += sizeof(std::uint64_t) + total;
    head.stream().seekp(static_cast<std::streamoff>(end));
    head.stream() << VtuArrays<D>::kTail;
    head.commit();
  }
  broadcast_values(start);
  std::fstream out(file_begun_on_rank_0(path), std::ios::in | std::ios::out | std::ios::binary);
  std::uint64_t at = start[0];
  for (std::size_t i = 0; i < block.size(); ++i) {
    if (process_rank() == 0) {
      out.seekp(static_cast<std::streamoff>(at));
      VtuArrays<D>::write_size(out, totals[i]);
    }
    std::uint64_t own = at + sizeof(std::uint64_t);
    for (int r = 0; r < process_rank(); ++r) own += runs[static_cast<std::size_t>(r)][i];
    out.seekp(static_cast<std::streamoff>(own));
    block[i].write(out);
    at += sizeof(std::uint64_t) + totals[i];
  }
  out.close();
  if (!out) throw Error(path + ": cannot write the arrays of rank " + std::to_string(process_rank()));
  all_gather_value(0);  // every run is in place before rank 0 commits the file
}

template void write_vtu_runs(const std::string&, const Mesh<2>&, const VtuData&);
template void write_vtu_runs(const std::string&, const Mesh<3>&, const VtuData&);

}  // namespace hocav
