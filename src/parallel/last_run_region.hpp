// The region of the distributed loop's last runs, cut among the processes (docs/distributed.md §The
// scheme, step 5): the elements near each interface of the last whole-mesh iteration go to one of the
// interface's two processes, so that the interface lies inside a part; only where two such regions
// meet (the seams, where three or more parts met) is a frozen face left, which the runs on rank 0
// mend.
#pragma once

#include <span>
#include <vector>

#include "parallel/mesh_parts.hpp"

namespace hocav {

// The process of `a` and `b` that takes the region around their interface: each in turn, by the
// parity of a + b, so that a process takes about half of the regions around its interfaces.
inline int region_taker(int a, int b) { return (a + b) % 2 == 0 ? std::min(a, b) : std::max(a, b); }

// The same by `loads` (per process): the lighter of the two, region_taker on a tie; region_taker
// without loads.
inline int region_taker(int a, int b, std::span<const Index> loads) {
  if (loads.empty() || loads[a] == loads[b]) return region_taker(a, b);
  return loads[a] < loads[b] ? a : b;
}

struct RegionCut {
  std::vector<int> destination;              // per element of the part: the process whose last run takes it
  std::vector<char> in_region;               // per element of the part: within the rings of an interface (its destination a taker)
  Index region_elements = 0;                 // the part's elements within the rings of its interfaces
  std::vector<std::vector<Index>> seeds_to;  // per process: the global ids of the interface vertices of the elements it takes
  std::vector<Index> seams;                  // the global ids of the vertices of faces between two regions' elements
};

// Every process at once: each element of its part within `rings` rings of an interface vertex goes
// where its nearest interface vertices say (one whose interface facets all face one other process:
// region_taker of the two, by `loads` when given, per process; one where more parts meet: its own
// process; the smallest process when the nearest say several); the others stay. Poor elements are no seeds here: next to a seam, a
// frozen poor element's coarse faces made one process's runs refine around them for 40 passes.
template <int D>
RegionCut cut_last_run_region(const MeshPart<D>& part, int rings, std::span<const Index> loads = {});

}  // namespace hocav
