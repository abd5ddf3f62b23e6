// Batches of operations that may run at the same time: each operation names the keys it touches
// (elements, vertices) and goes to the first batch where none of them is taken yet, so that two
// operations of one batch touch disjoint sets. Greedy and in the operations' order, so the
// batches depend only on that order, never on the thread count (docs/adaptation.md §Threads).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "base/index.hpp"

namespace hocav {

class ConflictBatches {
 public:
  // Keys are in [0, key_count).
  explicit ConflictBatches(Index key_count) : taken_(static_cast<std::size_t>(key_count), 0) {}

  // Forgets every item placed, at the cost of the keys they touched (a round after another).
  void clear();

  // Places item `item` (touching `keys`) in the first batch free of them; false when none of the
  // 64 batches is (the item is then among overflow(), for the caller's next round).
  bool place(Index item, std::span<const Index> keys);
  // The items of each batch in their placing order, the first batch first.
  const std::vector<std::vector<Index>>& batches() const { return batches_; }
  const std::vector<Index>& overflow() const { return overflow_; }

 private:
  std::vector<std::uint64_t> taken_;  // per key: a bit per batch that touches it
  std::vector<Index> touched_;        // the keys whose bits are set
  std::vector<std::vector<Index>> batches_;
  std::vector<Index> overflow_;
};

}  // namespace hocav
