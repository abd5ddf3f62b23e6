#include "parallel/mesh_parts.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "base/error.hpp"
#include "mesh/mesh_defects.hpp"
#include "parallel/entity_tags.hpp"

namespace hocav {
namespace {

std::unordered_map<std::uint64_t, Index> lines_by_edge(std::span<const std::array<Index, 2>> lines) {
  std::unordered_map<std::uint64_t, Index> by_edge;
  for (std::size_t l = 0; l < lines.size(); ++l)
    if (lines[l][0] != kNoIndex) by_edge.emplace(Mesh<3>::edge_key(lines[l][0], lines[l][1]), static_cast<Index>(l));
  return by_edge;
}

// Builds one part: `elements` (ascending) of `mesh`, `facets` the mesh's facets on them.
template <int D>
struct PartBuilder {
  const Mesh<D>& mesh;
  std::span<const int> part_of;
  const EntityTags<D>& tags;
  const std::unordered_map<std::uint64_t, Index>& line_of_edge;
  std::vector<Index>& local;       // per mesh vertex: its id in the part (kNoIndex outside), reset on return
  std::vector<Index>& line_stamp;  // per mesh line: the last part that took it
  // Per mesh vertex: at a non-manifold place of the mesh (non_manifold_places), where a part may
  // hold one of the parts of the mesh that meet there and not see the others: required in every
  // part, as the interfaces are, so that no part splits an edge there or moves the vertex.
  const std::vector<char>& non_manifold;

  MeshPart<D> build(int p, const std::vector<Index>& elements, const std::vector<Index>& facets) {
    MeshPart<D> part;
    add_vertices(part, elements);
    for (Index k : elements) part.mesh.add_element(mapped(mesh.element(k)), mesh.element_ref(k));
    for (Index f : facets) add_tagged_facet(part.mesh, mapped(mesh.facet(f)), mesh.facet_ref(f), tags, f);
    add_interface_facets(part, p, elements);
    if constexpr (D == 3) add_lines(part, p, elements);
    if (mesh.is_p2()) copy_nodes(part.mesh, elements);
    for (Index v : part.global_ids) local[v] = kNoIndex;
    return part;
  }

  // Part element i is mesh element elements[i], with its vertices in the same order.
  void copy_nodes(Mesh<D>& out, const std::vector<Index>& elements) const {
    out.make_p2();
    for (std::size_t i = 0; i < elements.size(); ++i)
      for (int e = 0; e < Simplex<D>::kEdges; ++e)
        out.edge_node(out.element_edge(static_cast<Index>(i), e)) = mesh.edge_node(mesh.element_edge(elements[i], e));
  }

  template <std::size_t N>
  std::array<Index, N> mapped(const std::array<Index, N>& ids) const {
    std::array<Index, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = local[ids[i]];
    return out;
  }

  void add_vertices(MeshPart<D>& part, const std::vector<Index>& elements) {
    for (Index k : elements) part.global_ids.insert(part.global_ids.end(), mesh.element(k).begin(), mesh.element(k).end());
    std::sort(part.global_ids.begin(), part.global_ids.end());
    part.global_ids.erase(std::unique(part.global_ids.begin(), part.global_ids.end()), part.global_ids.end());
    for (Index v : part.global_ids) {
      local[v] = part.mesh.add_vertex(mesh.vertex(v), mesh.vertex_ref(v));
      if (tags.corner[v]) part.mesh.corners().push_back(local[v]);
      part.pinned.push_back(static_cast<char>((tags.required_vertex[v] ? kPinnedByMesh : 0) | (non_manifold[v] ? kPinnedNonManifold : 0)));
      if (part.pinned.back()) part.mesh.required_vertices().push_back(local[v]);
    }
  }

