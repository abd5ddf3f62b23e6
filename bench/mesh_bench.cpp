// Mesh model: time to build topology, the vertex graph and the P2 edge table on a ~1M-tetrahedron
// cube, and the bytes held per tetrahedron (P1 with topology; P2 with edge table and nodes).
#include <benchmark/benchmark.h>

#include "cases/structured.hpp"
#include "cube_sizes.hpp"
#include "mesh/vertex_graph.hpp"

namespace hocav {
namespace {

const Mesh<3>& cube() {
  static const Mesh<3> mesh = generate_cube(kMillionCubeCellsPerSide);
  return mesh;
}

void BM_BuildTopology(benchmark::State& state) {
  Mesh<3> mesh = cube();
  for (auto _ : state) mesh.build_topology();
  state.counters["tets"] = mesh.element_count();
  state.counters["bytes_per_tet_p1"] = double(mesh.memory_bytes()) / mesh.element_count();
}
BENCHMARK(BM_BuildTopology)->Unit(benchmark::kMillisecond);

void BM_VertexGraph(benchmark::State& state) {
  const Mesh<3>& mesh = cube();
  std::size_t entries = 0;
  for (auto _ : state) entries = vertex_graph(mesh).neighbors.size();
  state.counters["neighbor_entries"] = static_cast<double>(entries);
}
BENCHMARK(BM_VertexGraph)->Unit(benchmark::kMillisecond);

void BM_MakeP2(benchmark::State& state) {
  Mesh<3> mesh = cube();
  for (auto _ : state) {
    mesh.make_p1();
    mesh.make_p2();
  }
  state.counters["edges"] = mesh.edge_count();
  state.counters["bytes_per_tet_p2"] = double(mesh.memory_bytes()) / mesh.element_count();
}
BENCHMARK(BM_MakeP2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace hocav
