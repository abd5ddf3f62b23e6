// Writing a .vtu in runs (write_vtu_runs, docs/distributed.md §A .vtu in runs), run by ctest under
// `mpirun -np N` (N = 2, 3, 4), on a square and a cube with four materials, P1 and P2 (nodes off the
// edges' middles), with a point field (a function of the point) and a cell field (the element's
// vertices' centroid):
// - all on rank 0 (the other parts empty), the runs must be write_vtu's file of the part, byte for
//   byte;
// - scattered over the processes (element k to process (7k + k/5) mod N), the file read back (its
//   raw arrays, by their offsets) must hold every part's points and cells rank after rank: cell i
//   the mesh's element in the parts' order, its points those of the element's vertices and nodes,
//   the point field the function of each point, the cell field and the refs the element's.
// Exit code 0 when all holds on every process, 1 otherwise.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <string>

#include "cases/structured.hpp"
#include "io/vtu_file.hpp"
#include "mesh/simplex.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/vtu_file_runs.hpp"
#include "tagged_meshes.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "vtu file runs (rank " << process_rank() << "): " << what << '\n';
  return false;
}

template <int D>
double point_function(const Vec<D>& x) {
  double value = 0;
  for (int i = 0; i < D; ++i) value += (i + 1) * x[i];
  return value;
}

// The point field "f" and the cell field "g" of a part.
template <int D>
VtuData data_of(const Mesh<D>& mesh) {
  VtuData data{{{"f", 1, {}}}, {{"g", 3, {}}}};
  for (const Vec<D>& x : mesh.vertices()) data.point_fields[0].values.push_back(point_function(x));
  for (Index e = 0; mesh.is_p2() && e < mesh.edge_count(); ++e) data.point_fields[0].values.push_back(point_function(mesh.edge_node(e)));
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int c = 0; c < 3; ++c) data.cell_fields[0].values.push_back(c < D ? centroid(mesh, k)[c] : 0.0);
  return data;
}

// A .vtu as write_vtu writes it: its counts and each DataArray's raw bytes by name.
struct ReadVtu {
  std::int64_t points = 0, cells = 0;
  std::map<std::string, std::string> arrays;

  template <typename T>
  T value(const std::string& name, std::size_t i) const {
    T x;
    std::memcpy(&x, arrays.at(name).data() + i * sizeof(T), sizeof(T));
    return x;
  }
};

std::string attribute(const std::string& text, std::size_t from, const std::string& name) {
  const std::size_t start = text.find(name + "=\"", from) + name.size() + 2;
  return text.substr(start, text.find('"', start) - start);
}

ReadVtu read_vtu(const std::string& path) {
  const std::string text = file_bytes(path);
  ReadVtu file;
  file.points = std::stoll(attribute(text, 0, "NumberOfPoints"));
  file.cells = std::stoll(attribute(text, 0, "NumberOfCells"));
  const std::string marker = "<AppendedData encoding=\"raw\">\n_";
  const std::size_t block = text.find(marker) + marker.size();
  for (std::size_t at = text.find("<DataArray "); at < block; at = text.find("<DataArray ", at + 1)) {
    const std::size_t offset = block + std::stoull(attribute(text, at, "offset"));
    std::uint64_t bytes;
    std::memcpy(&bytes, text.data() + offset, sizeof bytes);
    file.arrays[attribute(text, at, "Name")] = text.substr(offset + sizeof bytes, bytes);
  }
  return file;
}

// All on rank 0: the runs are write_vtu's file of rank 0's part.
template <int D>
bool same_bytes_as_serial(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  const MeshPart<D> part = scattered(mesh, to_rank_0);
  const std::string runs = directory + "/" + name + "-runs.vtu", serial = directory + "/" + name + "-serial.vtu";
  write_vtu_runs(runs, part.mesh, data_of(part.mesh));
  if (process_rank() != 0) return true;
  write_vtu(serial, part.mesh, data_of(part.mesh));
  return file_bytes(runs) == file_bytes(serial) || fail(name + ": " + runs + " is not write_vtu's file");
}

// The points of element k of `mesh`: its vertices, then its edges' nodes (P2).
template <int D>
std::vector<Vec<D>> element_points(const Mesh<D>& mesh, Index k) {
  std::vector<Vec<D>> points;
  for (Index v : mesh.element(k)) points.push_back(mesh.vertex(v));
  for (int e = 0; mesh.is_p2() && e < Simplex<D>::kEdges; ++e) points.push_back(mesh.edge_node(mesh.element_edge(k, e)));
  return points;
}

// Cell i of the file is `mesh`'s element k, with its points, fields and ref.
template <int D>
bool same_cell(const ReadVtu& file, std::int64_t i, const Mesh<D>& mesh, Index k) {
  const std::vector<Vec<D>> expected = element_points(mesh, k);
  const auto size = static_cast<std::int64_t>(expected.size());
  if (file.value<std::int64_t>("offsets", static_cast<std::size_t>(i)) != (i + 1) * size) return false;
  for (std::int64_t j = 0; j < size; ++j) {
    const auto point = static_cast<std::size_t>(file.value<std::int64_t>("connectivity", static_cast<std::size_t>(i * size + j)));
    for (int c = 0; c < 3; ++c)
      if (file.value<double>("Points", 3 * point + static_cast<std::size_t>(c)) != (c < D ? expected[static_cast<std::size_t>(j)][c] : 0.0))
        return false;
    if (file.value<double>("f", point) != point_function(expected[static_cast<std::size_t>(j)])) return false;
  }
  for (int c = 0; c < D; ++c)
    if (file.value<double>("g", static_cast<std::size_t>(3 * i + c)) != centroid(mesh, k)[c]) return false;
  return file.value<std::int32_t>("ref", static_cast<std::size_t>(i)) == mesh.element_ref(k);
}

// Scattered: the file holds every part's points and cells, rank after rank.
template <int D>
bool parts_read_back(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  const MeshPart<D> part = scattered(mesh, spread);
  const std::string path = directory + "/" + name + "-spread.vtu";
  write_vtu_runs(path, part.mesh, data_of(part.mesh));
  const Index points = sum_over_processes(part.mesh.vertex_count() + (part.mesh.is_p2() ? part.mesh.edge_count() : 0));
  if (process_rank() != 0) return true;
  const ReadVtu file = read_vtu(path);
  if (file.points != points || file.cells != mesh.element_count()) return fail(name + ": not the parts' counts in " + path);
  std::int64_t i = 0;
  for (int r = 0; r < process_count(); ++r)
    for (Index k = 0; k < mesh.element_count(); ++k)
      if (spread(k) == r && !same_cell(file, i++, mesh, k))
        return fail(name + ": cell " + std::to_string(i - 1) + " of " + path + " is wrong");
  return true;
}

template <int D>
bool check(const Mesh<D>& mesh, const std::string& directory, const std::string& name) {
  bool ok = true;
  for (const auto& [suffix, each] : {std::pair{"", mesh}, {"-p2", curved(mesh)}})
    ok = same_bytes_as_serial(each, directory, name + suffix) & parts_read_back(each, directory, name + suffix) & ok;
  return ok;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "vtu file runs", [] {
    const std::string directory = hocav::shared_directory("hocav-vtu-runs-");
    bool ok = hocav::check(hocav::tagged_mesh(hocav::generate_square(12)), directory, "square");
    ok = hocav::check(hocav::tagged_mesh(hocav::generate_cube(6)), directory, "cube") & ok;
    hocav::all_gather_value(0);
    if (hocav::process_rank() == 0) std::filesystem::remove_all(directory);
    return ok;
  });
}
