// Where the P2 cavity operator finds curved positions for boundary edges (docs/method.md §9): a table of
// proposed mid nodes, keyed by the edge, filled once from the boundary geometry (P3 surrogate or
// CAD) and emptied as cavities consume the proposals.
#pragma once

#include <optional>

#include "base/index.hpp"
#include "geom/vec.hpp"

namespace hocav {

template <int D>
class BoundaryNodeSource {
 public:
  virtual ~BoundaryNodeSource() = default;
  // The proposed P2 node of boundary edge (a, b) (either order), if one is waiting.
  virtual std::optional<Vec<D>> proposal(Index a, Index b) const = 0;
  // The proposal of (a, b) was applied in full: drop it.
  virtual void consume(Index a, Index b) = 0;
};

}  // namespace hocav