  // The faces towards other parts, as required facets with required vertices.
  void add_interface_facets(MeshPart<D>& part, int p, const std::vector<Index>& elements) {
    std::vector<char> on_interface(part.global_ids.size(), 0);
    for (Index k : elements)
      for (int face = 0; face <= D; ++face) {
        const Index other = mesh.neighbor(k, face);
        if (other == kNoIndex || part_of[other] == p) continue;
        typename Mesh<D>::Facet facet{};
        for (int i = 0; i < D; ++i) facet[i] = local[mesh.element(k)[face_vertices<D>(face)[i]]];
        required_facets(part.mesh).push_back(part.mesh.add_facet(facet, kInterfaceRef));
        for (Index v : facet) on_interface[v] = 1;
      }
    const std::vector<char> required = flags_of(part.mesh.required_vertices(), part.mesh.vertex_count());
    for (Index v = 0; v < part.mesh.vertex_count(); ++v)
      if (on_interface[v] && !required[v]) part.mesh.required_vertices().push_back(v);
  }

  // The feature lines along the part's element edges, each once.
  void add_lines(MeshPart<D>& part, int p, const std::vector<Index>& elements) {
    if (line_of_edge.empty()) return;
    for (Index k : elements)
      for (int e = 0; e < Simplex<D>::kEdges; ++e) {
        const auto& ends = edge_vertices<D>(e);
        const auto found = line_of_edge.find(Mesh<D>::edge_key(mesh.element(k)[ends[0]], mesh.element(k)[ends[1]]));
        if (found == line_of_edge.end() || line_stamp[found->second] == p) continue;
        const Index l = found->second;
        line_stamp[l] = p;
        add_tagged_line(part.mesh, mapped(mesh.line(l)), mesh.line_ref(l), tags, l);
      }
  }
};

}  // namespace

template <int D>
std::unordered_map<Index, Index> local_ids_of(const MeshPart<D>& part) {
  std::unordered_map<Index, Index> local;
  for (Index v = 0; v < part.mesh.vertex_count(); ++v)
    if (part.global_ids[v] != kNoIndex) local.emplace(part.global_ids[v], v);
  return local;
}

template <int D>
std::vector<char> flags_of_global_ids(const MeshPart<D>& part, const std::vector<Index>& ids) {
  std::vector<char> flags(part.global_ids.size(), 0);
  const std::unordered_map<Index, Index> local = local_ids_of(part);
  for (Index id : ids)
    if (const auto found = local.find(id); found != local.end()) flags[found->second] = 1;
  return flags;
}

template <int D>
void split_mesh_part_by_part(const Mesh<D>& mesh, std::span<const int> part_of, std::span<const int> order,
                             const std::function<void(int, MeshPart<D>)>& take) {
  std::vector<std::vector<Index>> elements(order.size()), facets(order.size());
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (part_of[k] >= 0) elements[part_of[k]].push_back(k);
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (const int p = part_of[mesh.facet_element_face(f) / (D + 1)]; p >= 0) facets[p].push_back(f);
  const EntityTags<D> tags(mesh);
  const auto line_of_edge = lines_by_edge(mesh.lines());
  std::vector<Index> local(static_cast<std::size_t>(mesh.vertex_count()), kNoIndex);
  std::vector<Index> line_stamp(static_cast<std::size_t>(mesh.line_count()), -1);
  const std::vector<char> non_manifold = flags_of(non_manifold_places(mesh).every_vertex(), mesh.vertex_count());
  PartBuilder<D> builder{mesh, part_of, tags, line_of_edge, local, line_stamp, non_manifold};
  for (int p : order) take(p, builder.build(p, elements[p], facets[p]));
}

template <int D>
std::vector<MeshPart<D>> split_mesh(const Mesh<D>& mesh, std::span<const int> part_of, int part_count) {
  std::vector<int> order(static_cast<std::size_t>(part_count));
  std::iota(order.begin(), order.end(), 0);
  std::vector<MeshPart<D>> parts;
  split_mesh_part_by_part<D>(mesh, part_of, order, [&](int, MeshPart<D> part) { parts.push_back(std::move(part)); });
  return parts;
}

std::vector<int> own_part_last(int count) {
  std::vector<int> order(static_cast<std::size_t>(count));
  std::iota(order.begin(), order.end(), 1);
  if (count > 0) order.back() = 0;
  return order;
}

template <int D>
MeshPart<D> whole_mesh_part(Mesh<D> mesh) {
  MeshPart<D> part;
  const std::vector<char> required = flags_of(mesh.required_vertices(), mesh.vertex_count());
  const std::vector<char> non_manifold = flags_of(non_manifold_places(mesh).every_vertex(), mesh.vertex_count());
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    part.global_ids.push_back(v);
    part.pinned.push_back(static_cast<char>((required[v] ? kPinnedByMesh : 0) | (non_manifold[v] ? kPinnedNonManifold : 0)));
  }
  part.mesh = std::move(mesh);
  return part;
}

