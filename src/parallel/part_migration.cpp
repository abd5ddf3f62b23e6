#include "parallel/part_migration.hpp"

#include <algorithm>
#include <string>

#include "base/error.hpp"
#include "parallel/byte_stream.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_graph.hpp"
#include "parallel/part_shipment.hpp"

namespace hocav {
namespace {

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

// What a process ships: the shipment of the elements it keeps as it is, the others' as bytes (its
// own slot empty): its kept elements are never serialized.
template <int D>
struct Outgoing {
  Shipment<D> own;
  std::vector<std::vector<std::byte>> bytes;
};

template <int D>
Outgoing<D> packed_shipments(const MeshPart<D>& part, std::span<const int> destination, long long* bytes_sent) {
  Outgoing<D> out{{}, std::vector<std::vector<std::byte>>(static_cast<std::size_t>(process_count()))};
  pack_shipments<D>(part, destination, process_count(), [&](int to, Shipment<D> shipment) {
    if (to == process_rank()) {
      out.own = std::move(shipment);
      return;
    }
    out.bytes[static_cast<std::size_t>(to)] = shipment.bytes();
    if (bytes_sent) *bytes_sent += static_cast<long long>(out.bytes[static_cast<std::size_t>(to)].size());
  });
  return out;
}

// `outgoing` sent; the new part built from what arrives, in rank order. Each buffer is let go as soon
// as it is read, so that at most one copy of the part's elements is held besides the part built.
template <int D>
MeshPart<D> part_of_outgoing(Outgoing<D> outgoing) {
  std::vector<std::vector<std::byte>> incoming = exchange_bytes(outgoing.bytes);
  outgoing.bytes = {};
  std::vector<Shipment<D>> arrived(incoming.size());
  for (std::size_t from = 0; from < incoming.size(); ++from) {
    if (static_cast<int>(from) == process_rank()) {
      arrived[from] = std::move(outgoing.own);
      continue;
    }
    arrived[from] = Shipment<D>::read(incoming[from]);
    incoming[from] = {};
  }
  return part_of_shipments(arrived);
}

}  // namespace

template <int D>
MeshPart<D> migrate_part(const MeshPart<D>& part, std::span<const int> destination, long long* bytes_sent) {
  check_part(part, destination);
  return part_of_outgoing(packed_shipments(part, destination, bytes_sent));
}

template <int D>
MeshPart<D> migrate_part(MeshPart<D>&& part, std::span<const int> destination, long long* bytes_sent) {
  check_part(part, destination);
  Outgoing<D> outgoing = packed_shipments(part, destination, bytes_sent);
  part = {};  // (let go before the new part is built)
  return part_of_outgoing(std::move(outgoing));
}

namespace {

// `outgoing` sent, what arrives joined in rank order (migrate_part's order: by source, each source's
// in its order); the bytes sent to other processes added to `bytes_sent` when given.
std::vector<Index> exchanged_values(const std::vector<std::vector<Index>>& outgoing, long long* bytes_sent) {
  if (bytes_sent)
    for (std::size_t to = 0; to < outgoing.size(); ++to)
      if (static_cast<int>(to) != process_rank()) *bytes_sent += static_cast<long long>(outgoing[to].size() * sizeof(Index));
  return exchange_values_joined(outgoing);
}

}  // namespace

std::vector<Index> migrated_element_values(std::span<const Index> values, std::span<const int> destination, long long* bytes_sent) {
  if (values.size() != destination.size()) throw Error("migrated element values: not one value per element");
  std::vector<std::vector<Index>> outgoing(static_cast<std::size_t>(process_count()));
  for (std::size_t k = 0; k < values.size(); ++k) outgoing.at(static_cast<std::size_t>(destination[k])).push_back(values[k]);
  return exchanged_values(outgoing, bytes_sent);
}

template <int D>
std::vector<Index> migrated_facet_values(const MeshPart<D>& part, std::span<const Index> values, std::span<const int> destination,
                                         long long* bytes_sent) {
  if (values.size() != static_cast<std::size_t>(part.mesh.facet_count()) ||
      destination.size() != static_cast<std::size_t>(part.mesh.element_count()))
    throw Error("migrated facet values: not one value per facet, or not one destination per element");
  std::vector<std::vector<Index>> outgoing(static_cast<std::size_t>(process_count()));
  for (const auto& [element, facet] : facets_by_element(part.mesh))  // (the order pack_shipments ships them in)
    outgoing.at(static_cast<std::size_t>(destination[static_cast<std::size_t>(element)]))
        .push_back(values[static_cast<std::size_t>(facet)]);
  return exchanged_values(outgoing, bytes_sent);
}

template std::vector<Index> migrated_facet_values(const MeshPart<2>&, std::span<const Index>, std::span<const int>, long long*);
template std::vector<Index> migrated_facet_values(const MeshPart<3>&, std::span<const Index>, std::span<const int>, long long*);

template <int D>
MeshPart<D> repartition(MeshPart<D>&& part, std::span<const double> loads, std::span<const char> kept_inside, std::int64_t partition_seed,
                        long long* bytes_sent) {
  // (The graph is a temporary: freed before the migration, which holds the old part and the new.)
  const std::vector<int> destination = partition_distributed_part(part, loads, kept_inside, partition_seed);
  return migrate_part(std::move(part), destination, bytes_sent);
}

template MeshPart<2> repartition(MeshPart<2>&&, std::span<const double>, std::span<const char>, std::int64_t, long long*);
template MeshPart<3> repartition(MeshPart<3>&&, std::span<const double>, std::span<const char>, std::int64_t, long long*);
template MeshPart<2> migrate_part(const MeshPart<2>&, std::span<const int>, long long*);
template MeshPart<3> migrate_part(const MeshPart<3>&, std::span<const int>, long long*);
template MeshPart<2> migrate_part(MeshPart<2>&&, std::span<const int>, long long*);
template MeshPart<3> migrate_part(MeshPart<3>&&, std::span<const int>, long long*);

}  // namespace hocav
