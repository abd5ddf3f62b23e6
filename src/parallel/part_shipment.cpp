#include "parallel/part_shipment.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "parallel/entity_tags.hpp"

namespace hocav {
namespace {

// Builds the shipments of one process's part (with its topology), one destination at a time.
template <int D>
struct Packer {
  const MeshPart<D>& part;
  const EntityTags<D> tags;
  std::vector<char> interface_face;                     // per element face: an interface facet lies on it
  std::vector<std::pair<Index, Index>> element_facets;  // (element, facet) of the mesh's facets, sorted
  std::unordered_map<std::uint64_t, Index> line_of_edge;
  std::vector<int> vertex_stamp, line_stamp, edge_stamp;  // the last destination that took each

  explicit Packer(const MeshPart<D>& p)
      : part(p),
        tags(p.mesh),
        interface_face(static_cast<std::size_t>(p.mesh.element_count()) * (D + 1), 0),
        vertex_stamp(static_cast<std::size_t>(p.mesh.vertex_count()), -1),
        line_stamp(static_cast<std::size_t>(p.mesh.line_count()), -1),
        edge_stamp(p.mesh.is_p2() ? static_cast<std::size_t>(p.mesh.edge_count()) : 0, -1) {
    const Mesh<D>& mesh = part.mesh;
    element_facets = facets_by_element(mesh);
    for (Index f = 0; f < mesh.facet_count(); ++f)
      if (mesh.facet_ref(f) == kInterfaceRef) interface_face[mesh.facet_element_face(f)] = 1;
    for (Index l = 0; l < mesh.line_count(); ++l) line_of_edge.emplace(Mesh<D>::edge_key(mesh.line(l)[0], mesh.line(l)[1]), l);
  }

  // The faces of element k that have a neighbour in the whole mesh: another element of the part, or
  // one across an interface facet.
  char inner_faces(Index k) const {
    char bits = 0;
    for (int face = 0; face <= D; ++face)
      if (part.mesh.neighbor(k, face) != kNoIndex || interface_face[static_cast<std::size_t>(k) * (D + 1) + face])
        bits = static_cast<char>(bits | (1 << face));
    return bits;
  }

  Shipment<D> ship(int to, std::span<const Index> leaving) {
    const Mesh<D>& mesh = part.mesh;
    Shipment<D> s;
    for (Index k : leaving) {
      for (Index v : mesh.element(k)) add_vertex(s, to, v);
      s.elements.push_back(global(mesh.element(k)));
      s.element_refs.push_back(mesh.element_ref(k));
      s.inner_faces.push_back(inner_faces(k));
      for (auto at = std::lower_bound(element_facets.begin(), element_facets.end(), std::pair{k, Index{0}});
           at != element_facets.end() && at->first == k; ++at) {
        const Index f = at->second;
        s.facets.push_back(global(mesh.facet(f)));
        s.facet_refs.push_back(mesh.facet_ref(f));
        s.facet_flags.push_back(
            static_cast<char>((tags.required_facet[f] ? kShippedRequired : 0) | (tags.ridge_facet[f] ? kShippedRidge : 0)));
      }
      if constexpr (D == 3) add_lines(s, to, k);
      if (mesh.is_p2()) add_nodes(s, to, k);
    }
    return s;
  }

  // Element k's edge nodes that the shipment to `to` lacks (an edge's node once per shipment).
  void add_nodes(Shipment<D>& s, int to, Index k) {
    for (int e = 0; e < Simplex<D>::kEdges; ++e) {
      const Index edge = part.mesh.element_edge(k, e);
      if (edge_stamp[edge] == to) continue;
      edge_stamp[edge] = to;
      s.nodes.push_back(part.mesh.edge_node(edge));
    }
  }

  void add_vertex(Shipment<D>& s, int to, Index v) {
    if (vertex_stamp[v] == to) return;
    vertex_stamp[v] = to;
    s.vertex_ids.push_back(part.global_ids[v]);
    s.points.push_back(part.mesh.vertex(v));
    s.vertex_refs.push_back(part.mesh.vertex_ref(v));
    s.vertex_flags.push_back(static_cast<char>((tags.corner[v] ? kShippedCorner : 0) | (part.pinned[v] << 1)));
  }

