// Built without MPI and PT-Scotch (HOCAV_WITH_MPI off): one process, one part.
#include "base/error.hpp"
#include "parallel/distributed_graph.hpp"

namespace hocav {

std::vector<int> partition_distributed_graph(const DistributedGraph& graph, int part_count, std::int64_t /*seed*/) {
  if (part_count > 1) throw Error("hocav was built without PT-Scotch (docs/distributed.md): it makes one part");
  return std::vector<int>(graph.rows.vertex_weights.size(), 0);
}

}  // namespace hocav
