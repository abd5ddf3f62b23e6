// A P1 mesh file and its metric file read in pieces, prepared and cut into parts
// (read_mesh_file_piece, prepare_input_piece, parts_of_pieces: docs/distributed.md §Curving from
// pieces), run by ctest under `mpirun -np N` (N = 2, 3, 4). Rank 0 writes a square and a cube (also
// with their vertices renumbered across the file) as .meshb with a .solb metric and as .mesh with a
// .sol, each vertex with a metric of its own; every process reads its pieces:
// 1. the parts are the mesh's (scattered_part_checks.hpp: each element in one part, each vertex its
//    point and its own metric, the metric rows read by other processes);
// 2. a file with every element inverted is reoriented (every part's elements positive) and a file
//    without its boundary facets gets them, each said once by rank 0 in the words, and with the
//    counts, of the serial preparation of the whole mesh (prepare_input_mesh), nothing by the others;
//    the parts are those of the serially prepared mesh, their facet ids those the serial
//    preparation gives the facets it makes.
// Exit code 0 when all holds on every process, 1 otherwise (with a message).
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cases/structured.hpp"
#include "io/mesh_file.hpp"
#include "io/node_metrics.hpp"
#include "io/solution_file.hpp"
#include "mesh/input_check.hpp"
#include "mesh/inverted_input.hpp"
#include "mesh/measure.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/piece_input_check.hpp"
#include "parallel/pieces_into_parts.hpp"
#include "scattered_part_checks.hpp"
#include "tagged_meshes.hpp"

namespace hocav {
namespace {

// Rank 0 writes `mesh` to `mesh_path` and each vertex's metric_of to `metric_path`; then all go on.
template <int D>
void write_case(const Mesh<D>& mesh, const std::string& mesh_path, const std::string& metric_path) {
  if (process_rank() == 0) {
    write_mesh_file(mesh_path, mesh);
    std::vector<SymMat<D>> metrics;
    for (Index v = 0; v < mesh.vertex_count(); ++v) metrics.push_back(metric_of<D>(v));
    write_solution_file(metric_path, SolutionFileContent{D, mesh.vertex_count(), {rows_of_metrics(metrics)}});
  }
  all_gather_value(0);  // the files are written
}

// Every process: the files read in pieces, prepared (the warnings rank 0 said, in order) and cut.
template <int D>
ScatteredPart<D> parts_of_files(const std::string& mesh_path, const std::string& metric_path, std::vector<std::string>& said) {
  MeshFilePiece<D> piece = read_mesh_file_piece<D>(mesh_path);
  prepare_input_piece(piece, mesh_path, [&](const std::string& warning) { said.push_back(warning); });
  return parts_of_pieces(std::move(piece), metric_path, 7);
}

template <int D>
bool check_parts(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  bool ok = true;
  for (const std::string extension : {".meshb", ".mesh"}) {
    const std::string mesh_path = directory + "/" + name + extension, metric_path = mesh_path + (extension == ".meshb" ? ".solb" : ".sol");
    write_case(mesh, mesh_path, metric_path);
    std::vector<std::string> said;
    const ScatteredPart<D> parts = parts_of_files<D>(mesh_path, metric_path, said);
    ok = check_scattered_part(mesh, parts, name + extension) && ok;
    if (!said.empty()) ok = fail_scattered(name + extension + ": a warning on a sound file: " + said.front());
  }
  return ok;
}

// A copy of `mesh` without its boundary facets, or with every element inverted.
template <int D>
Mesh<D> without_facets(const Mesh<D>& mesh) {
  Mesh<D> bare;
  for (Index v = 0; v < mesh.vertex_count(); ++v) bare.add_vertex(mesh.vertex(v), mesh.vertex_ref(v));
  for (Index k = 0; k < mesh.element_count(); ++k) bare.add_element(mesh.element(k), mesh.element_ref(k));
  return bare;
}
template <int D>
Mesh<D> inverted(Mesh<D> mesh) {
  reorient_every_element(mesh);
  return mesh;
}

// `defective` prepared in pieces: every part element positive, and rank 0 says what the serial
// preparation of the whole file says.
template <int D>
bool check_preparation(const Mesh<D>& defective, const std::string& directory, const std::string& name) {
  const std::string mesh_path = directory + "/" + name + ".meshb", metric_path = mesh_path + ".solb";
  write_case(defective, mesh_path, metric_path);
  std::vector<std::string> said, expected;
  const ScatteredPart<D> parts = parts_of_files<D>(mesh_path, metric_path, said);
  Mesh<D> whole = std::get<Mesh<D>>(read_mesh_file(mesh_path).mesh);  // (on every process: a small case)
  prepare_input_mesh(whole, mesh_path, [&](const std::string& warning) {
    if (process_rank() == 0) expected.push_back(warning);
  });
  if (!check_scattered_part(whole, parts, name)) return false;
  if (process_rank() == 0 && expected.empty()) return fail_scattered(name + ": the serial preparation says nothing: not a defective case");
  for (Index k = 0; k < parts.part.mesh.element_count(); ++k)
    if (!(element_measure(parts.part.mesh, k) > 0)) return fail_scattered(name + ": an element of non-positive measure in a part");
  if (said != expected) {
    return fail_scattered(name + ": said " + std::to_string(said.size()) + " warnings (first: " + (said.empty() ? "none" : said.front()) +
                          "), the serial preparation " + std::to_string(expected.size()));
  }
  return true;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "pieces into parts", [] {
    const std::string directory = hocav::shared_directory("hocav-pieces-parts-");
    const hocav::Mesh<2> square = hocav::generate_square(16);
    const hocav::Mesh<3> cube = hocav::generate_cube(6);
    const bool ok = hocav::check_parts(square, directory, "square") & hocav::check_parts(cube, directory, "cube") &
                    hocav::check_parts(hocav::shuffled(square), directory, "shuffled-square") &
                    hocav::check_parts(hocav::shuffled(cube), directory, "shuffled-cube") &
                    hocav::check_preparation(hocav::inverted(cube), directory, "inverted-cube") &
                    hocav::check_preparation(hocav::without_facets(cube), directory, "bare-cube") &
                    hocav::check_preparation(hocav::inverted(hocav::without_facets(square)), directory, "inverted-bare-square");
    hocav::all_gather_value(0);
    if (hocav::process_rank() == 0) std::filesystem::remove_all(directory);
    return ok;
  });
}
