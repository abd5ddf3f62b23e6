// Gamma mesh I/O: writing and reading a ~1M-tetrahedron curved P2 cube as .meshb (version 3) and
// as ASCII .mesh. Reading includes the assembly into Mesh<3> (topology and P2 edge table), since
// that is what a user waits for; the mesh_bench figures give the share of the assembly.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "cases/structured.hpp"
#include "cube_sizes.hpp"
#include "io/gamma_mesh.hpp"

namespace hocav {
namespace {

// Edge nodes moved off their midpoints, so the ASCII reals need their full 17 digits.
const Mesh<3>& curved_cube() {
  static const Mesh<3> mesh = [] {
    Mesh<3> cube = generate_cube(kMillionCubeCellsPerSide);
    cube.make_p2();
    for (Index e = 0; e < cube.edge_count(); ++e)
      for (int i = 0; i < 3; ++i) cube.edge_node(e)[i] += 1e-3 * std::sin(1.7 * e + i);
    return cube;
  }();
  return mesh;
}

std::string scratch_path(const char* extension) {
  return (std::filesystem::temp_directory_path() / (std::string("hocav_io_bench") + extension)).string();
}

void report_file(benchmark::State& state, const std::string& path) {
  const auto bytes = static_cast<double>(std::filesystem::file_size(path));
  state.counters["file_MB"] = bytes / 1e6;
  state.counters["MB_per_s"] = benchmark::Counter(bytes / 1e6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["tets"] = curved_cube().element_count();
}

void BM_WriteGamma(benchmark::State& state, const char* extension, bool binary) {
  const Mesh<3>& mesh = curved_cube();
  const std::string path = scratch_path(extension);
  for (auto _ : state) write_gamma_mesh(path, mesh, binary);
  report_file(state, path);
  std::filesystem::remove(path);
}

void BM_ReadGamma(benchmark::State& state, const char* extension, bool binary) {
  const std::string path = scratch_path(extension);
  write_gamma_mesh(path, curved_cube(), binary);
  for (auto _ : state) {
    MeshFileContent content = read_gamma_mesh(path);
    benchmark::DoNotOptimize(content);
  }
  report_file(state, path);
  std::filesystem::remove(path);
}

BENCHMARK_CAPTURE(BM_WriteGamma, meshb_p2, ".meshb", true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ReadGamma, meshb_p2, ".meshb", true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_WriteGamma, mesh_ascii_p2, ".mesh", false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ReadGamma, mesh_ascii_p2, ".mesh", false)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace hocav
