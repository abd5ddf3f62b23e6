#include "parallel/metrics_by_global_id.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "base/error.hpp"

namespace hocav {

HeldRuns::HeldRuns(Index held_first, Index held_count) {
  const std::vector<std::array<Index, 2>> runs = all_gather_value(std::array<Index, 2>{held_first, held_count});
  for (std::size_t p = 0; p < runs.size(); ++p)
    if (runs[p][1] > 0) starts_.push_back({runs[p][0], runs[p][0] + runs[p][1], static_cast<int>(p)});
  std::sort(starts_.begin(), starts_.end(), [](const Run& a, const Run& b) { return a.first < b.first; });
}

int HeldRuns::holder(Index id) const {
  auto after = std::upper_bound(starts_.begin(), starts_.end(), id, [](Index value, const Run& run) { return value < run.first; });
  if (after == starts_.begin() || id >= std::prev(after)->end)
    throw Error("values by vertex id: no process holds the value of vertex " + one_based(id));
  return std::prev(after)->process;
}

}  // namespace hocav
