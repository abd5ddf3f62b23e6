#include "parallel/part_migration.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "base/error.hpp"
#include "parallel/byte_stream.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_graph.hpp"
#include "parallel/entity_tags.hpp"

namespace hocav {
namespace {

// Vertex flags (a corner, then the pinned flags shifted by one), and facet and line flags, in a message.
constexpr char kCorner = 1;
constexpr char kRequired = 1, kRidge = 2;

// What one process sends another: its elements by global vertex ids, with per element the faces that
// have a neighbour in the whole mesh (a bit per face), the vertices they use, the mesh's facets and
// lines on them, and their P2 nodes (per element, per edge).
template <int D>
struct Shipment {
  std::vector<Index> vertex_ids;
  std::vector<Vec<D>> points;
  std::vector<int> vertex_refs;
  std::vector<char> vertex_flags;
  std::vector<typename Mesh<D>::Element> elements;
  std::vector<int> element_refs;
  std::vector<char> inner_faces;
  std::vector<typename Mesh<D>::Facet> facets;
  std::vector<int> facet_refs;
  std::vector<char> facet_flags;
  std::vector<typename Mesh<D>::Line> lines;
  std::vector<int> line_refs;
  std::vector<char> line_flags;
  std::vector<Vec<D>> nodes;

  std::vector<std::byte> bytes() const {
    ByteWriter out;
    out.put(vertex_ids), out.put(points), out.put(vertex_refs), out.put(vertex_flags);
    out.put(elements), out.put(element_refs), out.put(inner_faces);
    out.put(facets), out.put(facet_refs), out.put(facet_flags);
    out.put(lines), out.put(line_refs), out.put(line_flags);
    out.put(nodes);
    return std::move(out.bytes);
  }

  static Shipment read(const std::vector<std::byte>& bytes) {
    ByteReader in(bytes);
    Shipment s;
    s.vertex_ids = in.take<Index>(), s.points = in.take<Vec<D>>(), s.vertex_refs = in.take<int>(), s.vertex_flags = in.take<char>();
    s.elements = in.take<typename Mesh<D>::Element>(), s.element_refs = in.take<int>(), s.inner_faces = in.take<char>();
    s.facets = in.take<typename Mesh<D>::Facet>(), s.facet_refs = in.take<int>(), s.facet_flags = in.take<char>();
    s.lines = in.take<typename Mesh<D>::Line>(), s.line_refs = in.take<int>(), s.line_flags = in.take<char>();
    s.nodes = in.take<Vec<D>>();
    const std::size_t n = s.vertex_ids.size(), k = s.elements.size();
    if (!in.at_end() || s.points.size() != n || s.vertex_refs.size() != n || s.vertex_flags.size() != n || s.element_refs.size() != k ||
        s.inner_faces.size() != k || s.facet_refs.size() != s.facets.size() || s.facet_flags.size() != s.facets.size() ||
        s.line_refs.size() != s.lines.size() || s.line_flags.size() != s.lines.size() ||
        (!s.nodes.empty() && s.nodes.size() != k * Simplex<D>::kEdges))
      throw Error("a migration message has arrays of different lengths");
    return s;
  }
};

// Builds the shipments of one process's part (with its topology), one destination at a time.
template <int D>
struct Packer {
  const MeshPart<D>& part;
  const EntityTags<D> tags;
  std::vector<char> interface_face;                     // per element face: an interface facet lies on it
  std::vector<std::pair<Index, Index>> element_facets;  // (element, facet) of the mesh's facets, sorted
  std::unordered_map<std::uint64_t, Index> line_of_edge;
  std::vector<int> vertex_stamp, line_stamp;  // the last destination that took each

