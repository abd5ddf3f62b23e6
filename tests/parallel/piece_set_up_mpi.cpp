// The set-up of a distributed adaptation from pieces (docs/distributed.md §Adapting from pieces),
// run by ctest under `mpirun -np N` (N = 2, 3, 4). Rank 0 writes meshes without tags (a square, a
// cube, the cube with its vertices renumbered across the file); every process reads its piece of
// each, orients its facets and gathers the boundary:
// 0. orient_piece_facets orders every facet of the pieces of the cube with four materials and
//    facets between them, and of a square and a cube with a baffle across their middle (their
//    elements shuffled across the file, every other facet turned), as orient_boundary_facets_outward
//    orders the whole mesh's, facets between two pieces included;
// 1. classify_piece_vertices: the corners and feature lines (with their refs) that the pieces carry
//    together are those classify_vertices adds to the whole mesh, by file ids (on the cube with
//    four materials and on the one with a baffle too);
// 2. grade_piece_metrics, on a metric with a fine spot: every copy of a vertex ends with the same
//    metric, every edge of every piece meets the gradation (the test of grade_metrics' fixed point),
//    no metric is coarser than given, and each is within 1% of the serial grading's (the same
//    constraints, another order).
// Exit code 0 when all holds on every process, 1 otherwise (with a message).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <unordered_set>
#include <variant>
#include <vector>

#include "../mesh/inner_facet_meshes.hpp"
#include "adapt/vertex_classes.hpp"
#include "cases/structured.hpp"
#include "geom/sym_eigen.hpp"
#include "io/mesh_file.hpp"
#include "mpi_test_main.hpp"
#include "parallel/boundary_of_parts.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_gradation.hpp"
#include "parallel/face_key.hpp"
#include "parallel/mesh_file_pieces.hpp"
#include "parallel/piece_classification.hpp"
#include "parallel/piece_facet_orientation.hpp"
#include "parallel/piece_input_check.hpp"
#include "tagged_meshes.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "piece set-up (rank " << process_rank() << "): " << what << '\n';
  return false;
}

// `mesh` with its vertices, elements and facets only: no corners, lines or required entities.
template <int D>
Mesh<D> untagged(const Mesh<D>& mesh) {
  Mesh<D> out;
  for (Index v = 0; v < mesh.vertex_count(); ++v) out.add_vertex(mesh.vertex(v), mesh.vertex_ref(v));
  for (Index k = 0; k < mesh.element_count(); ++k) out.add_element(mesh.element(k), mesh.element_ref(k));
  for (Index f = 0; f < mesh.facet_count(); ++f) out.add_facet(mesh.facet(f), mesh.facet_ref(f));
  out.build_topology();
  return out;
}

// Corners by id, and feature lines by their sorted end ids with their refs.
struct Features {
  std::set<Index> corners;
  std::set<std::array<Index, 3>> lines;
  bool operator==(const Features&) const = default;
};

template <int D>
Features features_of(const Mesh<D>& mesh, const std::vector<Index>& global) {
  Features out;
  for (Index v : mesh.corners()) out.corners.insert(global[v]);
  for (Index l = 0; l < mesh.line_count(); ++l) {
    const Index a = global[mesh.line(l)[0]], b = global[mesh.line(l)[1]];
    out.lines.insert({std::min(a, b), std::max(a, b), mesh.line_ref(l)});
  }
  return out;
}

// Every process's features, joined.
Features joined(const Features& own) {
  std::vector<Index> corners(own.corners.begin(), own.corners.end());
  std::vector<Index> lines;
  for (const auto& line : own.lines) lines.insert(lines.end(), line.begin(), line.end());
  Features all;
  for (const std::vector<std::byte>& bytes : all_gather_bytes(bytes_of_values(corners)))
    for (Index v : values_of_bytes<Index>(bytes)) all.corners.insert(v);
  for (const std::vector<std::byte>& bytes : all_gather_bytes(bytes_of_values(lines))) {
    const std::vector<Index> ids = values_of_bytes<Index>(bytes);
    for (std::size_t i = 0; i + 2 < ids.size(); i += 3) all.lines.insert({ids[i], ids[i + 1], ids[i + 2]});
  }
  return all;
}

// Rank 0 writes `mesh` to `path`; then every process reads its piece, prepared for the set-up.
template <int D>
MeshFilePiece<D> piece_of(const Mesh<D>& mesh, const std::string& path) {
  if (process_rank() == 0) write_mesh_file(path, mesh);
  all_gather_value(0);  // the file is written
  MeshFilePiece<D> piece = read_mesh_file_piece<D>(path);
  if (!piece.part.mesh.has_topology()) piece.part.mesh.build_topology();
  orient_piece_facets(piece.part, piece.facet_ids);
  return piece;
}

