// The paper's §IV algorithm: curve an adapted mesh by reinserting every volume vertex with the P2
// cavity operator, its ball as the cavity. Boundary curvature, proposed beforehand from the
// surface geometry, enters through the cavities whose boundary holds a surface edge.
//
// Threads: the volume vertices are split into batches whose balls share no vertex
// (independent_batches.hpp); a fixed number of cavities of a batch is prepared at once, on all
// threads, then committed in order. The order of work depends on the mesh only, so the output is
// the same whatever the thread count.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "cavity/p2_cavity_operator.hpp"

namespace hocav {

struct ReinsertionOptions {
  P2CavityOptions cavity{};
  int passes = 1;
  int threads = 1;
  // Work not redone (docs/curving.md): a recreated edge still at its optimum is not optimized
  // again, and, when every input element certifies above the floor (checked once), an element a
  // cavity recreates with the same nodes is not certified again. Off: every cavity optimizes all
  // its inner edges and certifies all its new elements, as the paper describes.
  bool reuse_results = true;
  // Per vertex, when not empty: only the volume vertices flagged here are reinserted (a distributed
  // curving's second round, near the first round's interfaces: docs/distributed.md §Curving).
  std::span<const char> region;
  // Called now and then with the fraction of the work done (for progress on long runs).
  std::function<void(double)> progress;
};

struct ReinsertionResult {
  P2CavityCounters counters;
  double seconds = 0;  // the passes and their set-up (batches), no I/O, no topology
  Index vertices_reinserted = 0;
};

// Makes `mesh` P2 (straight nodes) when it is P1, then curves it. `vertex_metrics[v]` is the
// metric at vertex v (the field's back mesh must be this mesh's P1 copy, so both number vertices
// alike). `boundary` may be null.
template <int D>
ReinsertionResult curve_by_reinsertion(Mesh<D>& mesh, const MetricField<D>& field, BoundaryNodeSource<D>* boundary,
                                       const ReinsertionOptions& options = {});

// The vertices on no boundary facet: the ones the algorithm reinserts (in the region, when given).
template <int D>
std::vector<Index> volume_vertices(const Mesh<D>& mesh);

}  // namespace hocav
