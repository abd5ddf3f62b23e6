// Reading a mesh file in pieces (read_mesh_file_piece, docs/distributed.md §Reading in pieces), run
// by ctest under `mpirun -np N` (N = 2, 3, 4). Rank 0 writes a square and a cube with four materials
// (facets between them), feature lines, corners and required vertices, edges and facets, as .meshb
// and .mesh. Every process then reads its piece of each file, and it must be, entity by entity by
// global ids and with its elements in the same order, the part that migrate_part makes of the mesh
// rank 0 reads whole when element k goes to the process whose run holds it; the binary and the
// text file must give the same piece; so again with the vertices renumbered across the file (a run's
// elements then use ids from everywhere). Exit code 0 when all holds on every process, 1 otherwise.
#include <unistd.h>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>

#include "adapt/vertex_classes.hpp"
#include "cases/structured.hpp"
#include "io/gamma_mesh.hpp"
#include "io/mesh_file.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/mesh_file_pieces.hpp"
#include "parallel/part_migration.hpp"
#include "part_description.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "mesh file pieces (rank " << process_rank() << "): " << what << '\n';
  return false;
}

template <int D>
Vec<D> centroid(const Mesh<D>& mesh, Index k) {
  Vec<D> sum{};
  for (Index v : mesh.element(k)) sum = sum + mesh.vertex(v);
  return (1.0 / (D + 1)) * sum;
}

// The structured mesh with its tags, and four materials (cut at x = 0.5 and y = 0.4, across the runs
// of elements and along them) with facets of ref 9 between them.
template <int D>
Mesh<D> tagged_mesh(Mesh<D> mesh) {
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const Vec<D> c = centroid(mesh, k);
    mesh.set_element(k, mesh.element(k), 1 + (c[0] < 0.5 ? 1 : 0) + (c[1] < 0.4 ? 2 : 0));
  }
  mesh.build_topology();
  classify_vertices(mesh, 45);
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face)
      if (const Index other = mesh.neighbor(k, face); other != kNoIndex && mesh.element_ref(other) != mesh.element_ref(k) && other > k) {
        typename Mesh<D>::Facet facet{};
        for (int i = 0; i < D; ++i) facet[i] = mesh.element(k)[face_vertices<D>(face)[i]];
        mesh.add_facet(facet, 9);
      }
  for (Index v = 0; v < mesh.vertex_count(); v += 7) mesh.required_vertices().push_back(v);
  std::vector<Index>& required_facets = D == 2 ? mesh.required_edges() : mesh.required_triangles();
  for (Index f = 0; f < mesh.facet_count(); f += 5) required_facets.push_back(f);
  if constexpr (D == 3)
    for (Index l = 0; l < mesh.line_count(); l += 3) mesh.required_edges().push_back(l);
  mesh.build_topology();
  return mesh;
}

// The same mesh with its vertices renumbered v -> 7919 v mod n (a prime not dividing n): a run of
// elements then uses vertex ids from all over the file.
template <int D>
Mesh<D> shuffled(const Mesh<D>& mesh) {
  const Index n = mesh.vertex_count();
  const auto moved = [n](Index v) { return static_cast<Index>(static_cast<std::int64_t>(v) * 7919 % n); };
  std::vector<Index> old_of(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v) old_of[moved(v)] = v;
  Mesh<D> out;
  for (Index v = 0; v < n; ++v) out.add_vertex(mesh.vertex(old_of[v]), mesh.vertex_ref(old_of[v]));
  const auto renumbered = [&](auto ids) {
    for (Index& v : ids) v = moved(v);
    return ids;
  };
  for (Index k = 0; k < mesh.element_count(); ++k) out.add_element(renumbered(mesh.element(k)), mesh.element_ref(k));
  for (Index f = 0; f < mesh.facet_count(); ++f) out.add_facet(renumbered(mesh.facet(f)), mesh.facet_ref(f));
  for (Index l = 0; l < mesh.line_count(); ++l) out.add_line(renumbered(mesh.line(l)), mesh.line_ref(l));
  for (Index v : mesh.corners()) out.corners().push_back(moved(v));
  for (Index v : mesh.required_vertices()) out.required_vertices().push_back(moved(v));
  out.ridges() = mesh.ridges();
  out.required_edges() = mesh.required_edges();
  out.required_triangles() = mesh.required_triangles();
  out.build_topology();
  return out;
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

// A directory every process sees, named by rank 0.
std::string shared_directory() {
  std::string path = std::filesystem::temp_directory_path() / ("hocav-pieces-" + std::to_string(getpid()));
  std::vector<std::byte> bytes(path.size());
  std::memcpy(bytes.data(), path.data(), path.size());
  broadcast_bytes(bytes);
  path.assign(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (process_rank() == 0) std::filesystem::create_directories(path);
  return path;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "mesh file pieces", [] {
    const std::string directory = hocav::shared_directory();
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
