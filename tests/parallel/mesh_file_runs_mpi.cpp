// Writing a mesh file in runs (write_mesh_runs, docs/distributed.md §Writing in runs), run by ctest
// under `mpirun -np N` (N = 2, 3, 4). Rank 0 holds a square and a cube with four materials (facets
// between them), feature lines, corners and required vertices, edges and facets, each also P2 with
// its nodes moved off the edges' middles, and each also with its vertices renumbered across the mesh.
// - All on rank 0 (the other parts empty), the runs must be write_gamma_mesh's file of the part,
//   byte for byte, as .meshb and .mesh.
// - Scattered over the processes (element k to process (7k + k/5) mod N, so that parts touch at
//   many vertices, edges and lines), the file read back must be the mesh entity by entity, with its
//   vertices in order, its elements part after part in rank order, and each P2 node once; given
//   each element's, facet's and line's id in the mesh as the orders (the lines' found by their ends
//   after the migration), the file's elements, facets and lines are the mesh's in order, with their
//   tags (also for a cube of more elements than a window of that order's messages).
// Exit code 0 when all holds on every process, 1 otherwise.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "cases/structured.hpp"
#include "io/gamma_mesh.hpp"
#include "io/mesh_file.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/entity_tags.hpp"
#include "parallel/mesh_file_runs.hpp"
#include "part_description.hpp"
#include "tagged_meshes.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "mesh file runs (rank " << process_rank() << "): " << what << '\n';
  return false;
}

// All on rank 0: the runs are write_gamma_mesh's file of rank 0's part.
template <int D>
bool same_bytes_as_serial(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  const MeshPart<D> part = scattered(mesh, to_rank_0);
  bool ok = true;
  for (const bool binary : {true, false}) {
    const std::string runs = directory + "/" + name + "-runs" + (binary ? ".meshb" : ".mesh");
    const std::string serial = directory + "/" + name + "-serial" + (binary ? ".meshb" : ".mesh");
    write_mesh_runs(runs, part, binary);
    if (process_rank() != 0) continue;
    write_gamma_mesh(serial, part.mesh, binary);
    if (file_bytes(runs) != file_bytes(serial)) ok = fail(name + ": " + runs + " is not write_gamma_mesh's file");
  }
  return ok;
}

// Scattered: the file read back is the mesh, entity by entity.
template <int D>
bool same_mesh_read_back(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  const MeshPart<D> part = scattered(mesh, spread);
  bool ok = true;
  for (const bool binary : {true, false}) {
    const std::string path = directory + "/" + name + "-spread" + (binary ? ".meshb" : ".mesh");
    const MeshFileCounts counts = write_mesh_runs(path, part, binary);
    if (process_rank() != 0) continue;
    const MeshFileContent file = read_mesh_file(path);
    const Mesh<D>& got = std::get<Mesh<D>>(file.mesh);
    const std::string what = name + " (" + path + ")";
    const std::string difference = part_difference(whole_mesh_part(Mesh<D>(got)), whole_mesh_part(Mesh<D>(mesh)));
    if (!difference.empty()) ok = fail(what + ": " + difference);
    for (Index v = 0; v < got.vertex_count(); ++v)
      if (file.vertex_file_ids[v] != v) ok = fail(what + ": vertex " + std::to_string(v) + " is not in the order of its global id");
    const Index nodes = mesh.vertex_count() + (mesh.is_p2() ? mesh.edge_count() : 0);
    if (file.file_node_count != nodes || counts.vertices + counts.nodes != nodes || counts.elements != mesh.element_count())
      ok = fail(what + ": " + std::to_string(file.file_node_count) + " nodes in the file, " + std::to_string(nodes) + " expected");
    Index k = 0;
    for (int r = 0; r < process_count(); ++r)
      for (Index original = 0; original < mesh.element_count(); ++original)
        if (spread(original) == r && got.element(k++) != mesh.element(original)) {
          ok = fail(what + ": the elements are not part after part in the mesh's order");
          r = process_count();
          break;
        }
  }
  return ok;
}

// Scattered, written with the mesh's element, facet and line orders (each element's and facet's id
// carried through the migration, each line's found by its ends): the file's elements, facets and
// lines are the mesh's, in the mesh's order, with the mesh's tags.
template <int D>
bool entities_in_mesh_order(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  const OrderedPart<D> ordered = spread_in_mesh_order(mesh);
  bool ok = true;
  for (const bool binary : {true, false}) {
    const std::string path = directory + "/" + name + "-ordered" + (binary ? ".meshb" : ".mesh");
    write_mesh_runs(path, ordered.part, binary, 0, ordered.orders());
    if (process_rank() != 0) continue;
    const Mesh<D> got = std::get<Mesh<D>>(read_mesh_file(path).mesh);
    const std::string what = name + " (" + path + ")";
    if (got.element_count() != mesh.element_count() || got.facet_count() != mesh.facet_count()) ok = fail(what + ": not the mesh's counts");
    for (Index k = 0; ok && k < got.element_count(); ++k)
      if (got.element(k) != mesh.element(k) || got.element_ref(k) != mesh.element_ref(k))
        ok = fail(what + ": element " + std::to_string(k + 1) + " is not the mesh's");
    for (Index f = 0; ok && f < got.facet_count(); ++f)
      if (got.facet(f) != mesh.facet(f) || got.facet_ref(f) != mesh.facet_ref(f))
        ok = fail(what + ": facet " + std::to_string(f + 1) + " is not the mesh's");
    if (ok && (required_facets(got) != required_facets(mesh) || got.ridges() != mesh.ridges()))
      ok = fail(what + ": the facets' tags are not the mesh's");
    if (got.line_count() != mesh.line_count()) ok = fail(what + ": not the mesh's lines");
    for (Index l = 0; ok && l < got.line_count(); ++l)
      if (got.line(l) != mesh.line(l) || got.line_ref(l) != mesh.line_ref(l))
        ok = fail(what + ": line " + std::to_string(l + 1) + " is not the mesh's");
    if (ok && got.required_edges() != mesh.required_edges()) ok = fail(what + ": the lines' tags are not the mesh's");
  }
  return ok;
}

template <int D>
bool check(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  return same_bytes_as_serial(mesh, directory, name) & same_mesh_read_back(mesh, directory, name) &
         entities_in_mesh_order(mesh, directory, name);
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "mesh file runs", [] {
    const std::string directory = hocav::shared_directory("hocav-runs-");
    bool ok = hocav::check_tagged_meshes([&](const auto& mesh, const std::string& name) { return hocav::check(mesh, directory, name); });
    // More elements than a window of an element order's messages (65,536): written window by window.
    ok = hocav::entities_in_mesh_order(hocav::generate_cube(24), directory, "large-cube") & ok;
    hocav::all_gather_value(0);
    if (hocav::process_rank() == 0) std::filesystem::remove_all(directory);
    return ok;
  });
}
