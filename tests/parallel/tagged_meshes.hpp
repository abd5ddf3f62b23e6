// The meshes the MPI tests of reading, writing and measuring in pieces use: a structured square or
// cube with four materials, feature lines, corners and required entities, the same with its
// vertices renumbered across the file, and P2 with its nodes off the edges' middles; rank 0's mesh
// scattered over the processes; a directory every process sees; a file's bytes.
#pragma once

#include <unistd.h>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numeric>
#include <string>
#include <vector>

#include "adapt/vertex_classes.hpp"
#include "cases/structured.hpp"
#include "parallel/communicator.hpp"
#include "parallel/line_ids_by_ends.hpp"
#include "parallel/mesh_file_runs.hpp"
#include "parallel/part_migration.hpp"

namespace hocav {

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

// The mesh, P2 with each node moved off its edge's middle by an amount of its own.
template <int D>
Mesh<D> curved(Mesh<D> mesh) {
  mesh.make_p2();
  for (Index e = 0; e < mesh.edge_count(); ++e) mesh.edge_node(e)[e % D] += 1e-3 * static_cast<double>(e % 7 + 1);
  return mesh;
}

// `check(mesh, name)` on the writers' test meshes, true when it holds on each: the square and the
// cube with their tags (tagged_mesh), each as it is and renumbered (shuffled), each P1 and P2 (curved).
template <typename Check>
bool check_tagged_meshes(Check check) {
  bool ok = true;
  const auto each_variant = [&](const auto& mesh, const std::string& name) {
    for (const auto& [variant, label] : {std::pair{mesh, name}, std::pair{shuffled(mesh), "shuffled-" + name}}) {
      ok = check(variant, label) & ok;
      ok = check(curved(variant), label + "-p2") & ok;
    }
  };
  each_variant(tagged_mesh(generate_square(12)), "square");
  each_variant(tagged_mesh(generate_cube(6)), "cube");
  return ok;
}

// A file's bytes, to compare two files.
inline std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Element k of rank 0's mesh goes to part `destination(k)`.
template <int D>
MeshPart<D> scattered(const Mesh<D>& mesh, int (*destination)(Index)) {
  if (process_rank() != 0) return migrate_part(MeshPart<D>{}, {});
  std::vector<int> part_of;
  for (Index k = 0; k < mesh.element_count(); ++k) part_of.push_back(destination(k));
  return migrate_part(whole_mesh_part(Mesh<D>(mesh)), part_of);
}

// Destinations: every element on rank 0; or spread (7k + k/5 mod N), so that parts touch at many
// vertices, edges and lines.
inline int to_rank_0(Index) { return 0; }
inline int spread(Index k) { return static_cast<int>((7 * k + k / 5) % process_count()); }

// Rank 0's mesh spread (as `spread` says) with each element's, facet's and line's id in the mesh as
// its place, as the writers in runs take orders: the element and facet ids carried through the
// migration, the lines' found by their ends after it.
template <int D>
struct OrderedPart {
  MeshPart<D> part;
  std::vector<Index> elements, facets, lines;

  EntityOrders orders() const { return {elements, facets, lines}; }
};

template <int D>
OrderedPart<D> spread_in_mesh_order(const Mesh<D>& mesh) {
  std::vector<int> destination;
  std::vector<Index> element_ids, facet_ids;
  MeshPart<D> whole;
  if (process_rank() == 0) {
    for (Index k = 0; k < mesh.element_count(); ++k) destination.push_back(spread(k)), element_ids.push_back(k);
    for (Index f = 0; f < mesh.facet_count(); ++f) facet_ids.push_back(f);
    whole = whole_mesh_part(Mesh<D>(mesh));
  }
  OrderedPart<D> out;
  out.elements = migrated_element_values(element_ids, destination);
  out.facets = migrated_facet_values(whole, facet_ids, destination);
  std::vector<Index> line_ids(static_cast<std::size_t>(whole.mesh.line_count()));
  std::iota(line_ids.begin(), line_ids.end(), Index{0});
  const std::vector<KnownLine> known = known_lines(whole, line_ids);
  out.part = migrate_part(whole, destination);
  out.lines = line_ids_by_ends(out.part, known);
  return out;
}

// A directory every process sees, named by rank 0.
inline std::string shared_directory(const std::string& prefix) {
  std::string path = std::filesystem::temp_directory_path() / (prefix + std::to_string(getpid()));
  std::vector<std::byte> bytes(path.size());
  std::memcpy(bytes.data(), path.data(), path.size());
  broadcast_bytes(bytes);
  path.assign(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (process_rank() == 0) std::filesystem::create_directories(path);
  return path;
}

}  // namespace hocav
