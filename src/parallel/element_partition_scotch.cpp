// Scotch's serial graph partitioner (the int64 build of Debian's libscotch-dev); PT-Scotch, from the
// same package, partitions the distributed graph once the mesh is read in parallel
// (docs/distributed.md §Partitioning).
#include <memory>

#include "parallel/element_partition.hpp"
#include "parallel/scotch_support.hpp"

namespace hocav {
namespace {

struct ScotchGraph {
  SCOTCH_Graph graph;
  ScotchGraph() { check_scotch(SCOTCH_graphInit(&graph), "SCOTCH_graphInit"); }
  ~ScotchGraph() { SCOTCH_graphExit(&graph); }
};

}  // namespace

std::vector<int> partition_graph(const WeightedGraph& graph, int part_count, std::int64_t seed) {
  const auto vertex_count = static_cast<SCOTCH_Num>(graph.vertex_weights.size());
  std::vector<int> parts(graph.vertex_weights.size(), 0);
  if (part_count <= 1 || vertex_count == 0) return parts;
  ScotchContext context(seed);  // the same graph and seed, the same parts
  ScotchGraph scotch, bound;
  // Scotch reads the arrays without changing them (its interface is not const).
  auto* offsets = const_cast<SCOTCH_Num*>(reinterpret_cast<const SCOTCH_Num*>(graph.offsets.data()));
  auto* neighbours = const_cast<SCOTCH_Num*>(reinterpret_cast<const SCOTCH_Num*>(graph.neighbours.data()));
  auto* vertex_weights = const_cast<SCOTCH_Num*>(reinterpret_cast<const SCOTCH_Num*>(graph.vertex_weights.data()));
  auto* edge_weights = const_cast<SCOTCH_Num*>(reinterpret_cast<const SCOTCH_Num*>(graph.edge_weights.data()));
  check_scotch(SCOTCH_graphBuild(&scotch.graph, 0, vertex_count, offsets, offsets + 1, vertex_weights, nullptr,
                                 static_cast<SCOTCH_Num>(graph.neighbours.size()), neighbours, edge_weights),
               "SCOTCH_graphBuild");
  check_scotch(SCOTCH_contextBindGraph(&context.context, &scotch.graph, &bound.graph), "SCOTCH_contextBindGraph");
  ScotchStrategy strategy;
  check_scotch(SCOTCH_stratGraphMapBuild(&strategy.strategy, SCOTCH_STRATQUALITY, part_count, kPartImbalance), "SCOTCH_stratGraphMapBuild");
  std::vector<SCOTCH_Num> scotch_parts(graph.vertex_weights.size());
  check_scotch(SCOTCH_graphPart(&bound.graph, part_count, &strategy.strategy, scotch_parts.data()), "SCOTCH_graphPart");
  for (std::size_t k = 0; k < parts.size(); ++k) parts[k] = static_cast<int>(scotch_parts[k]);
  return parts;
}

}  // namespace hocav
