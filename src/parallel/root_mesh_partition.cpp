#include "parallel/root_mesh_partition.hpp"

#include "base/error.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_graph.hpp"
#include "parallel/part_message.hpp"
#include "parallel/spatial_cut.hpp"

namespace hocav {
namespace {

// Rank 0: the Morton pieces of `mesh`, each other process's sent as soon as it is made, its own made
// last; returns its own and the cut.
template <int D>
MeshPart<D> scatter_pieces(const Mesh<D>& mesh, std::vector<int>& cut, long long& bytes_sent) {
  const std::vector<double> loads(static_cast<std::size_t>(mesh.element_count()), 1.0);
  cut = spatial_cut(mesh, loads, process_count());
  MeshPart<D> own;
  split_mesh_part_by_part<D>(mesh, cut, own_part_last(process_count()), [&](int p, MeshPart<D> piece) {
    if (p == 0)
      own = std::move(piece);
    else
      send_bytes(p, pack_part(piece.mesh, std::span<const Index>(piece.global_ids)), bytes_sent);
  });
  return own;
}

// Rank 0: per element of the mesh, its part, from each piece's parts (a piece holds the elements of
// its process in the cut, in the mesh's order).
std::vector<int> parts_of_pieces(const std::vector<int>& cut, const std::vector<std::vector<int>>& piece_parts) {
  std::vector<std::size_t> next(piece_parts.size(), 0);
  std::vector<int> part_of(cut.size());
  for (std::size_t k = 0; k < cut.size(); ++k) {
    const std::vector<int>& parts = piece_parts[cut[k]];
    if (next[cut[k]] == parts.size()) throw Error("partition from rank 0: a piece came back with fewer elements than it was sent");
    part_of[k] = parts[next[cut[k]]++];
  }
  return part_of;
}

}  // namespace

template <int D>
std::vector<int> partition_from_root(const Mesh<D>& mesh, std::int64_t seed, long long* bytes_sent) {
  long long sent = 0;
  std::vector<int> cut;
  MeshPart<D> piece = process_rank() == 0 ? scatter_pieces(mesh, cut, sent) : unpack_part<D>(receive_bytes(0));
  piece.mesh.build_topology();
  const std::vector<double> loads(static_cast<std::size_t>(piece.mesh.element_count()), 1.0);
  const std::vector<int> parts = partition_distributed_part(piece, loads, {}, seed);
  if (bytes_sent) *bytes_sent += sent;
  if (process_rank() != 0) {
    send_values(0, parts);
    if (bytes_sent) *bytes_sent += static_cast<long long>(parts.size() * sizeof(int));
    return {};
  }
  std::vector<std::vector<int>> piece_parts{parts};
  for (int p = 1; p < process_count(); ++p) piece_parts.push_back(receive_values<int>(p));
  return parts_of_pieces(cut, piece_parts);
}

template std::vector<int> partition_from_root(const Mesh<2>&, std::int64_t, long long*);
template std::vector<int> partition_from_root(const Mesh<3>&, std::int64_t, long long*);

}  // namespace hocav
