// Entity indices: 32-bit everywhere to keep a 20M-tetrahedron mesh compact; growth is checked.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "base/error.hpp"

namespace hocav {

using Index = std::int32_t;
inline constexpr Index kNoIndex = -1;

// Converts a count or position to Index, refusing what 32 bits cannot hold.
inline Index checked_index(std::size_t value, const char* what) {
  if (value > static_cast<std::size_t>(std::numeric_limits<Index>::max()))
    throw Error(std::string("too many ") + what + " for 32-bit indices (" + std::to_string(value) + ")");
  return static_cast<Index>(value);
}

// The number of an entity, a node or a row in messages: one-based, as in the mesh files (Gamma, gmsh).
template <class Integer>
std::string one_based(Integer i) {
  return std::to_string(static_cast<long long>(i) + 1);
}

}  // namespace hocav
