// Membership in the short lists the mesh operators keep (a ball, a shell, a cavity's vertices: a
// few dozen ids). A scan without an early exit compiles to vector compares, which beats a
// branching std::find and any hashed set at these sizes (measured in docs/benchmarks.md).
#pragma once

#include <span>

#include "base/index.hpp"

namespace hocav {

inline bool small_set_holds(std::span<const Index> items, Index id) {
  Index hits = 0;  // a sum, which compilers vectorize (an or of bools they do not)
  for (Index item : items) hits += item == id ? 1 : 0;
  return hits > 0;
}

}  // namespace hocav
