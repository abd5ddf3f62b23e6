#include "adapt/conflict_batches.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace hocav {
namespace {

TEST(ConflictBatches, ItemsOfABatchTouchDisjointKeysAndEveryItemIsPlacedOnce) {
  std::mt19937 random(7);
  std::uniform_int_distribution<Index> key(0, 199);
  std::vector<std::vector<Index>> keys(500);
  ConflictBatches batches(200);
  for (Index item = 0; item < 500; ++item) {
    for (int i = 0; i < 4; ++i) keys[item].push_back(key(random));
    batches.place(item, keys[item]);
  }
  std::vector<int> seen(500, 0);
  for (const auto& batch : batches.batches()) {
    std::set<Index> touched;
    for (Index item : batch) {
      ++seen[item];
      for (Index k : std::set<Index>(keys[item].begin(), keys[item].end())) EXPECT_TRUE(touched.insert(k).second) << "key " << k;
    }
    EXPECT_TRUE(std::is_sorted(batch.begin(), batch.end()));  // placing order kept
  }
  for (Index item : batches.overflow()) ++seen[item];
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

TEST(ConflictBatches, AnItemGoesToTheFirstFreeBatchAndOverflowsAfterSixtyFour) {
  ConflictBatches batches(10);
  const Index shared[1] = {3};
  for (Index item = 0; item < 66; ++item) EXPECT_EQ(batches.place(item, shared), item < 64);
  EXPECT_EQ(batches.batches().size(), 64u);
  EXPECT_EQ(batches.overflow(), (std::vector<Index>{64, 65}));
  const Index other[2] = {4, 5};
  EXPECT_TRUE(batches.place(66, other));
  EXPECT_EQ(batches.batches()[0], (std::vector<Index>{0, 66}));
  batches.clear();  // a new round: every key free again
  EXPECT_TRUE(batches.batches().empty() && batches.overflow().empty());
  EXPECT_TRUE(batches.place(67, shared));
  EXPECT_EQ(batches.batches().size(), 1u);
}

}  // namespace
}  // namespace hocav
