// Membership in the short lists the mesh operators keep (a ball, a shell, a cavity's vertices: a
// few dozen ids). A scan without an early exit compiles to vector compares, which beats a
// branching std::find and any hashed set at these sizes (measured in docs/benchmarks.md).
#pragma once

#include <cstddef>
#include <span>

#include "base/index.hpp"

namespace hocav {

inline bool small_set_holds(std::span<const Index> items, Index id) {
  Index hits = 0;  // a sum, which compilers vectorize (an or of bools they do not)
  for (Index item : items) hits += item == id ? 1 : 0;
  return hits > 0;
}

// Where id is among the items (distinct ids), or items.size() when absent; a scan without an early
// exit, as above.
inline std::size_t small_set_place(std::span<const Index> items, Index id) {
  std::size_t place = items.size();
  for (std::size_t i = 0; i < items.size(); ++i) place = items[i] == id ? i : place;
  return place;
}

}  // namespace hocav
