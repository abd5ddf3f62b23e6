#include "parallel/root_mesh_scatter.hpp"

#include <chrono>

#include "base/stopwatch.hpp"
#include "parallel/communicator.hpp"
#include "parallel/part_migration.hpp"
#include "parallel/root_mesh_partition.hpp"

namespace hocav {
namespace {

// Collective: the metrics at the part's vertices, asked of rank 0, which holds `metrics` for every
// vertex by global id.
template <int D>
std::vector<SymMat<D>> metrics_from_root(const MeshPart<D>& part, const std::vector<SymMat<D>>& metrics, long long& bytes_sent) {
  std::vector<std::vector<Index>> asked(static_cast<std::size_t>(process_count()));
  asked[0] = part.global_ids;
  if (process_rank() != 0) bytes_sent += static_cast<long long>(part.global_ids.size() * sizeof(Index));
  const std::vector<std::vector<Index>> arrived = exchange_values(asked);
  std::vector<std::vector<SymMat<D>>> answers(arrived.size());
  for (std::size_t p = 0; p < arrived.size(); ++p) {
    for (Index g : arrived[p]) answers[p].push_back(metrics.at(static_cast<std::size_t>(g)));
    if (p != 0) bytes_sent += static_cast<long long>(answers[p].size() * sizeof(SymMat<D>));
  }
  return exchange_values(answers).at(0);
}

}  // namespace

template <int D>
ScatteredPart<D> scatter_from_root(Mesh<D> mesh, std::vector<SymMat<D>> metrics, std::int64_t seed) {
  const auto start = std::chrono::steady_clock::now();
  ScatteredPart<D> out;
  if (process_rank() == 0 && !mesh.has_topology()) mesh.build_topology();
  const std::vector<int> part_of = partition_from_root(mesh, seed, &out.bytes_sent);
  out.part = migrate_part(process_rank() == 0 ? whole_mesh_part(std::move(mesh)) : MeshPart<D>{}, part_of, &out.bytes_sent);
  out.metrics = metrics_from_root(out.part, metrics, out.bytes_sent);
  out.seconds = max_over_processes(seconds_since(start));
  return out;
}

template ScatteredPart<2> scatter_from_root(Mesh<2>, std::vector<SymMat<2>>, std::int64_t);
template ScatteredPart<3> scatter_from_root(Mesh<3>, std::vector<SymMat<3>>, std::int64_t);

}  // namespace hocav