  explicit Packer(const MeshPart<D>& p)
      : part(p),
        tags(p.mesh),
        interface_face(static_cast<std::size_t>(p.mesh.element_count()) * (D + 1), 0),
        vertex_stamp(static_cast<std::size_t>(p.mesh.vertex_count()), -1),
        line_stamp(static_cast<std::size_t>(p.mesh.line_count()), -1) {
    const Mesh<D>& mesh = part.mesh;
    for (Index f = 0; f < mesh.facet_count(); ++f) {
      const Index at = mesh.facet_element_face(f);
      if (at == kNoIndex) throw Error("migrating a part: its facet " + std::to_string(f + 1) + " is no face of its elements");
      if (mesh.facet_ref(f) == kInterfaceRef)
        interface_face[at] = 1;
      else
        element_facets.emplace_back(at / (D + 1), f);
    }
    std::sort(element_facets.begin(), element_facets.end());
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
        s.facet_flags.push_back(static_cast<char>((tags.required_facet[f] ? kRequired : 0) | (tags.ridge_facet[f] ? kRidge : 0)));
      }
      if constexpr (D == 3) add_lines(s, to, k);
      if (mesh.is_p2())
        for (int e = 0; e < Simplex<D>::kEdges; ++e) s.nodes.push_back(mesh.edge_node(mesh.element_edge(k, e)));
    }
    return s;
  }

  void add_vertex(Shipment<D>& s, int to, Index v) {
    if (vertex_stamp[v] == to) return;
    vertex_stamp[v] = to;
    s.vertex_ids.push_back(part.global_ids[v]);
    s.points.push_back(part.mesh.vertex(v));
    s.vertex_refs.push_back(part.mesh.vertex_ref(v));
    s.vertex_flags.push_back(static_cast<char>((tags.corner[v] ? kCorner : 0) | (part.pinned[v] << 1)));
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
      s.line_flags.push_back(static_cast<char>((tags.required_line[l] ? kRequired : 0) | (tags.ridge_line[l] ? kRidge : 0)));
    }
  }

  template <std::size_t N>
  std::array<Index, N> global(const std::array<Index, N>& ids) const {
    std::array<Index, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = part.global_ids[ids[i]];
    return out;
  }
};

template <int D>
void check_part(const MeshPart<D>& part, std::span<const int> destination) {
  const auto vertices = static_cast<std::size_t>(part.mesh.vertex_count());
  if (part.mesh.element_count() > 0 && !part.mesh.has_topology()) throw Error("migrating a part: it needs its topology");
  if (part.global_ids.size() != vertices || part.pinned.size() != vertices ||
      std::find(part.global_ids.begin(), part.global_ids.end(), kNoIndex) != part.global_ids.end())
    throw Error("migrating a part: every vertex needs its global id and pinned flag");
  if (destination.size() != static_cast<std::size_t>(part.mesh.element_count()))
    throw Error("migrating a part: " + std::to_string(destination.size()) + " destinations for " +
                std::to_string(part.mesh.element_count()) + " elements");
  for (int to : destination)
    if (to < 0 || to >= process_count()) throw Error("migrating a part: process " + std::to_string(to) + " does not exist");
}

