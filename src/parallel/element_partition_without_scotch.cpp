// Built without MPI and Scotch (HOCAV_WITH_MPI off): one process, one part.
#include "base/error.hpp"
#include "parallel/element_partition.hpp"

namespace hocav {

std::vector<int> partition_graph(const WeightedGraph& graph, int part_count, std::int64_t /*seed*/) {
  if (part_count > 1) throw Error("hocav was built without Scotch (docs/distributed.md): it makes one part");
  return std::vector<int>(graph.vertex_weights.size(), 0);
}

}  // namespace hocav
