// The first cut of the distributed adaptation (src/parallel/spatial_cut.hpp): runs of the Morton
// order of the elements' centroids, of balanced load.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "cases/structured.hpp"
#include "geom/box.hpp"
#include "mesh/spatial_order.hpp"
#include "parallel/spatial_cut.hpp"

namespace hocav {
namespace {

// Each element's Morton code in the box of the mesh's vertices.
std::vector<std::uint64_t> element_codes(const Mesh<3>& mesh) {
  Box<3> box = Box<3>::empty();
  for (const Vec<3>& x : mesh.vertices()) box.add(x);
  std::vector<std::uint64_t> codes;
  for (const auto& element : mesh.elements()) {
    Vec<3> centroid{};
    for (Index v : element) centroid += 0.25 * mesh.vertex(v);
    codes.push_back(morton_code<3>(centroid, box.lower, box.upper - box.lower));
  }
  return codes;
}

TEST(SpatialCut, RunsOfTheMortonOrderOfBalancedLoad) {
  const Mesh<3> mesh = generate_cube(6);
  // Loads growing with x, so that balanced parts hold different element counts.
  std::vector<double> loads;
  for (const auto& element : mesh.elements()) loads.push_back(1 + 10 * mesh.vertex(element[0])[0]);
  const double total = std::accumulate(loads.begin(), loads.end(), 0.0);
  const double largest = *std::max_element(loads.begin(), loads.end());
  const std::vector<std::uint64_t> codes = element_codes(mesh);
  for (int parts : {1, 2, 3, 7}) {
    const std::vector<int> part_of = spatial_cut(mesh, loads, parts);
    ASSERT_EQ(part_of.size(), loads.size());
    std::vector<double> load(static_cast<std::size_t>(parts), 0);
    std::vector<std::uint64_t> lowest(static_cast<std::size_t>(parts), UINT64_MAX), highest(static_cast<std::size_t>(parts), 0);
    for (std::size_t k = 0; k < part_of.size(); ++k) {
      const auto p = static_cast<std::size_t>(part_of[k]);
      ASSERT_LT(p, load.size());
      load[p] += loads[k];
      lowest[p] = std::min(lowest[p], codes[k]);
      highest[p] = std::max(highest[p], codes[k]);
    }
    for (int p = 0; p < parts; ++p) {
      // Each part holds its share of the load, to one element's.
      EXPECT_NEAR(load[p], total / parts, largest) << parts << " parts, part " << p;
      // Parts follow one another along the Morton order.
      if (p > 0) {
        EXPECT_LE(highest[p - 1], lowest[p]) << parts << " parts, part " << p;
      }
    }
  }
}

TEST(SpatialCut, NoLoadPutsEverythingInTheFirstPart) {
  const Mesh<3> mesh = generate_cube(2);
  const std::vector<int> part_of = spatial_cut(mesh, std::vector<double>(static_cast<std::size_t>(mesh.element_count()), 0.0), 4);
  EXPECT_TRUE(std::all_of(part_of.begin(), part_of.end(), [](int p) { return p == 0; }));
}

}  // namespace
}  // namespace hocav