// The shipment of this process's part to every process, as bytes.
template <int D>
std::vector<std::vector<std::byte>> packed_shipments(const MeshPart<D>& part, std::span<const int> destination) {
  std::vector<std::vector<Index>> leaving(static_cast<std::size_t>(process_count()));
  for (std::size_t k = 0; k < destination.size(); ++k) leaving[destination[k]].push_back(static_cast<Index>(k));
  Packer<D> packer(part);
  std::vector<std::vector<std::byte>> out;
  for (std::size_t to = 0; to < leaving.size(); ++to) out.push_back(packer.ship(static_cast<int>(to), leaving[to]).bytes());
  return out;
}

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
          throw Error("migrating parts: two processes give vertex " + std::to_string(arrived[s].vertex_ids[i] + 1) + " different points");
      }
    for (const auto& [global, where] : source) part.global_ids.push_back(global);
    std::sort(part.global_ids.begin(), part.global_ids.end());
    for (Index g : part.global_ids) {
      const auto [s, i] = source.at(g);
      const Index v = part.mesh.add_vertex(arrived[s].points[i], arrived[s].vertex_refs[i]);
      local.emplace(g, v);
      const char flags = arrived[s].vertex_flags[i];
      if (flags & kCorner) part.mesh.corners().push_back(v);
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
  // face with a neighbour in the whole mesh but none in the new part, as split_mesh makes them; the
  // topology again, with the facets.
  void add_elements_and_facets() {
    for (const Shipment<D>& s : arrived)
      for (std::size_t k = 0; k < s.elements.size(); ++k) part.mesh.add_element(mapped(s.elements[k]), s.element_refs[k]);
    if (part.mesh.element_count() == 0) return;
    part.mesh.build_topology();
    for (const Shipment<D>& s : arrived)
      for (std::size_t f = 0; f < s.facets.size(); ++f) {
        const Index id = part.mesh.add_facet(mapped(s.facets[f]), s.facet_refs[f]);
        if (s.facet_flags[f] & kRequired) required_facets(part.mesh).push_back(id);
        if (s.facet_flags[f] & kRidge) part.mesh.ridges().push_back(id);
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
        if (s.line_flags[l] & kRidge) part.mesh.ridges().push_back(id);
        if (s.line_flags[l] & kRequired) part.mesh.required_edges().push_back(id);
      }
  }

  void add_nodes() {
    const bool p2 = std::any_of(arrived.begin(), arrived.end(), [](const Shipment<D>& s) { return !s.nodes.empty(); });
    if (!p2) return;
    part.mesh.make_p2();
    Index k = 0;
    for (const Shipment<D>& s : arrived) {
      if (s.nodes.empty() && !s.elements.empty()) throw Error("migrating parts: P1 and P2 elements arrive together");
      for (std::size_t i = 0; i < s.elements.size(); ++i, ++k)
        for (int e = 0; e < Simplex<D>::kEdges; ++e)
          part.mesh.edge_node(part.mesh.element_edge(k, e)) = s.nodes[i * Simplex<D>::kEdges + static_cast<std::size_t>(e)];
    }
  }
};

}  // namespace

template <int D>
MeshPart<D> migrate_part(const MeshPart<D>& part, std::span<const int> destination, long long* bytes_sent) {
  check_part(part, destination);
  const std::vector<std::vector<std::byte>> outgoing = packed_shipments(part, destination);
  if (bytes_sent)
    for (std::size_t to = 0; to < outgoing.size(); ++to)
      if (static_cast<int>(to) != process_rank()) *bytes_sent += static_cast<long long>(outgoing[to].size());
  std::vector<Shipment<D>> arrived;
  for (const std::vector<std::byte>& bytes : exchange_bytes(outgoing)) arrived.push_back(Shipment<D>::read(bytes));
  Unpacker<D> unpacker{arrived, {}, {}};
  unpacker.add_vertices();
  unpacker.add_elements_and_facets();
  if constexpr (D == 3) unpacker.add_lines();
  unpacker.add_nodes();
  if (unpacker.part.mesh.element_count() > 0) unpacker.part.mesh.build_topology();
  return std::move(unpacker.part);
}

template <int D>
MeshPart<D> repartition(const MeshPart<D>& part, std::span<const double> loads, std::span<const char> old_interface,
                        std::int64_t partition_seed, long long* bytes_sent) {
  // (The graph is a temporary: freed before the migration, which holds the old part and the new.)
  const std::vector<int> destination = partition_distributed_graph(distributed_element_graph(part, loads, old_interface), process_count(),
                                                                   partition_seed);
  return migrate_part(part, destination, bytes_sent);
}

template MeshPart<2> repartition(const MeshPart<2>&, std::span<const double>, std::span<const char>, std::int64_t, long long*);
template MeshPart<3> repartition(const MeshPart<3>&, std::span<const double>, std::span<const char>, std::int64_t, long long*);
template MeshPart<2> migrate_part(const MeshPart<2>&, std::span<const int>, long long*);
template MeshPart<3> migrate_part(const MeshPart<3>&, std::span<const int>, long long*);

}  // namespace hocav
