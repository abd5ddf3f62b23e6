// PT-Scotch's partition of a distributed graph (the int64 build of Debian's libptscotch-dev): every
// process passes its rows, none holds the whole graph (docs/distributed.md §Partitioning).
#include <mpi.h>

#include "parallel/scotch_support.hpp"  // scotch.h, which ptscotch.h extends

#include <ptscotch.h>

#include "parallel/communicator.hpp"
#include "parallel/distributed_graph.hpp"

namespace hocav {
namespace {

struct ScotchDgraph {
  SCOTCH_Dgraph graph;
  ScotchDgraph() { check_scotch(SCOTCH_dgraphInit(&graph, MPI_COMM_WORLD), "SCOTCH_dgraphInit"); }
  ~ScotchDgraph() { SCOTCH_dgraphExit(&graph); }
};

// Scotch reads the arrays without changing them (its interface is not const).
SCOTCH_Num* scotch_array(const std::vector<std::int64_t>& values) {
  return const_cast<SCOTCH_Num*>(reinterpret_cast<const SCOTCH_Num*>(values.data()));
}

}  // namespace

std::vector<int> partition_distributed_graph(const DistributedGraph& graph, int part_count, std::int64_t seed) {
  const WeightedGraph& rows = graph.rows;
  std::vector<int> parts(rows.vertex_weights.size(), 0);
  if (part_count <= 1) return parts;
  int threads = MPI_THREAD_SINGLE;
  MPI_Query_thread(&threads);
  if (threads < MPI_THREAD_MULTIPLE) throw Error("PT-Scotch needs MPI_THREAD_MULTIPLE, which this MPI does not provide");
  ScotchContext context(seed);  // the same graph and seed, the same parts
  ScotchDgraph scotch, bound;
  const auto row_count = static_cast<SCOTCH_Num>(rows.vertex_weights.size());
  const auto edge_count = static_cast<SCOTCH_Num>(rows.neighbours.size());
  SCOTCH_Num* offsets = scotch_array(rows.offsets);
  check_scotch(SCOTCH_dgraphBuild(&scotch.graph, 0, row_count, row_count, offsets, offsets + 1, scotch_array(rows.vertex_weights), nullptr,
                                  edge_count, edge_count, scotch_array(rows.neighbours), nullptr, scotch_array(rows.edge_weights)),
               "SCOTCH_dgraphBuild");
  check_scotch(SCOTCH_contextBindDgraph(&context.context, &scotch.graph, &bound.graph), "SCOTCH_contextBindDgraph");
  ScotchStrategy strategy;
  check_scotch(SCOTCH_stratDgraphMapBuild(&strategy.strategy, SCOTCH_STRATQUALITY, process_count(), part_count, kPartImbalance),
               "SCOTCH_stratDgraphMapBuild");
  std::vector<SCOTCH_Num> scotch_parts(std::max<std::size_t>(parts.size(), 1));
  check_scotch(SCOTCH_dgraphPart(&bound.graph, part_count, &strategy.strategy, scotch_parts.data()), "SCOTCH_dgraphPart");
  for (std::size_t k = 0; k < parts.size(); ++k) parts[k] = static_cast<int>(scotch_parts[k]);
  return parts;
}

}  // namespace hocav
