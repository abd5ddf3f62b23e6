#include "parallel/output_file_runs.hpp"

#include <cstdint>
#include <vector>

#include "io/mesh_file.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distinct_ids.hpp"
#include "parallel/gmsh_msh_runs.hpp"
#include "parallel/vtu_file_runs.hpp"

namespace hocav {

template <int D>
MeshFileCounts distinct_mesh_counts(const MeshPart<D>& part) {
  MeshFileCounts counts;
  counts.vertices = distinct_count(part.global_ids);
  counts.elements = sum_over_processes(part.mesh.element_count());
  std::vector<std::uint64_t> edges;
  if (part.mesh.is_p2())
    for (const auto& [a, b] : part.mesh.edges()) edges.push_back(Mesh<D>::edge_key(part.global_ids[a], part.global_ids[b]));
  counts.nodes = distinct_count(edges);
  return counts;
}

template <int D>
MeshFileCounts write_mesh_file_runs(const std::string& path, const MeshPart<D>& part, const EntityOrders& orders) {
  const std::string extension = file_extension(path);
  if (extension == ".msh") return write_gmsh_msh_runs(path, part, orders);
  if (extension != ".vtu") return write_mesh_runs(path, part, extension == ".meshb", 0, orders);
  write_vtu_runs(path, part.mesh);
  return distinct_mesh_counts(part);
}

template MeshFileCounts distinct_mesh_counts(const MeshPart<2>&);
template MeshFileCounts distinct_mesh_counts(const MeshPart<3>&);
template MeshFileCounts write_mesh_file_runs(const std::string&, const MeshPart<2>&, const EntityOrders&);
template MeshFileCounts write_mesh_file_runs(const std::string&, const MeshPart<3>&, const EntityOrders&);

}  // namespace hocav
