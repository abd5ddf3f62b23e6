// The partitioner's seed (parallel/element_partition.hpp): a distributed run's figures are measured
// over several partitions of the same mesh (bench/distributed_draws.py), which only a seed that
// changes the cuts, and keeps them the same from run to run, gives. Built with Scotch only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <vector>

#include "cases/structured.hpp"
#include "parallel/element_partition.hpp"

namespace hocav {
namespace {

// Each part's element count within the partitioner's 5% of an even share (and one element).
void expect_balanced(const std::vector<int>& part_of, int parts) {
  const double share = static_cast<double>(part_of.size()) / parts;
  for (int p = 0; p < parts; ++p)
    EXPECT_NEAR(static_cast<double>(std::count(part_of.begin(), part_of.end(), p)), share, 0.05 * share + 1) << "part " << p;
}

TEST(ElementPartition, TheSeedChoosesAmongBalancedPartitionsAndRepeats) {
  Mesh<3> cube = generate_cube(6);
  cube.build_topology();
  const std::vector<double> loads(static_cast<std::size_t>(cube.element_count()), 1.0);
  const WeightedGraph graph = element_graph(cube, loads, {});
  EXPECT_EQ(partition_graph(graph, 3, 2), partition_graph(graph, 3, 2)) << "the same seed, other parts";
  std::set<std::vector<int>> partitions;
  for (std::int64_t seed : {0, 2, 3, 4, 7, 11, 100, 12345}) {
    const std::vector<int> part_of = partition_graph(graph, 3, seed);
    expect_balanced(part_of, 3);
    partitions.insert(part_of);
  }
  EXPECT_GE(partitions.size(), 2u) << "every seed cut the cube the same way";
}

}  // namespace
}  // namespace hocav
