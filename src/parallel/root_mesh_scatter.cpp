#include "parallel/root_mesh_scatter.hpp"

#include <chrono>
#include <numeric>

#include "base/stopwatch.hpp"
#include "parallel/communicator.hpp"
#include "parallel/line_ids_by_ends.hpp"
#include "parallel/metrics_by_global_id.hpp"
#include "parallel/part_migration.hpp"
#include "parallel/root_mesh_partition.hpp"

namespace hocav {

template <int D>
ScatteredPart<D> scatter_from_root(Mesh<D> mesh, std::vector<SymMat<D>> metrics, std::int64_t seed) {
  const auto start = std::chrono::steady_clock::now();
  ScatteredPart<D> out;
  if (process_rank() == 0 && !mesh.has_topology()) mesh.build_topology();
  const std::vector<int> part_of = partition_from_root(mesh, seed, &out.bytes_sent);
  std::vector<Index> element_ids(part_of.size());
  std::iota(element_ids.begin(), element_ids.end(), Index{0});
  out.element_ids = migrated_element_values(element_ids, part_of, &out.bytes_sent);
  {  // (rank 0's whole mesh freed once its elements have left)
    MeshPart<D> whole = process_rank() == 0 ? whole_mesh_part(std::move(mesh)) : MeshPart<D>{};
    std::vector<Index> facet_ids(static_cast<std::size_t>(whole.mesh.facet_count()));
    std::iota(facet_ids.begin(), facet_ids.end(), Index{0});
    out.facet_ids = migrated_facet_values(whole, facet_ids, part_of, &out.bytes_sent);
    std::vector<Index> line_ids(static_cast<std::size_t>(whole.mesh.line_count()));
    std::iota(line_ids.begin(), line_ids.end(), Index{0});
    const std::vector<KnownLine> known = known_lines(whole, line_ids);
    out.part = migrate_part(std::move(whole), part_of, &out.bytes_sent);
    out.line_ids = line_ids_by_ends(out.part, known);
  }
  out.metrics = metrics_by_global_id<D>(out.part.global_ids, 0, metrics, out.bytes_sent);
  out.seconds = max_over_processes(seconds_since(start));
  return out;
}

template ScatteredPart<2> scatter_from_root(Mesh<2>, std::vector<SymMat<2>>, std::int64_t);
template ScatteredPart<3> scatter_from_root(Mesh<3>, std::vector<SymMat<3>>, std::int64_t);

}  // namespace hocav
