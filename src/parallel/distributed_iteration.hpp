// The figures of one iteration of the distributed adaptation loop (docs/distributed.md): printed as
// it ends and kept in the report (`hocav adapt --report`).
#pragma once

#include <vector>

#include "base/index.hpp"

namespace hocav {

// The whole-mesh iterations are 1 to kDistributedIterations; the two entries after them are the
// last runs in the parts and on rank 0 (docs/distributed.md §The scheme, step 5).
struct DistributedIteration {
  int iteration = 0;                 // 1-based
  double metric_fraction = 1;        // of the way from the input's own metric to the target
  Index vertices = 0, elements = 0;  // of the whole mesh after it
  Index interface_vertices = 0;      // shared by parts in the iteration
  Index interface_faces = 0;         // between parts, each counted once
  // Before the parts' loops: the interface edges split, and the faces turned into the four triangles
  // of a uniform refinement (docs/distributed.md §Interfaces refined first).
  Index interface_edges_split = 0, interface_faces_turned = 0;
  // After the parts' loops: the vertices at an edge they left unadapted (longer than
  // kUnsettledEdgeLength in their metric), which the next partition keeps inside its parts.
  Index unsettled_vertices = 0;
  Index region_elements = 0;  // the last runs': the elements near their seeds (that moved to rank 0 for its runs)
  // What the processes sent one another, without the input's broadcast: the migrations (the whole-mesh
  // iterations; the last runs' regions to their processes and to rank 0, then every element to rank 0).
  long long bytes_sent = 0;
  // The shares of the metric's back mesh the processes sent one another for their parts.
  long long back_mesh_bytes = 0;
  // The iteration, and its partitioning with the migration or split (docs/usage.md).
  double seconds = 0, seconds_partition = 0;
  // Per rank: the wall time of its part's adaptation, and its peak resident memory so far.
  std::vector<double> part_seconds;
  std::vector<long long> peak_memory_bytes;
};

}  // namespace hocav
