// Which edges of a mesh hold, as their node, the converged result of their own length optimization,
// committed unchanged since. A cavity that recreates such an edge (same two vertices, which a cavity
// never moves, and a fixed metric) keeps its node: restarting the optimizer at its own optimum
// returns it. One bit per edge id, kept by the P2 cavity operators working on one mesh: every
// commit sets or clears the bits of the edges whose nodes it writes, new edges included, so a bit
// left on a removed edge's id is rewritten before a new edge with that id can be read.
#pragma once

#include <vector>

#include "base/index.hpp"

namespace hocav {

class OptimizedEdgeMarks {
 public:
  bool marked(Index edge) const { return static_cast<std::size_t>(edge) < marked_.size() && marked_[edge]; }
  void set(Index edge, bool optimal) {
    if (static_cast<std::size_t>(edge) >= marked_.size()) marked_.resize(static_cast<std::size_t>(edge) + 1, false);
    marked_[edge] = optimal;
  }

 private:
  std::vector<bool> marked_;  // bits: small enough to stay in cache
};

}  // namespace hocav
