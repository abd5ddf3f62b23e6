// Writing a gmsh .msh in runs (write_gmsh_msh_runs, docs/distributed.md §A .msh in runs), run by ctest
// under `mpirun -np N` (N = 2, 3, 4), on the meshes of the Gamma writer's test (a square and a cube
// with four materials, feature lines, corners and required entities, each also P2 with its nodes
// moved off the edges' middles, and each also with its vertices renumbered across the mesh).
// - All on rank 0 (the other parts empty), the runs must be write_gmsh_msh's file of rank 0's part,
//   byte for byte.
// - Scattered over the processes (element k to process (7k + k/5) mod N, so that parts touch at
//   many vertices, edges and lines), the file read back must hold the entities of write_gmsh_msh's
//   file read back (vertices in order, each P2 node once, every element, facet, line and corner
//   with its ref), and the counts returned must be the mesh's.
// Exit code 0 when all holds on every process, 1 otherwise.
#include <filesystem>
#include <iostream>
#include <string>

#include "io/gmsh_msh.hpp"
#include "io/mesh_file.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/gmsh_msh_runs.hpp"
#include "part_description.hpp"
#include "tagged_meshes.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "gmsh .msh runs (rank " << process_rank() << "): " << what << '\n';
  return false;
}

template <int D>
Mesh<D> read_back(const std::string& path) {
  return std::get<Mesh<D>>(read_mesh_file(path).mesh);
}

template <int D>
bool check(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  const std::string serial = directory + "/" + name + "-serial.msh", runs = directory + "/" + name + "-runs.msh",
                    spread_out = directory + "/" + name + "-spread.msh";
  const MeshPart<D> whole = scattered(mesh, to_rank_0);
  write_gmsh_msh_runs(runs, whole);
  if (process_rank() == 0) write_gmsh_msh(serial, whole.mesh);
  const MeshFileCounts counts = write_gmsh_msh_runs(spread_out, scattered(mesh, spread));
  if (process_rank() != 0) return true;
  bool ok = true;
  if (file_bytes(runs) != file_bytes(serial)) ok = fail(name + ": " + runs + " is not write_gmsh_msh's file");
  const std::string difference = part_difference(whole_mesh_part(read_back<D>(spread_out)), whole_mesh_part(read_back<D>(serial)));
  if (!difference.empty()) ok = fail(name + ": " + spread_out + ": " + difference);
  const Index nodes = mesh.is_p2() ? mesh.edge_count() : 0;
  if (counts.vertices != mesh.vertex_count() || counts.nodes != nodes || counts.elements != mesh.element_count() ||
      counts.facets != mesh.facet_count() || counts.lines != (D == 3 ? mesh.line_count() : 0))
    ok = fail(name + ": " + std::to_string(counts.vertices) + " vertices, " + std::to_string(counts.elements) + " elements counted");
  return ok;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "gmsh .msh runs", [] {
    const std::string directory = hocav::shared_directory("hocav-msh-runs-");
    const bool ok = hocav::check_tagged_meshes(
        [&](const auto& mesh, const std::string& name) { return hocav::check(mesh, directory, name); });
    hocav::all_gather_value(0);
    if (hocav::process_rank() == 0) std::filesystem::remove_all(directory);
    return ok;
  });
}
