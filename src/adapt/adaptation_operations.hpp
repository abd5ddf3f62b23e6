// The passes of the adaptation loop (docs/adaptation.md §Operators): each visits candidates listed
// at its start by stable keys (vertex pairs, vertices), re-checks each against the current mesh,
// and applies it as one plan/commit of the cavity operator when the result passes its tests. Every
// new element is checked by the operator (positive straight measure) and by the pass (quality).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "adapt/adaptation_mesh.hpp"
#include "base/thread_pool.hpp"

namespace hocav {

// Which edges at a required vertex the split may cut (AdaptationSettings::splits_at_required_vertices).
enum class SplitsAtRequiredVertices {
  kEvery,
  // None at a required vertex (the distributed loop's last runs, whose frozen border is not refined
  // first: splits next to it kept them from converging).
  kNone,
  // Not one at a required vertex on a required facet's edge longer than 2; at a required vertex on
  // the domain's boundary (a facet that is not required) only a boundary edge where the boundary is
  // flat (its point on the geometry its middle). (A required facet's own edges are kept as ever.)
  kNextToFineRequiredFacets,
};

struct AdaptationLimits {
  double split_length = std::sqrt(2.0);         // edges longer are split
  double collapse_length = 1 / std::sqrt(2.0);  // edges shorter are collapsed
  // A collapse may make edges up to this long: split_length once the loop's window has closed
  // (docs/adaptation.md §The loop), so that no collapse makes work for the next split.
  double collapse_new_length = std::sqrt(2.0);
  double cos_feature_angle = 0.7071067811865476;  // cos 45°: boundary changes may turn a facet by less
  double hausd = 0;                               // > 0 with a geometry: new boundary facets stay within it
  // AdaptationSettings::splits_at_required_vertices
  SplitsAtRequiredVertices splits_at_required_vertices = SplitsAtRequiredVertices::kEvery;
};

// Why a candidate operation was refused.
enum class Refusal : int {
  kNone = -1,    // accepted
  kClasses = 0,  // the vertices' classes forbid it (a corner, a collapse off its surface or line)
  kTopology,     // the cavity operator refused the star (not star-shaped, a boundary in the way, a flat element)
  kQuality,      // a new element below the quality floor
  kLength,       // a new edge outside the length window
  kGeometry,     // a new boundary facet turned or left the geometry
};
inline constexpr int kRefusalKinds = 5;
const char* to_string(Refusal refusal);

struct OperationCount {
  Index done = 0;
  std::array<Index, kRefusalKinds> refused{};  // candidates tried and refused, by reason