// Whether two facets are one with the same orientation: the same first vertex in 2D, a rotation in 3D.
template <int D>
bool same_orientation(const typename Mesh<D>::Facet& a, const typename Mesh<D>::Facet& b) {
  for (int shift = 0; shift < (D == 2 ? 1 : D); ++shift) {
    bool same = true;
    for (int i = 0; i < D; ++i) same &= a[(i + shift) % D] == b[i];
    if (same) return true;
  }
  return false;
}

// The interface facets of a part, by their sorted global ids.
template <int D>
std::unordered_set<FaceKey<D>, FaceKeyHash<D>> interface_keys(const MeshPart<D>& part) {
  std::unordered_set<FaceKey<D>, FaceKeyHash<D>> keys;
  for (Index f = 0; f < part.mesh.facet_count(); ++f)
    if (part.mesh.facet_ref(f) == kInterfaceRef) {
      FaceKey<D> key = part.mesh.facet(f);
      for (Index& v : key) v = part.global_ids[v];
      keys.insert(sorted_key<D>(key));
    }
  return keys;
}

template <int D>
bool check_orientation(const Mesh<D>& mesh, const std::string& path) {
  const MeshFilePiece<D> piece = piece_of(mesh, path);
  Mesh<D> whole = std::get<Mesh<D>>(read_mesh_file(path).mesh);  // (with its topology)
  whole.orient_boundary_facets_outward();
  const Mesh<D>& own = piece.part.mesh;
  const std::unordered_set<FaceKey<D>, FaceKeyHash<D>> between = interface_keys(piece.part);
  long long crossing = 0;
  for (Index f = 0; f < own.facet_count(); ++f) {
    if (own.facet_ref(f) == kInterfaceRef) continue;
    typename Mesh<D>::Facet global = own.facet(f);
    for (Index& v : global) v = piece.part.global_ids[v];
    if (!same_orientation<D>(global, whole.facet(piece.facet_ids[f])))
      return fail(path + ": facet " + std::to_string(piece.facet_ids[f] + 1) + " oriented otherwise than in the whole mesh");
    crossing += between.contains(sorted_key<D>(global));
  }
  crossing = sum_over_processes(crossing);
  if (process_rank() == 0) std::cerr << path << ": every facet oriented as in the whole mesh, " << crossing << " between two pieces\n";
  if (crossing == 0) return fail(path + ": no facet lies between two pieces");
  return true;
}

template <int D>
bool check_classification(const Mesh<D>& mesh, const std::string& path) {
  MeshFilePiece<D> piece = piece_of(mesh, path);
  classify_piece_vertices(piece.part, boundary_of_parts(piece.part), 45);
  Mesh<D> whole = mesh;
  whole.orient_boundary_facets_outward();
  classify_vertices(whole, 45);
  std::vector<Index> identity(static_cast<std::size_t>(whole.vertex_count()));
  for (Index v = 0; v < whole.vertex_count(); ++v) identity[v] = v;
  const Features serial = features_of(whole, identity), pieces = joined(features_of(piece.part.mesh, piece.part.global_ids));
  if (serial.corners.empty() && serial.lines.empty()) return fail(path + ": the whole mesh has no feature to find");
  if (pieces == serial) return true;
  return fail(path + ": the pieces carry " + std::to_string(pieces.corners.size()) + " corners and " + std::to_string(pieces.lines.size()) +
              " lines, the whole mesh " + std::to_string(serial.corners.size()) + " and " + std::to_string(serial.lines.size()));
}

// A metric 100 times finer near one point than elsewhere, with some anisotropy.
template <int D>
SymMat<D> spot_metric(const Vec<D>& x) {
  double distance2 = 0;
  for (int i = 0; i < D; ++i) distance2 += (x[i] - 0.3) * (x[i] - 0.3);
  const double size = distance2 < 0.01 ? 0.002 : 0.2;
  Vec<D> diagonal{};
  for (int i = 0; i < D; ++i) diagonal[i] = 1 / (size * size * (1 + i));
  return SymMat<D>::from_diagonal(diagonal);
}

// The largest relative difference of two SPD matrices' eigenvalues, each measured in the other.
template <int D>
double relative_gap(const SymMat<D>& a, const SymMat<D>& b) {
  return std::max(largest_relative_eigenvalue(a, b), largest_relative_eigenvalue(b, a)) - 1;
}

