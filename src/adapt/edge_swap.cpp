// Swaps (docs/adaptation.md §Swap): re-stars of small cavities that raise their worst quality.
// 2D: the two triangles of an interior edge re-starred from an opposite vertex (a flip). 3D: the
// shell of an interior edge re-starred from the shell vertex that gives the best worst quality
// (n → 2n − 4 elements), and two elements through a face re-starred from one's apex (2 → 3).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <tuple>

#include "adapt/adaptation_operations.hpp"
#include "adapt/conflict_batches.hpp"
#include "base/small_set.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/element_snapshot.hpp"

namespace hocav {
namespace {

// Shells of more elements are not swapped: on the sphere shell, 1 in 450 swaps of 7 or more
// elements succeeded, against 1 in 100 of 6 and 1 in 5 of 4.
constexpr std::size_t kLargestSwappedShell = 6;

// Candidates are swept this many at a time, so that the cavities kept for them take little memory
// whatever the mesh's size (a chunk's batches still hold hundreds of cavities each).
constexpr std::size_t kSweepChunk = 16384;
// Smaller batches are judged on the calling thread alone.
constexpr std::size_t kSmallestSwapBatch = 256;

// A swap must beat the worst quality it replaces by this factor: no swap undoes another.
constexpr double kSwapGain = 1.05;
// Elements below this quality have their edges (and 3D faces) tried: mmg's optimization threshold in
// 3D; the cheap 2D flips are tried wider.
template <int D>
constexpr double swap_quality() {
  return D == 2 ? 0.9 : 0.7;
}
// 3D faces (2 → 3) are tried only around elements below this quality: on the sphere shell, 1 in
// 600 face swaps around elements below 0.7 succeeded, and without them below 0.4 the worst
// elements rose on every 3D case of docs/benchmarks.md (ninth session).
constexpr double kFaceSwapQuality = 0.4;

template <int D>
struct alignas(64) SwapScratch {  // a cache line of its own: each thread writes its own
  std::vector<Index> neighbors;
  std::vector<typename Mesh<D>::Element> old_elements, star;
  std::vector<std::array<Index, D>> faces;  // the cavity's boundary faces, as its elements orient them
};

// The cavity of a swap and its candidate apexes as gathered, with its elements' vertices then: the
// cavity is still current while its slots hold them.
template <int D>
struct SwapCavity {
  std::vector<Index> elements, apexes;
  std::vector<typename Mesh<D>::Element> vertices;

  bool current(const Mesh<D>& mesh) const { return !elements.empty() && elements_unchanged<D>(mesh, elements, vertices); }
};

// The worst quality below which a cavity is judged. 3D shells of more elements rarely gain unless
// their worst element is poor: on the sphere shell (docs/benchmarks.md, twelfth session), 1
// judgement in 560 of shells of 5 elements whose worst was in [0.6, 0.7) found a swap (1 in 9
// below 0.3), and 1 in 1,400 of shells of 6 (1 in 70 below 0.3), against 1 in 14 of shells of 4 in
// [0.6, 0.7). Those judgements were 40% of all, and the larger shells cost the most to judge.
constexpr double kFiveShellQuality = 0.6;
constexpr double kLargeShellQuality = 0.3;
template <int D>
double swap_bar(const SwapCavity<D>& cavity) {
  if constexpr (D == 2) return swap_quality<D>();
  if (cavity.elements.size() == 2) return kFaceSwapQuality;  // 2 → 3
  if (cavity.elements.size() >= 6) return kLargeShellQuality;
  return cavity.elements.size() == 5 ? kFiveShellQuality : swap_quality<D>();
}

// A sweep's state: per candidate its cavity as last gathered; the batch's candidates and chosen
// apexes; a scratch per thread; per vertex the batch that took it; what waits for the next round.
template <int D>
struct SwapRound {
  std::vector<SwapCavity<D>> cavities;
  std::vector<Index> batch, chosen;
  std::vector<SwapScratch<D>> scratch;
  std::vector<int> taken;  // per vertex: the stamp of the batch whose cavity holds it
  int stamp = 0;
  std::vector<Index> waiting;  // candidates (by position) left for the next round
  std::vector<Index> keys;
  std::vector<Refusal> gathered;          // per pending candidate: why its cavity could not be gathered
  std::vector<char> unchanged;            // per pending candidate: no element of its cavity changed since the sweep's clock
  ConflictBatches coloring;               // keys: vertices
  std::vector<std::uint64_t> line_edges;  // 3D: the feature lines' edge keys, sorted (never swapped away)