  void add(Refusal outcome) {
    if (outcome == Refusal::kNone)
      ++done;
    else
      ++refused[static_cast<std::size_t>(outcome)];
  }
  Index refused_total() const {
    Index total = 0;
    for (Index n : refused) total += n;
    return total;
  }
  OperationCount& operator+=(const OperationCount& other) {
    done += other.done;
    for (std::size_t i = 0; i < refused.size(); ++i) refused[i] += other.refused[i];
    return *this;
  }
};

// Splits edges longer than split_length at their middle (on the geometry for boundary edges),
// longest first. A new vertex with an edge shorter than collapse_length is then collapsed onto that
// edge's other end when it can be: the long edge is cut at a vertex already there, not beside it
// (anisotropic refinement by midpoints would otherwise crowd the directions that need no refinement).
// Inside the domain the two are made in one, and when they cannot be, an edge shorter than 2 away
// from the boundary is not split (docs/adaptation.md §Split).
// In 3D, while many long edges are longer than 2, only those are split (the coarse phase).
struct SplitSweep {
  OperationCount count;
  bool coarse_phase = false;  // only the edges longer than 2 were candidates
};
template <int D>
SplitSweep split_long_edges(AdaptationMesh<D>& mesh, const AdaptationLimits& limits, ThreadPool& pool);

// Boundary-only elements below this quality are mended: caps removed (after the loop), the others cut.
inline constexpr double kBoundaryOnlyQuality = 0.2;

// 3D: removes the caps below kBoundaryOnlyQuality, worst first: a tetrahedron with two facets on
// one smooth surface (one ref, neither required, no feature line along their shared edge) and its
// other edge inside the domain. Its two inner faces become the boundary (the facets' shared edge
// flips to the cap's inner edge on the surface) when the boundary test of splits and collapses
// passes (feature angle, hausd): boundary_caps.cpp. 2D: none (a triangle's two boundary edges hold a
// vertex that only it has).
template <int D>
OperationCount remove_boundary_caps(AdaptationMesh<D>& mesh, const AdaptationLimits& limits);

// Cuts the poor elements whose vertices all lie on the boundary, worst first, by splitting their
// longest inner edge (no boundary facet through it) at its middle, without snapping. Swaps keep
// boundary edges and faces and smoothing keeps surface vertices on their surface, so nothing else
// mends such an element (mmg splits them too).
template <int D>
OperationCount cut_boundary_only_elements(AdaptationMesh<D>& mesh, const AdaptationLimits& limits);

// Collapses edges shorter than collapse_length, shortest first, one end onto the other when the
// classes allow it and no new edge is longer than collapse_new_length. The tests before each plan
// run on the pool's threads (the result does not depend on the thread count).
template <int D>
OperationCount collapse_short_edges(AdaptationMesh<D>& mesh, const AdaptationLimits& limits, ThreadPool& pool);

// Collapses the inner vertices that lie a hair above a boundary facet of a poor element (below 1% of
// the metric's size across it) onto that facet's nearest vertex, when collapse_edge allows it (any
// new edge length); one that no such collapse removes sinks onto the boundary (replaced by its
// closest point there, the facets under it re-starred): thin_vertices.cpp.
template <int D>
OperationCount collapse_thin_vertices(AdaptationMesh<D>& mesh, const AdaptationLimits& limits);

// Collapses `removed` onto `kept` (an edge) when the classes, the cavity operator and the tests
// of collapse_short_edges allow it.
template <int D>
struct alignas(64) CollapseScratch {  // a cache line of its own: each thread writes its own
  std::vector<Index> ball, facets, lines, kept_facets;
  std::vector<typename Mesh<D>::Element> star;
};
template <int D>
Refusal collapse_edge(AdaptationMesh<D>& mesh, Index removed, Index kept, const AdaptationLimits& limits, CollapseScratch<D>& scratch);

// Swaps that raise the worst quality of their cavity: 2D edge flips; 3D edge-shell swaps n → 2n − 4
// (the shell re-starred from its best vertex) and face swaps 2 → 3, around elements of quality below
// 0.7 (2D: 0.9) with a vertex whose ball changed since clock `since` (AdaptationMesh::changed_since).
// Swaps whose cavities share no vertex are judged on the pool's threads at once (the result does
// not depend on the thread count).
template <int D>
OperationCount swap_for_quality(AdaptationMesh<D>& mesh, const AdaptationLimits& limits, int since, ThreadPool& pool);

// Moves interior vertices toward the point where their edges would be unit, when that raises the
// worst quality of their ball; vertices whose balls share no element are tried on the pool's
// threads at once (the result does not depend on the thread count).
template <int D>
OperationCount smooth_vertices(AdaptationMesh<D>& mesh, const AdaptationLimits& limits, ThreadPool& pool);

// The edges of recently changed vertices (AdaptationMesh::changed_recently) whose length is above
// `bound` (longer = true: longest first) or below it (shortest first); ties by vertex ids, so the
// order does not depend on anything but the mesh (the lengths are measured on the pool's threads).
struct EdgeCandidate {
  double length;
  Index a, b;
};
template <int D>
std::vector<EdgeCandidate> edges_beyond(const AdaptationMesh<D>& mesh, double bound, bool longer, ThreadPool& pool);

// The vertices other than `center` of those of these elements (vertex lists) that hold it, once
// each, in the order met; with `places`, also each such element's vertices other than center in
// turn, as their places in `out`.
template <int D>
void neighbors_in(std::span<const typename Mesh<D>::Element> elements, Index center, std::vector<Index>& out,
                  std::vector<Index>* places = nullptr);

// The range of the lengths of the edges to these vertices from a point x with metric `metric_x`
// (a trial position of a vertex), and from vertex `center` where it is.
template <int D>
std::pair<double, double> length_range_from(const AdaptationMesh<D>& mesh, const Vec<D>& x, const SymMat<D>& metric_x,
                                            std::span<const Index> neighbors);
template <int D>
std::pair<double, double> length_range(const AdaptationMesh<D>& mesh, Index center, std::span<const Index> neighbors) {
  return length_range_from<D>(mesh, mesh.mesh().vertex(center), mesh.metric(center), neighbors);
}

// Whether lengths in range `after` keep within the unit window [collapse, split] widened to what
// `before` had: an operation may not create work for the next split or collapse (refine's closing
// window, kept local).
bool lengths_stay_in_window(std::pair<double, double> before, std::pair<double, double> after, const AdaptationLimits& limits);

// The worst quality of these elements (+inf for none), and of the elements a plan would create.
template <int D>
double worst_quality(const AdaptationMesh<D>& mesh, std::span<const Index> elements);
template <int D>
double worst_planned_quality(const AdaptationMesh<D>& mesh, const CavityOperator<D>& plan);

// Whether no edge from `center` in these elements is longer than `longest` (a collapse's or a
// reconnection's new edges: AdaptationLimits::collapse_new_length).
template <int D>
bool edges_from_within(const AdaptationMesh<D>& mesh, Index center, std::span<const typename Mesh<D>::Element> elements, double longest);

}  // namespace hocav
