// The figures of a distributed curving's rounds (docs/distributed.md §Curving in the parts): every
// part with its interfaces frozen, then the band around those interfaces on rank 0; the seed of
// the partition they start from.
#pragma once

#include <cstdint>

#include "base/index.hpp"

namespace hocav {

// PT-Scotch's seed for a curving's first partition: the same mesh, the same parts.
constexpr std::int64_t kCurvingPartitionSeed = 0;

struct DistributedCurvingRound {
  int round = 0;                 // 1-based
  int rounds = 0;                // in all
  Index interface_faces = 0;     // between parts, each counted once
  Index interface_vertices = 0;  // shared by parts in the round
  // Round 2: the vertices pending (on the first round's interfaces) that lie on the band's border
  // too (not reinserted).
  Index old_interface_vertices_frozen_again = 0;
  long long cavities = 0;    // prepared, summed over the parts
  long long bytes_sent = 0;  // the boundary and the band sent, the band's nodes broadcast; then the rings measured with
  double seconds = 0;
};

}  // namespace hocav
