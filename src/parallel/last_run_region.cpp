#include "parallel/last_run_region.hpp"

#include <algorithm>
#include <unordered_map>

#include "mesh/simplex.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/interface_sides.hpp"

namespace hocav {
namespace {

// One side's view of an interface face: the process that holds it and the process that takes the
// side's element (-1 before the region is cut).
template <int D>
struct RegionSide {
  FaceKey<D> face;
  int process;
  int taker;
};

constexpr int kNoProcess = kNoLabel;
constexpr int kSeveralProcesses = -2;

// A facet's vertices (local ids), sorted.
template <int D>
FaceKey<D> local_facet_key(const MeshPart<D>& part, Index f) {
  FaceKey<D> local;
  std::copy(part.mesh.facet(f).begin(), part.mesh.facet(f).end(), local.begin());
  return sorted_key<D>(local);
}

// Collective: per interface facet (in `facets`' order), the record of its side across, from each
// side's `taker`.
template <int D>
std::vector<RegionSide<D>> across_facets(const MeshPart<D>& part, const std::vector<Index>& facets, const std::vector<int>& taker) {
  std::vector<RegionSide<D>> own;
  for (std::size_t i = 0; i < facets.size(); ++i)
    own.push_back({global_key<D>(part, local_facet_key(part, facets[i])), process_rank(), taker[i]});
  const auto across = sides_across<D, RegionSide<D>>(own);
  std::vector<RegionSide<D>> sides;
  for (const RegionSide<D>& side : own) sides.push_back(across.at(side.face));
  return sides;
}

// Per interface vertex the process that takes its elements (kNoProcess for the others): one whose
// facets all face one process, region_taker of the two (by `loads`); one where more parts meet, its
// own process.
template <int D>
std::vector<int> seed_takers(const MeshPart<D>& part, const std::vector<Index>& facets, std::span<const Index> loads) {
  const std::vector<RegionSide<D>> across = across_facets(part, facets, std::vector<int>(facets.size(), kNoProcess));
  std::vector<int> partner(static_cast<std::size_t>(part.mesh.vertex_count()), kNoProcess);
  for (std::size_t i = 0; i < facets.size(); ++i)
    for (Index v : part.mesh.facet(facets[i])) {
      int& p = partner[static_cast<std::size_t>(v)];
      p = p == kNoProcess || p == across[i].process ? across[i].process : kSeveralProcesses;
    }
  std::vector<int> taker(partner.size(), kNoProcess);
  for (std::size_t v = 0; v < partner.size(); ++v)
    if (partner[v] != kNoProcess) taker[v] = partner[v] >= 0 ? region_taker(process_rank(), partner[v], loads) : process_rank();
  return taker;
}

// The part's faces between elements of two takers, each by its local vertices; with them the
// interface facets whose two sides' elements have two takers (collective).
template <int D>
std::vector<FaceKey<D>> seam_faces(const MeshPart<D>& part, const std::vector<int>& taker, const std::vector<Index>& facets) {
  std::unordered_map<FaceKey<D>, int, FaceKeyHash<D>> taker_of_face;  // of the region's faces, by sorted local key
  std::vector<FaceKey<D>> seams;
  for (Index k = 0; k < part.mesh.element_count(); ++k) {
    if (taker[k] == kNoProcess) continue;
    for (int face = 0; face <= D; ++face) {
      FaceKey<D> key;
      for (int i = 0; i < D; ++i) key[i] = part.mesh.element(k)[face_vertices<D>(face)[i]];
      key = sorted_key<D>(key);
      const auto [at, added] = taker_of_face.emplace(key, taker[k]);
      if (!added && at->second != taker[k]) seams.push_back(key);
    }
  }
  std::vector<int> facet_taker;
  for (Index f : facets) facet_taker.push_back(taker_of_face.at(local_facet_key(part, f)));  // an interface face's element is a seed's
  const std::vector<RegionSide<D>> across = across_facets(part, facets, facet_taker);
  for (std::size_t i = 0; i < facets.size(); ++i)
    if (across[i].taker != facet_taker[i]) std::copy_n(part.mesh.facet(facets[i]).begin(), D, seams.emplace_back().begin());
  return seams;
}

void unique_sorted(std::vector<Index>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

}  // namespace

template <int D>
RegionCut cut_last_run_region(const MeshPart<D>& part, int rings, std::span<const Index> loads) {
  const std::vector<Index> facets = interface_facets(part.mesh);
  const std::vector<int> seed_taker = seed_takers(part, facets, loads);
  const std::vector<int> taker = nearest_labels(part.mesh, seed_taker, rings);
  RegionCut cut;
  cut.seeds_to.resize(static_cast<std::size_t>(process_count()));
  for (Index k = 0; k < part.mesh.element_count(); ++k) {
    cut.destination.push_back(taker[k] == kNoProcess ? process_rank() : taker[k]);
    cut.in_region.push_back(taker[k] != kNoProcess);
    if (taker[k] == kNoProcess) continue;
    ++cut.region_elements;
    for (Index v : part.mesh.element(k))
      if (seed_taker[v] != kNoProcess) cut.seeds_to[static_cast<std::size_t>(taker[k])].push_back(part.global_ids[v]);
  }
  for (const FaceKey<D>& face : seam_faces(part, taker, facets))
    for (Index v : face) cut.seams.push_back(part.global_ids[v]);
  for (std::vector<Index>& ids : cut.seeds_to) unique_sorted(ids);
  unique_sorted(cut.seams);
  return cut;
}

template RegionCut cut_last_run_region(const MeshPart<2>&, int, std::span<const Index>);
template RegionCut cut_last_run_region(const MeshPart<3>&, int, std::span<const Index>);

}  // namespace hocav
