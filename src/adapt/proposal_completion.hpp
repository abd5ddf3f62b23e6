// The last step of `hocav curve` with a boundary geometry (docs/curving.md, "Boundary edges no
// cavity reaches"): the reinsertion gives a boundary edge its proposed node only when a volume
// vertex's ball holds one of the edge's elements, which misses every edge whose elements have all
// their vertices on the boundary (along ridges, in thin walls), and a cavity may have applied a
// proposal only in part. This pass takes every proposal left, in a fixed order, and moves its edge's
// node toward it: in full when every element around the edge passes (element_guard.hpp: certified
// above the Jacobian floor, and with a metric most of its curved quality kept), else with the
// layers above it bent along (layer_bending.hpp), else alone by the largest fraction (bisection)
// that passes. Sweeps repeat while they make progress, since a node placed may free a neighbour
// blocked by an element they share.
#pragma once

#include "mesh/mesh.hpp"
#include "metric/metric_field.hpp"
#include "surface/boundary_proposals.hpp"

namespace hocav {

struct ProposalCompletion {
  Index placed = 0;             // proposals applied in full (consumed)
  Index already_placed = 0;     // the edge's node was the proposal already (consumed)
  Index pulled_back = 0;        // left: moved only part of the way (ElementGuard forbids more)
  Index blocked = 0;            // left: not moved at all (an element around the edge fails at any fraction)
  Index absent = 0;             // left: the edge is not in the mesh any more
  Index bends = 0;              // layers bent with their wall so that its proposals could be placed
  Index volume_nodes_bent = 0;  // volume edges' nodes those bends moved
  double largest_gap = 0;       // the largest distance left between a node and its proposal
  long long elements_certified = 0;
  int sweeps = 0;
  double seconds = 0;
};

template <int D>
struct ProposalCompletionOptions {
  double jacobian_floor = 0.01;
  const MetricField<D>* field = nullptr;  // when given, every move keeps most of each element's curved quality
  int correction_steps = 4;               // bisection steps of the fraction (resolution 2^-steps)
  int max_sweeps = 4;
};

// The mesh must be P2 with its topology and its elements above the floor (a curving's output).
template <int D>
ProposalCompletion complete_boundary_proposals(Mesh<D>& mesh, BoundaryProposals<D>& proposals, const ProposalCompletionOptions<D>& options);

}  // namespace hocav
