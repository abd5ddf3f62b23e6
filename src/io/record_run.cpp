#include "io/record_run.hpp"

#include <algorithm>
#include <cstdint>

namespace hocav {

Index slice_start(Index total, int index, int count) { return static_cast<Index>(static_cast<std::int64_t>(total) * index / count); }

int slice_holding(Index id, Index total, int count) {
  int run = static_cast<int>(static_cast<std::int64_t>(id) * count / std::max<Index>(total, 1));
  while (run + 1 < count && slice_start(total, run + 1, count) <= id) ++run;
  while (run > 0 && slice_start(total, run, count) > id) --run;
  return run;
}

}  // namespace hocav