  explicit SwapRound(const Mesh<D>& mesh) : taken(static_cast<std::size_t>(mesh.vertex_count()), 0), coloring(mesh.vertex_count()) {
    if constexpr (D == 3)
      for (Index l = 0; l < mesh.line_count(); ++l)
        if (!mesh.line_removed(l)) line_edges.push_back(Mesh<D>::edge_key(mesh.line(l)[0], mesh.line(l)[1]));
    std::sort(line_edges.begin(), line_edges.end());
  }
};

// Whether the apex's edges in the star keep within the length window of its edges in the cavity.
template <int D>
bool apex_lengths_stay_in_window(const AdaptationMesh<D>& am, Index apex, SwapScratch<D>& scratch, const AdaptationLimits& limits) {
  neighbors_in<D>(scratch.old_elements, apex, scratch.neighbors);
  const auto before = length_range<D>(am, apex, scratch.neighbors);
  neighbors_in<D>(scratch.star, apex, scratch.neighbors);
  return lengths_stay_in_window(before, length_range<D>(am, apex, scratch.neighbors), limits);
}

// The boundary faces of the cavity (faces whose neighbour is outside it), vertices in the order
// the cavity operator stars them.
template <int D>
void cavity_faces(const Mesh<D>& mesh, std::span<const Index> cavity, std::vector<std::array<Index, D>>& faces) {
  faces.clear();
  for (Index k : cavity)
    for (int face = 0; face <= D; ++face) {
      const Index outer = mesh.neighbor(k, face);
      if (outer != kNoIndex && small_set_holds(cavity, outer)) continue;
      std::array<Index, D> vertices;
      for (int i = 0; i < D; ++i) vertices[i] = mesh.element(k)[face_vertices<D>(face)[i]];
      faces.push_back(vertices);
    }
}

// The elements the star of the cavity from `apex` would make (one per boundary face not through
// the apex, as the cavity operator makes them), without planning it: a swap tries every apex, and
// only the best is worth a plan.
template <int D>
void predicted_star(std::span<const std::array<Index, D>> faces, Index apex, std::vector<typename Mesh<D>::Element>& star) {
  star.clear();
  for (const auto& face : faces) {
    if (std::find(face.begin(), face.end(), apex) != face.end()) continue;
    typename Mesh<D>::Element element;
    element[0] = apex;
    std::copy(face.begin(), face.end(), element.begin() + 1);
    star.push_back(element);
  }
}

// The best of the cavity's apexes as the centre of its star: the one whose star beats the old
// worst quality by kSwapGain by the most and keeps the apex's edges in the length window
// (kNoIndex: none). Reads the mesh only, so cavities that share no vertex are judged at once.
template <int D>
Index best_apex(const AdaptationMesh<D>& am, const SwapCavity<D>& cavity, SwapScratch<D>& scratch, const AdaptationLimits& limits) {
  const double old_worst = worst_quality<D>(am, cavity.elements);
  if (old_worst >= swap_bar<D>(cavity)) return kNoIndex;  // an earlier swap mended it, or it is unlikely to win
  double best = kSwapGain * old_worst;
  Index chosen = kNoIndex;
  scratch.old_elements.clear();
  for (Index k : cavity.elements) scratch.old_elements.push_back(am.mesh().element(k));
  cavity_faces<D>(am.mesh(), cavity.elements, scratch.faces);
  for (Index apex : cavity.apexes) {
    predicted_star<D>(scratch.faces, apex, scratch.star);
    double worst = std::numeric_limits<double>::infinity();
    for (const auto& element : scratch.star)
      if (worst = std::min(worst, am.quality(element)); worst <= best) break;  // this apex cannot win
    if (worst > best && apex_lengths_stay_in_window(am, apex, scratch, limits)) {
      best = worst;
      chosen = apex;
    }
  }
  return chosen;
}

// Whether element k (an element id from the sweep's start, perhaps moved or rewritten since)
// still holds these vertices.
template <int D, std::size_t N>
bool still_holds(const Mesh<D>& mesh, Index k, const std::array<Index, N>& vertices) {
  return k < mesh.element_count() && std::all_of(vertices.begin(), vertices.end(), [&](Index v) { return local_vertex(mesh, k, v) >= 0; });
}

// A swap candidate: an edge or face by its sorted vertices, with the element that listed it (the
// shell's start while that element still holds it).
template <std::size_t N>
struct SwapCandidate {
  std::array<Index, N> vertices;
  Index element;
  bool operator<(const SwapCandidate& other) const { return vertices < other.vertices; }
  bool operator==(const SwapCandidate& other) const { return vertices == other.vertices; }
};

// Sorts the candidates by vertices and keeps one of each, the one the lowest element listed: a
// counting sort by the first vertex, then each bucket sorted on the pool's threads.
template <std::size_t N>
void sort_unique(std::vector<SwapCandidate<N>>& candidates, Index vertex_count, ThreadPool& pool) {
  std::vector<Index> first(static_cast<std::size_t>(vertex_count) + 1, 0);
  for (const auto& c : candidates) ++first[static_cast<std::size_t>(c.vertices[0]) + 1];
  for (std::size_t v = 1; v < first.size(); ++v) first[v] += first[v - 1];
  std::vector<SwapCandidate<N>> sorted(candidates.size());
  std::vector<Index> fill(first.begin(), first.end() - 1);
  for (const auto& c : candidates) sorted[static_cast<std::size_t>(fill[static_cast<std::size_t>(c.vertices[0])]++)] = c;
  run_chunked(pool, static_cast<std::size_t>(vertex_count), 2048, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v)
      std::sort(sorted.begin() + first[v], sorted.begin() + first[v + 1], [](const SwapCandidate<N>& x, const SwapCandidate<N>& y) {
        return std::tie(x.vertices, x.element) < std::tie(y.vertices, y.element);
      });
  });
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  candidates.swap(sorted);
}

