#include "adapt/curved_adaptation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <numeric>
#include <optional>

#include "adapt/adaptation_loop.hpp"
#include "adapt/curved_boundary.hpp"
#include "adapt/reinsertion_curving.hpp"
#include "base/thread_pool.hpp"
#include "bezier/p2_element.hpp"
#include "cavity/p2_operations.hpp"
#include "geom/sym_functions.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {

void CurvedOperationCount::add(CavityStatus status) {
  if (status == CavityStatus::kAccepted)
    ++done;
  else if (status == CavityStatus::kCrossesBoundary || status == CavityStatus::kBoundaryGeometry)
    ++on_boundary;
  else if (status == CavityStatus::kNoImprovement)
    ++no_gain;
  else if (status == CavityStatus::kFlatStraightElement)
    ++flat;
  else
    ++refused;
}

CurvedOperationCount& CurvedOperationCount::operator+=(const CurvedOperationCount& other) {
  done += other.done;
  boundary_done += other.boundary_done;
  on_boundary += other.on_boundary;
  too_long += other.too_long;
  no_gain += other.no_gain;
  flat += other.flat;
  refused += other.refused;
  return *this;
}

namespace {

const double kSplitLength = std::sqrt(2.0);
const double kCollapseLength = 1 / std::sqrt(2.0);
// A swap or move must raise the worst curved quality of its cavity by this factor, as the P1
// loop's smoothing (docs/adaptation.md): no move undoes another.
constexpr double kQualityGain = 1.01;
// Swaps and moves are tried on the elements below this curved quality: each try optimizes and
// certifies a whole shell or ball, and better elements gain little (docs/adaptation.md §Curved
// passes: moving every inner vertex took the sphere shell's curved run to 2.3x adapt-then-curve).
constexpr double kTryBelowQuality = 0.5;
// No operation makes a straight simplex of metric mean ratio below min(this, the worst it replaces):
// the P1 loop's collapse floor, which its output respects (min 0.093 on the boundary-layer shell).
// Without it the curved passes left straight simplices down to 0.001 there, valid curved elements
// with normalized Jacobians up to 4,046; 0.2 and 0.3 cost unit share (docs/benchmarks.md).
constexpr double kStraightQualityFloor = 0.1;

struct EdgeToFix {
  double length;
  Index a, b;
};

// Per chunk of kScanChunk ids, what `list` keeps of them, on the pool's threads, then the chunks in
// order: the same list for any thread count.
constexpr std::size_t kScanChunk = 2048;
template <typename T, typename List>
std::vector<T> scan_in_chunks(ThreadPool& pool, Index count, const List& list) {
  return joined(results_by_chunk<std::vector<T>>(pool, static_cast<std::size_t>(count), kScanChunk,
                                                 [&](std::size_t begin, std::size_t end, std::vector<T>& out) {
                                                   for (std::size_t i = begin; i < end; ++i) list(static_cast<Index>(i), out);
                                                 }));
}

// The edges whose curved length is outside (lower, upper), the ones furthest outside first; ties
// by vertex ids, so the order depends on the mesh only. The lengths are measured on the pool's threads.
template <int D>
std::vector<EdgeToFix> edges_outside(const Mesh<D>& mesh, const P2Operations<D>& operations, double lower, double upper, ThreadPool& pool) {
  std::vector<EdgeToFix> edges = scan_in_chunks<EdgeToFix>(pool, mesh.edge_count(), [&](Index e, std::vector<EdgeToFix>& out) {
    const auto& ends = mesh.edge_vertices(e);
    if (ends[0] == kNoIndex) return;  // a removed edge (Mesh::remove_edge)
    const double length = operations.edge_length(ends[0], ends[1]);
    if (length < lower || length > upper) out.push_back({length, std::min(ends[0], ends[1]), std::max(ends[0], ends[1])});
  });
  const bool shortest_first = upper == INFINITY;
  std::sort(edges.begin(), edges.end(), [shortest_first](const EdgeToFix& x, const EdgeToFix& y) {
    if (x.length != y.length) return shortest_first ? x.length < y.length : x.length > y.length;
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  return edges;
}

bool still_edge_of_length(const auto& mesh, const auto& operations, const EdgeToFix& edge, double lower, double upper) {
  if (mesh.vertex_removed(edge.a) || mesh.vertex_removed(edge.b) || mesh.find_edge(edge.a, edge.b) == kNoIndex) return false;
  const double length = operations.edge_length(edge.a, edge.b);
  return length < lower || length > upper;
}

template <int D>
double worst_quality(const P2Operations<D>& operations, std::span<const Index> elements) {
  double worst = INFINITY;
  for (Index k : elements) worst = std::min(worst, operations.quality(k));
  return worst;
}

// The refusals' kinds in their memo's digests.
enum RefusalKind : std::uint64_t { kSwapRefusal = 1, kMoveRefusal };

// What an operation on a cavity reads there: each element's P2 nodes and its vertices' log-metrics,
// in order, with the points that say which operation (its edge's ends, its vertex).
template <int D>
Digest cavity_digest(RefusalKind kind, const Mesh<D>& mesh, const P2Operations<D>& operations, std::span<const Index> elements,
                     std::initializer_list<Index> vertices) {
  Digest digest(kind);
  for (Index v : vertices) digest.add_all(mesh.vertex(v).c);
  for (Index k : elements) {
    for (const Vec<D>& node : gather_p2_element(mesh, k).nodes) digest.add_all(node.c);
    for (Index v : mesh.element(k)) digest.add_all(operations.log_metric(v).entries);
  }
  return digest;
}

// attempt()'s verdict, or the refusal remembered for the same cavity unchanged (not tried again).
// The digest leaves out the ring around the cavity, whose edges a correction may bend: a change
// there alone does not bring an operation back (most of a pass's candidates are the last pass's
// refusals, each a whole shell or ball optimized and certified).
template <typename Try>
CavityStatus unless_refused_before(DigestMemo& refusals, const Digest& cavity, const Try& attempt) {
  const Digest::Value key = cavity.value();
  if (const std::optional<double> refused = refusals.find(key)) return static_cast<CavityStatus>(static_cast<int>(*refused));
  const CavityStatus status = attempt();
  if (status != CavityStatus::kAccepted) refusals.remember(key, static_cast<double>(static_cast<int>(status)));
  return status;
}

// What the elements a collapse or split makes must beat: the worst curved quality of those it
// replaces, or the mesh's worst when they are all better. So the mesh's worst element never gets
// worse (the P1 loop's collapses allow a fall to 0.3 of the worst; on the sphere shell the passes
// took the worst curved element from 0.327 to 0.262).
template <int D>
double quality_to_keep(const P2Operations<D>& operations, std::span<const Index> cavity, double mesh_worst) {
  return std::min(worst_quality(operations, cavity), mesh_worst);
}

// The ring's vertices, the longest segment from `kept` first by its length in the metric at `kept`:
// a guess (one exponential for the whole ring), so that a verdict that is "too long" usually needs
// one quadrature, not several (the first pass measures each segment anew).
template <int D>
void longest_first(const Mesh<D>& mesh, const P2Operations<D>& operations, Index kept, std::vector<Index>& ring) {
  const SymMat<D> metric = exp_sym(operations.log_metric(kept));
  std::vector<std::pair<double, Index>> guessed;  // (−squared length, vertex): the longest first
  for (Index w : ring) guessed.emplace_back(-quadratic_form(metric, mesh.vertex(w) - mesh.vertex(kept)), w);
  std::sort(guessed.begin(), guessed.end());
  for (std::size_t i = 0; i < ring.size(); ++i) ring[i] = guessed[i].second;
}

// Whether collapsing `removed` onto `kept` leaves every straight segment from `kept` to the ball's
// vertices within √2: the curved edges the optimizer makes are no longer, so no collapse makes work
// for the next split (the P1 loop's closed window, docs/adaptation.md). The verdict does not depend
// on the order the segments are measured in.
template <int D>
bool collapse_keeps_lengths(const Mesh<D>& mesh, const P2Operations<D>& operations, Index removed, Index kept, std::span<const Index> ball,
                            std::vector<Index>& ring) {
  other_vertices<D>(mesh, ball, removed, kept, ring);
  longest_first(mesh, operations, kept, ring);
  return std::all_of(ring.begin(), ring.end(), [&](Index w) { return operations.straight_length(kept, w) <= kSplitLength; });
}

// What a pass changes: the mesh, its operations, and (with a geometry) its boundary.
template <int D>
struct PassTools {
  Mesh<D>& mesh;
  P2Operations<D>& operations;
  CurvedBoundary<D>* boundary;  // null: interior operations only
  double mesh_worst;            // the mesh's worst curved quality at the pass's start
};

// A collapse's verdict: the P2 operator's, with whether it was placed on the boundary; none when
// the collapse would make a long edge (not tried).
struct CollapseVerdict {
  CavityStatus status;
  bool on_boundary;
};
template <int D>
std::optional<CollapseVerdict> collapse(PassTools<D>& tools, Index removed, Index kept, std::vector<Index>& ball,
                                        std::vector<Index>& ring) {
  collect_ball(tools.mesh, removed, ball);
  if (!collapse_keeps_lengths(tools.mesh, tools.operations, removed, kept, ball, ring)) return std::nullopt;
  auto placement = tools.boundary ? tools.boundary->collapse_placement(ball, removed, kept) : std::nullopt;
  if (placement) placement->longest_edge = kSplitLength;  // its boundary edges follow the geometry: measured
  const typename P2Operations<D>::Bar bar{quality_to_keep(tools.operations, ball, tools.mesh_worst), -1};
  return CollapseVerdict{tools.operations.collapse_edge(removed, kept, bar, placement ? &*placement : nullptr), placement.has_value()};
}

// Each short edge collapses one way or the other; a refusal counts the reason of the second try.
template <int D>
CurvedOperationCount collapse_short_curved_edges(PassTools<D>& tools, ThreadPool& pool) {
  CurvedOperationCount count;
  std::vector<Index> ball, ring;
  for (const EdgeToFix& edge : edges_outside(tools.mesh, tools.operations, kCollapseLength, INFINITY, pool)) {
    if (!still_edge_of_length(tools.mesh, tools.operations, edge, kCollapseLength, INFINITY)) continue;
    std::optional<CollapseVerdict> verdict = collapse(tools, edge.a, edge.b, ball, ring);
    if (!verdict || verdict->status != CavityStatus::kAccepted) verdict = collapse(tools, edge.b, edge.a, ball, ring);
    if (!verdict) {
      ++count.too_long;
      continue;
    }
    count.add(verdict->status);
    count.boundary_done += verdict->status == CavityStatus::kAccepted && verdict->on_boundary;
  }
  return count;
}

template <int D>
CurvedOperationCount split_long_curved_edges(PassTools<D>& tools, ThreadPool& pool) {
  CurvedOperationCount count;
  std::vector<Index> shell;
  for (const EdgeToFix& edge : edges_outside(tools.mesh, tools.operations, -INFINITY, kSplitLength, pool)) {
    if (!still_edge_of_length(tools.mesh, tools.operations, edge, -INFINITY, kSplitLength)) continue;
    collect_shell(tools.mesh, edge.a, edge.b, shell);
    const auto placement = tools.boundary ? tools.boundary->edge_placement(shell, edge.a, edge.b, true) : std::nullopt;
    const typename P2Operations<D>::Bar bar{quality_to_keep(tools.operations, shell, tools.mesh_worst), -1};
    Index inserted = kNoIndex;
    const CavityStatus status = tools.operations.split_edge(edge.a, edge.b, &inserted, bar, placement ? &*placement : nullptr);
    count.add(status);
    if (status == CavityStatus::kAccepted && placement) {
      tools.boundary->add_boundary_vertex(inserted, placement->lines.empty() ? VertexClass::kSurface : VertexClass::kRidge);
      ++count.boundary_done;
    }
  }
  return count;
}

// The worst curved quality of the mesh's elements (measured on the pool's threads).
template <int D>
double worst_element_quality(const Mesh<D>& mesh, const P2Operations<D>& operations, ThreadPool& pool) {
  const auto count = static_cast<std::size_t>(mesh.element_count());
  const std::vector<double> worst = results_by_chunk<double>(
      pool, count, kScanChunk, [&](std::size_t begin, std::size_t end, double& chunk_worst) {
        chunk_worst = INFINITY;
        for (std::size_t k = begin; k < end; ++k) chunk_worst = std::min(chunk_worst, operations.quality(static_cast<Index>(k)));
      });
  return std::accumulate(worst.begin(), worst.end(), INFINITY, [](double x, double y) { return std::min(x, y); });
}

// The poor elements: below kTryBelowQuality, in order (their qualities measured on the pool's threads).
template <int D>
std::vector<Index> poor_elements(const Mesh<D>& mesh, const P2Operations<D>& operations, ThreadPool& pool) {
  return scan_in_chunks<Index>(pool, mesh.element_count(), [&](Index k, std::vector<Index>& out) {
    if (operations.quality(k) < kTryBelowQuality) out.push_back(k);
  });
}

// The edges of the poor elements, each once, in vertex order.
template <int D>
std::vector<std::pair<Index, Index>> edges_of_poor_elements(const Mesh<D>& mesh, const P2Operations<D>& operations, ThreadPool& pool) {
  std::vector<std::pair<Index, Index>> edges;
  for (Index k : poor_elements(mesh, operations, pool)) {
    const auto& v = mesh.element(k);
    for (int i = 0; i <= D; ++i)
      for (int j = i + 1; j <= D; ++j) edges.emplace_back(std::min(v[i], v[j]), std::max(v[i], v[j]));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

// Each edge's shell re-starred from the first vertex of its ring that raises the shell's worst
// curved quality; in 3D, with a boundary, a boundary edge is flipped on its surface (the apexes are
// the far vertices of its two facets).
template <int D>
CurvedOperationCount swap_poor_shells(PassTools<D>& tools, DigestMemo& refusals, ThreadPool& pool) {
  Mesh<D>& mesh = tools.mesh;
  P2Operations<D>& operations = tools.operations;
  CurvedOperationCount count;
  std::vector<Index> shell, ring;
  for (const auto& [first, second] : edges_of_poor_elements(mesh, operations, pool)) {
    const Index a = first, b = second;
    if (mesh.find_edge(a, b) == kNoIndex) continue;
    collect_shell(mesh, a, b, shell);
    bool flipped_on_boundary = false;  // (a refusal remembered answers without the placement)
    const CavityStatus status = unless_refused_before(refusals, cavity_digest(kSwapRefusal, mesh, operations, shell, {a, b}), [&] {
      const auto placement = D == 3 && tools.boundary ? tools.boundary->edge_placement(shell, a, b, false) : std::nullopt;
      // A cap's removal (a shell of one element) makes no edge: the edge it removes gives way to
      // the cap's inner edge, already there.
      const bool cap = placement && shell.size() == 1;
      const typename P2Operations<D>::Bar bar{kQualityGain * worst_quality(operations, shell),
                                              cap ? -1 : static_cast<int>(unit_length(operations.edge_length(a, b)))};
      ring.clear();
      if (placement)
        for (Index f : placement->facets)
          for (Index w : mesh.facet(f))
            if (w != a && w != b) ring.push_back(w);
      if (!placement) other_vertices<D>(mesh, shell, a, b, ring);
      flipped_on_boundary = placement.has_value();
      return operations.swap_edge(a, b, ring, bar, placement ? &*placement : nullptr);
    });
    count.add(status);
    count.boundary_done += status == CavityStatus::kAccepted && flipped_on_boundary;
  }
  return count;
}

// The inner vertices of the poor elements, each once, in order.
template <int D>
std::vector<Index> inner_vertices_of_poor_elements(const Mesh<D>& mesh, const P2Operations<D>& operations, ThreadPool& pool) {
  std::vector<bool> inner(static_cast<std::size_t>(mesh.vertex_count()), false);
  for (Index v : volume_vertices(mesh)) inner[static_cast<std::size_t>(v)] = !mesh.vertex_removed(v);
  std::vector<Index> vertices;
  for (Index k : poor_elements(mesh, operations, pool))
    for (Index v : mesh.element(k))
      if (inner[static_cast<std::size_t>(v)]) vertices.push_back(v);
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

// Each inner vertex of a poor element moved toward the mean of the points that would make its
// curved edges unit (w + (v − w)/l(v, w) over its neighbours w, as the P1 smoothing), the whole
// step or half of it, when that raises its ball's worst curved quality and keeps its unit edges.
template <int D>
CurvedOperationCount smooth_curved(Mesh<D>& mesh, P2Operations<D>& operations, DigestMemo& refusals, ThreadPool& pool) {
  CurvedOperationCount count;
  std::vector<Index> ball, neighbors;
  for (Index v : inner_vertices_of_poor_elements(mesh, operations, pool)) {
    collect_ball(mesh, v, ball);
    count.add(unless_refused_before(refusals, cavity_digest(kMoveRefusal, mesh, operations, ball, {v}), [&] {
      other_vertices<D>(mesh, ball, v, v, neighbors);
      Vec<D> target{};
      int unit = 0;
      for (Index w : neighbors) {
        const double length = operations.edge_length(v, w);
        target = target + (mesh.vertex(w) + (1 / length) * (mesh.vertex(v) - mesh.vertex(w)));
        unit += unit_length(length);
      }
      const Vec<D> from = mesh.vertex(v), step = (1.0 / static_cast<double>(neighbors.size())) * target - from;
      const typename P2Operations<D>::Bar bar{kQualityGain * worst_quality(operations, ball), unit};
      CavityStatus status = operations.move_vertex(v, from + step, bar);
      if (status == CavityStatus::kNoImprovement || status == CavityStatus::kRejectedByCurving)
        status = operations.move_vertex(v, from + 0.5 * step, bar);
      return status;
    }));
  }
  return count;
}

// One pass with operations made afresh: their per-vertex metrics follow the ids of a compact mesh.
// The memo keeps the lengths and qualities measured in earlier passes: most edges and elements come
// back unchanged, and each measure is a quadrature with a matrix exponential per point.
template <int D>
CurvedPass run_curved_pass(Mesh<D>& mesh, const MetricField<D>& field, const P2CavityOptions& options, CurvedBoundary<D>* boundary,
                           P2CavityCounters& counters, DigestMemo& measures, DigestMemo& refusals, ThreadPool& pool) {
  const auto start = std::chrono::steady_clock::now();
  CurvedPass pass;
  P2CavityOptions positive = options;
  positive.positive_straight_elements = true;
  positive.straight_quality_floor = kStraightQualityFloor;
  P2Operations<D> operations(mesh, field, nullptr, positive, &measures);
  // (Collapses and splits keep the mesh's worst: it holds for the whole pass.)
  PassTools<D> tools{mesh, operations, boundary, worst_element_quality(mesh, operations, pool)};
  pass.collapses = collapse_short_curved_edges(tools, pool);
  pass.splits = split_long_curved_edges(tools, pool);
  pass.swaps = swap_poor_shells(tools, refusals, pool);
  pass.moves = smooth_curved(mesh, operations, refusals, pool);
  counters += operations.cavity_operator().counters();
  mesh.compact();
  pass.vertices = mesh.vertex_count();
  pass.elements = mesh.element_count();
  pass.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return pass;
}

}  // namespace

template <int D>
CurvedAdaptationRun adapt_curved(Mesh<D>& mesh, const MetricField<D>& field, const P2CavityOptions& options, int max_passes, int threads,
                                 const CurvedPassGeometry<D>& geometry) {
  CurvedAdaptationRun run;
  ThreadPool pool(std::max(1, threads));
  DigestMemo measures, refusals;
  std::optional<CurvedBoundary<D>> boundary;
  if (geometry.geometry) boundary.emplace(mesh, *geometry.geometry, geometry.feature_angle_degrees);
  for (int pass = 1; pass <= max_passes && !run.converged; ++pass) {
    const CurvedPass& last = run.passes.emplace_back(
        run_curved_pass(mesh, field, options, boundary ? &*boundary : nullptr, run.counters, measures, refusals, pool));
    run.seconds += last.seconds;
    run.converged = static_cast<double>(last.splits.done + last.collapses.done) <= kConvergedChange * static_cast<double>(last.vertices);
  }
  return run;
}

template <int D>
CurvedMeasures measure_curved(Mesh<D>& mesh, const MetricField<D>& field, int threads, std::span<const char> skipped) {
  const P2Operations<D> operations(mesh, field, nullptr, {});
  ThreadPool pool(std::max(1, threads));
  // Each measure on the pool's threads, then the sums in order: the same figures for any count.
  const std::vector<double> lengths = scan_in_chunks<double>(pool, mesh.edge_count(), [&](Index e, std::vector<double>& out) {
    const auto& ends = mesh.edge_vertices(e);
    if (ends[0] != kNoIndex && (skipped.empty() || !skipped[e])) out.push_back(operations.edge_length(ends[0], ends[1]));
  });
  const std::vector<double> qualities = scan_in_chunks<double>(
      pool, mesh.element_count(), [&](Index k, std::vector<double>& out) { out.push_back(operations.quality(k)); });
  CurvedMeasures measures;
  measures.length_min = INFINITY;
  Index unit = 0;
  for (const double length : lengths) {
    ++measures.edge_count;
    measures.length_min = std::min(measures.length_min, length);
    measures.length_max = std::max(measures.length_max, length);
    measures.length_mean += length;
    unit += unit_length(length);
  }
  measures.length_mean /= static_cast<double>(std::max<Index>(1, measures.edge_count));
  measures.unit_share = static_cast<double>(unit) / static_cast<double>(std::max<Index>(1, measures.edge_count));
  measures.quality_min = INFINITY;
  for (const double quality : qualities) {
    measures.quality_min = std::min(measures.quality_min, quality);
    measures.quality_mean += quality;
  }
  measures.element_count = mesh.element_count();
  measures.quality_mean /= static_cast<double>(std::max<Index>(1, mesh.element_count()));
  return measures;
}

CurvedMeasures merge_curved_measures(const CurvedMeasures& a, const CurvedMeasures& b) {
  CurvedMeasures sum;
  sum.edge_count = a.edge_count + b.edge_count;
  sum.element_count = a.element_count + b.element_count;
  const auto weighted = [](double x, Index m, double y, Index n) {
    return m + n == 0 ? 0.0 : (x * double(m) + y * double(n)) / double(m + n);
  };
  sum.length_min = std::min(a.length_min, b.length_min);
  sum.length_max = std::max(a.length_max, b.length_max);
  sum.length_mean = weighted(a.length_mean, a.edge_count, b.length_mean, b.edge_count);
  sum.unit_share = weighted(a.unit_share, a.edge_count, b.unit_share, b.edge_count);
  sum.quality_min = std::min(a.quality_min, b.quality_min);
  sum.quality_mean = weighted(a.quality_mean, a.element_count, b.quality_mean, b.element_count);
  return sum;
}

template CurvedAdaptationRun adapt_curved(Mesh<2>&, const MetricField<2>&, const P2CavityOptions&, int, int, const CurvedPassGeometry<2>&);
template CurvedAdaptationRun adapt_curved(Mesh<3>&, const MetricField<3>&, const P2CavityOptions&, int, int, const CurvedPassGeometry<3>&);
template CurvedMeasures measure_curved(Mesh<2>&, const MetricField<2>&, int, std::span<const char>);
template CurvedMeasures measure_curved(Mesh<3>&, const MetricField<3>&, int, std::span<const char>);

}  // namespace hocav
