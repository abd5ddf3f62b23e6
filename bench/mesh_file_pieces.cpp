// Prints what reading a P1 Gamma mesh in pieces costs each process (docs/distributed.md §Reading in
// pieces; figures in docs/benchmarks.md): run under `mpirun -np N` (or alone, N = 1), it reads
// FILE with read_mesh_file_piece and prints per rank the wall seconds, the peak resident memory, the
// elements and vertices of its piece and its interface facets; with --whole, rank 0 reads the whole
// file with read_mesh_file instead, for comparison.
#include <chrono>
#include <iostream>
#include <string>

#include "base/memory_budget.hpp"
#include "io/gamma_mesh.hpp"
#include "io/mesh_file.hpp"
#include "parallel/communicator.hpp"
#include "parallel/mesh_file_pieces.hpp"

namespace hocav {
namespace {

template <int D>
void read_in_pieces(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  const MeshPart<D> piece = read_mesh_file_piece<D>(path).part;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "rank " << process_rank() << " of " << process_count() << ": " << seconds << " s, peak " << (peak_resident_bytes() >> 20)
            << " MiB, " << piece.mesh.element_count() << " elements, " << piece.mesh.vertex_count() << " vertices, "
            << interface_facet_count(piece.mesh) << " interface facets\n";
}

void read_whole(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  const MeshFileContent content = read_mesh_file(path);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "whole: " << seconds << " s, peak " << (peak_resident_bytes() >> 20) << " MiB\n";
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  hocav::MpiSession mpi(argc, argv);
  if (argc < 2) {
    std::cerr << "usage: [mpirun -np N] hocav_mesh_file_pieces FILE.meshb [--whole]\n";
    return 2;
  }
  const std::string path = argv[1];
  try {
    if (argc > 2 && std::string(argv[2]) == "--whole")
      hocav::read_whole(path);
    else if (hocav::gamma_mesh_dimension(path) == 2)
      hocav::read_in_pieces<2>(path);
    else
      hocav::read_in_pieces<3>(path);
  } catch (const std::exception& error) {
    std::cerr << error.what() << '\n';
    hocav::abort_processes(1);
  }
  return 0;
}