template <int D>
Index interface_facet_count(const Mesh<D>& part_mesh) {
  return static_cast<Index>(std::count(part_mesh.facet_refs().begin(), part_mesh.facet_refs().end(), kInterfaceRef));
}

template <int D>
std::vector<Index> interface_facets(const Mesh<D>& mesh) {
  std::vector<Index> facets;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (!mesh.facet_removed(f) && mesh.facet_ref(f) == kInterfaceRef) facets.push_back(f);
  return facets;
}

template <int D>
std::vector<char> interface_vertex_flags(const Mesh<D>& mesh) {
  std::vector<char> on(static_cast<std::size_t>(mesh.vertex_count()), 0);
  for (Index f : interface_facets(mesh))
    for (Index v : mesh.facet(f)) on[v] = 1;
  return on;
}

template <int D>
std::unordered_set<std::uint64_t> interface_edge_keys(const Mesh<D>& mesh) {
  std::unordered_set<std::uint64_t> edges;
  for (Index f : interface_facets(mesh))
    for (int i = 0; i < (D == 3 ? 3 : 1); ++i) edges.insert(Mesh<D>::edge_key(mesh.facet(f)[i], mesh.facet(f)[(i + 1) % D]));
  return edges;
}

template <int D>
std::vector<Index> global_ids_of(const MeshPart<D>& part, const std::vector<char>& flagged) {
  std::vector<Index> ids;
  for (Index v = 0; v < part.mesh.vertex_count(); ++v)
    if (flagged[v]) ids.push_back(part.global_ids[v]);
  return ids;
}

template std::vector<Index> interface_facets(const Mesh<2>&);
template std::vector<Index> interface_facets(const Mesh<3>&);
template std::vector<char> interface_vertex_flags(const Mesh<2>&);
template std::vector<char> interface_vertex_flags(const Mesh<3>&);
template std::unordered_map<Index, Index> local_ids_of(const MeshPart<2>&);
template std::unordered_map<Index, Index> local_ids_of(const MeshPart<3>&);
template std::vector<char> flags_of_global_ids(const MeshPart<2>&, const std::vector<Index>&);
template std::vector<char> flags_of_global_ids(const MeshPart<3>&, const std::vector<Index>&);
template std::unordered_set<std::uint64_t> interface_edge_keys(const Mesh<2>&);
template std::unordered_set<std::uint64_t> interface_edge_keys(const Mesh<3>&);
template std::vector<Index> global_ids_of(const MeshPart<2>&, const std::vector<char>&);
template std::vector<Index> global_ids_of(const MeshPart<3>&, const std::vector<char>&);
template void split_mesh_part_by_part(const Mesh<2>&, std::span<const int>, std::span<const int>,
                                      const std::function<void(int, MeshPart<2>)>&);
template void split_mesh_part_by_part(const Mesh<3>&, std::span<const int>, std::span<const int>,
                                      const std::function<void(int, MeshPart<3>)>&);
template std::vector<MeshPart<2>> split_mesh(const Mesh<2>&, std::span<const int>, int);
template std::vector<MeshPart<3>> split_mesh(const Mesh<3>&, std::span<const int>, int);
template MeshPart<2> whole_mesh_part(Mesh<2>);
template MeshPart<3> whole_mesh_part(Mesh<3>);
template Index interface_facet_count(const Mesh<2>&);
template Index interface_facet_count(const Mesh<3>&);

}  // namespace hocav