// The shell of edge (a, b); refused on the boundary (boundary edges change only with their facets,
// in split and collapse), on a feature line (`line_edges`, sorted keys: a line with no facet along
// it, an input's Edges inside the volume, has a closed shell), and when too small or too large.
template <int D>
Refusal gather_cavity(const Mesh<D>& mesh, const SwapCandidate<2>& edge, std::span<const std::uint64_t> line_edges, SwapCavity<D>& cavity) {
  const auto [a, b] = edge.vertices;
  if (std::binary_search(line_edges.begin(), line_edges.end(), Mesh<D>::edge_key(a, b))) return Refusal::kTopology;
  if (still_holds(mesh, edge.element, edge.vertices))
    collect_shell_from(mesh, edge.element, a, b, cavity.elements);
  else
    collect_shell(mesh, a, b, cavity.elements);
  if (cavity.elements.size() < (D == 2 ? 2u : 3u) || cavity.elements.size() > kLargestSwappedShell ||
      !shell_is_closed(mesh, cavity.elements, a, b))
    return Refusal::kTopology;
  other_vertices(mesh, cavity.elements, a, b, cavity.apexes);
  return Refusal::kNone;
}

// 3D, 2 → 3: the elements on both sides of interior face (a, b, c), to re-star from either apex.
Refusal gather_cavity(const Mesh<3>& mesh, const SwapCandidate<3>& candidate, std::span<const std::uint64_t>, SwapCavity<3>& cavity) {
  // Named one by one: clang refuses a structured binding captured by a lambda.
  const Index a = candidate.vertices[0], b = candidate.vertices[1], c = candidate.vertices[2];
  Index k = candidate.element;
  if (!still_holds(mesh, k, candidate.vertices)) {
    collect_shell(mesh, a, b, cavity.elements);
    const auto through_c = std::find_if(cavity.elements.begin(), cavity.elements.end(),
                                        [&](Index e) { return local_vertex(mesh, e, c) >= 0; });
    if (through_c == cavity.elements.end()) return Refusal::kTopology;
    k = *through_c;
  }
  // The face is the one of k opposite its fourth vertex; the other side is its neighbour.
  int face = 0;
  while (face < 3 && (mesh.element(k)[face] == a || mesh.element(k)[face] == b || mesh.element(k)[face] == c)) ++face;
  const Index other = mesh.neighbor(k, face);
  if (other == kNoIndex || mesh.face_has_facet(k, face)) return Refusal::kTopology;  // either side may link an inner facet
  cavity.elements.assign({k, other});
  other_vertices(mesh, cavity.elements, a, b, cavity.apexes);
  std::erase(cavity.apexes, c);
  return Refusal::kNone;
}

