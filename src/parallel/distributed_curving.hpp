// The figures of a distributed curving's rounds (docs/distributed.md §Curving in the parts): every
// part with its interfaces frozen, then the bands around those interfaces, each on one of its two
// processes, then their seams on rank 0; the seed of the partition they start from.
#pragma once

#include <cstdint>

#include "base/index.hpp"

namespace hocav {

// PT-Scotch's seed for a curving's first partition: the same mesh, the same parts.
constexpr std::int64_t kCurvingPartitionSeed = 0;

struct DistributedCurvingRound {
  int round = 0;                 // 1-based
  int rounds = 0;                // in all
  Index interface_faces = 0;     // round 1: between parts, each counted once; later: each band's border faces
  Index interface_vertices = 0;  // round 1: on the interfaces; later: on the bands' borders
  // Rounds 2 and 3: the vertices pending (on the first round's interfaces) that lie on a band's
  // border too (not reinserted: in round 2, those of the bands' seams, which round 3 reinserts).
  Index old_interface_vertices_frozen_again = 0;
  long long cavities = 0;    // prepared, summed over the parts
  long long bytes_sent = 0;  // the boundary, the bands and their nodes sent; then the rings measured with
  double seconds = 0;
};

}  // namespace hocav
