#include "parallel/part_migration.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "base/error.hpp"
#include "parallel/byte_stream.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_graph.hpp"
#include "parallel/entity_tags.hpp"
#include "parallel/part_shipment.hpp"

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
        s.facet_flags.push_back(
            static_cast<char>((tags.required_facet[f] ? kShippedRequired : 0) | (tags.ridge_facet[f] ? kShippedRidge : 0)));
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
  return part_of_shipments(arrived);
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