// The cavity of a candidate on the current mesh, with its elements' vertices.
template <int D, std::size_t N>
Refusal gather(const Mesh<D>& mesh, const SwapCandidate<N>& candidate, std::span<const std::uint64_t> line_edges, SwapCavity<D>& cavity) {
  const Refusal refusal = gather_cavity(mesh, candidate, line_edges, cavity);
  cavity.vertices.clear();
  if (refusal == Refusal::kNone)
    for (Index k : cavity.elements) cavity.vertices.push_back(mesh.element(k));
  else
    cavity.elements.clear();
  return refusal;
}

// One batch of swaps (docs/adaptation.md §Threads): each candidate's cavity gathered again if it
// changed since; one that now shares a vertex with an earlier one of the batch waits for the next
// round. The batch's cavities are judged on the pool's threads, then the chosen stars committed in
// order.
template <int D, std::size_t N>
void swap_batch(AdaptationMesh<D>& am, std::span<const SwapCandidate<N>> candidates, std::span<const Index> batch, SwapRound<D>& round,
                const AdaptationLimits& limits, ThreadPool& pool, OperationCount& count) {
  ++round.stamp;
  const auto taken = [&](Index v) { return round.taken[static_cast<std::size_t>(v)] == round.stamp; };
  round.batch.clear();
  for (Index item : batch) {
    const SwapCandidate<N>& candidate = candidates[static_cast<std::size_t>(item)];
    SwapCavity<D>& cavity = round.cavities[static_cast<std::size_t>(item)];
    if (!cavity.current(am.mesh()))
      if (const Refusal refusal = gather(am.mesh(), candidate, round.line_edges, cavity); refusal != Refusal::kNone) {
        count.add(refusal);
        continue;
      }
    if (std::any_of(candidate.vertices.begin(), candidate.vertices.end(), taken) ||
        std::any_of(cavity.apexes.begin(), cavity.apexes.end(), taken)) {
      round.waiting.push_back(item);
      continue;
    }
    for (Index v : candidate.vertices) round.taken[static_cast<std::size_t>(v)] = round.stamp;
    for (Index v : cavity.apexes) round.taken[static_cast<std::size_t>(v)] = round.stamp;
    round.batch.push_back(item);
  }
  const std::vector<Index>& judged = round.batch;
  round.chosen.assign(judged.size(), kNoIndex);
  run_in_blocks(pool, judged.size(), kSmallestSwapBatch, [&](std::size_t worker, std::size_t i) {
    round.chosen[i] = best_apex(am, round.cavities[static_cast<std::size_t>(judged[i])], round.scratch[worker], limits);
  });
  auto& work = am.workspace();
  for (std::size_t i = 0; i < judged.size(); ++i) {
    const SwapCavity<D>& cavity = round.cavities[static_cast<std::size_t>(judged[i])];
    if (round.chosen[i] == kNoIndex) {
      count.add(Refusal::kQuality);
    } else if (work.cavity_operator.plan(am.mesh(), cavity.elements, round.chosen[i], {}) != CavityStatus::kAccepted) {
      count.add(Refusal::kTopology);
    } else {
      am.commit(work.cavity_operator);
      count.add(Refusal::kNone);
    }
  }
}

