// Counting vertices that several processes hold, each by its global id.
#pragma once

#include <cstdint>
#include <vector>

#include "base/index.hpp"

namespace hocav {

// Collective: how many distinct ids all processes' `ids` name together (a vertex listed by every
// process that holds it counts once). Each id is counted by the process it hashes to.
Index distinct_count(const std::vector<Index>& ids);
// The same for 64-bit keys, such as an edge's two global ids in one word.
Index distinct_count(const std::vector<std::uint64_t>& keys);

}  // namespace hocav
