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
// - Scattered so, given each element's, facet's and line's id in the mesh as the orders, a P1 file
//   must be write_gmsh_msh's of the mesh byte for byte, and a P2 one hold its entities in order;
//   also for a cube of more elements than a window of an order's messages.
// Exit code 0 when all holds on every process, 1 otherwise.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>

#include "cases/structured.hpp"
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

// Spread with the mesh's orders: a P1 file is write_gmsh_msh's of the mesh (its corners listed in
// increasing order, as the runs list them by their numbers) byte for byte; a P2 one, whose nodes
// the processes number, holds the serial file's elements, facets and lines in its order, each with
// its ref and its nodes' points.
template <int D>
bool in_mesh_order(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  const std::string serial = directory + "/" + name + "-ordered-serial.msh", runs = directory + "/" + name + "-ordered.msh";
  const OrderedPart<D> ordered = spread_in_mesh_order(mesh);
  write_gmsh_msh_runs(runs, ordered.part, ordered.orders());
  if (process_rank() != 0) return true;
  Mesh<D> sorted_corners = mesh;
  std::sort(sorted_corners.corners().begin(), sorted_corners.corners().end());
  write_gmsh_msh(serial, sorted_corners);
  if (!mesh.is_p2()) return file_bytes(runs) == file_bytes(serial) || fail(name + ": " + runs + " is not write_gmsh_msh's file");
  const Mesh<D> got = read_back<D>(runs), expected = read_back<D>(serial);
  const auto nodes = [](const Mesh<D>& m, const auto& vertices) {
    std::string out;
    for (std::size_t i = 0; i < vertices.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) out += point<D>(m.edge_node(m.find_edge(vertices[i], vertices[j])));
    return out;
  };
  bool ok = got.element_count() == expected.element_count() && got.facet_count() == expected.facet_count() &&
            got.line_count() == expected.line_count();
  for (Index k = 0; ok && k < got.element_count(); ++k)
    ok = got.element(k) == expected.element(k) && got.element_ref(k) == expected.element_ref(k) &&
         nodes(got, got.element(k)) == nodes(expected, expected.element(k));
  for (Index f = 0; ok && f < got.facet_count(); ++f)
    ok = got.facet(f) == expected.facet(f) && got.facet_ref(f) == expected.facet_ref(f) &&
         nodes(got, got.facet(f)) == nodes(expected, expected.facet(f));
  for (Index l = 0; ok && l < got.line_count(); ++l)
    ok = got.line(l) == expected.line(l) && got.line_ref(l) == expected.line_ref(l) &&
         nodes(got, got.line(l)) == nodes(expected, expected.line(l));
  return ok || fail(name + ": " + runs + " does not hold the serial file's entities in its order");
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

template <int D>
bool check_all(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  return check(mesh, directory, name) & in_mesh_order(mesh, directory, name);
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "gmsh .msh runs", [] {
    const std::string directory = hocav::shared_directory("hocav-msh-runs-");
    bool ok = hocav::check_tagged_meshes(
        [&](const auto& mesh, const std::string& name) { return hocav::check_all(mesh, directory, name); });
    // More elements than a window of an order's messages (kOrderWindow): written window by window.
    ok = hocav::in_mesh_order(hocav::generate_cube(24), directory, "large-cube") & ok;
    hocav::all_gather_value(0);
    if (hocav::process_rank() == 0) std::filesystem::remove_all(directory);
    return ok;
  });
}