// Rounds of batches until every candidate of a chunk is tried: a round gathers the cavities that changed and
// colours the candidates by their cavities' vertices; what a batch or the colouring left waits for
// the next round.
template <int D, std::size_t N>
void swap_all(AdaptationMesh<D>& am, std::span<const SwapCandidate<N>> candidates, int since, SwapRound<D>& round,
              const AdaptationLimits& limits, ThreadPool& pool, OperationCount& count) {
  const Mesh<D>& mesh = am.mesh();
  round.cavities.resize(candidates.size());
  for (SwapCavity<D>& cavity : round.cavities) cavity.elements.clear();  // none gathered yet
  std::vector<Index> pending(candidates.size());
  for (std::size_t i = 0; i < pending.size(); ++i) pending[i] = static_cast<Index>(i);
  while (!pending.empty()) {
    // Gathering reads the mesh and writes only the candidate's own cavity: on the pool's threads.
    round.gathered.assign(pending.size(), Refusal::kNone);
    round.unchanged.assign(pending.size(), 0);
    run_in_blocks(pool, pending.size(), kSmallestSwapBatch, [&](std::size_t, std::size_t i) {
      const auto item = static_cast<std::size_t>(pending[i]);
      SwapCavity<D>& cavity = round.cavities[item];
      if (!cavity.current(mesh)) round.gathered[i] = gather(mesh, candidates[item], round.line_edges, cavity);
      round.unchanged[i] = std::none_of(cavity.elements.begin(), cavity.elements.end(),
                                        [&](Index k) { return am.element_changed_since(k, since); });
    });
    ConflictBatches& coloring = round.coloring;
    coloring.clear();
    for (std::size_t i = 0; i < pending.size(); ++i) {
      const Index item = pending[i];
      const SwapCandidate<N>& candidate = candidates[static_cast<std::size_t>(item)];
      const SwapCavity<D>& cavity = round.cavities[static_cast<std::size_t>(item)];
      if (round.gathered[i] != Refusal::kNone) {
        count.add(round.gathered[i]);
        continue;
      }
      if (round.unchanged[i]) continue;  // judged on this same cavity before, and refused
      round.keys.assign(candidate.vertices.begin(), candidate.vertices.end());
      round.keys.insert(round.keys.end(), cavity.apexes.begin(), cavity.apexes.end());
      coloring.place(item, round.keys);
    }
    round.waiting = coloring.overflow();
    for (const std::vector<Index>& batch : coloring.batches()) swap_batch<D, N>(am, candidates, batch, round, limits, pool, count);
    std::sort(round.waiting.begin(), round.waiting.end());
    pending.swap(round.waiting);
  }
}

}  // namespace

template <int D>
OperationCount swap_for_quality(AdaptationMesh<D>& am, const AdaptationLimits& limits, int since, ThreadPool& pool) {
  // Candidates by vertices (element ids move as cavities commit): the edges (and 3D faces) of the
  // elements below swap_quality() around recent changes.
  const Mesh<D>& mesh = am.mesh();
  std::vector<SwapCandidate<2>> edges;
  std::vector<SwapCandidate<3>> faces;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const auto& e = mesh.element(k);
    if (std::none_of(e.begin(), e.end(), [&](Index v) { return am.changed_since(v, since); }) || am.quality(k) >= swap_quality<D>())
      continue;
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j < i; ++j) edges.push_back({{std::min(e[i], e[j]), std::max(e[i], e[j])}, k});
    if constexpr (D == 3)
      if (am.quality(k) < kFaceSwapQuality)
        for (int f = 0; f < 4; ++f) {
          std::array<Index, 3> face{e[face_vertices<3>(f)[0]], e[face_vertices<3>(f)[1]], e[face_vertices<3>(f)[2]]};
          std::sort(face.begin(), face.end());
          faces.push_back({face, k});
        }
  }
  sort_unique(edges, mesh.vertex_count(), pool);
  sort_unique(faces, mesh.vertex_count(), pool);
  OperationCount count;
  SwapRound<D> round(mesh);
  round.scratch.resize(static_cast<std::size_t>(pool.thread_count()));
  for (std::size_t start = 0; start < edges.size(); start += kSweepChunk)
    swap_all<D, 2>(am, std::span(edges).subspan(start, std::min(kSweepChunk, edges.size() - start)), since, round, limits, pool, count);
  if constexpr (D == 3)
    for (std::size_t start = 0; start < faces.size(); start += kSweepChunk)
      swap_all<D, 3>(am, std::span(faces).subspan(start, std::min(kSweepChunk, faces.size() - start)), since, round, limits, pool, count);
  return count;
}

template OperationCount swap_for_quality(AdaptationMesh<2>&, const AdaptationLimits&, int, ThreadPool&);
template OperationCount swap_for_quality(AdaptationMesh<3>&, const AdaptationLimits&, int, ThreadPool&);

}  // namespace hocav
