#include "parallel/piece_facet_orientation.hpp"

#include <algorithm>
#include <optional>
#include <unordered_map>

#include "mesh/baffle_orientation.hpp"
#include "parallel/communicator.hpp"
#include "parallel/face_key.hpp"

namespace hocav {
namespace {

// One side of a face between two pieces, sent to where the two sides meet: the ref of its element.
template <int D>
struct FaceSide {
  FaceKey<D> key;
  std::int32_t ref;
};

// The meeting's answer to a side: the other side's ref, when the other side came.
struct RefAcross {
  std::int32_t ref;
  std::int32_t found;
};

// A baffle sent to every process: its file id, its vertices' global ids in its order, its ref.
template <int D>
struct BaffleRecord {
  Index id;
  typename Mesh<D>::Facet vertices;
  std::int32_t ref;
};

template <int D>
FaceKey<D> global_key(const MeshPart<D>& piece, Index f) {
  FaceKey<D> key;
  for (int i = 0; i < D; ++i) key[i] = piece.global_ids[piece.mesh.facet(f)[i]];
  return sorted_key<D>(key);
}

template <int D>
Index element_of_facet(const Mesh<D>& mesh, Index f) {
  return mesh.facet_element_face(f) / (D + 1);
}

// Per process that sent sides to this one, per side in its order: the other side's ref.
template <int D>
std::vector<std::vector<RefAcross>> meet_sides(const std::vector<std::vector<FaceSide<D>>>& arrived) {
  std::unordered_map<FaceKey<D>, std::vector<std::int32_t>, FaceKeyHash<D>> refs;
  for (const std::vector<FaceSide<D>>& sides : arrived)
    for (const FaceSide<D>& side : sides) refs[side.key].push_back(side.ref);
  std::vector<std::vector<RefAcross>> answers;
  for (const std::vector<FaceSide<D>>& sides : arrived) {
    answers.emplace_back();
    for (const FaceSide<D>& side : sides) {
      const std::vector<std::int32_t>& both = refs.at(side.key);
      const bool paired = both.size() == 2;
      answers.back().push_back({paired ? (both[0] == side.ref ? both[1] : both[0]) : 0, paired});
    }
  }
  return answers;
}

// Collective: per facet of the piece, the ref of the element across it when that element lies in
// another piece.
template <int D>
std::vector<std::optional<int>> refs_across_pieces(const MeshPart<D>& piece) {
  const Mesh<D>& mesh = piece.mesh;
  std::vector<std::vector<FaceSide<D>>> outgoing(static_cast<std::size_t>(process_count()));
  std::vector<std::vector<Index>> sent(outgoing.size());  // per message, its sides' interface facets
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (mesh.facet_ref(f) == kInterfaceRef) {
      const FaceKey<D> key = global_key(piece, f);
      const auto to = static_cast<std::size_t>(meeting_process<D>(key, process_count()));
      outgoing[to].push_back({key, mesh.element_ref(element_of_facet(mesh, f))});
      sent[to].push_back(f);
    }
  const std::vector<std::vector<RefAcross>> answers = exchange_values(meet_sides(exchange_values(outgoing)));
  std::unordered_map<FaceKey<D>, int, FaceKeyHash<D>> across_of_key;
  for (std::size_t from = 0; from < answers.size(); ++from)
    for (std::size_t j = 0; j < answers[from].size(); ++j)
      if (answers[from][j].found) across_of_key[global_key(piece, sent[from][j])] = answers[from][j].ref;
  std::vector<std::optional<int>> across(static_cast<std::size_t>(mesh.facet_count()));
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (mesh.facet_ref(f) != kInterfaceRef)
      if (const auto found = across_of_key.find(global_key(piece, f)); found != across_of_key.end()) across[f] = found->second;
  return across;
}

// Collective: turns the piece's baffles (facets `baffles`, of file ids `facet_ids`) that
// baffle_turns turns on every piece's baffles in file order.
template <int D>
void turn_baffles(MeshPart<D>& piece, const std::vector<Index>& baffles, std::span<const Index> facet_ids) {
  std::vector<BaffleRecord<D>> own;
  for (Index f : baffles) {
    BaffleRecord<D> record{facet_ids[f], piece.mesh.facet(f), piece.mesh.facet_ref(f)};
    for (Index& v : record.vertices) v = piece.global_ids[v];
    own.push_back(record);
  }
  std::vector<BaffleRecord<D>> all;
  for (const std::vector<std::byte>& bytes : all_gather_bytes(bytes_of_values(own))) {
    const std::vector<BaffleRecord<D>> theirs = values_of_bytes<BaffleRecord<D>>(bytes);
    all.insert(all.end(), theirs.begin(), theirs.end());
  }
  if (all.empty()) return;
  std::sort(all.begin(), all.end(), [](const BaffleRecord<D>& a, const BaffleRecord<D>& b) { return a.id < b.id; });
  std::vector<typename Mesh<D>::Facet> vertices;
  std::vector<int> refs;
  for (const BaffleRecord<D>& record : all) vertices.push_back(record.vertices), refs.push_back(record.ref);
  const std::vector<char> turns = baffle_turns<D>(vertices, refs);
  for (std::size_t b = 0; b < baffles.size(); ++b) {
    const auto at = std::lower_bound(all.begin(), all.end(), own[b].id, [](const BaffleRecord<D>& r, Index id) { return r.id < id; });
    if (turns[static_cast<std::size_t>(at - all.begin())]) piece.mesh.turn_facet(baffles[b]);
  }
}

}  // namespace

template <int D>
void orient_piece_facets(MeshPart<D>& piece, std::span<const Index> facet_ids) {
  Mesh<D>& mesh = piece.mesh;
  const std::vector<std::optional<int>> refs_across = refs_across_pieces(piece);
  std::vector<Index> baffles;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_removed(f) || mesh.facet_ref(f) == kInterfaceRef) continue;
    const Index k = element_of_facet(mesh, f);
    const int face = static_cast<int>(mesh.facet_element_face(f) % (D + 1));
    const Index across = mesh.neighbor(k, face);
    const std::optional<int> ref_across = across != kNoIndex ? std::optional<int>(mesh.element_ref(across)) : refs_across[f];
    if (ref_across == mesh.element_ref(k)) {
      baffles.push_back(f);
      continue;
    }
    mesh.orient_facet_as_face(f, k, face, ref_across && *ref_across < mesh.element_ref(k));
  }
  turn_baffles(piece, baffles, facet_ids);
}

template void orient_piece_facets(MeshPart<2>&, std::span<const Index>);
template void orient_piece_facets(MeshPart<3>&, std::span<const Index>);

}  // namespace hocav