template <int D>
bool check_gradation(const Mesh<D>& mesh, const std::string& path) {
  const MeshFilePiece<D> piece = piece_of(mesh, path);
  const GradationOptions options{1.3, 1e-3};
  std::vector<SymMat<D>> serial;
  for (const Vec<D>& x : mesh.vertices()) serial.push_back(spot_metric(x));
  grade_metrics(mesh, serial, options);
  const Mesh<D>& own = piece.part.mesh;
  std::vector<SymMat<D>> given, graded;
  for (const Vec<D>& x : own.vertices()) given.push_back(spot_metric(x));
  graded = given;
  const int rounds = grade_piece_metrics(piece.part, graded, options);
  bool ok = true;
  double gap = 0;
  for (Index v = 0; v < own.vertex_count(); ++v) {
    gap = std::max(gap, relative_gap(graded[v], serial[piece.part.global_ids[v]]));
    if (largest_relative_eigenvalue(given[v], graded[v]) > 1 + 1e-12) ok = fail(path + ": a graded metric coarser than given");
  }
  for (Index k = 0; k < own.element_count(); ++k)
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j <= D; ++j) {
        if (i == j) continue;
        const Index p = own.element(k)[i], q = own.element(k)[j];
        const Vec<D> pq = own.vertex(q) - own.vertex(p);
        const double factor = gradation_factor(std::sqrt(dot(pq, graded[p] * pq)), options.growth);
        if (largest_relative_eigenvalue(graded[p] * factor, graded[q]) > 1 + 2 * options.tolerance)
          return fail(path + ": an edge of a piece does not meet the gradation");
      }
  std::map<Index, SymMat<D>> copies;
  std::vector<double> flat;
  for (Index v = 0; v < own.vertex_count(); ++v) {
    flat.push_back(static_cast<double>(piece.part.global_ids[v]));
    for (double entry : graded[v].entries) flat.push_back(entry);
  }
  const std::size_t width = 1 + SymMat<D>{}.entries.size();
  for (const std::vector<std::byte>& bytes : all_gather_bytes(bytes_of_values(flat))) {
    const std::vector<double> values = values_of_bytes<double>(bytes);
    for (std::size_t i = 0; i + width <= values.size(); i += width) {
      SymMat<D> metric;
      std::copy(values.begin() + static_cast<std::ptrdiff_t>(i + 1), values.begin() + static_cast<std::ptrdiff_t>(i + width),
                metric.entries.begin());
      const auto [at, added] = copies.try_emplace(static_cast<Index>(values[i]), metric);
      if (!added && at->second != metric) ok = fail(path + ": two copies of a vertex with other metrics");
    }
  }
  if (process_rank() == 0) std::cerr << path << ": " << rounds << " rounds, largest gap to the serial grading " << gap << '\n';
  if (!(gap <= 0.01)) ok = fail(path + ": graded " + std::to_string(gap) + " away from the serial grading");
  return ok;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "piece set-up", [] {
    const std::string directory = hocav::shared_directory("hocav-piece-set-up-");
    const hocav::Mesh<2> square = hocav::untagged(hocav::generate_square(16));
    const hocav::Mesh<3> cube = hocav::untagged(hocav::generate_cube(6));
    bool ok = hocav::check_orientation(hocav::tagged_mesh(hocav::generate_cube(6)), directory + "/materials.meshb");
    ok &= hocav::check_orientation(hocav::mesh_test::elements_shuffled(hocav::mesh_test::baffle_across_the_middle<2>(16)),
                                   directory + "/baffle-square.meshb");
    ok &= hocav::check_orientation(hocav::mesh_test::elements_shuffled(hocav::mesh_test::baffle_across_the_middle<3>(6)),
                                   directory + "/baffle-cube.mesh");
    ok &= hocav::check_classification(square, directory + "/square.meshb");
    ok &= hocav::check_classification(cube, directory + "/cube.meshb");
    ok &= hocav::check_classification(hocav::untagged(hocav::shuffled(cube)), directory + "/shuffled-cube.mesh");
    ok &= hocav::check_classification(hocav::untagged(hocav::tagged_mesh(hocav::generate_cube(6))), directory + "/materials.meshb");
    ok &= hocav::check_classification(hocav::mesh_test::elements_shuffled(hocav::mesh_test::baffle_across_the_middle<3>(6)),
                                      directory + "/baffle-cube.meshb");
    ok &= hocav::check_gradation(square, directory + "/square.meshb");
    ok &= hocav::check_gradation(hocav::untagged(hocav::shuffled(cube)), directory + "/shuffled-cube.meshb");
    hocav::all_gather_value(0);
    if (hocav::process_rank() == 0) std::filesystem::remove_all(directory);
    return ok;
  });
}
