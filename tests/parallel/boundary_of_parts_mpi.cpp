// The whole mesh's boundary made of the parts' (boundary_of_parts, docs/distributed.md §Curving in
// the parts), run by ctest under `mpirun -np N` (N = 2, 3, 4). Every process builds a square and a
// cube with four materials and every kind of tag, as they are and with their vertices renumbered;
// rank 0's copy is scattered element by element (parts touching at many vertices, edges and lines)
// or kept whole. Each process's boundary must be the whole mesh's by global ids: the vertices of its
// facets, lines, corners and required vertices with their points and refs, in id order; its facets
// and lines once each with their refs and tags; no interface facet, no interface vertex required;
// the same facets in the same order on every process; and boundary_indices must find each part
// vertex there exactly when it is one of those.
// Exit code 0 when all holds on every process, 1 otherwise.
#include <algorithm>
#include <iostream>
#include <set>
#include <string>
#include <tuple>

#include "cases/structured.hpp"
#include "mpi_test_main.hpp"
#include "parallel/boundary_of_parts.hpp"
#include "parallel/communicator.hpp"
#include "parallel/entity_tags.hpp"
#include "tagged_meshes.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "boundary of parts (rank " << process_rank() << "): " << what << '\n';
  return false;
}

// A facet or line by its sorted global ids, with its ref and tags (required, ridge).
using Tagged = std::tuple<std::vector<Index>, int, char, char>;

template <std::size_t N>
std::vector<Index> sorted_ids(const std::array<Index, N>& ids, const std::vector<Index>& global) {
  std::vector<Index> out;
  for (Index v : ids) out.push_back(global.empty() ? v : global[v]);
  std::sort(out.begin(), out.end());
  return out;
}

template <int D>
std::multiset<Tagged> facets_of(const Mesh<D>& mesh, const std::vector<Index>& global) {
  const EntityTags<D> tags(mesh);
  std::multiset<Tagged> out;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    out.insert({sorted_ids(mesh.facet(f), global), mesh.facet_ref(f), tags.required_facet[f], tags.ridge_facet[f]});
  return out;
}

template <int D>
std::multiset<Tagged> lines_of(const Mesh<D>& mesh, const std::vector<Index>& global) {
  const EntityTags<D> tags(mesh);
  std::multiset<Tagged> out;
  if constexpr (D == 3)
    for (Index l = 0; l < mesh.line_count(); ++l)
      out.insert({sorted_ids(mesh.line(l), global), mesh.line_ref(l), tags.required_line[l], tags.ridge_line[l]});
  return out;
}

template <int D>
std::set<Index> ids_of(const std::vector<Index>& vertices, const std::vector<Index>& global) {
  std::set<Index> out;
  for (Index v : vertices) out.insert(global.empty() ? v : global[v]);
  return out;
}

// The whole mesh's boundary vertices: those of its facets and lines, its corners and required ones.
template <int D>
std::vector<Index> boundary_vertices_of(const Mesh<D>& mesh) {
  std::set<Index> out;
  for (const auto& facet : mesh.facets()) out.insert(facet.begin(), facet.end());
  for (Index l = 0; l < mesh.line_count(); ++l) out.insert(mesh.line(l).begin(), mesh.line(l).end());
  out.insert(mesh.corners().begin(), mesh.corners().end());
  out.insert(mesh.required_vertices().begin(), mesh.required_vertices().end());
  return {out.begin(), out.end()};
}

template <int D>
bool same_boundary(const Mesh<D>& mesh, int (*destination)(Index), const std::string& name) {
  const MeshPart<D> part = scattered(mesh, destination);
  const MeshPart<D> boundary = boundary_of_parts(part);
  bool ok = true;
  const std::vector<Index> expected = boundary_vertices_of(mesh);
  if (boundary.global_ids != expected)
    return fail(name + ": " + std::to_string(boundary.global_ids.size()) + " boundary vertices, the mesh has " +
                std::to_string(expected.size()));
  for (Index v = 0; v < boundary.mesh.vertex_count(); ++v)
    if (!(boundary.mesh.vertex(v) == mesh.vertex(expected[v])) || boundary.mesh.vertex_ref(v) != mesh.vertex_ref(expected[v]))
      ok = fail(name + ": vertex " + std::to_string(expected[v] + 1) + " has another point or ref");
  if (facets_of(boundary.mesh, boundary.global_ids) != facets_of(mesh, {})) ok = fail(name + ": other facets or facet tags");
  if (lines_of(boundary.mesh, boundary.global_ids) != lines_of(mesh, {})) ok = fail(name + ": other lines or line tags");
  if (ids_of<D>(boundary.mesh.corners(), boundary.global_ids) != ids_of<D>(mesh.corners(), {})) ok = fail(name + ": other corners");
  if (ids_of<D>(boundary.mesh.required_vertices(), boundary.global_ids) != ids_of<D>(mesh.required_vertices(), {}))
    ok = fail(name + ": other required vertices (an interface's left?)");
  if (boundary.mesh.element_count() != 0) ok = fail(name + ": the boundary has elements");
  // Every process's facets in the same order: the geometries made of them are the same.
  std::vector<Index> order;
  for (const auto& facet : boundary.mesh.facets()) order.insert(order.end(), facet.begin(), facet.end());
  const auto all = all_gather_bytes(bytes_of_values(order));
  if (!std::all_of(all.begin(), all.end(), [&](const auto& bytes) { return bytes == all[0]; })) ok = fail(name + ": processes differ");
  const std::vector<Index> indices = boundary_indices(part, boundary.global_ids);
  for (Index v = 0; v < part.mesh.vertex_count(); ++v) {
    const bool listed = std::binary_search(expected.begin(), expected.end(), part.global_ids[v]);
    if (listed != (indices[v] != kNoIndex) || (listed && boundary.global_ids[indices[v]] != part.global_ids[v]))
      ok = fail(name + ": boundary_indices wrong at vertex " + std::to_string(part.global_ids[v] + 1));
  }
  return ok;
}

template <int D>
bool check(const Mesh<D>& mesh, const std::string& name) {
  return same_boundary(mesh, to_rank_0, name + " on rank 0") & same_boundary(mesh, spread, name + " spread");
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "boundary of parts", [] {
    const hocav::Mesh<2> square = hocav::tagged_mesh(hocav::generate_square(12));
    const hocav::Mesh<3> cube = hocav::tagged_mesh(hocav::generate_cube(6));
    return hocav::check(square, "square") & hocav::check(hocav::shuffled(square), "shuffled square") & hocav::check(cube, "cube") &
           hocav::check(hocav::shuffled(cube), "shuffled cube");
  });
}
