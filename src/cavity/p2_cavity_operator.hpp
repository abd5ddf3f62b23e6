// The P2 cavity operator (the paper's §III.B), on top of the P1 operator:
//  1. plan the star with the straight-element checks off unless asked (a valid P2 element may be an inverted
//     P1 element); curve every new inner edge (vertex, boundary vertex) by minimizing its
//     Riemannian length; give the cavity's boundary edges that have a waiting boundary proposal
//     their proposed node;
//  2. certify every new element, and every element outside the cavity around a boundary edge whose
//     node changed, with the Bézier Jacobian test: min normalized Jacobian > floor;
//  3. correct instead of relaxing blindly: for an element that fails, scale the displacement of its
//     changed edges (fallback → target) by the largest factor, found by bisection, that certifies
//     it — inner edges first, boundary edges only if that is not enough; reject the cavity (mesh
//     untouched) only when no factor works. The fallback is the node the edge had before (a
//     reinsertion recreates its edges), the straight midpoint for a new edge, or the start node the
//     operation gives (P2CavityRequest: a split's subdivision, a moved vertex's shifted nodes), so
//     a reinsertion can always fall back to the configuration that was already certified;
//  4. commit.
// Work whose result is known is not redone (a reinsertion recreates the cavity it removes): a
// recreated inner edge marked as being at its optimum keeps its node, and, when the caller vouches
// that every element of the mesh is above the floor, a new element identical to the cavity element
// it recreates (same vertices, same nodes) keeps that element's certificate.
#pragma once

#include <cmath>
#include <functional>
#include <span>
#include <vector>

#include "bezier/p2_element.hpp"
#include "cavity/boundary_node_source.hpp"
#include "cavity/cavity_operator.hpp"
#include "cavity/optimized_edge_marks.hpp"
#include "curve/edge_optimizer.hpp"
#include "metric/metric_field.hpp"