  void add_lines(Shipment<D>& s, int to, Index k) {
    for (int e = 0; e < Simplex<D>::kEdges; ++e) {
      const auto& ends = edge_vertices<D>(e);
      const auto found = line_of_edge.find(Mesh<D>::edge_key(part.mesh.element(k)[ends[0]], part.mesh.element(k)[ends[1]]));
      if (found == line_of_edge.end() || line_stamp[found->second] == to) continue;
      const Index l = found->second;
      line_stamp[l] = to;
      s.lines.push_back(global(part.mesh.line(l)));
      s.line_refs.push_back(part.mesh.line_ref(l));
      s.line_flags.push_back(static_cast<char>((tags.required_line[l] ? kShippedRequired : 0) | (tags.ridge_line[l] ? kShippedRidge : 0)));
    }
  }

  template <std::size_t N>
  std::array<Index, N> global(const std::array<Index, N>& ids) const {
    std::array<Index, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = part.global_ids[ids[i]];
    return out;
  }
};

// Builds the new part from the shipments it receives (in rank order).
template <int D>
struct Unpacker {
  const std::vector<Shipment<D>>& arrived;
  MeshPart<D> part;
  std::unordered_map<Index, Index> local;  // global vertex id -> new part's id

  void add_vertices() {
    std::unordered_map<Index, std::pair<std::size_t, std::size_t>> source;  // global id -> (shipment, index)
    for (std::size_t s = 0; s < arrived.size(); ++s)
      for (std::size_t i = 0; i < arrived[s].vertex_ids.size(); ++i) {
        const auto [it, fresh] = source.emplace(arrived[s].vertex_ids[i], std::pair{s, i});
        if (!fresh && !(arrived[it->second.first].points[it->second.second] == arrived[s].points[i]))
          throw Error("migrating parts: two processes give vertex " + one_based(arrived[s].vertex_ids[i]) + " different points");
      }
    for (const auto& [global, where] : source) part.global_ids.push_back(global);
    std::sort(part.global_ids.begin(), part.global_ids.end());
    for (Index g : part.global_ids) {
      const auto [s, i] = source.at(g);
      const Index v = part.mesh.add_vertex(arrived[s].points[i], arrived[s].vertex_refs[i]);
      local.emplace(g, v);
      const char flags = arrived[s].vertex_flags[i];
      if (flags & kShippedCorner) part.mesh.corners().push_back(v);
      part.pinned.push_back(static_cast<char>(flags >> 1));
    }
  }

  template <std::size_t N>
  std::array<Index, N> mapped(const std::array<Index, N>& ids) const {
    std::array<Index, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = local.at(ids[i]);
    return out;
  }

  // The elements, then (with the topology the elements give) the mesh's facets and a facet on each
  // face with a neighbour in the whole mesh but none in the new part, as split_mesh makes them;
  // part_of_shipments links them to their faces at the end.
  // Pieces without elements (a boundary's) give the facets alone, and their pinned vertices required.
  void add_elements_and_facets() {
    for (const Shipment<D>& s : arrived)
      for (std::size_t k = 0; k < s.elements.size(); ++k) part.mesh.add_element(mapped(s.elements[k]), s.element_refs[k]);
    if (part.mesh.element_count() > 0) part.mesh.build_topology();
    for (const Shipment<D>& s : arrived)
      for (std::size_t f = 0; f < s.facets.size(); ++f) {
        const Index id = part.mesh.add_facet(mapped(s.facets[f]), s.facet_refs[f]);
        if (s.facet_flags[f] & kShippedRequired) required_facets(part.mesh).push_back(id);
        if (s.facet_flags[f] & kShippedRidge) part.mesh.ridges().push_back(id);
      }
    std::vector<char> on_interface(part.global_ids.size(), 0);
    Index k = 0;
    for (const Shipment<D>& s : arrived)
      for (const char inner : s.inner_faces) {
        for (int face = 0; face <= D; ++face) {
          if (!(inner & (1 << face)) || part.mesh.neighbor(k, face) != kNoIndex) continue;
          typename Mesh<D>::Facet facet{};
          for (int i = 0; i < D; ++i) facet[i] = part.mesh.element(k)[face_vertices<D>(face)[i]];
          required_facets(part.mesh).push_back(part.mesh.add_facet(facet, kInterfaceRef));
          for (Index v : facet) on_interface[v] = 1;
        }
        ++k;
      }
    for (Index v = 0; v < part.mesh.vertex_count(); ++v)
      if (part.pinned[v]) part.mesh.required_vertices().push_back(v);
    for (Index v = 0; v < part.mesh.vertex_count(); ++v)
      if (on_interface[v] && !part.pinned[v]) part.mesh.required_vertices().push_back(v);
  }

