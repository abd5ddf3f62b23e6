// Runs of a file's records: the cut every process of a distributed read or write makes of a
// keyword's entities (or a solution's rows), run `index` of `count` runs of nearly equal length.
#pragma once

#include <utility>

#include "base/index.hpp"

namespace hocav {

// The first entity of run `index` of `count` runs of `total` entities, and the run that holds
// entity `id`.
Index slice_start(Index total, int index, int count);
int slice_holding(Index id, Index total, int count);

// Run `index` of `count` (the defaults: one run, the whole file).
struct RecordRun {
  int index = 0, count = 1;
  // Its records [first, last) of `total`.
  std::pair<Index, Index> of(Index total) const { return {slice_start(total, index, count), slice_start(total, index + 1, count)}; }
};

}  // namespace hocav
