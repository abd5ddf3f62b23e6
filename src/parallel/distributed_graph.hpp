// The dual graph of a mesh distributed in parts, one per process (docs/distributed.md
// §Partitioning): each process holds the rows of its own elements or groups of them, numbered
// globally in rank order, and learns its neighbours across the interfaces from the other side,
// without any process holding the whole graph. PT-Scotch cuts it (partition_distributed_graph).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "parallel/element_groups.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

struct DistributedGraph {
  std::int64_t first = 0;  // the global number of this process's first row
  WeightedGraph rows;      // this process's groups of elements; their neighbours by global numbers
};

// Every process at once: the rows of its part's groups of elements (the part with its topology;
// `groups` within the part), weighted as element_graph weighs elements: a group's load is its
// elements' `loads` (their sum over every process scales the weights), and an arc between two groups
// weighs the faces between them, each as element_graph's (`kept_inside` per vertex of the part, may
// be empty). A neighbour across an interface facet is found by meeting the other side's request at
// the process that the facet's global vertex ids hash to.
template <int D>
DistributedGraph distributed_element_graph(const MeshPart<D>& part, std::span<const double> loads, std::span<const char> kept_inside,
                                           const ElementGroups& groups);

// PT-Scotch's partition of the distributed `graph` into `part_count` parts of balanced weight and
// small cut: the part of each of this process's rows. Every process calls it at once.
std::vector<int> partition_distributed_graph(const DistributedGraph& graph, int part_count, std::int64_t seed = 0);

// Every process at once: the process each element of its part (with its topology) goes to, PT-Scotch
// cutting the graph of neighbouring_element_groups (arguments as distributed_element_graph's).
template <int D>
std::vector<int> partition_distributed_part(const MeshPart<D>& part, std::span<const double> loads, std::span<const char> kept_inside,
                                            std::int64_t seed);

}  // namespace hocav