  void add_lines() {
    std::unordered_map<std::uint64_t, Index> seen;
    for (const Shipment<D>& s : arrived)
      for (std::size_t l = 0; l < s.lines.size(); ++l) {
        const auto ends = mapped(s.lines[l]);
        if (!seen.emplace(Mesh<D>::edge_key(ends[0], ends[1]), 0).second) continue;
        const Index id = part.mesh.add_line(ends, s.line_refs[l]);
        if (s.line_flags[l] & kShippedRidge) part.mesh.ridges().push_back(id);
        if (s.line_flags[l] & kShippedRequired) part.mesh.required_edges().push_back(id);
      }
  }

  void add_nodes() {
    const bool p2 = std::any_of(arrived.begin(), arrived.end(), [](const Shipment<D>& s) { return !s.nodes.empty(); });
    if (!p2) return;
    part.mesh.make_p2();
    std::vector<std::size_t> stamp(static_cast<std::size_t>(part.mesh.edge_count()), arrived.size());  // the last shipment that gave each
    Index k = 0;
    for (std::size_t from = 0; from < arrived.size(); ++from) {
      const Shipment<D>& s = arrived[from];
      if (s.nodes.empty() && !s.elements.empty()) throw Error("migrating parts: P1 and P2 elements arrive together");
      std::size_t next = 0;  // the shipment's nodes in the order its elements first reach their edges (Packer::add_nodes)
      for (std::size_t i = 0; i < s.elements.size(); ++i, ++k)
        for (int e = 0; e < Simplex<D>::kEdges; ++e) {
          const Index edge = part.mesh.element_edge(k, e);
          if (stamp[edge] == from) continue;
          stamp[edge] = from;
          if (next == s.nodes.size()) throw Error("a migration message has fewer nodes than its elements have edges");
          part.mesh.edge_node(edge) = s.nodes[next++];
        }
      if (next != s.nodes.size()) throw Error("a migration message has more nodes than its elements have edges");
    }
  }
};

}  // namespace

template <int D>
Shipment<D> shipment_of(const MeshPart<D>& part, std::span<const Index> elements) {
  return Packer<D>(part).ship(0, elements);
}

template <int D>
std::vector<std::pair<Index, Index>> facets_by_element(const Mesh<D>& mesh) {
  std::vector<std::pair<Index, Index>> out;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    const Index at = mesh.facet_element_face(f);
    if (at == kNoIndex) throw Error("migrating a part: its facet " + one_based(f) + " is no face of its elements");
    if (mesh.facet_ref(f) != kInterfaceRef) out.emplace_back(at / (D + 1), f);
  }
  std::sort(out.begin(), out.end());
  return out;
}

template <int D>
void pack_shipments(const MeshPart<D>& part, std::span<const int> destination, int destinations,
                    const std::function<void(int, Shipment<D>)>& take) {
  std::vector<std::vector<Index>> leaving(static_cast<std::size_t>(destinations));
  for (std::size_t k = 0; k < destination.size(); ++k) leaving[static_cast<std::size_t>(destination[k])].push_back(static_cast<Index>(k));
  Packer<D> packer(part);
  for (int to = 0; to < destinations; ++to) take(to, packer.ship(to, leaving[static_cast<std::size_t>(to)]));
}

template <int D>
MeshPart<D> part_of_shipments(const std::vector<Shipment<D>>& arrived) {
  Unpacker<D> unpacker{arrived, {}, {}};
  unpacker.add_vertices();
  unpacker.add_elements_and_facets();
  if constexpr (D == 3) unpacker.add_lines();
  unpacker.add_nodes();
  if (unpacker.part.mesh.element_count() > 0) unpacker.part.mesh.link_facets();
  return std::move(unpacker.part);
}

template std::vector<std::pair<Index, Index>> facets_by_element(const Mesh<2>&);
template std::vector<std::pair<Index, Index>> facets_by_element(const Mesh<3>&);
template void pack_shipments(const MeshPart<2>&, std::span<const int>, int, const std::function<void(int, Shipment<2>)>&);
template void pack_shipments(const MeshPart<3>&, std::span<const int>, int, const std::function<void(int, Shipment<3>)>&);
template Shipment<2> shipment_of(const MeshPart<2>&, std::span<const Index>);
template Shipment<3> shipment_of(const MeshPart<3>&, std::span<const Index>);
template MeshPart<2> part_of_shipments(const std::vector<Shipment<2>>&);
template MeshPart<3> part_of_shipments(const std::vector<Shipment<3>>&);

}  // namespace hocav
