// Reading a mesh file in pieces (read_mesh_file_piece, docs/distributed.md §Reading in pieces), run
// by ctest under `mpirun -np N` (N = 2, 3, 4). Rank 0 writes a square and a cube with four materials
// (facets between them), feature lines, corners and required vertices, edges and facets, as .meshb
// and .mesh. Every process then reads its piece of each file, and it must be, entity by entity by
// global ids and with its elements in the same order, the part that migrate_part makes of the mesh
// rank 0 reads whole when element k goes to the process whose run holds it; the binary and the
// text file must give the same piece; so again with the vertices renumbered across the file (a run's
// elements then use ids from everywhere). Exit code 0 when all holds on every process, 1 otherwise.
#include <filesystem>
#include <iostream>
#include <string>

#include "cases/structured.hpp"
#include "io/gamma_mesh.hpp"
#include "io/mesh_file.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/mesh_file_pieces.hpp"
#include "parallel/part_migration.hpp"
#include "part_description.hpp"
#include "tagged_meshes.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "mesh file pieces (rank " << process_rank() << "): " << what << '\n';
  return false;
}

// Rank 0's whole mesh read from `path`, migrated to the processes whose runs hold its elements.
template <int D>
MeshPart<D> expected_piece(const std::string& path) {
  if (process_rank() != 0) return migrate_part(MeshPart<D>{}, {});
  Mesh<D> mesh = std::get<Mesh<D>>(read_mesh_file(path).mesh);
  std::vector<int> destination;
  for (Index k = 0; k < mesh.element_count(); ++k) destination.push_back(slice_holding(k, mesh.element_count(), process_count()));
  return migrate_part(whole_mesh_part(std::move(mesh)), destination);
}

template <int D>
bool same_elements_in_order(const MeshPart<D>& got, const MeshPart<D>& expected, const std::string& what) {
  if (got.mesh.element_count() != expected.mesh.element_count()) return fail(what + ": element counts differ");
  for (Index k = 0; k < got.mesh.element_count(); ++k)
    for (int i = 0; i <= D; ++i)
      if (got.global_ids[got.mesh.element(k)[i]] != expected.global_ids[expected.mesh.element(k)[i]])
        return fail(what + ": element " + std::to_string(k) + " is not the file's in order");
  return true;
}

template <int D>
bool check(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  const std::string binary = directory + "/" + name + ".meshb", text = directory + "/" + name + ".mesh";
  if (process_rank() == 0) {
    write_mesh_file(binary, mesh);
    write_mesh_file(text, mesh);
  }
  all_gather_value(0);  // the files are written
  const MeshPart<D> expected = expected_piece<D>(binary);
  bool ok = true;
  for (const std::string& path : {binary, text}) {
    const MeshPart<D> piece = read_mesh_file_piece<D>(path).part;
    const std::string what = name + " (" + path + ")";
    const std::string difference = part_difference(piece, expected);
    if (!difference.empty()) ok = fail(what + ": " + difference);
    ok = same_elements_in_order(piece, expected, what) && ok;
    if (!piece.mesh.has_topology()) ok = fail(what + ": the piece has no topology");
    const Index first = slice_start(mesh.element_count(), process_rank(), process_count());
    if (piece.mesh.element_count() != slice_start(mesh.element_count(), process_rank() + 1, process_count()) - first)
      ok = fail(what + ": the piece does not hold its run of elements");
  }
  return ok;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "mesh file pieces", [] {
    const std::string directory = hocav::shared_directory("hocav-pieces-");
    const hocav::Mesh<2> square = hocav::tagged_mesh(hocav::generate_square(12));
    const hocav::Mesh<3> cube = hocav::tagged_mesh(hocav::generate_cube(6));
    const bool ok = hocav::check(square, directory, "square") & hocav::check(cube, directory, "cube") &
                    hocav::check(hocav::shuffled(square), directory, "shuffled-square") &
                    hocav::check(hocav::shuffled(cube), directory, "shuffled-cube");  // every process runs all
    hocav::all_gather_value(0);
    if (hocav::process_rank() == 0) std::filesystem::remove_all(directory);
    return ok;
  });
}