namespace hocav {

struct P2CavityOptions {
  // Every element the operator creates or changes ends with min normalized Jacobian above this.
  double jacobian_floor = 0.01;
  EdgeOptimizerOptions optimizer{};
  // Bisection steps of the correction factor (resolution 2^-steps). Finer does not pay: an edge
  // pulled back loses its optimum mark and is optimized again at its next cavity, and 4 steps gave
  // higher gains, fewer corrections and 22-26% fewer certifications than 10 (docs/benchmarks.md).
  int correction_steps = 4;
  // The caller vouches that every element of the mesh is certified above jacobian_floor (the
  // reinsertion driver checks its input once): every accepted cavity keeps it so, and a new element
  // identical to a cavity element is then not certified again.
  bool every_element_above_floor = false;
  // The new elements must also be positive as straight simplices (the P1 operator's measure check).
  // Off, a valid curved element may be a flat or inverted straight one; a flat one has no normalized
  // Jacobian (J / |J_straight| is infinite), so the curved passes keep them positive
  // (docs/adaptation.md §Curved passes).
  bool positive_straight_elements = false;
  // The curved operations (p2_operations.hpp) also refuse a new element whose straight simplex has
  // a metric mean ratio below min(this, the worst of the elements it replaces): a valid curved
  // element on a nearly flat straight one has a huge normalized Jacobian (docs/adaptation.md
  // §Curved passes). 0: not asked.
  double straight_quality_floor = 0;
};

// A new inner edge whose curving starts, and falls back, at a given node instead of the node it had
// (a recreated edge) or the straight midpoint: a split's pieces of the split edge, the edges of a
// moved vertex. Such an edge is always optimized (its old optimum mark no longer holds).
template <int D>
struct EdgeStart {
  Index a, b;  // either order
  Vec<D> node;
};

// What one cavity operation asks of the P2 operator besides its cavity and vertex.
template <int D>
struct P2CavityRequest {
  Index removable_vertex = kNoIndex;  // the one vertex that may disappear (a collapse), or kNoIndex
  std::span<const EdgeStart<D>> start_nodes{};
  // The smallest curved mean ratio of the new elements (docs/curving.md §Curved quality) must be
  // above this, else kNoImprovement: swaps and smoothing only improve.
  double quality_to_beat = -1;
  // At least this many of the new inner edges must be unit in their curved length (in [1/√2, √2]),
  // else kNoImprovement: a swap or move keeps the unit edges it replaces. Negative: not asked.
  int unit_edges_to_keep = -1;
  // Every new element's straight simplex must have a metric mean ratio (centroid_metric_mean_ratio)
  // of at least this, else kFlatStraightElement, refused before any curving. Negative: not asked.
  double straight_quality_to_keep = -1;
  // Boundary operations (docs/curving.md §Curved operations on the boundary): the boundary facets
  // the operation re-stars from its vertex (CavityOptions::removed_facets); the new inner edges
  // that lie on the boundary, each with its node on the geometry, which it takes instead of the
  // optimizer's (pulled
  // back toward its start node if the certification asks, but not refused: the operation is
  // refused, kBoundaryGeometry, unless every such node reaches the geometry, so the boundary never
  // leaves it); and a test of the planned boundary, before any curving (false: kBoundaryGeometry).
  std::span<const Index> removed_facets{};
  std::span<const Index> removed_lines{};  // 3D: the feature lines it re-stars too (CavityOptions::removed_lines)
  std::span<const EdgeStart<D>> boundary_nodes{};
  std::function<bool(const CavityOperator<D>&)> boundary_check{};
  // A cap's removal (CavityOptions::exposes_faces): its inner edge, on the cavity's boundary, becomes
  // a boundary edge; boundary_nodes may then name such an edge too, whose node moves onto the
  // geometry, and the elements outside the cavity around it must beat quality_to_beat as well.
  bool exposes_faces = false;
  // The edges placed on the geometry must be at most this long in their curved length, else
  // kNoImprovement (a boundary edge follows the geometry, not the optimizer, so its straight
  // length does not bound it).
  double longest_placed_edge = INFINITY;
};

// Whether a Riemannian edge length is unit (the loop's range [1/√2, √2]).
inline bool unit_length(double length) { return length >= 1 / std::sqrt(2.0) && length <= std::sqrt(2.0); }

struct P2CavityCounters {
  long long cavities = 0, accepted = 0;
  long long rejected_topology = 0, rejected_curving = 0, rejected_quality = 0;
  long long rejected_straight_quality = 0;  // a new straight simplex below the request's floor
  long long rejected_boundary = 0;          // the request's test of the new boundary facets failed
  long long edges_optimized = 0, optimizer_iterations = 0;
  long long edges_kept_optimal = 0;  // recreated at their optimum: not optimized again
  long long boundary_nodes_applied = 0;
  long long corrections = 0;  // elements that needed their edges pulled back
  long long elements_certified = 0;
  long long certificates_kept = 0;  // new elements identical to a certified cavity element
  double seconds_plan = 0, seconds_optimize = 0, seconds_certify = 0, seconds_commit = 0;

  P2CavityCounters& operator+=(const P2CavityCounters& other);
};

template <int D>
class P2CavityOperator {
 public:
  // `vertex_log_metrics[v]` is log M at front vertex v; `vertex_hints[v]` a back element near it
  // (both grow with the mesh: the caller owns them). `optimized_edges` (shared by the operators
  // working on one mesh, or null: every new inner edge is optimized) is read by prepare and updated
  // by commit. `boundary` may be null (no surface curving).
  P2CavityOperator(const MetricField<D>& field, std::vector<SymMat<D>>& vertex_log_metrics, std::vector<Index>& vertex_hints,
                   OptimizedEdgeMarks* optimized_edges, BoundaryNodeSource<D>* boundary, const P2CavityOptions& options);

  // Replaces `cavity` by the star of its boundary from `vertex`, curved and certified. The mesh
  // must be P2 with its topology; it is unchanged unless the result is kAccepted.
  CavityStatus apply(Mesh<D>& mesh, std::span<const Index> cavity, Index vertex, const P2CavityRequest<D>& request = {}) {
    CavityStatus status = prepare(mesh, cavity, vertex, request);
    if (status == CavityStatus::kAccepted) commit(mesh);
    return status;
  }
  // The two halves of apply: prepare reads the mesh only (plan, curve, certify, correct), so
  // cavities that share no vertex can be prepared at once on threads; commit writes the prepared
  // cavity (only after an accepted prepare, on the mesh it was prepared on).
  CavityStatus prepare(const Mesh<D>& mesh, std::span<const Index> cavity, Index vertex, const P2CavityRequest<D>& request = {});
  void commit(Mesh<D>& mesh);

  const P2CavityCounters& counters() const { return counters_; }

