// PT-Scotch's partition of a distributed graph (the int64 build of Debian's libptscotch-dev): every
// process passes its rows, none holds the whole graph (docs/distributed.md §Partitioning).
#include <mpi.h>
#include <stdint.h>  // ptscotch.h needs int64_t and FILE
#include <stdio.h>

#include <ptscotch.h>

#include "base/error.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_graph.hpp"

namespace hocav {
namespace {

static_assert(sizeof(SCOTCH_Num) == sizeof(std::int64_t), "hocav needs PT-Scotch's int64 build (scotch-int64)");

void check(int status, const char* what) {
  if (status != 0) throw Error(std::string("PT-Scotch failed in ") + what);
}

struct ScotchDgraph {
  SCOTCH_Dgraph graph;
  ScotchDgraph() { check(SCOTCH_dgraphInit(&graph, MPI_COMM_WORLD), "SCOTCH_dgraphInit"); }
  ~ScotchDgraph() { SCOTCH_dgraphExit(&graph); }
};

struct ScotchStrategy {
  SCOTCH_Strat strategy;
  ScotchStrategy() { check(SCOTCH_stratInit(&strategy), "SCOTCH_stratInit"); }
  ~ScotchStrategy() { SCOTCH_stratExit(&strategy); }
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
  // The same graph and seed, the same parts: Scotch's random generator from a fixed state.
  SCOTCH_randomSeed(static_cast<SCOTCH_Num>(seed));
  SCOTCH_randomReset();
  ScotchDgraph scotch;
  const auto row_count = static_cast<SCOTCH_Num>(rows.vertex_weights.size());
  const auto edge_count = static_cast<SCOTCH_Num>(rows.neighbours.size());
  SCOTCH_Num* offsets = scotch_array(rows.offsets);
  check(SCOTCH_dgraphBuild(&scotch.graph, 0, row_count, row_count, offsets, offsets + 1, scotch_array(rows.vertex_weights), nullptr,
                           edge_count, edge_count, scotch_array(rows.neighbours), nullptr, scotch_array(rows.edge_weights)),
        "SCOTCH_dgraphBuild");
  ScotchStrategy strategy;
  check(SCOTCH_stratDgraphMapBuild(&strategy.strategy, SCOTCH_STRATQUALITY, process_count(), part_count, kPartImbalance),
        "SCOTCH_stratDgraphMapBuild");
  std::vector<SCOTCH_Num> scotch_parts(std::max<std::size_t>(parts.size(), 1));
  check(SCOTCH_dgraphPart(&scotch.graph, part_count, &strategy.strategy, scotch_parts.data()), "SCOTCH_dgraphPart");
  for (std::size_t k = 0; k < parts.size(); ++k) parts[k] = static_cast<int>(scotch_parts[k]);
  return parts;
}

}  // namespace hocav
