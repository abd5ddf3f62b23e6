#include "parallel/piece_facet_orientation.hpp"

#include <algorithm>
#include <optional>

#include "mesh/baffle_orientation.hpp"
#include "parallel/communicator.hpp"
#include "parallel/interface_sides.hpp"

namespace hocav {
namespace {

// One side of a face between two pieces: the ref of its element.
template <int D>
struct RefSide {
  FaceKey<D> face;
  std::int32_t process, ref;
};

// A baffle sent to every process: its file id, its vertices' global ids in its order, its ref.
template <int D>
struct BaffleRecord {
  Index id;
  typename Mesh<D>::Facet vertices;
  std::int32_t ref;
};

template <int D>
Index element_of_facet(const Mesh<D>& mesh, Index f) {
  return mesh.facet_element_face(f) / (D + 1);
}

// Collective: per facet of the piece, the ref of the element across it when that element lies in
// another piece (learnt from the other side of the interface facet on its face).
template <int D>
std::vector<std::optional<int>> refs_across_pieces(const MeshPart<D>& piece) {
  const Mesh<D>& mesh = piece.mesh;
  std::vector<RefSide<D>> own;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (mesh.facet_ref(f) == kInterfaceRef)
      own.push_back({global_key<D>(piece, mesh.facet(f)), process_rank(), mesh.element_ref(element_of_facet(mesh, f))});
  const auto across = sides_across<D>(own);
  std::vector<std::optional<int>> refs(static_cast<std::size_t>(mesh.facet_count()));
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (mesh.facet_ref(f) != kInterfaceRef)
      if (const auto side = across.find(global_key<D>(piece, mesh.facet(f))); side != across.end()) refs[f] = side->second.ref;
  return refs;
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
  std::vector<BaffleRecord<D>> all = all_gather_values_joined(own);
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
