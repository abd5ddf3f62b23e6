#include "mesh/spatial_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "cases/structured.hpp"
#include "mesh/consistency.hpp"

namespace hocav {
namespace {

// A random permutation of 0..n-1.
std::vector<Index> shuffled(Index n, unsigned seed) {
  std::vector<Index> ids(static_cast<std::size_t>(n));
  std::iota(ids.begin(), ids.end(), 0);
  std::shuffle(ids.begin(), ids.end(), std::mt19937(seed));
  return ids;
}

// Each element as the sorted positions of its vertices, all sorted: the mesh as a set of shapes.
template <int D>
std::vector<std::vector<double>> element_shapes(const Mesh<D>& mesh) {
  std::vector<std::vector<double>> shapes;
  for (const auto& element : mesh.elements()) {
    std::vector<std::array<double, D>> points;
    for (Index v : element) points.push_back(mesh.vertex(v).c);
    std::sort(points.begin(), points.end());
    std::vector<double> flat;
    for (const auto& p : points) flat.insert(flat.end(), p.begin(), p.end());
    shapes.push_back(flat);
  }
  std::sort(shapes.begin(), shapes.end());
  return shapes;
}

// The mean distance between the ids of face neighbours: small when neighbours are near in memory.
template <int D>
double mean_neighbor_id_distance(const Mesh<D>& mesh) {
  double sum = 0;
  long count = 0;
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face)
      if (const Index n = mesh.neighbor(k, face); n != kNoIndex) {
        sum += std::abs(static_cast<double>(n) - static_cast<double>(k));
        ++count;
      }
  return sum / static_cast<double>(count);
}

// Everything that names a vertex or an element follows a renumbering: elements, facets, lines,
// corners, attributes, the P2 edge table, the topology.
TEST(SpatialOrder, RenumberingKeepsTheMeshAndItsData) {
  Mesh<3> mesh = generate_cube(3);
  mesh.make_p2();
  mesh.corners() = {0, 5};
  const int vertex_data = mesh.add_vertex_attribute(2);
  for (Index v = 0; v < mesh.vertex_count(); ++v) mesh.vertex_attribute(vertex_data, v)[1] = mesh.vertex(v)[0] + 10 * mesh.vertex(v)[2];
  const int element_data = mesh.add_element_attribute(0);
  for (Index k = 0; k < mesh.element_count(); ++k) mesh.set_element_attribute(element_data, k, mesh.vertex(mesh.element(k)[0])[1]);
  const Mesh<3> before = mesh;
  const std::vector<Index> new_vertex = shuffled(mesh.vertex_count(), 1), new_element = shuffled(mesh.element_count(), 2);
  mesh.renumber(new_vertex, new_element);

  ConsistencyOptions options;
  options.require_boundary_facets = true;
  EXPECT_EQ(check_consistency(mesh, options), std::vector<std::string>{});
  for (Index v = 0; v < before.vertex_count(); ++v) {
    const Index w = new_vertex[static_cast<std::size_t>(v)];
    EXPECT_EQ(mesh.vertex(w), before.vertex(v));
    EXPECT_EQ(mesh.vertex_attribute(vertex_data, w)[1], before.vertex(v)[0] + 10 * before.vertex(v)[2]);
  }
  for (Index k = 0; k < before.element_count(); ++k) {
    const Index moved = new_element[static_cast<std::size_t>(k)];
    for (int i = 0; i < 4; ++i) EXPECT_EQ(mesh.element(moved)[i], new_vertex[static_cast<std::size_t>(before.element(k)[i])]);
    EXPECT_EQ(mesh.element_attribute(element_data, moved), before.vertex(before.element(k)[0])[1]);
  }
  EXPECT_EQ(mesh.corners(), (std::vector<Index>{new_vertex[0], new_vertex[5]}));
  for (Index l = 0; l < before.line_count(); ++l)
    EXPECT_EQ(mesh.line(l), (Mesh<3>::Line{new_vertex[static_cast<std::size_t>(before.line(l)[0])],
                                           new_vertex[static_cast<std::size_t>(before.line(l)[1])]}));
  for (Index e = 0; e < before.edge_count(); ++e) {
    const auto [a, b] = before.edge_vertices(e);
    EXPECT_EQ(mesh.find_edge(new_vertex[static_cast<std::size_t>(a)], new_vertex[static_cast<std::size_t>(b)]), e);
  }
  EXPECT_EQ(element_shapes(mesh), element_shapes(before));
}

// After a random renumbering, the spatial order brings face neighbours near each other in memory
// again, in both dimensions, and keeps every element.
template <int D>
void expect_neighbors_near(Mesh<D> mesh) {
  const std::vector<std::vector<double>> shapes = element_shapes(mesh);
  mesh.renumber(shuffled(mesh.vertex_count(), 3), shuffled(mesh.element_count(), 4));
  const double scattered = mean_neighbor_id_distance(mesh);
  sort_spatially(mesh);
  EXPECT_LT(mean_neighbor_id_distance(mesh), 0.1 * scattered);
  EXPECT_EQ(check_consistency(mesh), std::vector<std::string>{});
  EXPECT_EQ(element_shapes(mesh), shapes);
  for (Index k = 1; k < mesh.element_count(); ++k)
    EXPECT_LE(*std::min_element(mesh.element(k - 1).begin(), mesh.element(k - 1).end()),
              *std::min_element(mesh.element(k).begin(), mesh.element(k).end()));
}

TEST(SpatialOrder, BringsNeighboursNearInMemory) {
  expect_neighbors_near(generate_cube(8));
  expect_neighbors_near(generate_square(32));
}

TEST(SpatialOrder, MortonCodeInterleavesTheAxes) {
  const Vec2 low{{0, 0}}, extent{{1, 1}};
  // The last cell of x alone sets the odd bits (x leads), of y the even ones.
  EXPECT_EQ(morton_code<2>(Vec2{{1, 0}}, low, extent), 0xAAAAAAAAAAAAAAAAull >> 2);
  EXPECT_EQ(morton_code<2>(Vec2{{0, 1}}, low, extent), 0x5555555555555555ull >> 2);
  EXPECT_LT(morton_code<2>(Vec2{{0.2, 0.2}}, low, extent), morton_code<2>(Vec2{{0.7, 0.2}}, low, extent));
}

}  // namespace
}  // namespace hocav
