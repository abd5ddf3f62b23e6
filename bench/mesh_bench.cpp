// Mesh model: time to build topology and the P2 edge table on a ~1M-tetrahedron cube, and the
// bytes held per tetrahedron (P1 with topology; P2 with edge table and nodes).
#include <benchmark/benchmark.h>

#include "cases/structured.hpp"

namespace hocav {
namespace {

constexpr int kCellsPerSide = 55;  // 6 * 55^3 = 998,250 tetrahedra

const Mesh<3>& cube() {
  static const Mesh<3> mesh = generate_cube(kCellsPerSide);
  return mesh;
}

void BM_BuildTopology(benchmark::State& state) {
  Mesh<3> mesh = cube();
  for (auto _ : state) mesh.build_topology();
  state.counters["tets"] = mesh.element_count();
  state.counters["bytes_per_tet_p1"] = double(mesh.memory_bytes()) / mesh.element_count();
}
BENCHMARK(BM_BuildTopology)->Unit(benchmark::kMillisecond);

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
