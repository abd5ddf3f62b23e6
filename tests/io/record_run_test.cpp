#include "io/record_run.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace hocav {
namespace {

// The runs of any count cover the records end to end, their lengths differ by one at most, and
// slice_holding finds the run of every record.
TEST(RecordRun, RunsCoverTheRecordsEndToEndAndHoldWhatTheyCover) {
  for (const Index total : {0, 1, 5, 7, 100, 1001})
    for (const int count : {1, 2, 3, 4, 7, 16}) {
      Index next = 0, shortest = total, longest = 0;
      for (int index = 0; index < count; ++index) {
        const auto [first, last] = RecordRun{index, count}.of(total);
        EXPECT_EQ(first, next) << total << " records, run " << index << " of " << count;
        shortest = std::min(shortest, last - first);
        longest = std::max(longest, last - first);
        for (Index id = first; id < last; ++id) EXPECT_EQ(slice_holding(id, total, count), index) << id << " of " << total;
        next = last;
      }
      EXPECT_EQ(next, total);
      EXPECT_LE(longest - shortest, 1) << total << " records in " << count << " runs";
    }
  EXPECT_EQ(RecordRun{}.of(42), std::make_pair(Index{0}, Index{42}));  // one run: the whole file
}

}  // namespace
}  // namespace hocav