  // The edges the last prepare curved (valid until the next prepare), for checks of the result.
  struct CurvedEdge {
    Index a, b;
    Vec<D> fallback, target;
    double scale = 1;             // node = fallback + scale · (target − fallback)
    bool inner;                   // a new inner edge (else a boundary edge taking a proposal)
    Index id;                     // index in the plan's inner edges, or the mesh edge id
    bool optimal;                 // target is the edge's converged optimum
    Index start_hint = kNoIndex;  // the back element its optimization started from (it depends on it)
    bool placed = false;          // a new edge the request places on the geometry (boundary_nodes)
    Vec<D> node() const { return fallback + scale * (target - fallback); }
  };
  std::span<const CurvedEdge> curved_edges() const { return curved_; }

 private:
  // An element to certify: a new one (its vertices) or one outside the cavity (its mesh id), with
  // the nodes of its unchanged edges looked up once and, per edge, its entry in curved_ (or −1).
  struct Candidate {
    typename Mesh<D>::Element vertices;
    Index mesh_element;  // kNoIndex for a new element
    P2Element<D> fixed_nodes;
    std::array<int, Simplex<D>::kEdges> curved;
  };

  void curve_inner_edges(const Mesh<D>& mesh, const P2CavityRequest<D>& request);
  // The new nodes of the cavity's boundary edges: the request's placed ones (an exposed edge), then
  // the boundary source's proposals.
  void take_boundary_proposals(const Mesh<D>& mesh, const P2CavityRequest<D>& request);
  void collect_candidates(const Mesh<D>& mesh);
  // The cavity's elements as (sorted vertices, parity of the sort), sorted: to find the one a new
  // element recreates.
  void collect_cavity_vertex_sets(const Mesh<D>& mesh);
  // A new element with the vertices, orientation and nodes of a cavity element.
  bool recreates_cavity_element(const Candidate& candidate) const;
  // In commit: each edge whose node the cavity wrote is marked optimal or not.
  void mark_optimized_edges();
  void add_candidate(const Mesh<D>& mesh, const typename Mesh<D>::Element& vertices, Index mesh_element);
  P2Element<D> element_of(const Candidate& candidate) const;
  bool certified(const Candidate& candidate);
  std::array<SymMat<D>, D + 1> log_metrics_of(const typename Mesh<D>::Element& vertices) const;
  // Whether every new element's straight simplex has a metric mean ratio of at least `floor`.
  bool new_straight_elements_above(const Mesh<D>& mesh, double floor) const;
  // Whether every new element's curved mean ratio is above `bar`, and every element outside the
  // cavity around a placed boundary edge (a cap's exposed edge).
  bool new_elements_above(double bar) const;
  // How many new inner edges are unit in their curved length.
  int unit_new_inner_edges(const Mesh<D>& mesh) const;
  // Whether every edge placed on the geometry is at most `longest` in its curved length.
  bool placed_edges_within(const Mesh<D>& mesh, double longest) const;
  double curved_length(const Mesh<D>& mesh, const CurvedEdge& edge) const;
  // Pulls back the changed edges of a failing candidate; false when nothing certifies it.
  bool correct(const Candidate& candidate);
  // After a correction: the candidates holding an edge it moved need certifying again.
  void forget_certificates_of_corrected_edges();

  const MetricField<D>& field_;
  std::vector<SymMat<D>>& vertex_log_metrics_;
  std::vector<Index>& vertex_hints_;
  OptimizedEdgeMarks* optimized_edges_;
  BoundaryNodeSource<D>* boundary_;
  P2CavityOptions options_;
  CavityOperator<D> p1_;
  P2CavityCounters counters_;
  std::vector<CurvedEdge> curved_;
  std::vector<Candidate> candidates_;
  std::vector<std::pair<std::uint64_t, int>> curved_by_key_;  // (edge key, index in curved_), sorted
  std::vector<CurvedEdge*> corrected_edges_;
  std::vector<double> corrected_scales_;
  std::vector<bool> certified_already_;  // per candidate: certified, and none of its nodes moved since
  std::vector<Index> shell_;
  std::vector<std::pair<typename Mesh<D>::Element, bool>> cavity_vertex_sets_;
  std::vector<Vec<D>> inner_nodes_;
  LocatorScratch locator_scratch_;  // the optimizer's localizations, from one edge to the next
  std::vector<std::pair<Index, Vec<D>>> boundary_nodes_;
};

extern template class P2CavityOperator<2>;
extern template class P2CavityOperator<3>;

}  // namespace hocav
