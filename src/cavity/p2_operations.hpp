// The adaptation's four operations as P2 cavity operations (docs/curving.md §Curved operations): on a
// P2 mesh with its metric, each one is a cavity of the P2 operator (p2_cavity_operator.hpp), so
// its new inner edges are curved by the length optimizer, every element it creates is certified
// above the Jacobian floor (corrected toward the fallback nodes if needed), and a refusal leaves
// the mesh as it was, byte for byte.
//   split     edge (a, b): a new vertex at the edge's P2 node, the shell re-starred from it
//   collapse  edge (removed, kept): the ball of `removed` re-starred from `kept`
//   swap      edge (a, b): its shell re-starred from an apex (a 2D flip when the shell is two triangles)
//   move      vertex v to x: its ball re-starred from it
// With P2CavityOptions::straight_quality_floor, none makes a straight simplex poorer than
// min(floor, the worst it replaces) (kFlatStraightElement).
// An edge or vertex on a boundary face is refused (kCrossesBoundary) unless the caller places the
// split, collapse or swap on the boundary (BoundaryPlacement: which facets, and the geometry): the
// new vertex and the new boundary edges then lie on the geometry. Moves are interior only. The decision figures are curved too:
// `edge_length` is the Riemannian length of the curved edge, `quality` the curved mean ratio.
#pragma once

#include <cmath>
#include <functional>
#include <span>
#include <vector>

#include "base/digest_memo.hpp"
#include "cavity/p2_cavity_operator.hpp"

namespace hocav {

// A split, collapse or swap on the boundary, as the caller's geometry decides it: the boundary
// facets through the split or swapped edge or around the removed vertex, which it re-stars, and in
// 3D the feature lines it re-stars with them (a split or collapse along a line); where a point goes
// on the boundary (`place(x, w)`: for the new vertex, w = kNoIndex; for the new boundary edge from
// the operation's vertex to w, its node); and a test of the planned boundary
// (P2CavityRequest::boundary_check; none when empty).
template <int D>
struct BoundaryPlacement {
  std::span<const Index> facets;
  std::span<const Index> lines{};
  std::function<Vec<D>(const Vec<D>&, Index)> place;
  std::function<bool(const CavityOperator<D>&)> check{};
  double longest_edge = INFINITY;  // P2CavityRequest::longest_placed_edge
};

template <int D>
class P2Operations {
 public:
  // `mesh`: P2 with its topology; `field`: the metric on its back mesh (both outlive this object).
  // Each vertex's log-metric is evaluated in the field; new vertices get theirs on creation.
  // `boundary` (may be null) proposes boundary nodes for the cavities' boundary edges. `memo` (may be
  // null; used with this field only) remembers edge lengths and qualities by their exact inputs.
  P2Operations(Mesh<D>& mesh, const MetricField<D>& field, BoundaryNodeSource<D>* boundary, P2CavityOptions options,
               DigestMemo* memo = nullptr);

  // An operation with `bar.quality_to_beat` ≥ 0 is refused (kNoImprovement) unless every new
  // element's curved mean ratio is above it, and with `bar.unit_edges_to_keep` ≥ 0 unless as many
  // of its new inner edges are unit (P2CavityRequest).
  struct Bar {
    double quality_to_beat = -1;
    int unit_edges_to_keep = -1;
  };
  // Each returns the P2 operator's verdict; on anything but kAccepted the mesh is unchanged.
  // With `boundary`, the edge or the removed vertex is on it (else refused when on a boundary face).
  CavityStatus split_edge(Index a, Index b, Index* inserted = nullptr, Bar bar = {}, const BoundaryPlacement<D>* boundary = nullptr);
  CavityStatus collapse_edge(Index removed, Index kept, Bar bar = {}, const BoundaryPlacement<D>* boundary = nullptr);
  // The shell of (a, b) re-starred from the first of `apexes` that the operator accepts.
  // With `boundary`, (a, b) is a boundary edge flipped on its surface: the apexes are the far
  // vertices of its two facets, and the new boundary edge between them goes on the geometry. When
  // its shell is one element (a cap), the flip removes it: its inner faces become the boundary, and
  // its inner edge's node goes on the geometry.
  CavityStatus swap_edge(Index a, Index b, std::span<const Index> apexes, Bar bar = {}, const BoundaryPlacement<D>* boundary = nullptr);
  CavityStatus swap_edge(Index a, Index b, Index apex, Bar bar = {}) { return swap_edge(a, b, std::span(&apex, 1), bar); }
  CavityStatus move_vertex(Index v, const Vec<D>& x, Bar bar = {});

  // The Riemannian length of the curved edge (a, b) (high-precision quadrature of the length the
  // optimizer minimizes), and the curved mean ratio of element k (src/curve/curved_quality.hpp).
  double edge_length(Index a, Index b) const;
  // The Riemannian length of the straight segment between vertices a and b (an edge or not): the
  // curved edge the optimizer would make is no longer (docs/curving.md §Curved operations).
  double straight_length(Index a, Index b) const;
  double quality(Index k) const;
  // The metric mean ratio of element k's straight simplex (centroid_metric_mean_ratio).
  double straight_quality(Index k) const;

  const SymMat<D>& log_metric(Index v) const { return log_metrics_[static_cast<std::size_t>(v)]; }
  const P2CavityOperator<D>& cavity_operator() const { return operator_; }

 private:
  // Whether a face of `elements` holding every vertex of `vertices` is on the boundary (a facet,
  // or no neighbour).
  bool on_boundary(std::span<const Index> elements, std::span<const Index> vertices) const;
  // Adds vertex x with its log-metric and back hint (found from vertex `near`'s).
  Index add_vertex(const Vec<D>& x, Index near);
  void remove_last_vertex();
  std::array<SymMat<D>, D + 1> element_log_metrics(Index k) const;
  // The memo's value for the digest key() makes, or compute() without a memo (and no digest).
  template <typename Key, typename Compute>
  double remembered(const Key& key, const Compute& compute) const {
    return memo_ ? memo_->value(key().value(), compute) : compute();
  }
  // The floor of the new straight simplices' quality for an operation replacing `elements`:
  // min(options' straight_quality_floor, their worst), or −1 when the options ask none.
  double straight_quality_to_keep(std::span<const Index> elements) const;
  // Start nodes of the edges (center, w) of a vertex moved from `from` to its place now: each old
  // node of (from_vertex, w) shifted by half the move, so the edge keeps its bend.
  void shifted_starts(Index from_vertex, const Vec<D>& from, Index center);
  // The request's boundary part: the placement's facets and lines to re-star, its check and bound,
  // and for each start edge of `center` to a vertex of those facets that does not exist yet, its
  // node on the geometry (the placement's point for the start node).
  void place_on_boundary(const BoundaryPlacement<D>& boundary, Index center, P2CavityRequest<D>& request);
  // Whether one of these facets holds both v and w.
  bool on_a_facet(std::span<const Index> facets, Index v, Index w) const;

  Mesh<D>& mesh_;
  const MetricField<D>& field_;
  DigestMemo* memo_;
  double straight_quality_floor_;
  std::vector<SymMat<D>> log_metrics_;
  std::vector<Index> hints_;
  P2CavityOperator<D> operator_;
  std::vector<Index> cavity_, neighbors_;
  std::vector<EdgeStart<D>> starts_, boundary_nodes_;
};

extern template class P2Operations<2>;
extern template class P2Operations<3>;

}  // namespace hocav
